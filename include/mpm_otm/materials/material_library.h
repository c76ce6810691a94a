#ifndef mpm_otm_materials_material_library_h
#define mpm_otm_materials_material_library_h

#include <deal.II/base/parameter_handler.h>

#include <mpm_otm/materials/material.h>

#include <memory>
#include <string>
#include <vector>

namespace MpmOtm
{
  /**
   * The materials of a run: the default one of subsection "Material" (named
   * "default", number 0, the material of the built-in benchmarks) and one
   * per name of the entry "Materials", read from subsection
   * "Material <name>" (numbers 1, 2, ... in the order of the list). Each is
   * a model created by name from the registered Material plugins. The
   * library also assigns each material's internal variables their places
   * in a point's property array, after PropertyLayout::n_fixed_properties.
   */
  template <int dim>
  class MaterialLibrary
  {
  public:
    /**
     * Declare subsection "Material" and one subsection "Material <name>"
     * per name in @p names, each with the common entries and those of every
     * registered model.
     */
    static void
    declare_parameters(ParameterHandler               &prm,
                       const std::vector<std::string> &names);

    /**
     * Create and read the materials (names from the entry "Materials").
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Number of materials (at least 1).
     */
    unsigned int
    n_materials() const;

    /**
     * The number of the material called @p name; @p entry names the
     * parameter that asks for it in the message if there is no such
     * material.
     */
    unsigned int
    material_id(const std::string &name, const std::string &entry) const;

    /**
     * The name of material @p id.
     */
    const std::string &
    name(const unsigned int id) const;

    /**
     * Material @p id.
     */
    const Material<dim> &
    operator[](const unsigned int id) const;

    /**
     * The material of subsection "Material".
     */
    const Material<dim> &
    default_material() const;

    /**
     * Index in a point's property array of the first internal variable of
     * material @p id.
     */
    unsigned int
    first_internal_variable(const unsigned int id) const;

    /**
     * Number of internal variables of material @p id.
     */
    unsigned int
    n_internal_variables(const unsigned int id) const;

    /**
     * The state of a point of material @p id whose property array is
     * @p properties: its stress, out-of-plane stress and a view of its
     * internal variables.
     */
    StressState<dim>
    stress_state(const unsigned int       id,
                 const ArrayView<double> &properties) const;

    /**
     * Store @p state in the property array @p properties.
     */
    static void
    store(const StressState<dim> &state, const ArrayView<double> &properties);

    /**
     * Number of doubles per point: the fixed properties, the internal
     * variables of all materials and the point variables of
     * add_point_variables().
     */
    unsigned int
    n_properties() const;

    /**
     * Reserve one slot per name in every point's property array for a
     * variable that is not a material's (e.g. APIC's affine velocity
     * matrix) and return the place of the first; the slots follow those of
     * the materials and are written out under @p names. Call after
     * parse_parameters() and before the points are seeded.
     */
    unsigned int
    add_point_variables(const std::vector<std::string> &names);

    /**
     * Names of all internal variables, "<material>.<variable>", and of the
     * point variables (in the order of their places), for output.
     */
    std::vector<std::string>
    internal_variable_names() const;

    /**
     * Divide the strength of every material by @p factor
     * (Material::reduce_strength()).
     */
    void
    reduce_strength(const double factor);

    /**
     * The largest wave speed of all materials (for the CFL bound).
     */
    double
    maximal_wave_speed() const;

  private:
    std::vector<std::string>                    names;
    std::vector<std::unique_ptr<Material<dim>>> materials;
    std::vector<unsigned int>                   first_variable;
    std::vector<unsigned int>                   n_variables;
    unsigned int                                n_total = 0;
    std::vector<std::string>                    point_variable_names;
  };
} // namespace MpmOtm

#endif
