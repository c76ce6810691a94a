#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/problems/body_seeder.h>
#include <mpm_otm/problems/problem.h>

#include <algorithm>

namespace MpmOtm
{
  template <int dim>
  BodySeeder<dim>::BodySeeder(const Problem<dim>         &problem,
                              const MaterialLibrary<dim> &materials)
    : problem(problem)
    , materials(materials)
  {}



  template <int dim>
  unsigned int
  BodySeeder<dim>::n_bodies() const
  {
    return problem.n_bodies();
  }



  template <int dim>
  std::string
  BodySeeder<dim>::body_name(const unsigned int body) const
  {
    return problem.body_name(body);
  }



  template <int dim>
  unsigned int
  BodySeeder<dim>::body_containing(const Point<dim> &X) const
  {
    return problem.body_containing(X);
  }



  template <int dim>
  unsigned int
  BodySeeder<dim>::n_properties() const
  {
    return materials.n_properties();
  }



  template <int dim>
  void
  BodySeeder<dim>::set_properties(const Point<dim>    &X,
                                  const unsigned int   body,
                                  const double         volume,
                                  std::vector<double> &properties) const
  {
    using Layout = PropertyLayout<dim>;
    std::fill(properties.begin(), properties.end(), 0.);
    const unsigned int material_id  = problem.material_id(body);
    properties[Layout::material_id] = material_id;
    properties[Layout::mass]        = materials[material_id].density() * volume;
    const auto [sigma, out_of_plane] = problem.initial_stress(X, body);
    Layout::set_stress(ArrayView<double>(properties), sigma);
    if (dim < 3)
      properties[Layout::out_of_plane_stress] = out_of_plane;
    properties[Layout::initial_volume] = volume;
    const Tensor<1, dim> v0            = problem.initial_velocity(X);
    for (unsigned int d = 0; d < dim; ++d)
      {
        properties[Layout::initial_position + d]               = X[d];
        properties[Layout::velocity + d]                       = v0[d];
        properties[Layout::deformation_gradient + d * dim + d] = 1.;
      }
  }



  template <int dim>
  std::vector<types::boundary_id>
  BodySeeder<dim>::traction_boundaries() const
  {
    return problem.traction_boundaries();
  }



  template <int dim>
  BoundingBox<dim>
  BodySeeder<dim>::material_region() const
  {
    return problem.material_region();
  }



  template class BodySeeder<1>;
  template class BodySeeder<2>;
  template class BodySeeder<3>;
} // namespace MpmOtm
