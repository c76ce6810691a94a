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
    models.clear();
    for (unsigned int id = 0; id < materials.n_materials(); ++id)
      models.push_back({&materials[id],
                        materials.first_internal_variable(id),
                        materials.n_internal_variables(id),
                        materials[id].can_lose_contact()});
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
  FBar<dim>::correct(MaterialPoints<dim>          &material_points,
                     const ParticleShapeData<dim> &shape_data,
                     const double                  dt,
                     std::vector<Tensor<2, dim>>  &velocity_gradients)
  {
    using Layout            = PropertyLayout<dim>;
    const unsigned int n    = velocity_gradients.size();
    const auto         unit = unit_symmetric_tensor<dim>();
    trial_jacobian.resize(n);
    average_jacobian.resize(n);
    groups.clear();
    groups.reserve(shape_data.n_batches());
    positions.resize(n);
    stress_views.resize(n);
    pressure.resize(n);
    weight.resize(n);
    material.resize(n);

    // The points of a cell are a batch of the shape data (the families
    // start a batch per cell), which saves asking every point for its cell.
    unsigned int p     = 0;
    unsigned int batch = 0;
#ifdef DEBUG
    typename Triangulation<dim>::active_cell_iterator batch_cell;
#endif
    for (auto &particle : material_points.particle_handler())
      {
        if (batch < shape_data.n_batches() &&
            p == shape_data.first_particle(batch))
          {
            if (batch > 0)
              average_group(shape_data.first_particle(batch - 1), p);
            ++batch;
#ifdef DEBUG
            batch_cell = particle.get_surrounding_cell();
#endif
          }
#ifdef DEBUG
        Assert(particle.get_surrounding_cell() == batch_cell,
               ExcMessage("A batch of shape data spans two cells."));
#endif
        const auto properties = particle.get_properties();
        stress_views[p]       = properties.data();
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
        const unsigned int id    = Layout::get_material_id(properties);
        const auto        &model = models[id];
        material[p] =
          (model.may_lose_contact &&
           model.material->is_disconnected(
             ArrayView<const double>(properties.data() + model.first_variable,
                                     model.n_variables))) ?
            numbers::invalid_unsigned_int :
            id;
        ++p;
      }
    if (batch > 0)
      average_group(shape_data.first_particle(batch - 1), n);
    AssertDimension(p, n);

    // dFbar = (Jbar / J)^(1/dim) (I + dt L), Lbar = (dFbar - I) / dt. A point
    // whose Jacobian is not positive is left alone: the time step stops on
    // it with a message.
    for (unsigned int q = 0; q < n; ++q)
      if (trial_jacobian[q] > 0. && average_jacobian[q] > 0. &&
          average_jacobian[q] != trial_jacobian[q])
        {
          const double ratio  = average_jacobian[q] / trial_jacobian[q];
          const double factor = (dim == 2) ? std::sqrt(ratio) :
                                (dim == 3) ? std::cbrt(ratio) :
                                             ratio;
          velocity_gradients[q] =
            (factor * (unit + dt * velocity_gradients[q]) - unit) / dt;
        }
  }



  template <int dim>
  void
  FBar<dim>::average_group(const unsigned int first, const unsigned int end)
  {
    // Usually all points of a cell are of one material and in contact.
    bool uniform = material[first] != numbers::invalid_unsigned_int;
    for (unsigned int q = first + 1; q < end && uniform; ++q)
      uniform = (material[q] == material[first]);
    if (uniform)
      {
        double weighted = 0., total = 0.;
        for (unsigned int q = first; q < end; ++q)
          {
            weighted += weight[q] * trial_jacobian[q];
            total += weight[q];
          }
        std::fill(average_jacobian.begin() + first,
                  average_jacobian.begin() + end,
                  weighted / total);
        groups.emplace_back(first, end);
        return;
      }
    // Otherwise each material is averaged on its own, so that a stiff body
    // does not take the volume change of the soil beside it.
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
  FBar<dim>::after_stress_update(MaterialPoints<dim> &)
  {
    using Layout = PropertyLayout<dim>;
    // The property arrays of correct() hold the updated stresses.
    for (const auto &[first, end] : groups)
      {
        if (end - first < 2)
          continue;
        const unsigned int id = material[first];
        // Weighted least squares p = a + b . (x - x_c) over the group's
        // points, x_c their centroid: a is the mean, b the gradient (zero if
        // the points do not span the cell). One pass for the sums of w,
        // w x, w x x^T, w p and w p x, relative to the group's first point.
        const Point<dim>        origin = positions[first];
        double                  total = 0., a = 0.;
        Tensor<1, dim>          centre, weighted_pressure;
        SymmetricTensor<2, dim> moments;
        for (unsigned int q = first; q < end; ++q)
          if (material[q] == id)
            {
              const double         w = weight[q];
              const Tensor<1, dim> x = positions[q] - origin;
              pressure[q]            = mean_stress<dim>(stress_views[q]);
              total += w;
              a += w * pressure[q];
              centre += w * x;
              weighted_pressure += (w * pressure[q]) * x;
              moments += w * symmetrize(outer_product(x, x));
            }
        a /= total;
        centre /= total;
        moments -= total * symmetrize(outer_product(centre, centre));
        const Tensor<1, dim> right_hand_side =
          weighted_pressure - (total * a) * centre;
        Tensor<1, dim> gradient;
        const double   scale = trace(moments);
        if (scale > 0. && determinant(moments) >
                            1e-6 * Utilities::fixed_power<dim>(scale / dim))
          gradient = invert(moments) * right_hand_side;
        for (unsigned int q = first; q < end; ++q)
          if (material[q] == id)
            {
              double *const properties = stress_views[q];
              const double  change =
                a + gradient * (positions[q] - origin - centre) - pressure[q];
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
