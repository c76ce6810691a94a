#ifndef mpm_otm_algorithms_update_scheme_method_h
#define mpm_otm_algorithms_update_scheme_method_h

#include <mpm_otm/algorithms/method.h>

#include <string>

namespace MpmOtm
{
  /**
   * A method whose nodal update is the one the entry "Update scheme" names
   * (MPM and the unified approach of the journal, Alg. 1 and 3), with the
   * method's own choice for "automatic". The grid motion is left to the
   * method.
   */
  template <int dim>
  class UpdateSchemeMethod : public Method<dim>
  {
  public:
    /**
     * @p automatic_scheme is the nodal update that "automatic" stands for.
     */
    explicit UpdateSchemeMethod(const std::string &automatic_scheme);

    void
    parse_parameters(ParameterHandler &prm) override;

    std::unique_ptr<NodalUpdate<dim>>
    create_nodal_update() const override;

  private:
    const std::string automatic_scheme;
    std::string       update_scheme;
  };
} // namespace MpmOtm

#endif
