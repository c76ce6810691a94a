#include <mpm_otm/base/plugins.h>
#include <mpm_otm/base/subsection_names.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/materials/material_library.h>

#include <algorithm>

namespace MpmOtm
{
  namespace
  {
    std::string
    subsection_of(const std::string &name)
    {
      return name == "default" ? "Material" : "Material " + name;
    }
  } // namespace



  template <int dim>
  void
  MaterialLibrary<dim>::declare_parameters(
    ParameterHandler               &prm,
    const std::vector<std::string> &names)
  {
    std::vector<std::string> all{"default"};
    all.insert(all.end(), names.begin(), names.end());
    for (const auto &name : all)
      {
        prm.enter_subsection(subsection_of(name));
        Material<dim>::declare_common_parameters(
          prm,
          PluginRegistry<Material<dim>>::selection(),
          PluginRegistry<Material<dim>>::documentation());
        PluginRegistry<Material<dim>>::declare_parameters(prm);
        prm.leave_subsection();
      }
  }



  template <int dim>
  void
  MaterialLibrary<dim>::parse_parameters(ParameterHandler &prm)
  {
    names             = {"default"};
    const auto others = SubsectionNames::names_in(prm, "Materials");
    names.insert(names.end(), others.begin(), others.end());
    materials.clear();
    first_variable.clear();
    n_variables.clear();
    n_total = PropertyLayout<dim>::n_fixed_properties;
    point_variable_names.clear();
    for (const auto &name : names)
      {
        prm.enter_subsection(subsection_of(name));
        auto material = PluginRegistry<Material<dim>>::create(prm.get("Model"));
        material->set_subsection_path(subsection_of(name));
        material->parse_parameters(prm);
        prm.leave_subsection();
        first_variable.push_back(n_total);
        n_variables.push_back(material->internal_variables().size());
        n_total += n_variables.back();
        materials.push_back(std::move(material));
      }
  }



  template <int dim>
  unsigned int
  MaterialLibrary<dim>::n_materials() const
  {
    return materials.size();
  }



  template <int dim>
  unsigned int
  MaterialLibrary<dim>::material_id(const std::string &name,
                                    const std::string &entry) const
  {
    const auto  found = std::find(names.begin(), names.end(), name);
    std::string known;
    for (const auto &n : names)
      known += (known.empty() ? "" : ", ") + n;
    AssertThrow(found != names.end(),
                ExcMessage(entry + ": there is no material <" + name +
                           ">; the materials are: " + known +
                           " ('default' is subsection 'Material', the "
                           "others are listed in the entry 'Materials' and "
                           "defined in subsections 'Material <name>')."));
    return found - names.begin();
  }



  template <int dim>
  const std::string &
  MaterialLibrary<dim>::name(const unsigned int id) const
  {
    AssertIndexRange(id, names.size());
    return names[id];
  }



  template <int dim>
  const Material<dim> &
  MaterialLibrary<dim>::operator[](const unsigned int id) const
  {
    AssertIndexRange(id, materials.size());
    return *materials[id];
  }



  template <int dim>
  const Material<dim> &
  MaterialLibrary<dim>::default_material() const
  {
    return *materials[0];
  }



  template <int dim>
  unsigned int
  MaterialLibrary<dim>::first_internal_variable(const unsigned int id) const
  {
    AssertIndexRange(id, first_variable.size());
    return first_variable[id];
  }



  template <int dim>
  unsigned int
  MaterialLibrary<dim>::n_internal_variables(const unsigned int id) const
  {
    AssertIndexRange(id, n_variables.size());
    return n_variables[id];
  }



  template <int dim>
  StressState<dim>
  MaterialLibrary<dim>::stress_state(const unsigned int       id,
                                     const ArrayView<double> &properties) const
  {
    using Layout = PropertyLayout<dim>;
    StressState<dim> state;
    state.stress              = Layout::get_stress(properties);
    state.out_of_plane_stress = Layout::get_out_of_plane_stress(properties);
    state.internal_variables =
      ArrayView<double>(properties.data() + first_internal_variable(id),
                        n_variables[id]);
    return state;
  }



  template <int dim>
  void
  MaterialLibrary<dim>::store(const StressState<dim>  &state,
                              const ArrayView<double> &properties)
  {
    using Layout = PropertyLayout<dim>;
    Layout::set_stress(properties, state.stress);
    if (dim < 3)
      properties[Layout::out_of_plane_stress] = state.out_of_plane_stress;
  }



  template <int dim>
  unsigned int
  MaterialLibrary<dim>::n_properties() const
  {
    return n_total;
  }



  template <int dim>
  unsigned int
  MaterialLibrary<dim>::add_point_variables(
    const std::vector<std::string> &variable_names)
  {
    const unsigned int first = n_total;
    point_variable_names.insert(point_variable_names.end(),
                                variable_names.begin(),
                                variable_names.end());
    n_total += variable_names.size();
    return first;
  }



  template <int dim>
  std::vector<std::string>
  MaterialLibrary<dim>::internal_variable_names() const
  {
    std::vector<std::string> result;
    for (unsigned int id = 0; id < materials.size(); ++id)
      for (const auto &variable : materials[id]->internal_variables())
        result.push_back(names[id] + "." + variable);
    result.insert(result.end(),
                  point_variable_names.begin(),
                  point_variable_names.end());
    return result;
  }



  template <int dim>
  void
  MaterialLibrary<dim>::reduce_strength(const double factor)
  {
    for (auto &material : materials)
      material->reduce_strength(factor);
  }



  template <int dim>
  double
  MaterialLibrary<dim>::maximal_wave_speed() const
  {
    double speed = 0;
    for (const auto &material : materials)
      speed = std::max(speed, material->wave_speed());
    return speed;
  }



  template class MaterialLibrary<1>;
  template class MaterialLibrary<2>;
  template class MaterialLibrary<3>;
} // namespace MpmOtm
