// Simulator::setup(): the grid, points, shape functions, time step and
// output of a new or resumed run. parameters.cc reads the parameters,
// simulator.cc runs the time loop.

#include <deal.II/base/timer.h>

#include <mpm_otm/algorithms/grid_motion.h>
#include <mpm_otm/algorithms/particle_transfer.h>
#include <mpm_otm/algorithms/softening_regularisation.h>
#include <mpm_otm/algorithms/stable_time_step.h>
#include <mpm_otm/algorithms/volumetric_locking_remedy.h>
#include <mpm_otm/base/activity.h>
#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/base/exception_message.h>
#include <mpm_otm/boundary_conditions/boundary_conditions.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/grid_system/mass_matrix.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/io/checkpoint.h>
#include <mpm_otm/io/monitoring_points.h>
#include <mpm_otm/io/output_directory.h>
#include <mpm_otm/io/output_writer.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/problems/problem.h>
#include <mpm_otm/shape_functions/shape_functions.h>
#include <mpm_otm/simulator/simulator.h>
#include <mpm_otm/simulator/stage_plan.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>

namespace MpmOtm
{
  template <int dim>
  void
  Simulator<dim>::setup(const ParameterHandler &prm, const bool resume)
  {
    Activity::set("creating the grid (Mesh)");
    grid->create(communicator, grid_motion->moves_vertices());
    checkpoint->set_grid_fingerprint(grid->fingerprint());

    problem_description->initialize(materials->default_material(), *grid);
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
    Activity::set("seeding the material points (Particles per cell)");
    stage_plan->seed(*points, *grid, *problem_description, *materials);
    problem_description->surface_loads().assign_points(*points);
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
    Activity::set("setting up the shape functions");
    shape_functions->initialize(*grid);
    shape_function_timer.stop();
    boundary_conditions->setup(*shape_functions, *grid);
    boundary_conditions->check_run(end_time);
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
    Activity::set("setting up the nodal system and the mass matrix");
    system = std::make_unique<NodalSystem<dim>>();
    system->setup(*shape_functions,
                  fixed_components,
                  deactivation_threshold,
                  mass_matrix->needs_material_boundary());
    if (locking_remedy && automatic_locking_remedy &&
        shape_functions->gradients_constant_on_cells())
      {
        locking_remedy.reset();
        pcout << "volumetric locking remedy: none (automatic): linear "
                 "functions on triangles/tetrahedra have one velocity "
                 "gradient per cell, so F-bar has nothing to average; the "
                 "crossed triangles of Mesh/Cell type = simplex do not lock, "
                 "other triangulations may (manual, 'Volumetric locking')"
              << std::endl;
      }
    if (locking_remedy)
      locking_remedy->initialize(*shape_functions, *system, *materials);
    if (softening_regularisation)
      softening_regularisation->initialize(*materials, *system);
    particle_transfer->initialize(*shape_functions, system->partitioner());
    // The material that sets the time step, for the messages below: a
    // wrong modulus or density shows up first as an absurd time step.
    std::ostringstream fastest;
    {
      unsigned int fastest_id = 0;
      for (unsigned int id = 1; id < materials->n_materials(); ++id)
        if ((*materials)[id].wave_speed() >
            (*materials)[fastest_id].wave_speed())
          fastest_id = id;
      const auto &material = (*materials)[fastest_id];
      fastest << " The fastest material is <" << materials->name(fastest_id)
              << ">: Young's modulus = " << material.youngs_modulus()
              << " Pa and Density = " << material.density()
              << " kg/m^3 give a wave speed of " << material.wave_speed()
              << " m/s; check both if that is not what you meant.";
    }
    {
      // Beyond this the Lanczos products overflow in double precision.
      const double rate =
        materials->maximal_wave_speed() / grid->minimal_cell_size();
      AssertThrow(std::isfinite(rate) && rate < 1e100,
                  ExcMessage("The wave speed over the smallest cell size, "
                             "c / h = " +
                             Utilities::to_string(rate) +
                             " 1/s, is beyond what the stable time step can "
                             "be computed for (at most 1e100 1/s): a time "
                             "step of at most h / c would be needed." +
                             fastest.str()));
    }
    Activity::set("estimating the stable time step");
    // The stable time step of this discretisation at the start; a larger
    // time step is rejected before anything is written.
    const auto stable =
      StableTimeStep<dim>().estimate(*points,
                                     *shape_functions,
                                     *system,
                                     *mass_matrix,
                                     *materials,
                                     *problem_description,
                                     particle_transfer->velocity_for_stability(
                                       nodal_update->particle_velocity()));
    stable_step = stable.time_step;
    if (automatic_time_step)
      time_step = courant_factor * stable.time_step;
    AssertThrow(stable.time_step > 0.,
                ExcMessage("The stable time step 2 / omega_max of this "
                           "discretisation is 0 (omega_max = " +
                           Utilities::to_string(stable.largest_frequency) +
                           " 1/s): no time step is stable." + fastest.str()));
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
                << ", or Time step = auto (manual, 'Time step')."
                << fastest.str();
        AssertThrow(false, ExcMessage(message.str()));
      }
    AssertThrow(end_time / time_step < 1e9,
                ExcMessage(
                  "Time/End time / Time/Time step is above 1e9 time steps; " +
                  (automatic_time_step ?
                     "the time step is " + Utilities::to_string(time_step) +
                       " = Courant factor x the stable time step." +
                       fastest.str() :
                     std::string("check both entries."))));
    output->check_basis_picture(*shape_functions, communicator);
    grid_motion->initialize(*grid,
                            *shape_functions,
                            *system,
                            grid->minimal_cell_size() * time_step /
                              stable.time_step);
    // Every load expression is evaluated before anything is written: the
    // body force at every point's initial position, the tractions and the
    // surface loads, at
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
              problem_description->surface_loads().check_expressions(*points,
                                                                     t);
            }
        }
      catch (const std::exception &error)
        {
          problem = message_of(error) + " ";
        }
      stop_if_any_rank_failed(communicator, problem, "", "");
    }
    current_time = 0;
    Activity::set("reading the checkpoint");
    // A resumed run, or a trial of a strength reduction that starts from
    // the state before the last stage another trial wrote.
    const bool  starts_from_state = starts_from_stored_state();
    std::string resumed_from;
    if (resume || starts_from_state)
      {
        // The grid moves first; the points then enter their saved cells.
        resumed_from = Checkpoint<dim>::newest(resume ? output->directory() :
                                                        state_before_last_stage,
                                               communicator);
        resumed_state = std::make_unique<CheckpointState>();
        std::tie(resumed_step, current_time) =
          checkpoint->read(resumed_from, *points, *resumed_state, communicator);
        // The run continues with the step it was started with: its steps
        // are counted in it, and Time step = auto would find another to
        // round-off on another number of ranks. (An explicit step is the
        // same: the checkpoint refuses other parameters.)
        time_step = resumed_state->shared("simulator/time step").at(0);
        grid_motion->load(*resumed_state);
        shape_functions->load(*resumed_state);
        system->load(*resumed_state);
        boundary_conditions->load(*resumed_state);
      }
    // A continued run follows the points it followed before.
    std::string monitored;
    if (monitoring->enabled() && (resume || starts_from_state))
      monitoring->load(*resumed_state);
    else if (monitoring->enabled())
      monitored = monitoring->locate(*points, communicator);
    output->initialize(prm,
                       problem_description->has_exact_solution(),
                       problem_description->has_exact_stress(),
                       communicator,
                       *materials,
                       reaction_names(),
                       problem_description->has_gravity() ||
                         stage_plan->sets_gravity(),
                       resume ? resumed_step : 0);
    if (resume)
      output->load(*resumed_state);
    else
      output->write_basis_picture(*shape_functions);
    if (monitoring->enabled())
      monitoring->write_header(output->directory(), resume, communicator);
    if (stage_plan->staged() && !resume)
      {
        std::string problem;
        if (Utilities::MPI::this_mpi_process(communicator) == 0)
          problem = OutputDirectory::write_file_atomically(
            output->directory() + "/stages.csv",
            [](std::ostream &out) {
              out << "step,stage,name,first_step,start_time,end_time,end\n";
            });
        stop_if_any_rank_failed(communicator,
                                problem,
                                "",
                                "Free space on the disk of Output/Directory "
                                "or choose another one.");
      }

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
    if (locking_remedy)
      pcout << locking_remedy->description() << std::endl;
    if (softening_regularisation)
      pcout << softening_regularisation->description() << std::endl;
    if (particle_transfer->flip_fraction() < 1.)
      pcout << particle_transfer->description() << std::endl;
    pcout << monitored;
    if (resume)
      pcout << "resumed from <" << resumed_from << ">, written after time step "
            << resumed_step << " (t = " << current_time << ")" << std::endl;
    else if (starts_from_state)
      pcout << "starts from the state before the last stage <" << resumed_from
            << ">, written after time step " << resumed_step
            << " (t = " << current_time << ")" << std::endl;
  }



  template void
  Simulator<1>::setup(const ParameterHandler &, const bool);
  template void
  Simulator<2>::setup(const ParameterHandler &, const bool);
  template void
  Simulator<3>::setup(const ParameterHandler &, const bool);
} // namespace MpmOtm
