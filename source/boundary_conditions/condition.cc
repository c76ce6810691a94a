#include <mpm_otm/boundary_conditions/condition.h>

#include <algorithm>

namespace MpmOtm
{
  template <int dim>
  bool
  Condition<dim>::needs_normal() const
  {
    return false;
  }



  template <int dim>
  bool
  Condition<dim>::holds_nodes() const
  {
    return true;
  }



  template <int dim>
  bool
  Condition<dim>::needs_lumped_mass() const
  {
    return false;
  }



  template <int dim>
  void
  Condition<dim>::initialize(const ShapeFunctions<dim> &)
  {}



  template <int dim>
  Tensor<1, dim>
  Condition<dim>::add_loads(NodalSystem<dim> &, const double, const double)
  {
    return Tensor<1, dim>();
  }



  template <int dim>
  void
  Condition<dim>::check_run(const double) const
  {}



  template <int dim>
  std::array<bool, dim>
  Condition<dim>::constrained_components() const
  {
    return std::array<bool, dim>{};
  }



  template <int dim>
  void
  Condition<dim>::target_velocities(const double,
                                    std::vector<Tensor<1, dim>> &targets) const
  {
    std::fill(targets.begin(), targets.end(), Tensor<1, dim>());
  }



  template <int dim>
  std::vector<FixedComponents<dim>>
  Condition<dim>::fixed_components() const
  {
    return {};
  }



  template <int dim>
  bool
  Condition<dim>::moves() const
  {
    return false;
  }



  template <int dim>
  void
  Condition<dim>::prepare(const MaterialPoints<dim> &,
                          const ParticleShapeData<dim> &,
                          const NodalSystem<dim> &)
  {}



  template <int dim>
  void
  Condition<dim>::correct_accelerations(NodalSystem<dim> &,
                                        const double,
                                        const double)
  {}



  template <int dim>
  void
  Condition<dim>::correct_velocities(NodalSystem<dim> &, const double) const
  {}



  template <int dim>
  double
  Condition<dim>::advance(const std::vector<Tensor<1, dim>> &,
                          const double,
                          const double)
  {
    return 0.;
  }



  template <int dim>
  const ConditionNodes<dim> &
  Condition<dim>::nodes() const
  {
    return where;
  }



  template class Condition<1>;
  template class Condition<2>;
  template class Condition<3>;
} // namespace MpmOtm
