// Simulator: construction, the time loop (run()), checkpoints and the
// accessors. parameters.cc reads the parameters, setup.cc builds the run.

#include <deal.II/base/timer.h>

#include <mpm_otm/algorithms/energy_monitor.h>
#include <mpm_otm/algorithms/grid_motion.h>
#include <mpm_otm/algorithms/nodal_update.h>
#include <mpm_otm/algorithms/particle_transfer.h>
#include <mpm_otm/algorithms/quasi_static_end.h>
#include <mpm_otm/algorithms/softening_regularisation.h>
#include <mpm_otm/algorithms/stable_time_step.h>
#include <mpm_otm/algorithms/time_stepper.h>
#include <mpm_otm/algorithms/volumetric_locking_remedy.h>
#include <mpm_otm/base/activity.h>
#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/base/exception_message.h>
#include <mpm_otm/base/stop_signal.h>
#include <mpm_otm/boundary_conditions/boundary_conditions.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/grid_system/local_damping.h>
#include <mpm_otm/grid_system/mass_matrix.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/io/checkpoint.h>
#include <mpm_otm/io/monitoring_points.h>
#include <mpm_otm/io/output_directory.h>
#include <mpm_otm/io/output_writer.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/problems/problem.h>
#include <mpm_otm/shape_functions/shape_functions.h>
#include <mpm_otm/simulator/simulator.h>
#include <mpm_otm/simulator/stage_plan.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace MpmOtm
{
  template <int dim>
  Simulator<dim>::Simulator(const MPI_Comm communicator, std::ostream &log)
    : communicator(communicator)
    , pcout(log, Utilities::MPI::this_mpi_process(communicator) == 0)
  {}



  template <int dim>
  Simulator<dim>::~Simulator() = default;



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
                               locking_remedy.get(),
                               softening_regularisation.get(),
                               *particle_transfer,
                               timer);

      const auto &stages = stage_plan->stages();
      // The stage that runs, its first step and start time, and the step at
      // which it ends at the latest.
      unsigned int stage_number     = 0;
      unsigned int stage_first_step = 1;
      double       stage_start_time = 0;
      unsigned int last_step        = 0;
      Timer        wall_clock(communicator, true);

      // An output that only a signal asks for does not start a new window
      // of the averaged reactions (see reactions_and_displacements()).
      const auto report = [&](const unsigned int step,
                              const bool         regular_output) {
        TimerOutput::Scope scope(timer, "output");
        statistics.compute(*points,
                           *materials,
                           *problem_description,
                           current_time);
        statistics.supplied_work =
          Utilities::MPI::sum(stepper.supplied_work(), communicator);
        statistics.grid_kinetic_energy = system->kinetic_energy();
        particle_transfer
          ->add_affine_angular_momentum(*points, statistics.angular_momentum);
        statistics.boundary_names = reaction_names();
        statistics.boundary_reactions =
          boundary_conditions->reactions_and_displacements(regular_output);
        for (const auto &load :
             problem_description->surface_loads()
               .forces_and_displacements(*points, current_time))
          statistics.boundary_reactions.push_back(load);
        output->write(step,
                      current_time,
                      *points,
                      *grid,
                      *shape_functions,
                      *system,
                      statistics);
        const double elapsed = wall_clock.wall_time();
        pcout << "step " << std::setw(7) << step << " of " << last_step
              << "  t = " << std::scientific << std::setprecision(4)
              << current_time
              << "  kinetic energy = " << statistics.kinetic_energy
              << "  wall time = " << std::fixed << std::setprecision(2)
              << elapsed << " s";
        if (step > resumed_step && step < last_step)
          {
            const double remaining =
              elapsed * (last_step - step) / (step - resumed_step);
            pcout << ", about " << std::setprecision(remaining < 10. ? 1 : 0)
                  << remaining << " s to go";
          }
        pcout << std::defaultfloat << std::setprecision(6) << std::endl;
        if (observer)
          observer(step, statistics);
      };

      // The rows of monitoring.csv.
      const auto monitor = [&](const unsigned int step) {
        TimerOutput::Scope scope(timer, "output");
        monitoring->write(step,
                          current_time,
                          *points,
                          *materials,
                          output->directory(),
                          communicator);
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
      // Whether the run continues inside the stage it was interrupted in.
      bool resumed_inside_stage = false;
      if (resumed_state)
        {
          stepper.load(*resumed_state);
          energy_monitor.load(*resumed_state);
          quasi_static_end->load(*resumed_state);
          const auto &stage = resumed_state->shared("simulator/stage");
          AssertThrow(stage.size() == 3 && stage[0] < stages.size(),
                      ExcMessage("The checkpoint's stage is damaged or not "
                                 "one of this run's Stages."));
          stage_number     = static_cast<unsigned int>(stage[0]);
          stage_first_step = static_cast<unsigned int>(stage[1]);
          stage_start_time = stage[2];
          stage_plan->restore(stage_number,
                              *damping,
                              *problem_description,
                              *boundary_conditions,
                              *system);
          resumed_state.reset();
          // The state before the last stage was written before the stage
          // began.
          resumed_inside_stage = !starts_from_stored_state();
        }
      unsigned int step = resumed_step;
      // A checkpoint after this step, in this stage.
      const auto checkpoint_into = [&](const std::string &directory) {
        write_checkpoint(directory,
                         step,
                         stepper,
                         energy_monitor,
                         {double(stage_number),
                          double(stage_first_step),
                          stage_start_time});
      };
      Activity::set("the time steps");
      for (; stage_number < stages.size() && stop_message.empty();
           ++stage_number)
        {
          const auto &stage      = stages[stage_number];
          const bool  last_stage = (stage_number + 1 == stages.size());
          if (!resumed_inside_stage)
            {
              stage_first_step = step + 1;
              stage_start_time = current_time;
              if (last_stage && writes_state_before_last_stage)
                {
                  TimerOutput::Scope scope(timer, "checkpoint");
                  checkpoint_into(state_before_last_stage);
                }
              try
                {
                  TimerOutput::Scope scope(timer, "stages");
                  std::string        changes =
                    stage_plan->staged() ?
                             stage_plan->begin(stage_number,
                                        *points,
                                        *problem_description,
                                        *materials,
                                        *damping,
                                        *boundary_conditions,
                                        *system) :
                             std::string();
                  if (last_stage && pending_strength_factor != 1.)
                    {
                      materials->reduce_strength(pending_strength_factor);
                      changes += "; strengths divided by " +
                                 Utilities::to_string(pending_strength_factor);
                    }
                  if (stage_plan->staged())
                    {
                      pcout << "Stage " << stage.name << " begins at step "
                            << stage_first_step << ", t = " << current_time
                            << ": " << changes << '.' << std::endl;
                      if (!stage.added_bodies.empty())
                        check_time_step_after_adding(stage.name);
                      if (stage_number > 0)
                        energy_monitor.restart();
                      quasi_static_end->restart(
                        Utilities::MPI::sum(stepper.supplied_work(),
                                            communicator));
                    }
                }
              catch (const std::exception &error)
                {
                  stop_message = "Stopped at the start of stage " + stage.name +
                                 " (t = " + Utilities::to_string(current_time) +
                                 "); the output up to the last output step "
                                 "is in <" +
                                 output->directory() + ">. " +
                                 message_of(error);
                  timer.disable_output();
                  break;
                }
              if (stage_number == 0)
                {
                  energy_monitor.check(*points,
                                       *materials,
                                       stepper.supplied_work());
                  report(0, true);
                  monitor(0);
                }
              else
                energy_monitor.check(*points,
                                     *materials,
                                     stepper.supplied_work());
            }
          resumed_inside_stage = false;
          last_step =
            step + static_cast<unsigned int>(std::ceil(
                     (stage.end_time - current_time) / time_step - 1e-8));
          bool at_rest = false;
          for (++step; step <= last_step; ++step)
            {
              const double dt =
                std::min(time_step, stage.end_time - current_time);
              const bool output_step =
                output->is_output_step(step,
                                       current_time,
                                       current_time + dt,
                                       step == last_step);
              try
                {
                  stepper.advance(current_time, dt);
                  if (step % 10 == 0 || output_step)
                    {
                      energy_monitor.check(*points,
                                           *materials,
                                           stepper.supplied_work());
                      signal = stop_signal.received(communicator);
                      if (stage.end_at_rest &&
                          quasi_static_end->check(
                            *system,
                            current_time + dt,
                            Utilities::MPI::sum(stepper.supplied_work(),
                                                communicator)))
                        at_rest = true;
                    }
                }
              catch (const std::exception &error)
                {
                  std::ostringstream message;
                  message << "Stopped in time step " << step
                          << " (t = " << current_time << " to "
                          << current_time + dt
                          << "); the output up to the last output step is "
                             "in <"
                          << output->directory() << ">. " << message_of(error);
                  stop_message = message.str();
                  timer.disable_output();
                  break;
                }
              current_time =
                (step == last_step) ? stage.end_time : current_time + dt;
              const bool run_ends =
                last_stage && (step == last_step || at_rest);
              if (output_step || !signal.empty() || at_rest)
                report(step, output_step || at_rest);
              if (monitoring->is_due(step,
                                     output_step,
                                     step == last_step || at_rest ||
                                       !signal.empty()))
                monitor(step);
              if (at_rest || step == last_step)
                {
                  if (stage_plan->staged())
                    record_stage(stage_number,
                                 stage_first_step,
                                 stage_start_time,
                                 step,
                                 at_rest ? "at rest" : "end time");
                  if (at_rest)
                    pcout << "Quasi-static end: " << quasi_static_end->summary()
                          << (run_ends ?
                                "; the run ends here." :
                                "; stage " + stage.name + " ends here.")
                          << std::endl;
                  else if (stage.end_at_rest)
                    pcout << "Quasi-static end"
                          << (stage_plan->staged() ? " of stage " + stage.name :
                                                     std::string())
                          << ": " << quasi_static_end->summary() << '.'
                          << std::endl;
                  if (at_rest || run_ends)
                    break;
                }
              if (!run_ends &&
                  (!signal.empty() || checkpoint->is_due(step, communicator)))
                {
                  TimerOutput::Scope scope(timer, "checkpoint");
                  checkpoint_into(output->directory());
                }
              if (!signal.empty() && !run_ends)
                {
                  std::ostringstream message;
                  message
                    << "Stopped by " << signal << " after time step " << step
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
          // The loop's increment would count the step that ended the stage
          // twice.
          if (step > last_step)
            step = last_step;
        }
    }
    if (!stopped_by.empty())
      throw StoppedBySignal(stop_message, stopped_by);
    AssertThrow(stop_message.empty(), ExcMessage(stop_message));
    return statistics;
  }



  template <int dim>
  std::vector<std::string>
  Simulator<dim>::reaction_names() const
  {
    auto names = boundary_conditions->names();
    for (const auto &name : problem_description->surface_loads().names())
      names.push_back(name);
    return names;
  }



  template <int dim>
  void
  Simulator<dim>::write_checkpoint(const std::string         &directory,
                                   const unsigned int         step,
                                   const TimeStepper<dim>    &stepper,
                                   const EnergyMonitor<dim>  &energy_monitor,
                                   const std::vector<double> &stage)
  {
    CheckpointState state;
    state.set_shared("simulator/time step", {time_step});
    state.set_shared("simulator/stage", stage);
    stepper.save(state);
    energy_monitor.save(state);
    quasi_static_end->save(state);
    grid_motion->save(state);
    shape_functions->save(state);
    system->save(state);
    boundary_conditions->save(state);
    monitoring->save(state);
    output->save(state);
    checkpoint
      ->write(directory, step, current_time, *points, state, communicator);
  }



  template <int dim>
  void
  Simulator<dim>::check_time_step_after_adding(
    const std::string &stage_name) const
  {
    const auto stable =
      StableTimeStep<dim>().estimate(*points,
                                     *shape_functions,
                                     *system,
                                     *mass_matrix,
                                     *materials,
                                     *problem_description,
                                     particle_transfer->velocity_for_stability(
                                       nodal_update->particle_velocity()));
    AssertThrow(time_step <= stable.time_step,
                ExcMessage(
                  "With the bodies that stage " + stage_name +
                  " adds, the stable time step 2 / omega_max is " +
                  Utilities::to_string(stable.time_step) +
                  " s, below the run's time step " +
                  Utilities::to_string(time_step) + " s (" +
                  (automatic_time_step ?
                     "Time step = auto takes it from the bodies present at "
                     "the start). Choose Time/Time step = " :
                     "Time/Time step). Choose a time step of at most ") +
                  Utilities::to_string(stable.time_step) +
                  " s or less (manual, 'Stages')."));
  }



  template <int dim>
  void
  Simulator<dim>::record_stage(const unsigned int stage,
                               const unsigned int first_step,
                               const double       start_time,
                               const unsigned int last_step,
                               const std::string &ending) const
  {
    std::string problem;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ostringstream row;
        row << std::setprecision(12) << last_step << ',' << stage << ','
            << stage_plan->stages()[stage].name << ',' << first_step << ','
            << start_time << ',' << current_time << ',' << ending << '\n';
        problem =
          OutputDirectory::append_to_file(output->directory() + "/stages.csv",
                                          row.str());
      }
    stop_if_any_rank_failed(communicator,
                            problem,
                            "",
                            "Free space on the disk of Output/Directory.");
  }



  template <int dim>
  void
  Simulator<dim>::reduce_strength(const double factor)
  {
    AssertThrow(factor > 0 && std::isfinite(factor), ExcInternalError());
    pending_strength_factor = factor;
  }



  template <int dim>
  bool
  Simulator<dim>::starts_from_stored_state() const
  {
    return !state_before_last_stage.empty() && !writes_state_before_last_stage;
  }



  template <int dim>
  void
  Simulator<dim>::share_state_before_last_stage(const std::string &directory,
                                                const bool         write)
  {
    state_before_last_stage        = directory;
    writes_state_before_last_stage = write;
  }



  template <int dim>
  double
  Simulator<dim>::largest_displacement() const
  {
    double largest = 0;
    for (const auto &particle : points->particle_handler())
      largest = std::max(largest,
                         particle.get_location().distance(
                           Point<dim>(PropertyLayout<dim>::get_vector(
                             particle.get_properties(),
                             PropertyLayout<dim>::initial_position))));
    return Utilities::MPI::max(largest, communicator);
  }



  template <int dim>
  bool
  Simulator<dim>::ends_at_rest() const
  {
    return stage_plan->stages().back().end_at_rest;
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
  bool
  Simulator<dim>::at_rest() const
  {
    return quasi_static_end->at_rest();
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
