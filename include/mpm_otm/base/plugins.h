#ifndef mpm_otm_base_plugins_h
#define mpm_otm_base_plugins_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * Named, self-registering implementations of one interface (a material
   * model, a problem, a shape-function family, a nodal update, a mass-matrix
   * treatment). Each implementation registers its name, a one-line
   * description, a function that declares its parameters and a factory, with
   * MPM_OTM_REGISTER_PLUGIN at the bottom of its .cc file. The list of names
   * becomes the Patterns::Selection of the parameter that chooses among them,
   * so adding an implementation touches no other file.
   */
  template <typename Interface>
  class PluginRegistry
  {
  public:
    /**
     * What is known about one registered implementation.
     */
    struct Entry
    {
      std::string                                 name;
      std::string                                 description;
      std::function<void(ParameterHandler &)>     declare_parameters;
      std::function<std::unique_ptr<Interface>()> create;
    };

    /**
     * Register an implementation; returns true so that it can initialise a
     * static variable.
     */
    static bool
    add(const Entry &entry)
    {
      entries().push_back(entry);
      return true;
    }

    /**
     * The names, separated by '|', for a Patterns::Selection.
     */
    static std::string
    selection()
    {
      std::string result;
      for (const auto &entry : entries())
        result += (result.empty() ? "" : "|") + entry.name;
      return result;
    }

    /**
     * One line per implementation, "name: description", for the
     * documentation string of the selecting parameter.
     */
    static std::string
    documentation()
    {
      std::string result;
      for (const auto &entry : entries())
        result += "\n  " + entry.name + ": " + entry.description;
      return result;
    }

    /**
     * Let every implementation declare its own parameters.
     */
    static void
    declare_parameters(ParameterHandler &prm)
    {
      for (const auto &entry : entries())
        if (entry.declare_parameters)
          entry.declare_parameters(prm);
    }

    /**
     * Create the implementation called @p name.
     */
    static std::unique_ptr<Interface>
    create(const std::string &name)
    {
      for (const auto &entry : entries())
        if (entry.name == name)
          return entry.create();
      AssertThrow(false,
                  ExcMessage("Unknown name <" + name +
                             ">; the names allowed here are: " + selection()));
      return nullptr;
    }

  private:
    static std::vector<Entry> &
    entries()
    {
      static std::vector<Entry> list;
      return list;
    }
  };
} // namespace MpmOtm

#define MPM_OTM_PLUGIN_CONCAT_(a, b) a##b
#define MPM_OTM_PLUGIN_CONCAT(a, b) MPM_OTM_PLUGIN_CONCAT_(a, b)

/**
 * Register @p Class (derived from @p Interface) under @p name. @p Class must
 * have a static declare_parameters(ParameterHandler &) and a default
 * constructor.
 */
#define MPM_OTM_REGISTER_PLUGIN(Interface, Class, name, description) \
  namespace                                                          \
  {                                                                  \
    const bool MPM_OTM_PLUGIN_CONCAT(registered_, __LINE__) =        \
      ::MpmOtm::PluginRegistry<Interface>::add(                      \
        {name,                                                       \
         description,                                                \
         &Class::declare_parameters,                                 \
         []() -> std::unique_ptr<Interface> {                        \
           return std::make_unique<Class>();                         \
         }});                                                        \
  }

#endif
