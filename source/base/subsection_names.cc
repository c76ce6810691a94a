#include <deal.II/base/utilities.h>

#include <mpm_otm/base/subsection_names.h>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <tuple>

namespace MpmOtm
{
  void
  SubsectionNames::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Materials",
                      "",
                      Patterns::List(Patterns::Anything()),
                      "Names of further materials, each defined in a "
                      "subsection 'Material <name>' with the entries of "
                      "subsection 'Material' (which defines the material "
                      "named 'default'), e.g. 'sand, clay'.");
    prm.declare_entry("Bodies",
                      "",
                      Patterns::List(Patterns::Anything()),
                      "Names of the bodies of Problem = custom, each defined "
                      "in a subsection 'Body <name>' (shape, material, "
                      "initial velocity and stress). Empty: one box given "
                      "by 'Custom problem/Material lower corner' and "
                      "'Material upper corner' of the default material.");
    prm.declare_entry("Boundaries",
                      "",
                      Patterns::List(Patterns::Anything()),
                      "Names of boundary conditions, each defined in a "
                      "subsection 'Boundary <name>' (where: boundary ids or "
                      "the grid nodes in a box; what: fixed, slip, friction "
                      "or a prescribed velocity). Sides not named keep the "
                      "problem's own conditions (free for Problem = custom "
                      "unless 'Custom problem/Fixed components' fixes them).");
    prm.declare_entry("Surface loads",
                      "",
                      Patterns::List(Patterns::Anything()),
                      "Names of loads on parts of the bodies' surfaces (a "
                      "pressure or a traction on a segment in 2D, an "
                      "axis-parallel rectangle in 3D), each defined in a "
                      "subsection 'Surface load <name>'.");
    prm.declare_entry("Stages",
                      "",
                      Patterns::List(Patterns::Anything()),
                      "Names of the stages of a staged analysis, in the "
                      "order they run, each defined in a subsection "
                      "'Stage <name>' (its end, the bodies it removes or "
                      "adds, ...; manual, 'Stages'). Empty: one stage, "
                      "from t = 0 to Time/End time.");
  }



  std::vector<std::string>
  SubsectionNames::names_in(const ParameterHandler &prm,
                            const std::string      &entry)
  {
    const auto names = Utilities::split_string_list(prm.get(entry));
    for (unsigned int i = 0; i < names.size(); ++i)
      {
        AssertThrow(!names[i].empty() &&
                      std::all_of(names[i].begin(),
                                  names[i].end(),
                                  [](const char c) {
                                    return std::isalnum(
                                             static_cast<unsigned char>(c)) ||
                                           c == '_' || c == '-';
                                  }),
                    ExcMessage(entry + ": the name <" + names[i] +
                               "> may contain only letters, digits, '_' and "
                               "'-'."));
        AssertThrow(std::find(names.begin(), names.begin() + i, names[i]) ==
                        names.begin() + i &&
                      (entry != "Materials" || names[i] != "default"),
                    ExcMessage(entry + ": the name <" + names[i] +
                               "> is given twice (or is 'default', the name "
                               "of subsection 'Material')."));
      }
    return names;
  }



  SubsectionNames
  SubsectionNames::read(const std::string &parameter_text)
  {
    ParameterHandler prm;
    declare_parameters(prm);
    prm.parse_input_from_string(parameter_text, "", true);
    SubsectionNames result;
    result.materials     = names_in(prm, "Materials");
    result.bodies        = names_in(prm, "Bodies");
    result.boundaries    = names_in(prm, "Boundaries");
    result.surface_loads = names_in(prm, "Surface loads");
    result.stages        = names_in(prm, "Stages");

    // The subsections the text opens, as "<kind> <name>" (comments and
    // surplus spaces removed). A file that includes others may define them
    // there: it is not checked.
    std::vector<std::string> opened;
    bool                     includes = false;
    std::istringstream       lines(parameter_text);
    std::string              line;
    while (std::getline(lines, line))
      {
        const auto words =
          Utilities::split_string_list(line.substr(0, line.find('#')), ' ');
        std::vector<std::string> nonempty;
        for (const auto &word : words)
          if (!word.empty())
            nonempty.push_back(word);
        if (nonempty.size() >= 3 && nonempty[0] == "subsection")
          {
            std::string opened_name = nonempty[1];
            for (unsigned int i = 2; i < nonempty.size(); ++i)
              opened_name += " " + nonempty[i];
            opened.push_back(opened_name);
          }
        includes = includes || (!nonempty.empty() && nonempty[0] == "include");
      }
    if (includes)
      return result;
    for (const auto &[kind, entry, names] :
         {std::make_tuple("Material", "Materials", &result.materials),
          std::make_tuple("Body", "Bodies", &result.bodies),
          std::make_tuple("Boundary", "Boundaries", &result.boundaries),
          std::make_tuple("Surface load",
                          "Surface loads",
                          &result.surface_loads),
          std::make_tuple("Stage", "Stages", &result.stages)})
      for (const auto &name : *names)
        AssertThrow(std::find(opened.begin(),
                              opened.end(),
                              std::string(kind) + " " + name) != opened.end(),
                    ExcMessage(std::string(entry) + " lists <" + name +
                               ">, but there is no subsection <" + kind + " " +
                               name +
                               "> defining it (it would run on the "
                               "defaults): add the subsection or remove the "
                               "name."));
    return result;
  }
} // namespace MpmOtm
