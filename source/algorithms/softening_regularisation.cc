#include <mpm_otm/algorithms/softening_regularisation.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/materials/material_library.h>

namespace MpmOtm
{
  template <int dim>
  void
  SofteningRegularisation<dim>::initialize(
    const MaterialLibrary<dim> &materials,
    const NodalSystem<dim>     &system)
  {
    offsets.clear();
    for (unsigned int id = 0; id < materials.n_materials(); ++id)
      {
        const unsigned int variable = materials[id].softening_variable();
        if (variable == numbers::invalid_unsigned_int)
          offsets.emplace_back(numbers::invalid_unsigned_int,
                               numbers::invalid_unsigned_int);
        else
          {
            // The equivalent plastic strain is the first internal variable
            // of the plastic models.
            const unsigned int first = materials.first_internal_variable(id);
            offsets.emplace_back(first, first + variable);
          }
      }
    weighted_strain.reinit(system.lumped_mass);
    weight.reinit(system.lumped_mass);
  }



  template <int dim>
  std::string
  SofteningRegularisation<dim>::description() const
  {
    return "softening regularisation: nodal average, the strength of a point "
           "softens with the average of the equivalent plastic strain over "
           "the support of its shape functions";
  }



  template <int dim>
  void
  SofteningRegularisation<dim>::update(MaterialPoints<dim> &material_points,
                                       const ParticleShapeData<dim> &shape_data)
  {
    using Layout    = PropertyLayout<dim>;
    weighted_strain = 0.;
    weight          = 0.;
    weighted_strain.zero_out_ghost_values();
    weight.zero_out_ghost_values();
    double *const strain_sums = weighted_strain.get_values();
    double *const weight_sums = weight.get_values();
    // Both passes visit the points of the softening materials with their
    // functions, their property arrays and the offsets of their strains.
    const auto for_each_softening_point = [&](const auto &action) {
      typename ParticleShapeData<dim>::Cursor functions(shape_data);
      for (auto &particle : material_points.particle_handler())
        {
          const auto point      = functions.next();
          const auto properties = particle.get_properties();
          const auto offset     = offsets[Layout::get_material_id(properties)];
          if (offset.second != numbers::invalid_unsigned_int)
            action(point, properties, offset.first, offset.second);
        }
    };

    for_each_softening_point([&](const auto        &point,
                                 const auto        &properties,
                                 const unsigned int plastic,
                                 const unsigned int) {
      const double volume = properties[Layout::initial_volume];
      const double strain = properties[plastic];
      for (unsigned int j = 0; j < point.n; ++j)
        {
          const double w = volume * point.values[j];
          strain_sums[point.indices[j]] += w * strain;
          weight_sums[point.indices[j]] += w;
        }
    });
    weighted_strain.compress(VectorOperation::add);
    weight.compress(VectorOperation::add);
    weighted_strain.update_ghost_values();
    weight.update_ghost_values();

    for_each_softening_point([&](const auto &point,
                                 const auto &properties,
                                 const unsigned int,
                                 const unsigned int softening) {
      double sum = 0., total = 0.;
      for (unsigned int j = 0; j < point.n; ++j)
        {
          const unsigned int i = point.indices[j];
          if (weight_sums[i] > 0.)
            {
              sum += point.values[j] * strain_sums[i] / weight_sums[i];
              total += point.values[j];
            }
        }
      if (total > 0.)
        properties[softening] = sum / total;
    });
  }



  template class SofteningRegularisation<1>;
  template class SofteningRegularisation<2>;
  template class SofteningRegularisation<3>;
} // namespace MpmOtm
