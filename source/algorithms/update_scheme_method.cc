#include <mpm_otm/algorithms/update_scheme_method.h>
#include <mpm_otm/base/plugins.h>

namespace MpmOtm
{
  template <int dim>
  UpdateSchemeMethod<dim>::UpdateSchemeMethod(
    const std::string &automatic_scheme)
    : automatic_scheme(automatic_scheme)
  {}



  template <int dim>
  void
  UpdateSchemeMethod<dim>::parse_parameters(ParameterHandler &prm)
  {
    update_scheme = prm.get("Update scheme");
    if (update_scheme == "automatic")
      update_scheme = automatic_scheme;
  }



  template <int dim>
  std::unique_ptr<NodalUpdate<dim>>
  UpdateSchemeMethod<dim>::create_nodal_update() const
  {
    return PluginRegistry<NodalUpdate<dim>>::create(update_scheme);
  }



  template class UpdateSchemeMethod<1>;
  template class UpdateSchemeMethod<2>;
  template class UpdateSchemeMethod<3>;
} // namespace MpmOtm
