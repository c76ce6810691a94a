#ifndef mpm_otm_base_subsection_names_h
#define mpm_otm_base_subsection_names_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * The names a parameter file gives to its repeated subsections: the
   * entries "Materials", "Bodies", "Boundaries", "Surface loads" and
   * "Stages" list them, and each name then has a subsection
   * "Material <name>", "Body <name>", "Boundary <name>",
   * "Surface load <name>" or "Stage <name>". ParameterHandler
   * needs every subsection declared before it parses a file, so the names are
   * read first, from the file's text, by read().
   */
  struct SubsectionNames
  {
    /// Names of the materials beside the default one ("Material").
    std::vector<std::string> materials;
    /// Names of the bodies.
    std::vector<std::string> bodies;
    /// Names of the boundary conditions.
    std::vector<std::string> boundaries;
    /// Names of the loads on parts of the bodies' surfaces.
    std::vector<std::string> surface_loads;
    /// Names of the stages of a staged run, in the order they run.
    std::vector<std::string> stages;

    /**
     * Declare the entries that list the names.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * The names listed in @p parameter_text (the text of a parameter file;
     * everything else in it is skipped). Stops on a repeated name, one
     * that contains a character other than letters, digits, '_' and '-',
     * and one whose subsection the text does not have (it would run on the
     * defaults; not checked in a text that includes other files).
     */
    static SubsectionNames
    read(const std::string &parameter_text);

    /**
     * The names listed in entry @p entry of @p prm.
     */
    static std::vector<std::string>
    names_in(const ParameterHandler &prm, const std::string &entry);
  };
} // namespace MpmOtm

#endif
