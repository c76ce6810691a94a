#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <mpm_otm/shape_functions/fe_powell_sabin.h>

namespace MpmOtm
{
  FE_PowellSabin::FE_PowellSabin(
    std::shared_ptr<const PowellSabinGeometry> geometry)
    : FiniteElement<2>(
        FiniteElementData<2>({3, 0, 0},
                             ReferenceCells::Triangle,
                             1,
                             2,
                             FiniteElementData<2>::H1),
        std::vector<bool>(PowellSabinGeometry::n_cell_functions, false),
        std::vector<ComponentMask>(PowellSabinGeometry::n_cell_functions,
                                   ComponentMask(1, true)))
    , splines(std::move(geometry))
  {
    Assert(splines != nullptr, ExcMessage("FE_PowellSabin needs a geometry."));
  }



  std::string
  FE_PowellSabin::get_name() const
  {
    return "FE_PowellSabin";
  }



  std::unique_ptr<FiniteElement<2>>
  FE_PowellSabin::clone() const
  {
    return std::make_unique<FE_PowellSabin>(*this);
  }



  UpdateFlags
  FE_PowellSabin::requires_update_flags(const UpdateFlags flags) const
  {
    UpdateFlags out = flags & (update_values | update_gradients);
    if (out != update_default)
      out |= update_quadrature_points;
    return out;
  }



  const PowellSabinGeometry &
  FE_PowellSabin::geometry() const
  {
    return *splines;
  }



  std::unique_ptr<FiniteElement<2>::InternalDataBase>
  FE_PowellSabin::get_data(
    const UpdateFlags update_flags,
    const Mapping<2> &,
    const Quadrature<2>                                           &quadrature,
    internal::FEValuesImplementation::FiniteElementRelatedData<2> &output_data)
    const
  {
    AssertThrow(!(update_flags & (update_hessians | update_3rd_derivatives)),
                ExcMessage("FE_PowellSabin provides values and gradients, "
                           "not higher derivatives."));
    auto data         = std::make_unique<FiniteElement<2>::InternalDataBase>();
    data->update_each = requires_update_flags(update_flags);
    output_data.initialize(quadrature.size(), *this, data->update_each);
    return data;
  }



  std::unique_ptr<FiniteElement<2>::InternalDataBase>
  FE_PowellSabin::get_face_data(
    const UpdateFlags                                              update_flags,
    const Mapping<2>                                              &mapping,
    const hp::QCollection<1>                                      &quadrature,
    internal::FEValuesImplementation::FiniteElementRelatedData<2> &output_data)
    const
  {
    AssertDimension(quadrature.size(), 1);
    return get_data(update_flags,
                    mapping,
                    Quadrature<2>(quadrature[0].size()),
                    output_data);
  }



  std::unique_ptr<FiniteElement<2>::InternalDataBase>
  FE_PowellSabin::get_subface_data(
    const UpdateFlags                                              update_flags,
    const Mapping<2>                                              &mapping,
    const Quadrature<1>                                           &quadrature,
    internal::FEValuesImplementation::FiniteElementRelatedData<2> &output_data)
    const
  {
    return get_data(update_flags,
                    mapping,
                    Quadrature<2>(quadrature.size()),
                    output_data);
  }



  void
  FE_PowellSabin::fill_fe_values(
    const Triangulation<2>::cell_iterator &cell,
    const CellSimilarity::Similarity,
    const Quadrature<2> &,
    const Mapping<2> &,
    const Mapping<2>::InternalDataBase &,
    const internal::FEValuesImplementation::MappingRelatedData<2> &mapping_data,
    const FiniteElement<2>::InternalDataBase                      &fe_internal,
    internal::FEValuesImplementation::FiniteElementRelatedData<2> &output_data)
    const
  {
    fill_at_points(cell,
                   mapping_data.quadrature_points,
                   fe_internal.update_each,
                   output_data);
  }



  void
  FE_PowellSabin::fill_fe_face_values(
    const Triangulation<2>::cell_iterator &cell,
    const unsigned int,
    const hp::QCollection<1> &,
    const Mapping<2> &,
    const Mapping<2>::InternalDataBase &,
    const internal::FEValuesImplementation::MappingRelatedData<2> &mapping_data,
    const InternalDataBase                                        &fe_internal,
    internal::FEValuesImplementation::FiniteElementRelatedData<2> &output_data)
    const
  {
    fill_at_points(cell,
                   mapping_data.quadrature_points,
                   fe_internal.update_each,
                   output_data);
  }



  void
  FE_PowellSabin::fill_fe_subface_values(
    const Triangulation<2>::cell_iterator &,
    const unsigned int,
    const unsigned int,
    const Quadrature<1> &,
    const Mapping<2> &,
    const Mapping<2>::InternalDataBase &,
    const internal::FEValuesImplementation::MappingRelatedData<2> &,
    const InternalDataBase &,
    internal::FEValuesImplementation::FiniteElementRelatedData<2> &) const
  {
    AssertThrow(false,
                ExcMessage("FE_PowellSabin is not defined on locally refined "
                           "triangulations (no subface values)."));
  }



  void
  FE_PowellSabin::fill_at_points(
    const Triangulation<2>::cell_iterator                         &cell,
    const std::vector<Point<2>>                                   &points,
    const UpdateFlags                                              update_each,
    internal::FEValuesImplementation::FiniteElementRelatedData<2> &output_data)
    const
  {
    if (!(update_each & (update_values | update_gradients)))
      return;

    // Reference coordinates in the affine triangle: x = V_0 + J xi.
    Tensor<2, 2> jacobian;
    for (unsigned int d = 0; d < 2; ++d)
      for (unsigned int c = 0; c < 2; ++c)
        jacobian[c][d] = cell->vertex(d + 1)[c] - cell->vertex(0)[c];
    const Tensor<2, 2> inverse = invert(jacobian);

    constexpr unsigned int n = PowellSabinGeometry::n_cell_functions;
    double                 values[n];
    Tensor<1, 2>           gradients[n];
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        splines->cell_values(cell,
                             Point<2>(inverse * (points[q] - cell->vertex(0))),
                             values,
                             gradients);
        for (unsigned int i = 0; i < n; ++i)
          {
            if (update_each & update_values)
              output_data.shape_values(i, q) = values[i];
            if (update_each & update_gradients)
              output_data.shape_gradients[i][q] = gradients[i];
          }
      }
  }
} // namespace MpmOtm
