#include <deal.II/base/symmetric_tensor.h>

#include <mpm_otm/algorithms/particle_transfer.h>
#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <cmath>

namespace MpmOtm
{
  namespace
  {
    /**
     * The inverse of the symmetric positive semi-definite @p D, or its
     * pseudo-inverse if D is nearly singular: directions whose eigenvalue is
     * below 1e-12 of the largest (a point on a grid line of linear
     * functions, where no function reaches beyond it) are left out, as the
     * velocity has no slope to transfer there.
     */
    template <int dim>
    Tensor<2, dim>
    pseudo_inverse(const SymmetricTensor<2, dim> &D)
    {
      Tensor<2, dim> result;
      if constexpr (dim == 1)
        {
          if (D[0][0] > 0.)
            result[0][0] = 1. / D[0][0];
        }
      else if (determinant(D) > 1e-6 * std::pow(trace(D) / dim, dim))
        result = invert(Tensor<2, dim>(D));
      else
        {
          const auto   eigen   = eigenvectors(D);
          const double largest = eigen[0].first;
          for (const auto &[value, vector] : eigen)
            if (value > 1e-12 * largest)
              result += outer_product(vector, vector) / value;
        }
      return result;
    }
  } // namespace



  template <int dim>
  void
  ParticleTransfer<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Particle velocity",
      "FLIP",
      Patterns::Selection("FLIP|PIC|blend|APIC"),
      "How the material points' velocities follow the grid in MPM and the "
      "unified approach (USL and MUSL): FLIP (v_p += dt sum_i phi_i a_i, the "
      "sources' rule: keeps the kinetic energy, and the grid's ringing), "
      "PIC (v_p = sum_i phi_i v_i: damps every motion the grid cannot "
      "carry, strongly), blend ('FLIP fraction' FLIP + the rest PIC, "
      "Stomakhin et al. 2013) or APIC (PIC with an affine velocity per "
      "point, Jiang et al. 2015: conserves the angular momentum and damps "
      "far less than PIC; fixed grids and lumped mass only). PIC's "
      "velocity is sum_i phi_i v_i of the grid's own update, M^-1 q + dt "
      "a, also under MUSL, which then projects the new velocities. OTM "
      "takes the points' velocities from their displacements and takes "
      "only FLIP here.");
    prm.declare_entry("FLIP fraction",
                      "0.99",
                      Patterns::Double(0., 1.),
                      "The weight of FLIP's velocity in Particle velocity = "
                      "blend (1: FLIP, 0: PIC).");
  }



  template <int dim>
  void
  ParticleTransfer<dim>::parse_parameters(ParameterHandler &prm)
  {
    rule = prm.get("Particle velocity");
    if (rule == "FLIP")
      flip_weight = 1.;
    else if (rule == "blend")
      flip_weight = prm.get_double("FLIP fraction");
    else
      flip_weight = 0.;
  }



  template <int dim>
  void
  ParticleTransfer<dim>::check(const NodalUpdate<dim> &nodal_update,
                               const std::string      &method,
                               const bool              fixed_grid,
                               const bool              lumped_mass) const
  {
    using ParticleVelocity = typename NodalUpdate<dim>::ParticleVelocity;
    if (rule == "FLIP")
      return;
    const std::string entry = "Particle velocity = " + rule + ": ";
    AssertThrow(
      nodal_update.particle_velocity() != ParticleVelocity::from_displacement,
      ExcMessage(entry + "Method = " + method +
                 " moves the points with the nodal displacements and takes "
                 "their velocities from them (journal Eq. 49), so it has no "
                 "other rule. Remove the entry, or use Method = MPM."));
    AssertThrow(!is_affine() || fixed_grid,
                ExcMessage(entry + "Method = " + method +
                           " moves the grid, and APIC's transfer needs the "
                           "points of the functions where they were in the "
                           "step before. Use Method = MPM, or Particle "
                           "velocity = PIC or blend."));
    AssertThrow(!is_affine() || lumped_mass,
                ExcMessage(entry +
                           "APIC's transfer adds affine momenta to the "
                           "row-sum lumped masses; a consistent (or "
                           "partially lumped) mass matrix projects the "
                           "points' velocities onto the functions, which "
                           "carries affine velocity fields already (PIC "
                           "with it loses almost nothing: doc/benchmarks.md, "
                           "'Particle velocity rules'). Use Mass matrix = "
                           "lumped, or Particle velocity = PIC."));
  }



  template <int dim>
  void
  ParticleTransfer<dim>::reserve_point_variables(
    MaterialLibrary<dim> &materials)
  {
    if (!is_affine())
      return;
    std::vector<std::string> names;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        names.push_back("apic_B_" + std::to_string(i) + std::to_string(j));
    first_slot = materials.add_point_variables(names);
  }



  template <int dim>
  void
  ParticleTransfer<dim>::initialize(
    const ShapeFunctions<dim>         &shape_functions,
    const Utilities::MPI::Partitioner &partitioner)
  {
    if (!is_affine())
      return;
    const bool found =
      shape_functions.function_points(partitioner, function_points);
    stop_if_any_rank_failed(
      partitioner.get_mpi_communicator(),
      found ? "" :
              "these shape functions do not belong to points x_i with "
              "sum_i phi_i(x) x_i = x (Powell-Sabin splines combine three "
              "functions per vertex), and APIC transfers the affine "
              "velocity with them. ",
      "Particle velocity = APIC: ",
      "Use Shape functions = linear, B-spline or max-ent, or Particle "
      "velocity = PIC or blend.");
  }



  template <int dim>
  double
  ParticleTransfer<dim>::flip_fraction() const
  {
    return flip_weight;
  }



  template <int dim>
  bool
  ParticleTransfer<dim>::is_affine() const
  {
    return rule == "APIC";
  }



  template <int dim>
  typename NodalUpdate<dim>::ParticleVelocity
  ParticleTransfer<dim>::velocity_for_stability(
    const typename NodalUpdate<dim>::ParticleVelocity particle_velocity) const
  {
    using ParticleVelocity = typename NodalUpdate<dim>::ParticleVelocity;
    if (rule == "PIC" &&
        particle_velocity == ParticleVelocity::from_acceleration)
      return ParticleVelocity::from_displacement;
    return particle_velocity;
  }



  template <int dim>
  std::string
  ParticleTransfer<dim>::description() const
  {
    if (rule == "blend")
      return "particle velocity: blend of " +
             Utilities::to_string(flip_weight) + " FLIP and " +
             Utilities::to_string(1. - flip_weight) + " PIC";
    return "particle velocity: " + rule;
  }



  template <int dim>
  Tensor<2, dim>
  ParticleTransfer<dim>::affine_velocity(
    const ArrayView<const double> &properties) const
  {
    Tensor<2, dim> B;
    if (is_affine())
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          B[i][j] = properties[first_slot + i * dim + j];
    return B;
  }



  template <int dim>
  void
  ParticleTransfer<dim>::add_affine_momentum(
    const MaterialPoints<dim>    &material_points,
    const ParticleShapeData<dim> &shape_data,
    NodalSystem<dim>             &system) const
  {
    if (!is_affine())
      return;
    using Layout = PropertyLayout<dim>;
    double *q[dim];
    for (unsigned int c = 0; c < dim; ++c)
      q[c] = system.momentum[c].get_values();
    typename ParticleShapeData<dim>::Cursor functions(shape_data);
    for (const auto &particle : material_points.particle_handler())
      {
        const auto              properties = particle.get_properties();
        const Point<dim>       &x          = particle.get_location();
        const auto              point      = functions.next();
        SymmetricTensor<2, dim> D;
        for (unsigned int j = 0; j < point.n; ++j)
          {
            const Tensor<1, dim> d = function_points[point.indices[j]] - x;
            D += point.values[j] * symmetrize(outer_product(d, d));
          }
        const Tensor<2, dim> C =
          properties[Layout::mass] *
          (affine_velocity(properties) * pseudo_inverse(D));
        for (unsigned int j = 0; j < point.n; ++j)
          {
            const Tensor<1, dim> momentum =
              point.values[j] * (C * (function_points[point.indices[j]] - x));
            for (unsigned int c = 0; c < dim; ++c)
              q[c][point.indices[j]] += momentum[c];
          }
      }
  }



  template <int dim>
  void
  ParticleTransfer<dim>::store_affine_velocity(
    const ArrayView<double>                               &properties,
    const Point<dim>                                      &location,
    const typename ParticleShapeData<dim>::PointFunctions &point,
    const Tensor<1, dim> *nodal_velocities) const
  {
    Tensor<2, dim> B;
    for (unsigned int j = 0; j < point.n; ++j)
      B += point.values[j] *
           outer_product(nodal_velocities[j],
                         function_points[point.indices[j]] - location);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        properties[first_slot + i * dim + j] = B[i][j];
  }



  template <int dim>
  void
  ParticleTransfer<dim>::add_affine_angular_momentum(
    const MaterialPoints<dim> &material_points,
    double                     angular_momentum[3]) const
  {
    if (!is_affine() || dim == 1)
      return;
    // (d x v)_k = eps_kij d_i v_j = eps_kij B_ji for B = sum phi v d^T.
    double sums[3] = {0, 0, 0};
    for (const auto &particle : material_points.particle_handler())
      {
        const auto           properties = particle.get_properties();
        const double         m          = properties[PropertyLayout<dim>::mass];
        const Tensor<2, dim> B          = affine_velocity(properties);
        if constexpr (dim == 2)
          sums[2] += m * (B[1][0] - B[0][1]);
        if constexpr (dim == 3)
          for (unsigned int k = 0; k < 3; ++k)
            sums[k] +=
              m * (B[(k + 2) % 3][(k + 1) % 3] - B[(k + 1) % 3][(k + 2) % 3]);
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 3),
                        material_points.communicator(),
                        ArrayView<double>(sums, 3));
    for (unsigned int k = 0; k < 3; ++k)
      angular_momentum[k] += sums[k];
  }



  template class ParticleTransfer<1>;
  template class ParticleTransfer<2>;
  template class ParticleTransfer<3>;
} // namespace MpmOtm
