#ifndef mpm_otm_material_points_property_layout_h
#define mpm_otm_material_points_property_layout_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * Where each quantity of a material point lives in the property array that
   * Particles::ParticleHandler stores for it (one contiguous slot of doubles
   * per particle). Position and reference position are kept by the particle
   * handler itself; the quantities every point has are here, at fixed
   * places; after them, from n_fixed_properties on, come the internal
   * variables the materials of the run ask for, whose places
   * MaterialLibrary assigns at start-up. Tensors are stored row by row, the
   * symmetric stress as its dim (dim + 1) / 2 independent components in the
   * order of SymmetricTensor::unrolled_index.
   */
  template <int dim>
  struct PropertyLayout
  {
    /// Mass m_p, constant in time.
    static constexpr unsigned int mass = 0;
    /// Initial volume V_p^0.
    static constexpr unsigned int initial_volume = 1;
    /// Boundary measure (length in 2D, area in 3D, 1 in 1D) this particle
    /// represents on a traction boundary, 0 for interior particles.
    static constexpr unsigned int traction_measure = 2;
    /// Boundary id whose traction acts on the particle (meaningful only
    /// when traction_measure > 0).
    static constexpr unsigned int traction_boundary = 3;
    /// Number of the point's material in the run's MaterialLibrary.
    static constexpr unsigned int material_id = 4;
    /// Initial position X_p (dim components).
    static constexpr unsigned int initial_position = 5;
    /// Velocity v_p (dim components).
    static constexpr unsigned int velocity = initial_position + dim;
    /// Deformation gradient F_p (dim x dim components).
    static constexpr unsigned int deformation_gradient = velocity + dim;
    /// Cauchy stress sigma_p (dim (dim + 1) / 2 components).
    static constexpr unsigned int stress = deformation_gradient + dim * dim;
    /// Number of independent stress components.
    static constexpr unsigned int n_stress_components = dim * (dim + 1) / 2;
    /// The stress normal to the plane (2D, plane strain) or the line (1D,
    /// uniaxial strain): StressState::out_of_plane_stress. 3D has none.
    static constexpr unsigned int out_of_plane_stress =
      stress + n_stress_components;
    /// Number of doubles before the materials' internal variables.
    static constexpr unsigned int n_fixed_properties =
      out_of_plane_stress + (dim < 3 ? 1 : 0);

    /**
     * The vector of dim components that starts at @p first.
     */
    template <typename Number>
    static Tensor<1, dim>
    get_vector(const ArrayView<Number> &properties, const unsigned int first)
    {
      Tensor<1, dim> result;
      for (unsigned int d = 0; d < dim; ++d)
        result[d] = properties[first + d];
      return result;
    }

    /**
     * Store @p value in the dim components that start at @p first.
     */
    static void
    set_vector(const ArrayView<double> &properties,
               const unsigned int       first,
               const Tensor<1, dim>    &value)
    {
      for (unsigned int d = 0; d < dim; ++d)
        properties[first + d] = value[d];
    }

    /**
     * The deformation gradient.
     */
    template <typename Number>
    static Tensor<2, dim>
    get_deformation_gradient(const ArrayView<Number> &properties)
    {
      Tensor<2, dim> F;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F[i][j] = properties[deformation_gradient + i * dim + j];
      return F;
    }

    /**
     * The current volume V_p = det(F_p) V_p^0 (journal Eqs. 30 and 53); it
     * is not stored, since it follows from F_p.
     */
    template <typename Number>
    static double
    volume(const ArrayView<Number> &properties)
    {
      return determinant(get_deformation_gradient(properties)) *
             properties[initial_volume];
    }

    /**
     * Store the deformation gradient.
     */
    static void
    set_deformation_gradient(const ArrayView<double> &properties,
                             const Tensor<2, dim>    &F)
    {
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          properties[deformation_gradient + i * dim + j] = F[i][j];
    }

    /**
     * The Cauchy stress.
     */
    template <typename Number>
    static SymmetricTensor<2, dim>
    get_stress(const ArrayView<Number> &properties)
    {
      SymmetricTensor<2, dim> sigma;
      for (unsigned int k = 0; k < n_stress_components; ++k)
        sigma.access_raw_entry(k) = properties[stress + k];
      return sigma;
    }

    /**
     * The stress normal to the plane (0 in 3D).
     */
    template <typename Number>
    static double
    get_out_of_plane_stress(const ArrayView<Number> &properties)
    {
      return (dim < 3) ? properties[out_of_plane_stress] : 0.;
    }

    /**
     * The three-dimensional Cauchy stress of the point: its in-plane stress
     * and, in 2D (plane strain), sigma_zz; in 1D (uniaxial strain) the
     * lateral stress in yy and zz.
     */
    template <typename Number>
    static SymmetricTensor<2, 3>
    get_full_stress(const ArrayView<Number> &properties)
    {
      const SymmetricTensor<2, dim> sigma = get_stress(properties);
      SymmetricTensor<2, 3>         full;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          full[i][j] = sigma[i][j];
      for (unsigned int d = dim; d < 3; ++d)
        full[d][d] = get_out_of_plane_stress(properties);
      return full;
    }

    /**
     * The material number of the point.
     */
    template <typename Number>
    static unsigned int
    get_material_id(const ArrayView<Number> &properties)
    {
      return static_cast<unsigned int>(properties[material_id]);
    }

    /**
     * Store the Cauchy stress.
     */
    static void
    set_stress(const ArrayView<double>       &properties,
               const SymmetricTensor<2, dim> &sigma)
    {
      for (unsigned int k = 0; k < n_stress_components; ++k)
        properties[stress + k] = sigma.access_raw_entry(k);
    }
  };
} // namespace MpmOtm

#endif
