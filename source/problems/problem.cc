#include <deal.II/base/utilities.h>

#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/problems/problem.h>

namespace MpmOtm
{
  template <int dim>
  void
  Problem<dim>::declare_common_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Gravity");
    prm.declare_entry("Vector",
                      "0",
                      Patterns::List(Patterns::Double(), 1, dim),
                      "Gravitational acceleration g (m/s^2), one value per "
                      "direction, e.g. '0, -9.81' (a single value: the same "
                      "in every direction; 0: no gravity). It acts on every "
                      "material point as the body force m g, in addition to "
                      "the problem's own body force.");
    prm.declare_entry("Ramp time",
                      "0",
                      Patterns::Double(0.),
                      "Gravity grows linearly from 0 to its full value over "
                      "this time (s) from t = 0; 0: full from the start.");
    prm.leave_subsection();
  }



  template <int dim>
  void
  Problem<dim>::parse(ParameterHandler           &prm,
                      const MaterialLibrary<dim> &material_library)
  {
    materials = &material_library;
    prm.enter_subsection("Gravity");
    const auto values = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Vector")));
    gravity_ramp_time = prm.get_double("Ramp time");
    prm.leave_subsection();
    AssertThrow(values.size() == 1 || values.size() == dim,
                ExcMessage("Gravity/Vector needs one value or " +
                           std::to_string(dim) +
                           " values (one per direction)."));
    for (unsigned int d = 0; d < dim; ++d)
      gravity_vector[d] = values.size() == dim ? values[d] : values[0];
    parse_parameters(prm);
    loads.parse_parameters(prm);
  }



  template <int dim>
  const SurfaceLoads<dim> &
  Problem<dim>::surface_loads() const
  {
    return loads;
  }



  template <int dim>
  SurfaceLoads<dim> &
  Problem<dim>::surface_loads()
  {
    return loads;
  }



  template <int dim>
  Tensor<1, dim>
  Problem<dim>::gravity(const double time) const
  {
    if (gravity_ramp_time > 0. && time < gravity_ramp_time)
      return (time / gravity_ramp_time) * gravity_vector;
    return gravity_vector;
  }



  template <int dim>
  bool
  Problem<dim>::has_gravity() const
  {
    return gravity_vector.norm() > 0.;
  }



  template <int dim>
  void
  Problem<dim>::set_gravity(const Tensor<1, dim> &g)
  {
    gravity_vector    = g;
    gravity_ramp_time = 0.;
  }



  template <int dim>
  unsigned int
  Problem<dim>::n_bodies() const
  {
    return 1;
  }



  template <int dim>
  std::string
  Problem<dim>::body_name(const unsigned int) const
  {
    return "material region";
  }



  template <int dim>
  unsigned int
  Problem<dim>::body_containing(const Point<dim> &X) const
  {
    return material_region().point_inside(X) ? 0 :
                                               numbers::invalid_unsigned_int;
  }



  template <int dim>
  unsigned int
  Problem<dim>::material_id(const unsigned int) const
  {
    return 0;
  }



  template <int dim>
  std::pair<SymmetricTensor<2, dim>, double>
  Problem<dim>::initial_stress(const Point<dim> &, const unsigned int) const
  {
    return {SymmetricTensor<2, dim>(), 0.};
  }

  template <int dim>
  void
  Problem<dim>::set_present_bodies(const std::vector<bool> &)
  {}



  template <int dim>
  bool
  Problem<dim>::runs_on_any_grid() const
  {
    return false;
  }



  template <int dim>
  bool
  Problem<dim>::defines_bodies() const
  {
    return false;
  }



  template <int dim>
  void
  Problem<dim>::initialize(const Material<dim> &,
                           const BackgroundGrid<dim> &grid)
  {
    grid_box = grid.box();
  }



  template <int dim>
  BoundingBox<dim>
  Problem<dim>::material_region() const
  {
    return grid_box;
  }



  template <int dim>
  bool
  Problem<dim>::has_body_force() const
  {
    return false;
  }



  template <int dim>
  Tensor<1, dim>
  Problem<dim>::body_force(const Point<dim> &, const double) const
  {
    return Tensor<1, dim>();
  }



  template <int dim>
  std::vector<types::boundary_id>
  Problem<dim>::traction_boundaries() const
  {
    return {};
  }



  template <int dim>
  Tensor<1, dim>
  Problem<dim>::traction(const types::boundary_id, const double) const
  {
    return Tensor<1, dim>();
  }



  template <int dim>
  bool
  Problem<dim>::has_exact_solution() const
  {
    return false;
  }



  template <int dim>
  bool
  Problem<dim>::has_exact_stress() const
  {
    return has_exact_solution();
  }



  template <int dim>
  Tensor<1, dim>
  Problem<dim>::exact_displacement(const Point<dim> &, const double) const
  {
    AssertThrow(false, ExcMessage("This problem has no exact solution."));
    return Tensor<1, dim>();
  }



  template <int dim>
  SymmetricTensor<2, dim>
  Problem<dim>::exact_stress(const Point<dim> &, const double) const
  {
    AssertThrow(false, ExcMessage("This problem has no exact solution."));
    return SymmetricTensor<2, dim>();
  }



  template <int dim>
  std::vector<FixedComponents<dim>>
  Problem<dim>::parse_fixed_components(const std::string &text,
                                       const std::string &entry)
  {
    const std::string                 names = std::string("xyz").substr(0, dim);
    std::vector<FixedComponents<dim>> result;
    for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        const auto parts = Utilities::split_string_list(item, ':');
        AssertThrow(parts.size() == 2,
                    ExcMessage(entry + ": <" + item +
                               "> is not of the form 'boundary id: "
                               "components', e.g. '0: x, y; 2: y'."));
        FixedComponents<dim> fixed;
        const int            id = Utilities::string_to_int(parts[0]);
        AssertThrow(id >= 0,
                    ExcMessage(entry + ": boundary id <" + parts[0] +
                               "> must be a non-negative integer (box "
                               "grids: 0 to " +
                               std::to_string(2 * dim - 1) +
                               "; Mesh file: its physical tags)."));
        fixed.boundary_id = id;
        fixed.fixed.fill(false);
        for (const auto &component : Utilities::split_string_list(parts[1]))
          {
            const auto position = names.find(component);
            AssertThrow(component.size() == 1 && position != std::string::npos,
                        ExcMessage(entry + ": component <" + component +
                                   "> must be one of " + names + "."));
            fixed.fixed[position] = true;
          }
        result.push_back(fixed);
      }
    return result;
  }



  template class Problem<1>;
  template class Problem<2>;
  template class Problem<3>;
} // namespace MpmOtm
