#ifndef mpm_otm_materials_material_h
#define mpm_otm_materials_material_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * The stress state of one material point as a constitutive model updates
   * it: the in-plane Cauchy stress, the stress normal to the plane of a 2D
   * (plane strain) or 1D (uniaxial strain) model, and the model's own
   * internal variables (Material::internal_variables()).
   */
  template <int dim>
  struct StressState
  {
    /// Cauchy stress sigma_p (the dim x dim components).
    SymmetricTensor<2, dim> stress;
    /// sigma_zz in 2D (plane strain), the lateral stress sigma_yy = sigma_zz
    /// in 1D (uniaxial strain); 0 and unused in 3D.
    double out_of_plane_stress = 0.;
    /// The model's internal variables, in the order of
    /// Material::internal_variables().
    ArrayView<double> internal_variables;
  };

  /**
   * A constitutive model: the Cauchy stress of a material point after a time
   * step, from its deformation gradient, velocity gradient and previous
   * stress state (journal Alg. 1, step 12). The elastic constants and the
   * density are shared by all models and read here; a model's own entries
   * live in a subsection named after the model inside the material's
   * subsection (e.g. "Material sand/Drucker-Prager"). In 2D the models are
   * plane strain, in 1D uniaxial strain.
   */
  template <int dim>
  class Material
  {
  public:
    virtual ~Material() = default;

    /**
     * Declare, in the current subsection of @p prm, the entries common to
     * every model: Model (chosen among @p model_names), Young's modulus,
     * Poisson's ratio, Density.
     */
    static void
    declare_common_parameters(ParameterHandler  &prm,
                              const std::string &model_names,
                              const std::string &model_documentation);

    /**
     * Read the common entries from the current subsection of @p prm (the
     * material's, called @p subsection_path in messages) and check them.
     * Models with entries of their own override this, call it first, and
     * read their subsection.
     */
    virtual void
    parse_parameters(ParameterHandler &prm);

    /**
     * Set the name of the subsection this material is read from (e.g.
     * "Material" or "Material sand"), which messages name.
     */
    void
    set_subsection_path(const std::string &path);

    /**
     * The names of the internal variables the model keeps per point (one
     * number each, 0 at the start), e.g. the equivalent plastic strain. The
     * point storage reserves a slot for each.
     */
    virtual std::vector<std::string>
    internal_variables() const;

    /**
     * Replace @p state (on entry the state of the previous step) by the state
     * for the deformation gradient @p F, reached with the velocity gradient
     * @p velocity_gradient over the step @p dt.
     */
    virtual void
    update_stress(const Tensor<2, dim> &F,
                  const Tensor<2, dim> &velocity_gradient,
                  const double          dt,
                  StressState<dim>     &state) const = 0;

    /**
     * Stored elastic energy of a material point with initial volume
     * @p initial_volume, current volume @p volume, deformation gradient @p F
     * and stress @p stress.
     */
    virtual double
    strain_energy(const Tensor<2, dim>          &F,
                  const SymmetricTensor<2, dim> &stress,
                  const double                   initial_volume,
                  const double                   volume) const = 0;

    /**
     * The equivalent plastic strain of a point with these internal
     * variables (0 for elastic models).
     */
    virtual double
    equivalent_plastic_strain(
      const ArrayView<const double> &internal_variables) const;

    /**
     * The index among internal_variables() of the strain the model's
     * strength softens with, or numbers::invalid_unsigned_int if it does not
     * soften (the default). The model updates it with its own plastic strain
     * increments; a SofteningRegularisation may replace it between steps by
     * an average of the equivalent plastic strain over the point's
     * neighbourhood.
     */
    virtual unsigned int
    softening_variable() const;

    /**
     * Whether the model flows plastically (false for the elastic models).
     * Isochoric plastic flow locks with linear functions and several points
     * per cell, so the default volumetric locking remedy depends on it.
     */
    virtual bool
    is_plastic() const;

    /**
     * Divide the strength of the model by @p factor (> 0), once, for a
     * trial of a strength reduction (StrengthReduction): the plastic models
     * override it (the manual's "Strength reduction" says how each does);
     * the elastic models have no strength and ignore it.
     */
    virtual void
    reduce_strength(const double factor);

    /**
     * Whether the model keeps an initial stress: true for the models that
     * integrate a stress rate (hypo-elastic and the plastic ones), false for
     * those whose stress is a function of the deformation gradient alone
     * (linear elastic, neo-Hookean), which would replace an initial stress
     * by that of F = I, zero, in the first step.
     */
    virtual bool
    keeps_initial_stress() const;

    /**
     * Whether a point with these internal variables has lost contact with
     * its neighbours: a granular point opened beyond the density at which
     * it lost contact, without stress (false for models without such a
     * state).
     */
    virtual bool
    is_disconnected(const ArrayView<const double> &internal_variables) const;

    /**
     * Whether the model's points can lose contact at all (is_disconnected()
     * is false for every state otherwise). False by default.
     */
    virtual bool
    can_lose_contact() const;

    /**
     * The friction angle phi (radians) of a frictional model, 0 otherwise;
     * a geostatic initial stress uses K0 = 1 - sin(phi) by default for
     * phi > 0 and the elastic nu / (1 - nu) otherwise.
     */
    virtual double
    friction_angle() const;

    /**
     * The out-of-plane stress of an elastic point whose in-plane stress is
     * @p stress and whose out-of-plane strain is zero: nu (sigma_xx +
     * sigma_yy) in 2D (plane strain), nu / (1 - nu) sigma_xx in 1D
     * (uniaxial strain); 0 in 3D.
     */
    double
    elastic_out_of_plane_stress(const SymmetricTensor<2, dim> &stress) const;

    /**
     * Initial mass density.
     */
    double
    density() const;

    /**
     * Young's modulus.
     */
    double
    youngs_modulus() const;

    /**
     * Poisson's ratio.
     */
    double
    poissons_ratio() const;

    /**
     * Lame's first parameter.
     */
    double
    lambda() const;

    /**
     * Shear modulus.
     */
    double
    mu() const;

    /**
     * Speed of a longitudinal wave, sqrt((lambda + 2 mu) / rho): the speed in
     * the CFL bound (thesis Eq. 2.48; equal to sqrt(E / rho) for nu = 0).
     */
    double
    wave_speed() const;

  protected:
    /**
     * "<subsection>/<entry>", for messages about the entry @p entry.
     */
    std::string
    entry_name(const std::string &entry) const;

    std::string subsection_path = "Material";
    double      young           = 0;
    double      poisson         = 0;
    double      rho             = 0;
    double      lambda_lame     = 0;
    double      mu_lame         = 0;
  };
} // namespace MpmOtm

#endif
