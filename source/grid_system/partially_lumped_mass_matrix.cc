#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid_system/partially_lumped_mass_matrix.h>

#include <algorithm>
#include <iterator>

namespace MpmOtm
{
  template <int dim>
  void
  PartiallyLumpedMassMatrix<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  bool
  PartiallyLumpedMassMatrix<dim>::needs_material_boundary() const
  {
    return true;
  }



  template <int dim>
  void
  PartiallyLumpedMassMatrix<dim>::solve(
    const NodalSystem<dim>       &system,
    const ParticleShapeData<dim> &shape_data,
    const VectorType             &right_hand_side,
    VectorType                   &solution,
    const unsigned int            component) const
  {
    const std::vector<unsigned int> excluded =
      system.excluded_functions(component);
    const std::vector<unsigned int> &edge =
      system.material_boundary_functions();
    std::vector<unsigned int> lumped_rows;
    std::set_difference(edge.begin(),
                        edge.end(),
                        excluded.begin(),
                        excluded.end(),
                        std::back_inserter(lumped_rows));

    // a_B = f_B / m_B on the lumped rows.
    VectorType lumped_part;
    lumped_part.reinit(right_hand_side);
    for (const unsigned int i : lumped_rows)
      lumped_part.local_element(i) =
        right_hand_side.local_element(i) / system.lumped_mass.local_element(i);

    // M_II a_I = f_I - M_IB a_B on the others.
    VectorType product;
    product.reinit(right_hand_side, true);
    this->multiply(system, shape_data, lumped_part, product, excluded);
    VectorType remainder;
    remainder.reinit(right_hand_side, true);
    for (unsigned int i = 0; i < remainder.locally_owned_size(); ++i)
      remainder.local_element(i) =
        right_hand_side.local_element(i) - product.local_element(i);
    std::vector<unsigned int> consistent_excluded;
    std::set_union(excluded.begin(),
                   excluded.end(),
                   lumped_rows.begin(),
                   lumped_rows.end(),
                   std::back_inserter(consistent_excluded));
    this->solve_without(system,
                        shape_data,
                        remainder,
                        solution,
                        consistent_excluded);

    for (const unsigned int i : lumped_rows)
      solution.local_element(i) = lumped_part.local_element(i);
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
