#ifndef mpm_otm_tests_unit_components_h
#define mpm_otm_tests_unit_components_h

// The pieces of one MPM set-up, built from parameter text without the
// Simulator, so that unit tests can drive single steps and inspect the
// nodal system.

#include <deal.II/base/timer.h>

#include <mpm_otm/algorithms/fixed_grid.h>
#include <mpm_otm/algorithms/nodal_update.h>
#include <mpm_otm/algorithms/time_stepper.h>
#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid_system/background_grid.h>
#include <mpm_otm/grid_system/mass_matrix.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material.h>
#include <mpm_otm/problems/problem.h>
#include <mpm_otm/shape_functions/shape_functions.h>
#include <mpm_otm/simulator/simulator.h>

#include "../tests.h"

using namespace dealii;

template <int dim>
struct Components
{
  explicit Components(const std::string &parameters)
    : timer(MPI_COMM_WORLD, quiet, TimerOutput::never, TimerOutput::wall_times)
  {
    using namespace MpmOtm;
    ParameterHandler prm;
    Simulator<dim>::declare_parameters(prm);
    prm.parse_input_from_string(parameters);
    problem = PluginRegistry<Problem<dim>>::create(prm.get("Problem"));
    problem->parse_parameters(prm);
    update = PluginRegistry<NodalUpdate<dim>>::create(prm.get("Update scheme"));
    shape_functions =
      PluginRegistry<ShapeFunctions<dim>>::create(prm.get("Shape functions"));
    mass_matrix =
      PluginRegistry<MassMatrix<dim>>::create(prm.get("Mass matrix"));
    prm.enter_subsection("Material");
    material = PluginRegistry<Material<dim>>::create(prm.get("Model"));
    prm.leave_subsection();
    material->parse_parameters(prm);
    grid.parse_parameters(prm);
    points.parse_parameters(prm);

    grid.create(MPI_COMM_WORLD);
    problem->initialize(*material, grid.box());
    points.seed(grid, *material, *problem);
    shape_functions->initialize(grid);
    system.setup(*shape_functions, problem->fixed_components());
    stepper = std::make_unique<TimeStepper<dim>>(points,
                                                 *shape_functions,
                                                 system,
                                                 *mass_matrix,
                                                 *update,
                                                 grid_motion,
                                                 *material,
                                                 *problem,
                                                 timer);
  }

  std::ostringstream                           quiet;
  TimerOutput                                  timer;
  MpmOtm::BackgroundGrid<dim>                  grid;
  MpmOtm::MaterialPoints<dim>                  points;
  MpmOtm::NodalSystem<dim>                     system;
  std::unique_ptr<MpmOtm::Problem<dim>>        problem;
  std::unique_ptr<MpmOtm::NodalUpdate<dim>>    update;
  MpmOtm::FixedGrid<dim>                       grid_motion;
  std::unique_ptr<MpmOtm::ShapeFunctions<dim>> shape_functions;
  std::unique_ptr<MpmOtm::MassMatrix<dim>>     mass_matrix;
  std::unique_ptr<MpmOtm::Material<dim>>       material;
  std::unique_ptr<MpmOtm::TimeStepper<dim>>    stepper;
};

#endif
