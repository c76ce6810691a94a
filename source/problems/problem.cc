#include <deal.II/base/utilities.h>

#include <mpm_otm/materials/material.h>
#include <mpm_otm/problems/problem.h>

namespace MpmOtm
{
  template <int dim>
  void
  Problem<dim>::initialize(const Material<dim> &, const BoundingBox<dim> &box)
  {
    grid_box = box;
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
        AssertThrow(id >= 0 && id < static_cast<int>(2 * dim),
                    ExcMessage(entry + ": boundary id <" + parts[0] +
                               "> must be between 0 and " +
                               std::to_string(2 * dim - 1) + "."));
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
