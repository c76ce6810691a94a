#ifndef mpm_otm_shape_functions_fe_powell_sabin_h
#define mpm_otm_shape_functions_fe_powell_sabin_h

#include <deal.II/fe/fe.h>

#include <mpm_otm/shape_functions/powell_sabin_geometry.h>

#include <memory>

namespace MpmOtm
{
  /**
   * The quadratic Powell-Sabin splines of a PowellSabinGeometry as a deal.II
   * finite element, so that a DoFHandler numbers and distributes them and
   * FEValues, FEFaceValues, DataOut and AffineConstraints work with them.
   *
   * The element is non-parametric (like FE_P1NC): the functions are not
   * mapped from a reference cell but defined on the real triangle by its
   * own split points and its vertices' control triangles, which differ
   * from cell to cell. fill_fe_values() therefore takes the real quadrature
   * points from the mapping, computes their barycentric coordinates in the
   * (affine) cell and evaluates the functions there with the geometry's
   * kernel, the one the time step uses. There are three degrees of freedom
   * per vertex (function q of vertex j is the cell's degree of freedom
   * 3 j + q) and none on edges or inside; the functions are C1, quadratic
   * on each of the six sub-triangles of a cell. Values and gradients are
   * available, second derivatives and values on the reference cell are
   * not.
   *
   * The element refers to the geometry of one triangulation (shared by its
   * copies); it must only be used on that triangulation's cells, and
   * reinitializing the geometry (a moved mesh) changes the functions of
   * every FEValues object that uses the element.
   */
  class FE_PowellSabin : public FiniteElement<2>
  {
  public:
    /**
     * The element of the functions of @p geometry.
     */
    explicit FE_PowellSabin(
      std::shared_ptr<const PowellSabinGeometry> geometry);

    std::string
    get_name() const override;

    std::unique_ptr<FiniteElement<2>>
    clone() const override;

    /**
     * Values and gradients need the real quadrature points.
     */
    UpdateFlags
    requires_update_flags(const UpdateFlags flags) const override;

    /**
     * The geometry whose functions this element evaluates.
     */
    const PowellSabinGeometry &
    geometry() const;

  protected:
    std::unique_ptr<FiniteElement<2>::InternalDataBase>
    get_data(const UpdateFlags    update_flags,
             const Mapping<2>    &mapping,
             const Quadrature<2> &quadrature,
             internal::FEValuesImplementation::FiniteElementRelatedData<2>
               &output_data) const override;

    using FiniteElement<2>::get_face_data;

    std::unique_ptr<FiniteElement<2>::InternalDataBase>
    get_face_data(const UpdateFlags         update_flags,
                  const Mapping<2>         &mapping,
                  const hp::QCollection<1> &quadrature,
                  internal::FEValuesImplementation::FiniteElementRelatedData<2>
                    &output_data) const override;

    std::unique_ptr<FiniteElement<2>::InternalDataBase>
    get_subface_data(
      const UpdateFlags    update_flags,
      const Mapping<2>    &mapping,
      const Quadrature<1> &quadrature,
      internal::FEValuesImplementation::FiniteElementRelatedData<2>
        &output_data) const override;

    void
    fill_fe_values(const Triangulation<2>::cell_iterator &cell,
                   const CellSimilarity::Similarity       cell_similarity,
                   const Quadrature<2>                   &quadrature,
                   const Mapping<2>                      &mapping,
                   const Mapping<2>::InternalDataBase    &mapping_internal,
                   const internal::FEValuesImplementation::MappingRelatedData<2>
                                                            &mapping_data,
                   const FiniteElement<2>::InternalDataBase &fe_internal,
                   internal::FEValuesImplementation::FiniteElementRelatedData<2>
                     &output_data) const override;

    using FiniteElement<2>::fill_fe_face_values;

    void
    fill_fe_face_values(
      const Triangulation<2>::cell_iterator &cell,
      const unsigned int                     face_no,
      const hp::QCollection<1>              &quadrature,
      const Mapping<2>                      &mapping,
      const Mapping<2>::InternalDataBase    &mapping_internal,
      const internal::FEValuesImplementation::MappingRelatedData<2>
                             &mapping_data,
      const InternalDataBase &fe_internal,
      internal::FEValuesImplementation::FiniteElementRelatedData<2>
        &output_data) const override;

    /**
     * Not implemented: the grids of this program are not refined locally.
     */
    void
    fill_fe_subface_values(
      const Triangulation<2>::cell_iterator &cell,
      const unsigned int                     face_no,
      const unsigned int                     sub_no,
      const Quadrature<1>                   &quadrature,
      const Mapping<2>                      &mapping,
      const Mapping<2>::InternalDataBase    &mapping_internal,
      const internal::FEValuesImplementation::MappingRelatedData<2>
                             &mapping_data,
      const InternalDataBase &fe_internal,
      internal::FEValuesImplementation::FiniteElementRelatedData<2>
        &output_data) const override;

  private:
    /**
     * Values and gradients (as @p update_each asks) of the functions of
     * @p cell at the real points @p points into @p output_data.
     */
    void
    fill_at_points(const Triangulation<2>::cell_iterator &cell,
                   const std::vector<Point<2>>           &points,
                   const UpdateFlags                      update_each,
                   internal::FEValuesImplementation::FiniteElementRelatedData<2>
                     &output_data) const;

    std::shared_ptr<const PowellSabinGeometry> splines;
  };
} // namespace MpmOtm

#endif
