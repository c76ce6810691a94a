#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid_system/lumped_mass_matrix.h>

namespace MpmOtm
{
  template <int dim>
  void
  LumpedMassMatrix<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  bool
  LumpedMassMatrix<dim>::is_lumped() const
  {
    return true;
  }



  template <int dim>
  void
  LumpedMassMatrix<dim>::vmult(const NodalSystem<dim> &system,
                               const ParticleShapeData<dim> &,
                               const VectorType &vector,
                               VectorType       &product) const
  {
    for (unsigned int i = 0; i < product.locally_owned_size(); ++i)
      product.local_element(i) =
        system.lumped_mass.local_element(i) * vector.local_element(i);
  }



  template <int dim>
  void
  LumpedMassMatrix<dim>::solve(
    const NodalSystem<dim> &system,
    const ParticleShapeData<dim> &,
    const VectorType                &right_hand_side,
    VectorType                      &solution,
    const AffineConstraints<double> &constraints) const
  {
    const VectorType &mass = system.lumped_mass;
    for (unsigned int i = 0; i < solution.locally_owned_size(); ++i)
      {
        const double m = mass.local_element(i);
        solution.local_element(i) =
          (m > 0.) ? right_hand_side.local_element(i) / m : 0.;
      }
    for (const auto &line : constraints.get_lines())
      solution(line.index) = line.inhomogeneity;
  }



  template class LumpedMassMatrix<1>;
  template class LumpedMassMatrix<2>;
  template class LumpedMassMatrix<3>;
} // namespace MpmOtm

#define MPM_OTM_LUMPED_DESCRIPTION "row-sum lumped (journal Eq. 17)"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::MassMatrix<1>,
                        MpmOtm::LumpedMassMatrix<1>,
                        "lumped",
                        MPM_OTM_LUMPED_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::MassMatrix<2>,
                        MpmOtm::LumpedMassMatrix<2>,
                        "lumped",
                        MPM_OTM_LUMPED_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::MassMatrix<3>,
                        MpmOtm::LumpedMassMatrix<3>,
                        "lumped",
                        MPM_OTM_LUMPED_DESCRIPTION)
