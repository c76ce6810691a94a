#ifndef mpm_otm_materials_material_h
#define mpm_otm_materials_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * A constitutive model: the Cauchy stress of a material point after a time
   * step, from its deformation gradient, velocity gradient and previous
   * stress (journal Alg. 1, step 12). The elastic constants are shared by all
   * models and read here from the "Material" subsection; in 2D the models are
   * plane strain, in 1D uniaxial strain.
   */
  template <int dim>
  class Material
  {
  public:
    virtual ~Material() = default;

    /**
     * Declare the entries of subsection "Material" common to every model:
     * Model (chosen among @p model_names), Young's modulus, Poisson's ratio,
     * Density.
     */
    static void
    declare_common_parameters(ParameterHandler  &prm,
                              const std::string &model_names,
                              const std::string &model_documentation);

    /**
     * Read the common entries and check them.
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Replace @p stress (on entry the stress of the previous step) by the
     * Cauchy stress for the deformation gradient @p F, reached with the
     * velocity gradient @p velocity_gradient over the step @p dt.
     */
    virtual void
    update_stress(const Tensor<2, dim>    &F,
                  const Tensor<2, dim>    &velocity_gradient,
                  const double             dt,
                  SymmetricTensor<2, dim> &stress) const = 0;

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
    double young       = 0;
    double poisson     = 0;
    double rho         = 0;
    double lambda_lame = 0;
    double mu_lame     = 0;
  };
} // namespace MpmOtm

#endif
