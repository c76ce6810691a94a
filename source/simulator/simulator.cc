#include <deal.II/base/timer.h>

#include <mpm_otm/algorithms/advected_grid.h>
#include <mpm_otm/algorithms/advected_knots.h>
#include <mpm_otm/algorithms/energy_monitor.h>
#include <mpm_otm/algorithms/fixed_grid.h>
#include <mpm_otm/algorithms/nodal_update.h>
#include <mpm_otm/algorithms/optimal_transportation_update.h>
#include <mpm_otm/algorithms/stable_time_step.h>
#include <mpm_otm/algorithms/time_stepper.h>
#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/base/plugins.h>
#include <mpm_otm/base/stop_signal.h>
#include <mpm_otm/boundary_conditions/boundary_conditions.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/grid_system/local_damping.h>
#include <mpm_otm/grid_system/mass_matrix.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/io/checkpoint.h>
#include <mpm_otm/io/output_writer.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/problems/body.h>
#include <mpm_otm/problems/problem.h>
#include <mpm_otm/shape_functions/b_splines.h>
#include <mpm_otm/shape_functions/shape_functions.h>
#include <mpm_otm/simulator/simulator.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <tuple>

namespace MpmOtm
{
  namespace
  {
    /**
     * The "additional information" of a deal.II exception, without the
     * banner.
     */
    std::string
    message_of(const std::exception &error)
    {
      if (const auto *exception = dynamic_cast<const ExceptionBase *>(&error))
        {
          // print_info() indents the text and ends it with a new line.
          std::ostringstream text;
          exception->print_info(text);
          const std::string info  = text.str();
          const auto        begin = info.find_first_not_of(" \n");
          const auto        end   = info.find_last_not_of(" \n");
          return (begin == std::string::npos) ?
                   std::string() :
                   info.substr(begin, end - begin + 1);
        }
      return error.what();
    }
  } // namespace



  unsigned int
  read_dimension(const std::string &filename)
  {
    ParameterHandler prm;
    prm.declare_entry("Dimension",
                      "1",
                      Patterns::Integer(1, 3),
                      "Space dimension: 1, 2 or 3.");
    if (!filename.empty())
      {
        AssertThrow(std::filesystem::is_regular_file(filename),
                    ExcMessage("Parameter file <" + filename +
                               "> does not exist or is not a file."));
        prm.parse_input(filename, "", true);
      }
    return prm.get_integer("Dimension");
  }



  template <int dim>
  Simulator<dim>::Simulator(const MPI_Comm communicator, std::ostream &log)
    : communicator(communicator)
    , pcout(log, Utilities::MPI::this_mpi_process(communicator) == 0)
  {}



  template <int dim>
  Simulator<dim>::~Simulator() = default;



  template <int dim>
  void
  Simulator<dim>::declare_parameters(ParameterHandler      &prm,
                                     const SubsectionNames &names)
  {
    SubsectionNames::declare_parameters(prm);
    prm.declare_entry("Dimension",
                      "1",
                      Patterns::Integer(1, 3),
                      "Space dimension: 1, 2 or 3.");
    prm.declare_entry("Problem",
                      "vibrating bar",
                      Patterns::Selection(
                        PluginRegistry<Problem<dim>>::selection()),
                      "Benchmark or user problem:" +
                        PluginRegistry<Problem<dim>>::documentation());
    prm.declare_entry(
      "Method",
      "MPM",
      Patterns::Selection("MPM|OTM|Unified"),
      "MPM: material-point method, shape functions on the fixed background "
      "grid (journal Alg. 1; nodal update from 'Update scheme'). "
      "OTM: optimal transportation meshfree method (journal Alg. 2): the "
      "grid's vertices move with the material every step, nodal update of "
      "Eq. 51, particle velocities from the displacements; needs linearly "
      "complete shape functions. "
      "Unified: the unified approach (journal Alg. 3): the grid moves as in "
      "OTM, the particle update is that of 'Update scheme'; the journal uses "
      "it with Mass matrix = consistent. OTM and Unified mesh only the "
      "material domain.");
    prm.declare_entry(
      "Update scheme",
      "automatic",
      Patterns::Selection("automatic|" +
                          PluginRegistry<NodalUpdate<dim>>::selection()),
      "Nodal update of Method = MPM and Unified:" +
        PluginRegistry<NodalUpdate<dim>>::documentation() +
        ". automatic: MUSL for MPM (USL, the sources' update, gained energy "
        "and blew up on the user problems G1-G3, where MUSL ran: manual, "
        "'Your own problem'), USL for Unified (journal Alg. 3). OTM has its "
        "own update (Eq. 51) and takes no other.");
    prm.declare_entry("Shape functions",
                      "linear",
                      Patterns::Selection(
                        PluginRegistry<ShapeFunctions<dim>>::selection()),
                      "Shape-function family:" +
                        PluginRegistry<ShapeFunctions<dim>>::documentation());
    prm.declare_entry("Mass matrix",
                      "lumped",
                      Patterns::Selection(
                        PluginRegistry<MassMatrix<dim>>::selection()),
                      "Use of the mass matrix:" +
                        PluginRegistry<MassMatrix<dim>>::documentation());
    prm.declare_entry(
      "Deactivation threshold",
      "0",
      Patterns::Double(0.),
      "Deactivate, in every step, the functions whose diagonal mass-matrix "
      "entry M_ii = sum_p m_p phi_i(x_p)^2 (a mass, in the units of the "
      "problem) is below this value: their coefficients are set to zero, as "
      "for functions without material (thesis Sect. 5.2, which uses 1e-2 for "
      "the soil column of Table 4.6). It stabilises nearly empty cells at "
      "the cost of an error near them. 0: no deactivation.");

    prm.enter_subsection("Time");
    prm.declare_entry("End time",
                      "1e-3",
                      Patterns::Double(0.),
                      "Simulated time T (s).");
    prm.declare_entry(
      "Time step",
      "1e-5",
      Patterns::Anything(),
      "Time step dt (s), a positive number or 'auto'. It must not exceed the "
      "stable time step 2 / omega_max of the discretisation, which the "
      "program estimates at the start (omega_max^2 the largest eigenvalue "
      "of M^-1 K at the initial configuration; manual, 'Time step') and "
      "prints. auto: dt = Courant factor x 2 / omega_max.");
    prm.declare_entry(
      "Courant factor",
      "0.5",
      Patterns::Double(0., 1.),
      "With Time step = auto, the fraction of the stable time step "
      "2 / omega_max used, in (0, 1]. Large deformations change the "
      "stable time step during a run, so keep a margin.");
    prm.declare_entry(
      "Energy growth limit",
      "1",
      Patterns::Double(0.),
      "Stop the run as unstable when the kinetic plus strain energy of the "
      "points exceeds (1 + this) times the energy supplied: the energy at "
      "the start plus the work of gravity, body forces, tractions and "
      "prescribed velocities. Checked every 10 steps and at every output. "
      "A stable run errs on this balance by a few per cent; an unstable one "
      "gains energy by a fixed factor per step (manual, 'Safety').");
    prm.leave_subsection();

    BackgroundGrid<dim>::declare_parameters(prm);
    MaterialPoints<dim>::declare_parameters(prm);
    MaterialLibrary<dim>::declare_parameters(prm, names.materials);
    Problem<dim>::declare_common_parameters(prm);
    for (const auto &name : names.bodies)
      {
        prm.enter_subsection("Body " + name);
        Body<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
    OutputWriter<dim>::declare_parameters(prm);
    Checkpoint<dim>::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm, names.boundaries);
    LocalDamping<dim>::declare_parameters(prm);

    PluginRegistry<Problem<dim>>::declare_parameters(prm);
    PluginRegistry<NodalUpdate<dim>>::declare_parameters(prm);
    PluginRegistry<ShapeFunctions<dim>>::declare_parameters(prm);
    PluginRegistry<MassMatrix<dim>>::declare_parameters(prm);
  }



  template <int dim>
  void
  Simulator<dim>::parse_parameters(ParameterHandler &prm)
  {
    AssertThrow(prm.get_integer("Dimension") == dim, ExcInternalError());

    materials = std::make_unique<MaterialLibrary<dim>>();
    materials->parse_parameters(prm);
    problem_description =
      PluginRegistry<Problem<dim>>::create(prm.get("Problem"));
    problem_description->parse(prm, *materials);
    shape_functions =
      PluginRegistry<ShapeFunctions<dim>>::create(prm.get("Shape functions"));
    shape_functions->parse_parameters(prm);
    const std::string method = prm.get("Method");
    AssertThrow(method == "MPM" || prm.get("Shape functions") != "Powell-Sabin",
                ExcMessage("Shape functions = Powell-Sabin run with Method = "
                           "MPM (Update scheme = USL or MUSL): their three "
                           "functions per vertex do not move with the "
                           "vertices, which OTM and the unified approach "
                           "need (a moving triangulation is future work)."));
    std::string update_scheme = prm.get("Update scheme");
    if (update_scheme == "automatic")
      update_scheme = (method == "MPM") ? "MUSL" : "USL";
    if (method == "OTM")
      {
        AssertThrow(prm.get("Update scheme") == "automatic",
                    ExcMessage("Update scheme = " + prm.get("Update scheme") +
                               " applies to Method = MPM or Unified; OTM has "
                               "its own nodal update (journal Eq. 51). Remove "
                               "the entry."));
        AssertThrow(shape_functions->is_linearly_complete(),
                    ExcMessage(
                      "Method = OTM needs linearly complete shape "
                      "functions (journal Eq. 47); Shape functions = " +
                      prm.get("Shape functions") +
                      (prm.get("Shape functions") == "B-spline" ?
                         " of degree " + prm.get("B-spline degree") :
                         std::string()) +
                      " are not. Use Method = MPM or Unified, or "
                      "linearly complete functions (B-spline degree = 1)."));
        nodal_update = std::make_unique<OptimalTransportationUpdate<dim>>();
        if (prm.get("Mass matrix") != "consistent")
          pcout << "Note: OTM with Mass matrix = " << prm.get("Mass matrix")
                << " smooths the particle velocities (journal Eq. 57) "
                << "every step and is dissipative; Alg. 2 uses the "
                << "consistent mass matrix (Eq. 48)." << std::endl;
      }
    else
      nodal_update = PluginRegistry<NodalUpdate<dim>>::create(update_scheme);
    if (method == "MPM")
      grid_motion = std::make_unique<FixedGrid<dim>>();
    else if (auto *splines =
               dynamic_cast<BSplines<dim> *>(shape_functions.get()))
      {
        // Knots move with direction-averaged velocities in 2D and 3D while
        // OTM moves the points with the full field (Alg. 2 needs points
        // that keep their place in the moving discretisation).
        AssertThrow(method == "Unified" || dim == 1,
                    ExcMessage("Method = OTM with Shape functions = B-spline "
                               "runs in 1D only: in 2D and 3D the knots move "
                               "per direction with averaged velocities, which "
                               "is the unified approach (Method = Unified), "
                               "not OTM. Use Method = Unified, or linear "
                               "functions for OTM."));
        grid_motion = std::make_unique<AdvectedKnots<dim>>(*splines);
      }
    else
      grid_motion = std::make_unique<AdvectedGrid<dim>>();
    mass_matrix =
      PluginRegistry<MassMatrix<dim>>::create(prm.get("Mass matrix"));
    deactivation_threshold = prm.get_double("Deactivation threshold");

    prm.enter_subsection("Time");
    end_time                     = prm.get_double("End time");
    const std::string step_entry = prm.get("Time step");
    automatic_time_step          = (step_entry == "auto");
    courant_factor               = prm.get_double("Courant factor");
    energy_growth_limit          = prm.get_double("Energy growth limit");
    prm.leave_subsection();
    if (!automatic_time_step)
      {
        char *end = nullptr;
        time_step = std::strtod(step_entry.c_str(), &end);
        AssertThrow(end != step_entry.c_str() && *end == '\0' &&
                      std::isfinite(time_step) && time_step > 0,
                    ExcMessage("Time/Time step = " + step_entry +
                               ": must be a positive number (s) or auto."));
      }
    AssertThrow(courant_factor > 0,
                ExcMessage("Time/Courant factor must be positive (at most "
                           "1)."));

    grid = std::make_unique<BackgroundGrid<dim>>();
    grid->parse_parameters(prm);
    AssertThrow(grid->is_box() || problem_description->runs_on_any_grid(),
                ExcMessage("Mesh/Mesh file: Problem = " + prm.get("Problem") +
                           " is a benchmark defined on a box grid (its "
                           "boundary ids are the box's sides 0 to " +
                           std::to_string(2 * dim - 1) +
                           "); on the mesh of a file use Problem = custom."));
    points = std::make_unique<MaterialPoints<dim>>();
    points->parse_parameters(prm);
    output = std::make_unique<OutputWriter<dim>>();
    output->parse_parameters(prm);
    checkpoint = std::make_unique<Checkpoint<dim>>();
    checkpoint->parse_parameters(prm);
    boundary_conditions = std::make_unique<BoundaryConditions<dim>>();
    boundary_conditions->parse_parameters(prm);
    AssertThrow(boundary_conditions->empty() || method == "MPM",
                ExcMessage("Boundaries: the boundary conditions of the entry "
                           "'Boundaries' act on the nodes of a fixed grid and "
                           "need Method = MPM; OTM and Unified move the grid "
                           "with the material (use the problem's fixed "
                           "components there)."));
    damping = std::make_unique<LocalDamping<dim>>();
    damping->parse_parameters(prm);
  }



  template <int dim>
  void
  Simulator<dim>::setup(const ParameterHandler &prm, const bool resume)
  {
    grid->create(communicator, grid_motion->moves_vertices());

    problem_description->initialize(materials->default_material(), grid->box());
    if (grid_motion->moves_vertices() && grid->is_box())
      {
        // OTM and the unified approach mesh the material domain only: a
        // node without material would stay behind while the cells around
        // it move with the material.
        const auto   region    = problem_description->material_region();
        const auto   box       = grid->box();
        const double tolerance = 1e-10 * box.side_length(0);
        bool         same      = true;
        for (unsigned int d = 0; d < dim; ++d)
          same =
            same &&
            std::abs(region.lower_bound(d) - box.lower_bound(d)) <= tolerance &&
            std::abs(region.upper_bound(d) - box.upper_bound(d)) <= tolerance;
        if (!same)
          {
            std::ostringstream message;
            message << "Method = OTM and Unified move the grid with the "
                       "material, so the grid must be the material domain: "
                       "the material fills ["
                    << region.get_boundary_points().first << "] to ["
                    << region.get_boundary_points().second
                    << "] but the grid (Mesh/Lower corner, Upper corner) "
                       "spans ["
                    << box.get_boundary_points().first << "] to ["
                    << box.get_boundary_points().second
                    << "]. Set the Mesh corners to the material's.";
            AssertThrow(false, ExcMessage(message.str()));
          }
      }
    points->seed(*grid, *materials, *problem_description);
    if (grid_motion->moves_vertices() && !grid->is_box())
      {
        // The same condition on a Mesh file: no point of the seeding
        // pattern may lie outside the material.
        const auto outside = points->n_pattern_points_outside_bodies();
        AssertThrow(outside == 0,
                    ExcMessage(
                      "Method = OTM and Unified move the grid with the "
                      "material, so the material must fill the grid, but " +
                      std::to_string(outside) +
                      " points of the seeding pattern in the cells of "
                      "Mesh/Mesh file <" +
                      grid->mesh_file() +
                      "> lie in no body. Mesh only the material, or let the "
                      "bodies cover every cell."));
      }
    AssertThrow(points->n_global_points() > 0,
                ExcMessage("No material point was created: the problem's "
                           "material region contains no block centre of "
                           "the grid."));
    Timer shape_function_timer(communicator, true);
    shape_functions->initialize(*grid);
    shape_function_timer.stop();
    boundary_conditions->setup(*shape_functions, *grid);
    auto fixed_components = problem_description->fixed_components();
    {
      const auto grid_ids = grid->boundary_ids();
      for (const auto &fixed : fixed_components)
        if (!std::binary_search(grid_ids.begin(),
                                grid_ids.end(),
                                fixed.boundary_id))
          {
            std::string ids;
            for (const auto id : grid_ids)
              ids += (ids.empty() ? "" : ", ") + std::to_string(id);
            AssertThrow(false,
                        ExcMessage(
                          "The problem's fixed components (Custom "
                          "problem/Fixed components) name boundary id " +
                          std::to_string(fixed.boundary_id) +
                          ", which no boundary face of the grid has; the "
                          "grid's boundary ids are " +
                          ids +
                          " (for a Mesh file its physical tags, 0 on "
                          "untagged faces)."));
          }
    }
    for (const auto &fixed : boundary_conditions->fixed_components())
      fixed_components.push_back(fixed);
    system = std::make_unique<NodalSystem<dim>>();
    system->setup(*shape_functions,
                  fixed_components,
                  deactivation_threshold,
                  mass_matrix->needs_material_boundary());
    // The stable time step of this discretisation at the start; a larger
    // time step is rejected before anything is written.
    const auto stable = StableTimeStep<dim>().estimate(*points,
                                                       *shape_functions,
                                                       *system,
                                                       *mass_matrix,
                                                       *materials,
                                                       *problem_description);
    stable_step       = stable.time_step;
    if (automatic_time_step)
      time_step = courant_factor * stable.time_step;
    if (!(time_step <= stable.time_step))
      {
        std::ostringstream message;
        message << "Time/Time step = " << time_step
                << " exceeds the stable time step 2 / omega_max = "
                << stable.time_step << " of this discretisation (omega_max = "
                << stable.largest_frequency
                << " 1/s, the largest frequency of its shape functions, mass "
                   "matrix and material points at the start; for reference "
                   "h / c = "
                << grid->minimal_cell_size() / materials->maximal_wave_speed()
                << " with the smallest cell size h and the wave speed c). "
                   "Choose a time step of at most "
                << stable.time_step
                << ", or Time step = auto (manual, 'Time step').";
        AssertThrow(false, ExcMessage(message.str()));
      }
    grid_motion->initialize(*grid,
                            *shape_functions,
                            *system,
                            grid->minimal_cell_size() * time_step /
                              stable.time_step);
    // Every load expression is evaluated before anything is written: the
    // body force at every point's initial position and the tractions, at
    // the start and at the end time. An expression that does not evaluate
    // then stops the run here instead of in its first step.
    {
      std::string problem;
      try
        {
          using Layout = PropertyLayout<dim>;
          for (const double t : {0., end_time})
            {
              if (problem_description->has_body_force())
                for (const auto &particle : points->particle_handler())
                  problem_description->body_force(
                    Point<dim>(Layout::get_vector(particle.get_properties(),
                                                  Layout::initial_position)),
                    t);
              for (const auto id : problem_description->traction_boundaries())
                problem_description->traction(id, t);
            }
        }
      catch (const std::exception &error)
        {
          problem = message_of(error) + " ";
        }
      stop_if_any_rank_failed(communicator, problem, "", "");
    }
    current_time = 0;
    std::string resumed_from;
    if (resume)
      {
        // The grid moves first; the points then enter their saved cells.
        resumed_from =
          Checkpoint<dim>::newest(output->directory(), communicator);
        resumed_state = std::make_unique<CheckpointState>();
        std::tie(resumed_step, current_time) =
          Checkpoint<dim>::read(resumed_from,
                                *points,
                                *resumed_state,
                                communicator);
        grid_motion->load(*resumed_state);
        shape_functions->load(*resumed_state);
        system->load(*resumed_state);
        boundary_conditions->load(*resumed_state);
      }
    output->initialize(prm,
                       problem_description->has_exact_solution(),
                       problem_description->has_exact_stress(),
                       communicator,
                       *materials,
                       boundary_conditions->names(),
                       problem_description->has_gravity(),
                       resumed_step);
    if (resume)
      output->load(*resumed_state);
    else
      output->write_powell_sabin_basis(*shape_functions);

    pcout << "mpm-otm: " << dim << "D, "
          << grid->triangulation().n_global_active_cells() << " cells, "
          << shape_functions->n_functions() << " shape functions, "
          << points->n_global_points() << " material points, "
          << Utilities::MPI::n_mpi_processes(communicator) << " MPI rank(s)"
          << std::endl;
    pcout << "time step " << time_step << " s = " << std::setprecision(3)
          << time_step / stable.time_step
          << " x the stable time step 2 / omega_max = " << stable.time_step
          << " s (Lanczos, " << stable.iterations << " iterations";
    if (!stable.converged)
      pcout << ", not converged: omega_max^2 changed by " << stable.last_change
            << " in the last one";
    pcout << ")" << std::setprecision(6) << std::endl;
    pcout << "set-up of the shape functions: wall time = " << std::fixed
          << std::setprecision(3) << shape_function_timer.wall_time() << " s"
          << std::defaultfloat << std::endl;
    if (resume)
      pcout << "resumed from <" << resumed_from << ">, written after time step "
            << resumed_step << " (t = " << current_time << ")" << std::endl;
  }



  template <int dim>
  Statistics<dim>
  Simulator<dim>::run(
    const std::function<void(unsigned int, const Statistics<dim> &)> &observer)
  {
    Statistics<dim> statistics;
    // A step that fails ends the loop with this message, thrown once the
    // timer is gone: deal.II's TimerOutput prints a notice in front of the
    // error if it is destroyed while an exception is in flight.
    std::string stop_message;
    std::string stopped_by;
    {
      TimerOutput      timer(communicator,
                        pcout,
                        TimerOutput::summary,
                        TimerOutput::wall_times);
      TimeStepper<dim> stepper(*points,
                               *shape_functions,
                               *system,
                               *mass_matrix,
                               *nodal_update,
                               *grid_motion,
                               *materials,
                               *problem_description,
                               *boundary_conditions,
                               *damping,
                               timer);

      AssertThrow(end_time / time_step < 1e9,
                  ExcMessage("Time/End time / Time/Time step is above 1e9 time "
                             "steps; check both entries."));
      const unsigned int n_steps =
        static_cast<unsigned int>(std::ceil(end_time / time_step - 1e-8));
      Timer wall_clock(communicator, true);

      const auto report = [&](const unsigned int step) {
        TimerOutput::Scope scope(timer, "output");
        statistics.compute(*points,
                           *materials,
                           *problem_description,
                           current_time);
        statistics.supplied_work =
          Utilities::MPI::sum(stepper.supplied_work(), communicator);
        statistics.boundary_names = boundary_conditions->names();
        statistics.boundary_reactions =
          boundary_conditions->reactions_and_displacements();
        output->write(step,
                      current_time,
                      *points,
                      *grid,
                      *shape_functions,
                      *system,
                      statistics);
        const double elapsed = wall_clock.wall_time();
        pcout << "step " << std::setw(7) << step << " of " << n_steps
              << "  t = " << std::scientific << std::setprecision(4)
              << current_time
              << "  kinetic energy = " << statistics.kinetic_energy
              << "  wall time = " << std::fixed << std::setprecision(2)
              << elapsed << " s";
        if (step > resumed_step && step < n_steps)
          {
            const double remaining =
              elapsed * (n_steps - step) / (step - resumed_step);
            pcout << ", about " << std::setprecision(remaining < 10. ? 1 : 0)
                  << remaining << " s to go";
          }
        pcout << std::defaultfloat << std::setprecision(6) << std::endl;
        if (observer)
          observer(step, statistics);
      };

      EnergyMonitor<dim> energy_monitor(energy_growth_limit,
                                        grid->minimal_cell_size() / time_step,
                                        communicator);
      // SIGTERM or SIGINT ends the run after a complete step, with its
      // output and a checkpoint; the ranks agree on it where they check the
      // energy. Installed before the first output, which a scheduler may
      // already interrupt.
      const StopSignal stop_signal;
      std::string      signal;
      if (resumed_state)
        {
          stepper.load(*resumed_state);
          energy_monitor.load(*resumed_state);
          resumed_state.reset();
        }
      else
        {
          energy_monitor.check(*points, *materials, stepper.supplied_work());
          report(0);
        }
      for (unsigned int step = resumed_step + 1; step <= n_steps; ++step)
        {
          const double dt = std::min(time_step, end_time - current_time);
          try
            {
              stepper.advance(current_time, dt);
              if (step % 10 == 0 ||
                  output->is_output_step(step, step == n_steps))
                {
                  energy_monitor.check(*points,
                                       *materials,
                                       stepper.supplied_work());
                  signal = stop_signal.received(communicator);
                }
            }
          catch (const std::exception &error)
            {
              std::ostringstream message;
              message << "Stopped in time step " << step
                      << " (t = " << current_time << " to " << current_time + dt
                      << "); the output up to the last output step is in <"
                      << output->directory() << ">. " << message_of(error);
              stop_message = message.str();
              timer.disable_output();
              break;
            }
          current_time = (step == n_steps) ? end_time : current_time + dt;
          if (output->is_output_step(step, step == n_steps) || !signal.empty())
            report(step);
          if (step < n_steps &&
              (!signal.empty() || checkpoint->is_due(step, communicator)))
            {
              TimerOutput::Scope scope(timer, "checkpoint");
              write_checkpoint(step, stepper, energy_monitor);
            }
          if (!signal.empty() && step < n_steps)
            {
              std::ostringstream message;
              message << "Stopped by " << signal << " after time step " << step
                      << " (t = " << current_time
                      << "); the output of this step and of the output steps "
                      << "before it and a checkpoint of this step are in <"
                      << output->directory()
                      << ">. Continue the run with: mpm-otm --resume "
                      << output->directory();
              stop_message = message.str();
              stopped_by   = signal;
              timer.disable_output();
              break;
            }
        }
    }
    if (!stopped_by.empty())
      throw StoppedBySignal(stop_message, stopped_by);
    AssertThrow(stop_message.empty(), ExcMessage(stop_message));
    return statistics;
  }



  template <int dim>
  void
  Simulator<dim>::write_checkpoint(const unsigned int        step,
                                   const TimeStepper<dim>   &stepper,
                                   const EnergyMonitor<dim> &energy_monitor)
  {
    CheckpointState state;
    stepper.save(state);
    energy_monitor.save(state);
    grid_motion->save(state);
    shape_functions->save(state);
    system->save(state);
    boundary_conditions->save(state);
    output->save(state);
    checkpoint->write(output->directory(),
                      step,
                      current_time,
                      *points,
                      state,
                      communicator);
  }



  template <int dim>
  const MaterialPoints<dim> &
  Simulator<dim>::material_points() const
  {
    return *points;
  }



  template <int dim>
  const BackgroundGrid<dim> &
  Simulator<dim>::background_grid() const
  {
    return *grid;
  }



  template <int dim>
  const ShapeFunctions<dim> &
  Simulator<dim>::shape_function_family() const
  {
    return *shape_functions;
  }



  template <int dim>
  const NodalSystem<dim> &
  Simulator<dim>::nodal_system() const
  {
    return *system;
  }



  template <int dim>
  const MaterialLibrary<dim> &
  Simulator<dim>::material_library() const
  {
    return *materials;
  }



  template <int dim>
  const Problem<dim> &
  Simulator<dim>::problem() const
  {
    return *problem_description;
  }



  template <int dim>
  double
  Simulator<dim>::time() const
  {
    return current_time;
  }



  template <int dim>
  double
  Simulator<dim>::time_step_size() const
  {
    return time_step;
  }



  template <int dim>
  double
  Simulator<dim>::stable_time_step() const
  {
    return stable_step;
  }



  template class Simulator<1>;
  template class Simulator<2>;
  template class Simulator<3>;
} // namespace MpmOtm
