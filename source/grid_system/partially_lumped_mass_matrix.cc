#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid_system/partially_lumped_mass_matrix.h>

#include <algorithm>
#include <utility>

namespace MpmOtm
{
  template <int dim>
  void
  PartiallyLumpedMassMatrix<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  bool
  PartiallyLumpedMassMatrix<dim>::is_consistent() const
  {
    return false;
  }



  template <int dim>
  bool
  PartiallyLumpedMassMatrix<dim>::needs_material_boundary() const
  {
    return true;
  }



  template <int dim>
  void
  PartiallyLumpedMassMatrix<dim>::vmult(
    const NodalSystem<dim>       &system,
    const ParticleShapeData<dim> &shape_data,
    const VectorType             &vector,
    VectorType                   &product) const
  {
    ConsistentMassMatrix<dim>::vmult(system, shape_data, vector, product);
    for (const unsigned int i : system.material_boundary_functions())
      product.local_element(i) =
        system.lumped_mass.local_element(i) * vector.local_element(i);
  }



  template <int dim>
  void
  PartiallyLumpedMassMatrix<dim>::solve(
    const NodalSystem<dim>          &system,
    const ParticleShapeData<dim>    &shape_data,
    const VectorType                &right_hand_side,
    VectorType                      &solution,
    const AffineConstraints<double> &constraints) const
  {
    // a_B = f_B / m_B on the lumped rows (the edge functions that are not
    // constrained), then M_II a_I = f_I - M_IB a_B on the others: a solve
    // with the lumped rows prescribed like the constrained ones.
    std::vector<std::pair<unsigned int, double>> prescribed =
      system.local_lines(constraints);
    const auto n_constrained = prescribed.size();
    for (const unsigned int i : system.material_boundary_functions())
      if (!std::binary_search(prescribed.begin(),
                              prescribed.begin() + n_constrained,
                              std::make_pair(i, 0.),
                              [](const auto &a, const auto &b) {
                                return a.first < b.first;
                              }))
        prescribed.emplace_back(i,
                                right_hand_side.local_element(i) /
                                  system.lumped_mass.local_element(i));
    std::sort(prescribed.begin(), prescribed.end());
    this->solve_prescribed(system,
                           shape_data,
                           right_hand_side,
                           solution,
                           prescribed);
  }



  template class PartiallyLumpedMassMatrix<1>;
  template class PartiallyLumpedMassMatrix<2>;
  template class PartiallyLumpedMassMatrix<3>;
} // namespace MpmOtm

#define MPM_OTM_PARTIALLY_LUMPED_DESCRIPTION                                \
  "partially lumped: rows of the functions at the edge of the material "    \
  "(on cells with and without points) lumped, the rest consistent (thesis " \
  "Sect. 5.4; the grid must reach beyond a free surface)"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::MassMatrix<1>,
                        MpmOtm::PartiallyLumpedMassMatrix<1>,
                        "partially lumped",
                        MPM_OTM_PARTIALLY_LUMPED_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::MassMatrix<2>,
                        MpmOtm::PartiallyLumpedMassMatrix<2>,
                        "partially lumped",
                        MPM_OTM_PARTIALLY_LUMPED_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::MassMatrix<3>,
                        MpmOtm::PartiallyLumpedMassMatrix<3>,
                        "partially lumped",
                        MPM_OTM_PARTIALLY_LUMPED_DESCRIPTION)
