#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <mpm_otm/base/subsection_names.h>
#include <mpm_otm/boundary_conditions/boundary_conditions.h>
#include <mpm_otm/grid_system/local_damping.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/material_points/seeding_bodies.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/problems/body_seeder.h>
#include <mpm_otm/problems/problem.h>
#include <mpm_otm/simulator/stage_plan.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace MpmOtm
{
  namespace
  {
    /**
     * Some of the bodies of a run, for seeding: the points of the others
     * are left out, and each new point records its body (its number among
     * all bodies) in the point variable at @p body_slot.
     */
    template <int dim>
    class BodySelection : public SeedingBodies<dim>
    {
    public:
      BodySelection(const SeedingBodies<dim>        &all,
                    const std::vector<unsigned int> &selected,
                    const unsigned int               body_slot)
        : all(all)
        , selected(selected)
        , body_slot(body_slot)
      {}

      unsigned int
      n_bodies() const override
      {
        return selected.size();
      }

      std::string
      body_name(const unsigned int body) const override
      {
        return all.body_name(selected[body]);
      }

      unsigned int
      body_containing(const Point<dim> &X) const override
      {
        const auto found =
          std::find(selected.begin(), selected.end(), all.body_containing(X));
        return found == selected.end() ? numbers::invalid_unsigned_int :
                                         found - selected.begin();
      }

      unsigned int
      n_properties() const override
      {
        return all.n_properties();
      }

      void
      set_properties(const Point<dim>    &X,
                     const unsigned int   body,
                     const double         volume,
                     std::vector<double> &properties) const override
      {
        all.set_properties(X, selected[body], volume, properties);
        properties[body_slot] = selected[body];
      }

      std::vector<types::boundary_id>
      traction_boundaries() const override
      {
        return all.traction_boundaries();
      }

      BoundingBox<dim>
      material_region() const override
      {
        return all.material_region();
      }

    private:
      const SeedingBodies<dim>        &all;
      const std::vector<unsigned int> &selected;
      const unsigned int               body_slot;
    };

    /**
     * A positive number read from entry @p entry (its value @p text), or
     * the message that it is not.
     */
    double
    number_in(const std::string &text, const std::string &entry)
    {
      char        *end   = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      AssertThrow(!text.empty() && end != text.c_str() && *end == '\0' &&
                    std::isfinite(value),
                  ExcMessage(entry + " = <" + text + ">: must be a number."));
      return value;
    }

    /**
     * The place of @p name in @p names; stops with @p message followed by
     * the names (or "none") and @p advice if it is not there.
     */
    unsigned int
    place_in(const std::vector<std::string> &names,
             const std::string              &name,
             const std::string              &message,
             const std::string              &advice = "")
    {
      const auto  found = std::find(names.begin(), names.end(), name);
      std::string known;
      for (const auto &each : names)
        known += (known.empty() ? "" : ", ") + each;
      AssertThrow(found != names.end(),
                  ExcMessage(message + (known.empty() ? "none" : known) + "." +
                             advice));
      return found - names.begin();
    }

    /**
     * The gravity that @p stage sets (dim values).
     */
    template <int dim>
    Tensor<1, dim>
    gravity_of(const typename StagePlan<dim>::Stage &stage)
    {
      Tensor<1, dim> g;
      for (unsigned int d = 0; d < dim; ++d)
        g[d] = stage.gravity[d];
      return g;
    }
  } // namespace



  template <int dim>
  void
  StagePlan<dim>::declare_parameters(ParameterHandler               &prm,
                                     const std::vector<std::string> &names)
  {
    for (const auto &name : names)
      {
        prm.enter_subsection("Stage " + name);
        prm.declare_entry("End time",
                          "",
                          Patterns::Anything(),
                          "The time (s, from the start of the run, not of "
                          "the stage) at which this stage ends at the "
                          "latest; later than the End time of the stage "
                          "before. Required.");
        prm.declare_entry(
          "End at rest",
          "false",
          Patterns::Bool(),
          "Whether the stage ends as soon as the body has come to rest by "
          "the criterion of subsection 'Quasi-static end' (which must then "
          "be on); the next stage starts there. A stage that reaches its "
          "End time still moving says so in the log.");
        prm.declare_entry(
          "Remove bodies",
          "",
          Patterns::List(Patterns::Anything()),
          "Bodies (names in Bodies) whose material points are removed at "
          "the start of this stage: an excavation. The rest of the material "
          "then carries the loads the removed bodies carried.");
        prm.declare_entry(
          "Add bodies",
          "",
          Patterns::List(Patterns::Anything()),
          "Bodies (names in Bodies) that are seeded at the start of this "
          "stage, in the initial state their subsections give (velocity, "
          "stress): a fill or a structure placed later. They are absent "
          "before, and must not overlap the material present.");
        prm.declare_entry(
          "Reset displacements",
          "false",
          Patterns::Bool(),
          "Whether the displacements restart from zero at the start of this "
          "stage (as Plaxis users expect of a loading phase): the output, "
          "monitoring points and statistics show the displacement since. "
          "Stresses and strains are kept. Body forces and surface loads "
          "given as functions of the initial position X then take the "
          "position at the stage's start.");
        prm.declare_entry("Local damping coefficient",
                          "",
                          Patterns::Anything(),
                          "The local damping coefficient alpha in [0, 1) "
                          "from the start of this stage on (Damping/Local "
                          "damping coefficient before any stage sets it). "
                          "Empty: unchanged.");
        prm.declare_entry(
          "Gravity",
          "",
          Patterns::Anything(),
          "The gravitational acceleration (m/s^2) from the start of this "
          "stage on, one value per direction as Gravity/Vector (e.g. '1.47, "
          "-9.81' for a pseudo-static horizontal seismic coefficient of "
          "0.15), applied at once. Empty: unchanged.");
        prm.declare_entry(
          "Boundaries",
          "",
          Patterns::List(Patterns::Anything()),
          "The boundary conditions (names in Boundaries) that act from the "
          "start of this stage on, 'none' for none; the others leave their "
          "nodes free, have no reaction (0 in statistics.csv) and do not "
          "move. Empty: those of the stage before (every condition, before "
          "a stage names them). A prescribed Velocity is evaluated at the "
          "time t of the run. The problem's own fixed components (Custom "
          "problem/Fixed components) always act.");
        prm.declare_entry(
          "Surface loads",
          "",
          Patterns::List(Patterns::Anything()),
          "The surface loads (names in Surface loads) that act from the "
          "start of this stage on, 'none' for none; the others give no "
          "force. Empty: those of the stage before (every load, before a "
          "stage names them). A load acts as its Pressure and Traction say "
          "at the time t of the run, so that a load switched on at a stage "
          "whose start time is not known (after a stage that ends at rest) "
          "should not depend on t.");
        prm.leave_subsection();
      }
  }



  template <int dim>
  void
  StagePlan<dim>::parse_parameters(ParameterHandler &prm,
                                   const bool        fixed_grid,
                                   const bool        quasi_static_end)
  {
    const auto names      = SubsectionNames::names_in(prm, "Stages");
    const auto body_names = SubsectionNames::names_in(prm, "Bodies");
    const auto load_names = SubsectionNames::names_in(prm, "Surface loads");
    const auto condition_names = SubsectionNames::names_in(prm, "Boundaries");
    named                      = !names.empty();
    prm.enter_subsection("Time");
    const std::string time    = prm.get("End time");
    const double      run_end = prm.get_double("End time");
    prm.leave_subsection();
    stage_list.clear();
    present_in_stage.clear();
    present_at_start.assign(body_names.size(), true);
    if (!named)
      {
        Stage whole;
        whole.end_time    = run_end;
        whole.end_at_rest = quasi_static_end;
        stage_list.push_back(whole);
        return;
      }
    AssertThrow(time == "1e-3",
                ExcMessage("Time/End time = " + time +
                           ": with Stages, each stage has its own End time "
                           "(Stage NAME/End time) and the run ends with the "
                           "last; remove Time/End time."));

    // Whether each body exists, stage by stage.
    std::vector<bool> present(body_names.size(), true);
    const auto        body_numbers = [&](const std::string &entry,
                                  const std::string &stage) {
      std::vector<unsigned int> numbers;
      for (const auto &body : Utilities::split_string_list(prm.get(entry), ','))
        {
          const unsigned int number =
            place_in(body_names,
                     body,
                     "Stage " + stage + "/" + entry + ": <" + body +
                       "> is not a body; the bodies (entry Bodies) are: ");
          AssertThrow(fixed_grid,
                      ExcMessage("Stage " + stage + "/" + entry +
                                 ": bodies can be removed or added only on a "
                                        "fixed grid (Method = MPM); OTM and Unified "
                                        "move the grid with the material, which must "
                                        "fill it at every stage."));
          numbers.push_back(number);
        }
      return numbers;
    };
    // A body that some stage adds is absent before it.
    for (const auto &name : names)
      {
        prm.enter_subsection("Stage " + name);
        for (const auto body : body_numbers("Add bodies", name))
          {
            AssertThrow(present_at_start[body],
                        ExcMessage("Stage " + name + "/Add bodies: <" +
                                   body_names[body] +
                                   "> is added by an earlier stage too; a "
                                   "body is added once."));
            present_at_start[body] = false;
          }
        prm.leave_subsection();
      }
    present = present_at_start;

    double     previous_end = 0;
    const auto seconds      = [](const double time) {
      std::ostringstream text;
      text << time;
      return text.str();
    };
    for (const auto &name : names)
      {
        prm.enter_subsection("Stage " + name);
        Stage stage;
        stage.name = name;
        stage.end_time =
          number_in(prm.get("End time"), "Stage " + name + "/End time");
        AssertThrow(stage.end_time > previous_end,
                    ExcMessage("Stage " + name +
                               "/End time = " + prm.get("End time") +
                               " must be after the end of the stage before "
                               "(" +
                               seconds(previous_end) +
                               " s; the times count from the start of the "
                               "run)."));
        previous_end      = stage.end_time;
        stage.end_at_rest = prm.get_bool("End at rest");
        AssertThrow(!stage.end_at_rest || quasi_static_end,
                    ExcMessage("Stage " + name +
                               "/End at rest = true needs the criterion of "
                               "rest: set Quasi-static end/Kinetic energy "
                               "ratio (e.g. 1e-6)."));
        stage.removed_bodies = body_numbers("Remove bodies", name);
        stage.added_bodies   = body_numbers("Add bodies", name);
        for (const auto body : stage.removed_bodies)
          {
            AssertThrow(present[body],
                        ExcMessage("Stage " + name + "/Remove bodies: <" +
                                   body_names[body] +
                                   "> is not there at the start of this "
                                   "stage (added by a later stage, or "
                                   "removed before)."));
            AssertThrow(std::count(stage.removed_bodies.begin(),
                                   stage.removed_bodies.end(),
                                   body) == 1,
                        ExcMessage("Stage " + name + "/Remove bodies names <" +
                                   body_names[body] + "> twice."));
            present[body] = false;
          }
        for (const auto body : stage.added_bodies)
          present[body] = true;
        present_in_stage.push_back(present);
        stage.reset_displacements = prm.get_bool("Reset displacements");
        const std::string damping = prm.get("Local damping coefficient");
        const std::string damping_entry =
          "Stage " + name + "/Local damping coefficient";
        if (!Utilities::trim(damping).empty())
          {
            stage.damping_coefficient =
              number_in(Utilities::trim(damping), damping_entry);
            AssertThrow(stage.damping_coefficient >= 0. &&
                          stage.damping_coefficient < 1.,
                        ExcMessage(damping_entry + " = " + damping +
                                   ": must lie in [0, 1)."));
          }
        const std::string gravity_entry = "Stage " + name + "/Gravity";
        for (const auto &value :
             Utilities::split_string_list(prm.get("Gravity"), ','))
          stage.gravity.push_back(number_in(value, gravity_entry));
        AssertThrow(stage.gravity.size() <= 1 || stage.gravity.size() == dim,
                    ExcMessage(gravity_entry + " = " + prm.get("Gravity") +
                               ": give one value per direction (" +
                               std::to_string(dim) +
                               "), one for every direction, or none "
                               "(unchanged)."));
        if (stage.gravity.size() == 1)
          stage.gravity.assign(dim, stage.gravity[0]);
        const std::string acting = Utilities::trim(prm.get("Boundaries"));
        if (!acting.empty())
          {
            stage.acting_conditions.assign(condition_names.size(), false);
            if (acting != "none")
              for (const auto &condition :
                   Utilities::split_string_list(acting, ','))
                stage.acting_conditions[place_in(
                  condition_names,
                  condition,
                  "Stage " + name + "/Boundaries: <" + condition +
                    "> is not a boundary condition; the conditions (entry "
                    "Boundaries) are: ",
                  " Write none for none.")] = true;
          }
        const std::string loads = Utilities::trim(prm.get("Surface loads"));
        if (!loads.empty())
          {
            stage.acting_loads.assign(load_names.size(), false);
            if (loads != "none")
              for (const auto &load : Utilities::split_string_list(loads, ','))
                {
                  stage.acting_loads[place_in(
                    load_names,
                    load,
                    "Stage " + name + "/Surface loads: <" + load +
                      "> is not a surface load; the loads (entry Surface "
                      "loads) are: ",
                    " Write none for none.")] = true;
                }
          }
        prm.leave_subsection();
        stage_list.push_back(stage);
      }
    AssertThrow(std::find(present_at_start.begin(),
                          present_at_start.end(),
                          true) != present_at_start.end(),
                ExcMessage("Every body is added by a stage (Stage NAME/Add "
                           "bodies), so the run would start without "
                           "material; let at least one body be there from "
                           "the start."));
  }



  template <int dim>
  bool
  StagePlan<dim>::staged() const
  {
    return named;
  }



  template <int dim>
  const std::vector<typename StagePlan<dim>::Stage> &
  StagePlan<dim>::stages() const
  {
    return stage_list;
  }



  template <int dim>
  bool
  StagePlan<dim>::sets_gravity() const
  {
    return std::any_of(stage_list.begin(),
                       stage_list.end(),
                       [](const Stage &stage) {
                         return std::any_of(stage.gravity.begin(),
                                            stage.gravity.end(),
                                            [](const double g) {
                                              return g != 0.;
                                            });
                       });
  }



  template <int dim>
  std::string
  StagePlan<dim>::end_time_entry() const
  {
    return named ? "Stage " + stage_list.back().name + "/End time" :
                   "Time/End time";
  }



  template <int dim>
  void
  StagePlan<dim>::reserve_point_variables(MaterialLibrary<dim> &materials)
  {
    if (named)
      body_slot = materials.add_point_variables({"body"});
  }



  template <int dim>
  void
  StagePlan<dim>::seed(MaterialPoints<dim>        &points,
                       const BackgroundGrid<dim>  &grid,
                       Problem<dim>               &problem,
                       const MaterialLibrary<dim> &materials) const
  {
    const BodySeeder<dim> bodies(problem, materials);
    if (!named)
      {
        points.seed(grid, bodies);
        return;
      }
    problem.set_present_bodies(present_at_start);
    std::vector<unsigned int> at_start;
    for (unsigned int body = 0; body < bodies.n_bodies(); ++body)
      if (body >= present_at_start.size() || present_at_start[body])
        at_start.push_back(body);
    points.seed(grid, BodySelection<dim>(bodies, at_start, body_slot));
  }



  template <int dim>
  void
  StagePlan<dim>::set_acting_conditions(const std::vector<bool> &acting,
                                        const Problem<dim>      &problem,
                                        BoundaryConditions<dim> &conditions,
                                        NodalSystem<dim>        &system) const
  {
    conditions.set_acting(acting);
    auto fixed = problem.fixed_components();
    for (const auto &condition_fixed : conditions.fixed_components())
      fixed.push_back(condition_fixed);
    system.set_fixed_components(fixed);
  }



  template <int dim>
  std::string
  StagePlan<dim>::begin(const unsigned int          stage_number,
                        MaterialPoints<dim>        &points,
                        Problem<dim>               &problem,
                        const MaterialLibrary<dim> &materials,
                        LocalDamping<dim>          &damping,
                        BoundaryConditions<dim>    &conditions,
                        NodalSystem<dim>           &system) const
  {
    const BodySeeder<dim> bodies(problem, materials);
    problem.set_present_bodies(present_in_stage.at(stage_number));
    using Layout          = PropertyLayout<dim>;
    const Stage &stage    = stage_list.at(stage_number);
    auto        &handler  = points.particle_handler();
    const auto   names_of = [&](const std::vector<unsigned int> &numbers) {
      std::string text;
      for (const auto body : numbers)
        text += (text.empty() ? "" : ", ") + bodies.body_name(body);
      return text;
    };
    std::ostringstream changes;
    if (!stage.gravity.empty())
      {
        problem.set_gravity(gravity_of<dim>(stage));
        changes << "gravity (" << stage.gravity[0];
        for (unsigned int d = 1; d < dim; ++d)
          changes << ", " << stage.gravity[d];
        changes << ") m/s^2; ";
      }
    if (!stage.removed_bodies.empty())
      {
        std::vector<typename Particles::ParticleHandler<dim>::particle_iterator>
          removed;
        for (auto particle = handler.begin(); particle != handler.end();
             ++particle)
          if (std::count(stage.removed_bodies.begin(),
                         stage.removed_bodies.end(),
                         static_cast<unsigned int>(
                           particle->get_properties()[body_slot])) > 0)
            removed.push_back(particle);
        const auto n_removed =
          Utilities::MPI::sum(removed.size(), points.communicator());
        handler.remove_particles(removed);
        handler.update_cached_numbers();
        changes << "removed the " << n_removed << " points of "
                << names_of(stage.removed_bodies) << "; ";
      }
    if (!stage.added_bodies.empty())
      {
        const auto before = points.n_global_points();
        points.add(BodySelection<dim>(bodies, stage.added_bodies, body_slot));
        changes << "added " << points.n_global_points() - before
                << " points of " << names_of(stage.added_bodies) << "; ";
      }
    if (stage.reset_displacements)
      {
        for (auto &particle : handler)
          Layout::set_vector(particle.get_properties(),
                             Layout::initial_position,
                             particle.get_location());
        changes << "displacements reset to zero; ";
      }
    if (stage.damping_coefficient >= 0.)
      {
        damping.set_coefficient(stage.damping_coefficient);
        changes << "local damping coefficient " << stage.damping_coefficient
                << "; ";
      }
    if (!stage.acting_conditions.empty())
      {
        set_acting_conditions(stage.acting_conditions,
                              problem,
                              conditions,
                              system);
        std::string acting;
        for (const auto &name : conditions.acting_names())
          acting += (acting.empty() ? "" : ", ") + name;
        changes << "boundary conditions acting: "
                << (acting.empty() ? std::string("none") : acting) << "; ";
      }
    if (!stage.acting_loads.empty())
      {
        problem.surface_loads().set_acting(stage.acting_loads);
        std::string acting;
        const auto &load_names = problem.surface_loads().names();
        for (unsigned int k = 0; k < load_names.size(); ++k)
          if (stage.acting_loads[k])
            acting += (acting.empty() ? "" : ", ") + load_names[k];
        changes << "surface loads acting: "
                << (acting.empty() ? std::string("none") : acting) << "; ";
      }
    std::string text = changes.str();
    return text.empty() ? "no change" : text.substr(0, text.size() - 2);
  }



  template <int dim>
  void
  StagePlan<dim>::restore(const unsigned int       stage,
                          LocalDamping<dim>       &damping,
                          Problem<dim>            &problem,
                          BoundaryConditions<dim> &conditions,
                          NodalSystem<dim>        &system) const
  {
    for (unsigned int k = 0; k <= stage && k < stage_list.size(); ++k)
      {
        if (stage_list[k].damping_coefficient >= 0.)
          damping.set_coefficient(stage_list[k].damping_coefficient);
        if (!stage_list[k].acting_loads.empty())
          problem.surface_loads().set_acting(stage_list[k].acting_loads);
        if (!stage_list[k].gravity.empty())
          problem.set_gravity(gravity_of<dim>(stage_list[k]));
        if (!stage_list[k].acting_conditions.empty())
          set_acting_conditions(stage_list[k].acting_conditions,
                                problem,
                                conditions,
                                system);
      }
  }



  template class StagePlan<1>;
  template class StagePlan<2>;
  template class StagePlan<3>;
} // namespace MpmOtm
