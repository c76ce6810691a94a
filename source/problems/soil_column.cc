#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/materials/material.h>
#include <mpm_otm/problems/soil_column.h>

#include <cmath>

namespace MpmOtm
{
  template <int dim>
  void
  SoilColumn<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Soil column");
    prm.declare_entry("Gravity",
                      "-9.81",
                      Patterns::Double(),
                      "Gravitational acceleration g in the last coordinate "
                      "direction (m/s^2; negative points down).");
    prm.declare_entry("Series terms",
                      "400",
                      Patterns::Integer(1),
                      "Number of terms of the exact series solution.");
    prm.declare_entry("Column height",
                      "0",
                      Patterns::Double(0.),
                      "Height H of the column, from the grid's bottom; the "
                      "grid above it stays empty (partial lumping needs "
                      "empty cells above the free top, thesis Sect. 5.4). "
                      "0: the grid's height.");
    prm.leave_subsection();
  }



  template <int dim>
  void
  SoilColumn<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Soil column");
    gravity          = prm.get_double("Gravity");
    n_terms          = prm.get_integer("Series terms");
    requested_height = prm.get_double("Column height");
    prm.leave_subsection();
  }



  template <int dim>
  void
  SoilColumn<dim>::initialize(const Material<dim>       &material,
                              const BackgroundGrid<dim> &grid)
  {
    Problem<dim>::initialize(material, grid);
    const BoundingBox<dim> &box         = grid.box();
    const double            grid_height = box.side_length(dim - 1);
    AssertThrow(requested_height <= grid_height * (1. + 1e-12),
                ExcMessage("Soil column/Column height = " +
                           Utilities::to_string(requested_height) +
                           " exceeds the grid's height " +
                           Utilities::to_string(grid_height) +
                           ": set it to at most that, or 0 for the grid's "
                           "height, or raise Mesh/Upper corner."));
    height  = requested_height > 0. ? requested_height : grid_height;
    bottom  = box.get_boundary_points().first[dim - 1];
    c       = material.wave_speed();
    rho     = material.density();
    lateral = material.lambda() / (material.lambda() + 2. * material.mu());
  }



  template <int dim>
  BoundingBox<dim>
  SoilColumn<dim>::material_region() const
  {
    auto corners            = this->grid_box.get_boundary_points();
    corners.second[dim - 1] = bottom + height;
    return BoundingBox<dim>(corners);
  }



  template <int dim>
  Tensor<1, dim>
  SoilColumn<dim>::initial_velocity(const Point<dim> &) const
  {
    return Tensor<1, dim>();
  }



  template <int dim>
  bool
  SoilColumn<dim>::has_body_force() const
  {
    return true;
  }



  template <int dim>
  Tensor<1, dim>
  SoilColumn<dim>::body_force(const Point<dim> &, const double) const
  {
    Tensor<1, dim> g;
    g[dim - 1] = gravity;
    return g;
  }



  template <int dim>
  std::vector<FixedComponents<dim>>
  SoilColumn<dim>::fixed_components() const
  {
    // The base clamped, the walls rollers.
    std::vector<FixedComponents<dim>> result{
      FixedComponents<dim>::all(2 * (dim - 1))};
    for (unsigned int side = 0; side < 2 * (dim - 1); ++side)
      result.push_back(FixedComponents<dim>::normal(side));
    return result;
  }



  template <int dim>
  bool
  SoilColumn<dim>::has_exact_solution() const
  {
    return true;
  }



  template <int dim>
  Tensor<1, dim>
  SoilColumn<dim>::exact_displacement(const Point<dim> &X,
                                      const double      time) const
  {
    const double y   = X[dim - 1] - bottom;
    double       sum = 0;
    for (unsigned int n = 1; n <= n_terms; ++n)
      {
        const double m = 2. * n - 1.;
        const double k = m * numbers::PI / (2. * height);
        sum += 16. * height * height / (m * m * m * std::pow(numbers::PI, 3)) *
               (1. - std::cos(c * k * time)) * std::sin(k * y);
      }
    Tensor<1, dim> u;
    u[dim - 1] = gravity / (c * c) * sum;
    return u;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  SoilColumn<dim>::exact_stress(const Point<dim> &X, const double time) const
  {
    const double y   = X[dim - 1] - bottom;
    double       sum = 0;
    for (unsigned int n = 1; n <= n_terms; ++n)
      {
        const double m = 2. * n - 1.;
        const double k = m * numbers::PI / (2. * height);
        sum += 16. * height * height / (m * m * m * std::pow(numbers::PI, 3)) *
               (1. - std::cos(c * k * time)) * k * std::cos(k * y);
      }
    SymmetricTensor<2, dim> sigma;
    sigma[dim - 1][dim - 1] = rho * gravity * sum;
    for (unsigned int d = 0; d + 1 < dim; ++d)
      sigma[d][d] = lateral * sigma[dim - 1][dim - 1];
    return sigma;
  }



  template class SoilColumn<1>;
  template class SoilColumn<2>;
  template class SoilColumn<3>;
} // namespace MpmOtm

#define MPM_OTM_SOIL_COLUMN_DESCRIPTION \
  "column under self-weight, fixed bottom, free top (B6)"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<1>,
                        MpmOtm::SoilColumn<1>,
                        "soil column",
                        MPM_OTM_SOIL_COLUMN_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<2>,
                        MpmOtm::SoilColumn<2>,
                        "soil column",
                        MPM_OTM_SOIL_COLUMN_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<3>,
                        MpmOtm::SoilColumn<3>,
                        "soil column",
                        MPM_OTM_SOIL_COLUMN_DESCRIPTION)
