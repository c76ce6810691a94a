#include <mpm_otm/algorithms/energy_monitor.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/materials/point_energy.h>

#include <sstream>

namespace MpmOtm
{
  template <int dim>
  EnergyMonitor<dim>::EnergyMonitor(const double   growth_limit,
                                    const double   reference_speed,
                                    const MPI_Comm communicator)
    : growth_limit(growth_limit)
    , reference_speed(reference_speed)
    , communicator(communicator)
  {}



  template <int dim>
  void
  EnergyMonitor<dim>::check(const MaterialPoints<dim>  &material_points,
                            const MaterialLibrary<dim> &materials,
                            const double                local_supplied_work)
  {
    // kinetic, strain, supplied work, mass
    double sums[4] = {0., 0., local_supplied_work, 0.};
    for (const auto &particle : material_points.particle_handler())
      {
        const auto        properties = particle.get_properties();
        const PointEnergy energy     = point_energy(properties, materials);
        sums[0] += energy.kinetic;
        sums[1] += energy.strain;
        sums[3] += properties[PropertyLayout<dim>::mass];
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 4),
                        communicator,
                        ArrayView<double>(sums, 4));
    const double energy = sums[0] + sums[1];
    if (!started)
      {
        started        = true;
        initial_energy = energy;
        work_at_start  = sums[2];
        energy_floor =
          1e-12 * 0.5 * sums[3] * reference_speed * reference_speed;
        return;
      }
    const double work     = sums[2] - work_at_start;
    const double supplied = initial_energy + work;
    const double bound    = (1. + growth_limit) * supplied;
    if (energy <= bound || energy <= energy_floor)
      return;
    std::ostringstream message;
    message << "The computation became unstable: the kinetic plus strain "
            << "energy of the points, " << energy << " J (kinetic " << sums[0]
            << " J), is above (1 + Time/Energy growth limit = " << growth_limit
            << ") x the energy supplied, " << supplied << " J ("
            << initial_energy << " J at the start"
            << (stage_started ? " of the stage, " : ", ") << work
            << " J of work by loads and prescribed velocities). " << advice();
    AssertThrow(false, ExcMessage(message.str()));
  }



  template <int dim>
  void
  EnergyMonitor<dim>::restart()
  {
    started       = false;
    stage_started = true;
  }



  template <int dim>
  std::string
  EnergyMonitor<dim>::advice()
  {
    return "What helps, most likely first: Update scheme = MUSL if it was "
           "USL; a smaller Time/Time step (Time step = auto); if cells at "
           "the material's edge were nearly empty, Mass matrix = lumped or "
           "partially lumped (manual, 'Instability' and 'Nearly empty "
           "cells').";
  }



  template <int dim>
  void
  EnergyMonitor<dim>::save(CheckpointState &state) const
  {
    state.set_shared("energy monitor/reference",
                     {started ? 1. : 0.,
                      initial_energy,
                      energy_floor,
                      work_at_start,
                      stage_started ? 1. : 0.});
  }



  template <int dim>
  void
  EnergyMonitor<dim>::load(const CheckpointState &state)
  {
    const auto &saved = state.shared("energy monitor/reference");
    AssertThrow(saved.size() == 5,
                ExcMessage("The checkpoint's energy reference is damaged."));
    started        = saved[0] != 0.;
    initial_energy = saved[1];
    energy_floor   = saved[2];
    work_at_start  = saved[3];
    stage_started  = saved[4] != 0.;
  }



  template class EnergyMonitor<1>;
  template class EnergyMonitor<2>;
  template class EnergyMonitor<3>;
} // namespace MpmOtm
