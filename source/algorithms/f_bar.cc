#include <mpm_otm/algorithms/f_bar.h>
#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <algorithm>
#include <cmath>

namespace MpmOtm
{
  namespace
  {
    /**
     * The mean stress tr(sigma) / 3 of the three-dimensional stress of a
     * point with the property array @p properties (sigma_zz of plane strain
     * in 2D).
     */
    template <int dim>
    double
    mean_stress(const double *properties)
    {
      using Layout = PropertyLayout<dim>;
      double sum =
        (dim < 3) ? (3 - dim) * properties[Layout::out_of_plane_stress] : 0.;
      for (unsigned int d = 0; d < dim; ++d)
        sum += properties[Layout::stress +
                          SymmetricTensor<2, dim>::component_to_unrolled_index(
                            TableIndices<2>(d, d))];
      return sum / 3.;
    }
  } // namespace



  template <int dim>
  void
  FBar<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  FBar<dim>::parse_parameters(ParameterHandler &)
  {
    AssertThrow(dim > 1,
                ExcMessage(
                  "Volumetric locking remedy = F-bar needs Dimension = 2 or "
                  "3: in 1D (uniaxial strain) the volume change is the only "
                  "strain, so there is no locking to remedy, and averaging it "
                  "would only smooth the solution. Use Volumetric locking "
                  "remedy = none (automatic chooses none in 1D)."));
  }



  template <int dim>
  void
  FBar<dim>::initialize(const ShapeFunctions<dim> &shape_functions,
                        const NodalSystem<dim> &,
                        const MaterialLibrary<dim> &materials)
  {
    this->materials = &materials;
    AssertThrow(!shape_functions.gradients_constant_on_cells(),
                ExcMessage(
                  "Volumetric locking remedy = F-bar: the gradients of "
                  "linear functions on triangles/tetrahedra are constant on "
                  "each cell, so every point of a cell has the same J "
                  "already and an average over the cell changes nothing. "
                  "Use Volumetric locking remedy = none (automatic does): "
                  "the crossed triangles of Mesh/Cell type = simplex do not "
                  "lock (manual, 'Volumetric locking'); for plastic flow on "
                  "other triangulations use quadrilaterals, B-splines or "
                  "Powell-Sabin splines."));
  }



  template <int dim>
  std::string
  FBar<dim>::description() const
  {
    return "volumetric locking remedy: F-bar, J = det F averaged over the "
           "points of each material in each cell";
  }



  template <int dim>
  void
  FBar<dim>::correct(const MaterialPoints<dim> &material_points,
                     const ParticleShapeData<dim> &,
                     const double                 dt,
                     std::vector<Tensor<2, dim>> &velocity_gradients)
  {
    using Layout            = PropertyLayout<dim>;
    const unsigned int n    = velocity_gradients.size();
    const auto         unit = unit_symmetric_tensor<dim>();
    trial_jacobian.resize(n);
    average_jacobian.resize(n);
    groups.clear();
    positions.resize(n);
    weight.resize(n);
    material.resize(n);

    unsigned int                                      p     = 0;
    unsigned int                                      first = 0;
    typename Triangulation<dim>::active_cell_iterator group_cell;
    for (const auto &particle : material_points.particle_handler())
      {
        const auto cell = particle.get_surrounding_cell();
        if (p == 0 || cell != group_cell)
          {
            average_group(first, p);
            first      = p;
            group_cell = cell;
          }
        const auto properties = particle.get_properties();
        trial_jacobian[p] =
          determinant(Layout::get_deformation_gradient(properties)) *
          determinant(unit + dt * velocity_gradients[p]);
        weight[p]    = properties[Layout::initial_volume];
        positions[p] = particle.get_location();
        // A point that has lost contact (a granular point opened beyond
        // its density at contact) is its own group: averaging the volume of
        // a dilated, stress-free point with that of its dense neighbours
        // would swell them, and their forces V_p sigma_p grad phi_i with
        // them.
        const unsigned int id = Layout::get_material_id(properties);
        material[p] =
          (*materials)[id].is_disconnected(
            ArrayView<const double>(properties.data() +
                                      materials->first_internal_variable(id),
                                    materials->n_internal_variables(id))) ?
            numbers::invalid_unsigned_int :
            id;
        ++p;
      }
    AssertDimension(p, n);
    average_group(first, n);

    // dFbar = (Jbar / J)^(1/dim) (I + dt L), Lbar = (dFbar - I) / dt. A point
    // whose Jacobian is not positive is left alone: the time step stops on
    // it with a message.
    for (unsigned int q = 0; q < n; ++q)
      if (trial_jacobian[q] > 0. && average_jacobian[q] > 0. &&
          average_jacobian[q] != trial_jacobian[q])
        {
          const double factor =
            std::pow(average_jacobian[q] / trial_jacobian[q], 1. / dim);
          velocity_gradients[q] =
            (factor * (unit + dt * velocity_gradients[q]) - unit) / dt;
        }
  }



  template <int dim>
  void
  FBar<dim>::average_group(const unsigned int first, const unsigned int end)
  {
    // Usually all points of a cell are of one material; otherwise each
    // material is averaged on its own, so that a stiff body does not take
    // the volume change of the soil beside it.
    for (unsigned int start = first; start < end; ++start)
      {
        if (material[start] == numbers::invalid_unsigned_int)
          {
            average_jacobian[start] = trial_jacobian[start];
            continue;
          }
        if (start > first &&
            std::find(material.begin() + first,
                      material.begin() + start,
                      material[start]) != material.begin() + start)
          continue;
        double weighted = 0., total = 0.;
        for (unsigned int q = start; q < end; ++q)
          if (material[q] == material[start])
            {
              weighted += weight[q] * trial_jacobian[q];
              total += weight[q];
            }
        const double average = weighted / total;
        for (unsigned int q = start; q < end; ++q)
          if (material[q] == material[start])
            average_jacobian[q] = average;
        groups.emplace_back(start, end);
      }
  }



  template <int dim>
  void
  FBar<dim>::after_stress_update(MaterialPoints<dim> &material_points)
  {
    using Layout = PropertyLayout<dim>;
    // The stresses of the points in the order of the particle handler.
    stress_views.clear();
    for (auto &particle : material_points.particle_handler())
      stress_views.push_back(particle.get_properties().data());
    AssertDimension(stress_views.size(), material.size());
    for (const auto &[first, end] : groups)
      {
        if (end - first < 2)
          continue;
        const unsigned int id = material[first];
        // Weighted least squares p = a + b . (x - x_c) over the group's
        // points, x_c their centroid: a is the mean, b the gradient (zero if
        // the points do not span the cell).
        double     total = 0., a = 0.;
        Point<dim> centre;
        for (unsigned int q = first; q < end; ++q)
          if (material[q] == id)
            {
              const double p = mean_stress<dim>(stress_views[q]);
              total += weight[q];
              a += weight[q] * p;
              centre += weight[q] * positions[q];
            }
        a /= total;
        centre /= total;
        SymmetricTensor<2, dim> moments;
        Tensor<1, dim>          right_hand_side;
        for (unsigned int q = first; q < end; ++q)
          if (material[q] == id)
            {
              const Tensor<1, dim> d = positions[q] - centre;
              moments += weight[q] * symmetrize(outer_product(d, d));
              right_hand_side +=
                weight[q] * (mean_stress<dim>(stress_views[q]) - a) * d;
            }
        Tensor<1, dim> gradient;
        const double   scale = trace(moments);
        if (scale > 0. && determinant(moments) >
                            1e-6 * Utilities::fixed_power<dim>(scale / dim))
          gradient = invert(moments) * right_hand_side;
        for (unsigned int q = first; q < end; ++q)
          if (material[q] == id)
            {
              double *const properties = stress_views[q];
              const double  change = a + gradient * (positions[q] - centre) -
                                    mean_stress<dim>(properties);
              for (unsigned int d = 0; d < dim; ++d)
                properties[Layout::stress +
                           SymmetricTensor<2, dim>::component_to_unrolled_index(
                             TableIndices<2>(d, d))] += change;
              if (dim < 3)
                properties[Layout::out_of_plane_stress] += change;
            }
      }
  }



  template class FBar<1>;
  template class FBar<2>;
  template class FBar<3>;
} // namespace MpmOtm

#define MPM_OTM_F_BAR_DESCRIPTION                                             \
  "the F-bar method: each point keeps the isochoric part of its deformation " \
  "gradient and takes the average of J = det F over the points of its "       \
  "material in its cell"

MPM_OTM_REGISTER_PLUGIN(MpmOtm::VolumetricLockingRemedy<1>,
                        MpmOtm::FBar<1>,
                        "F-bar",
                        MPM_OTM_F_BAR_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::VolumetricLockingRemedy<2>,
                        MpmOtm::FBar<2>,
                        "F-bar",
                        MPM_OTM_F_BAR_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::VolumetricLockingRemedy<3>,
                        MpmOtm::FBar<3>,
                        "F-bar",
                        MPM_OTM_F_BAR_DESCRIPTION)
