// Simulator: the parameters (declare_parameters, parse_parameters) and
// read_dimension(). setup.cc builds the run, simulator.cc runs it.


#include <mpm_otm/algorithms/method.h>
#include <mpm_otm/algorithms/particle_transfer.h>
#include <mpm_otm/algorithms/quasi_static_end.h>
#include <mpm_otm/algorithms/softening_regularisation.h>
#include <mpm_otm/algorithms/volumetric_locking_remedy.h>
#include <mpm_otm/base/plugins.h>
#include <mpm_otm/boundary_conditions/boundary_conditions.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/grid_system/local_damping.h>
#include <mpm_otm/grid_system/mass_matrix.h>
#include <mpm_otm/io/checkpoint.h>
#include <mpm_otm/io/monitoring_points.h>
#include <mpm_otm/io/output_writer.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/problems/body.h>
#include <mpm_otm/problems/problem.h>
#include <mpm_otm/shape_functions/shape_functions.h>
#include <mpm_otm/simulator/simulator.h>
#include <mpm_otm/simulator/stage_plan.h>
#include <mpm_otm/simulator/strength_reduction.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace MpmOtm
{
  namespace
  {
    /**
     * Stop if a file that the parameter file @p filename includes
     * (`include FILE`), directly or through other files, is not a regular
     * file, or if the includes form a cycle, which deal.II's reader would
     * follow until the stack overflows. @p chain holds the files that
     * include @p filename, outermost first.
     */
    void
    check_included_files(const std::string        &filename,
                         std::vector<std::string> &chain)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      const auto      canonical = fs::weakly_canonical(filename, error);
      for (const auto &outer : chain)
        if (fs::weakly_canonical(outer, error) == canonical)
          {
            std::string cycle;
            for (const auto &file : chain)
              cycle += "<" + file + "> includes ";
            AssertThrow(false,
                        ExcMessage("Parameter file <" + chain.front() +
                                   ">: the includes form a cycle (" + cycle +
                                   "<" + filename +
                                   "> again), which would be read for ever. "
                                   "Remove the include that closes it."));
          }
      std::ifstream input(filename);
      std::string   line;
      while (std::getline(input, line))
        {
          line = Utilities::trim(line.substr(0, line.find('#')));
          if (line.rfind("include ", 0) != 0 && line.rfind("INCLUDE ", 0) != 0)
            continue;
          const std::string included = Utilities::trim(line.substr(8));
          AssertThrow(fs::is_regular_file(included, error),
                      ExcMessage("Parameter file <" + filename +
                                 "> includes <" + included +
                                 ">, which does not exist or is not a regular "
                                 "file (a relative path starts in the "
                                 "directory the program runs in)."));
          chain.push_back(filename);
          check_included_files(included, chain);
          chain.pop_back();
        }
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
        std::vector<std::string> chain;
        check_included_files(filename, chain);
        prm.parse_input(filename, "", true);
      }
    return prm.get_integer("Dimension");
  }



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
    prm.declare_entry("Method",
                      "MPM",
                      Patterns::Selection(
                        PluginRegistry<Method<dim>>::selection()),
                      "Method:" + PluginRegistry<Method<dim>>::documentation() +
                        ". OTM and Unified mesh only the material domain.");
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
    ParticleTransfer<dim>::declare_parameters(prm);
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
      "Volumetric locking remedy",
      "automatic",
      Patterns::Selection(
        "automatic|none|" +
        PluginRegistry<VolumetricLockingRemedy<dim>>::selection()),
      "Treatment of volumetric locking, the over-stiff response of an "
      "isochoric (plastic, or nearly incompressible elastic) flow when "
      "several points per cell cannot all deform at constant volume:" +
        PluginRegistry<VolumetricLockingRemedy<dim>>::documentation() +
        ". none: the points' own velocity gradients. automatic: F-bar in 2D "
        "and 3D if a material is plastic (von Mises, Drucker-Prager, "
        "Mohr-Coulomb), none otherwise and for linear functions on "
        "triangles/tetrahedra (manual, 'Volumetric locking').");
    prm.declare_entry(
      "Softening regularisation",
      "automatic",
      Patterns::Selection("automatic|none|nodal average"),
      "How the strength of a softening material (Mohr-Coulomb or "
      "Drucker-Prager with Softening strains) follows its plastic strain. "
      "none: each point softens with its own equivalent plastic strain (a "
      "shear band is as narrow as the grid lets it be, and its result "
      "depends on the cell size). nodal average: with the average of the "
      "equivalent plastic strain over the support of the point's shape "
      "functions, projected to the nodes and back each step, so that all "
      "points of a band's cells soften together. automatic: nodal average "
      "if a material softens, none otherwise (manual, 'Materials').");
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
      Patterns::Double(0., 0.95),
      "With Time step = auto, the fraction of the stable time step "
      "2 / omega_max used, in (0, 0.95]: at 1 the fastest mode sits on the "
      "stability limit and grows, and a Lanczos estimate that has not "
      "converged errs on the large side. Large deformations change the "
      "stable time step during a run, so keep a margin.");
    prm.declare_entry(
      "Energy growth limit",
      "0.25",
      Patterns::Double(0.),
      "Stop the run as unstable when the kinetic plus strain energy of the "
      "points exceeds (1 + this) times the energy supplied: the energy at "
      "the start plus the work of gravity, body forces, tractions and "
      "prescribed velocities. Checked every 10 steps and at every output. "
      "A stable run errs on this balance by a few per cent (12 % the largest "
      "seen); an unstable one gains energy by a fixed factor per step "
      "(manual, 'Instability').");
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
    SurfaceLoads<dim>::declare_parameters(prm, names.surface_loads);
    OutputWriter<dim>::declare_parameters(prm);
    MonitoringPoints<dim>::declare_parameters(prm);
    Checkpoint<dim>::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm, names.boundaries);
    LocalDamping<dim>::declare_parameters(prm);
    QuasiStaticEnd<dim>::declare_parameters(prm);
    StagePlan<dim>::declare_parameters(prm, names.stages);
    StrengthReduction<dim>::declare_parameters(prm);

    PluginRegistry<Problem<dim>>::declare_parameters(prm);
    PluginRegistry<NodalUpdate<dim>>::declare_parameters(prm);
    PluginRegistry<ShapeFunctions<dim>>::declare_parameters(prm);
    PluginRegistry<MassMatrix<dim>>::declare_parameters(prm);
    PluginRegistry<VolumetricLockingRemedy<dim>>::declare_parameters(prm);
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
    AssertThrow(problem_description->defines_bodies() ||
                  Utilities::trim(prm.get("Bodies")).empty(),
                ExcMessage("Bodies = " + prm.get("Bodies") +
                           ": bodies are the material of Problem = custom; "
                           "Problem = " +
                           prm.get("Problem") +
                           " places its own. Remove the entry Bodies, or set "
                           "Problem = custom."));
    shape_functions =
      PluginRegistry<ShapeFunctions<dim>>::create(prm.get("Shape functions"));
    shape_functions->parse_parameters(prm);
    const auto method = PluginRegistry<Method<dim>>::create(prm.get("Method"));
    method->parse_parameters(prm);
    nodal_update = method->create_nodal_update();
    nodal_update->parse_parameters(prm);
    grid_motion = method->create_grid_motion(*shape_functions);
    if (!method->note().empty())
      pcout << method->note() << std::endl;
    mass_matrix =
      PluginRegistry<MassMatrix<dim>>::create(prm.get("Mass matrix"));
    mass_matrix->parse_parameters(prm);
    particle_transfer = std::make_unique<ParticleTransfer<dim>>();
    particle_transfer->parse_parameters(prm);
    particle_transfer->check(*nodal_update,
                             prm.get("Method"),
                             method->fixed_grid(),
                             mass_matrix->is_lumped());
    particle_transfer->reserve_point_variables(*materials);
    problem_description->surface_loads().reserve_point_variables(*materials);
    deactivation_threshold = prm.get_double("Deactivation threshold");
    {
      std::string remedy       = prm.get("Volumetric locking remedy");
      automatic_locking_remedy = (remedy == "automatic");
      if (automatic_locking_remedy)
        {
          bool plastic = false;
          for (unsigned int id = 0; id < materials->n_materials(); ++id)
            plastic = plastic || (*materials)[id].is_plastic();
          remedy = (dim > 1 && plastic) ? "F-bar" : "none";
        }
      if (remedy != "none")
        {
          locking_remedy =
            PluginRegistry<VolumetricLockingRemedy<dim>>::create(remedy);
          locking_remedy->parse_parameters(prm);
        }
    }

    {
      std::string regularisation = prm.get("Softening regularisation");
      bool        softening      = false;
      for (unsigned int id = 0; id < materials->n_materials(); ++id)
        softening = softening || ((*materials)[id].softening_variable() !=
                                  numbers::invalid_unsigned_int);
      AssertThrow(softening || regularisation != "nodal average",
                  ExcMessage(
                    "Softening regularisation = nodal average: no material "
                    "softens. It regularises the strain softening of "
                    "Mohr-Coulomb and Drucker-Prager (their entry Softening "
                    "strains); give them, or use Softening regularisation = "
                    "none or automatic."));
      if (regularisation == "automatic")
        regularisation = softening ? "nodal average" : "none";
      if (regularisation == "nodal average")
        softening_regularisation =
          std::make_unique<SofteningRegularisation<dim>>();
    }

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
    monitoring = std::make_unique<MonitoringPoints<dim>>();
    monitoring->parse_parameters(prm);
    checkpoint = std::make_unique<Checkpoint<dim>>();
    checkpoint->parse_parameters(prm);
    boundary_conditions = std::make_unique<BoundaryConditions<dim>>();
    boundary_conditions->parse_parameters(prm);
    for (const auto &name : problem_description->surface_loads().names())
      {
        const auto boundaries = boundary_conditions->names();
        AssertThrow(std::find(boundaries.begin(), boundaries.end(), name) ==
                      boundaries.end(),
                    ExcMessage("Surface loads and Boundaries both name <" +
                               name + ">: statistics.csv has the columns " +
                               name +
                               "_force_* of each, so give them different "
                               "names."));
      }
    boundary_conditions->check_method(prm.get("Method"),
                                      method->fixed_grid(),
                                      nodal_update->needs_nodal_accelerations(),
                                      mass_matrix->is_lumped());
    damping = std::make_unique<LocalDamping<dim>>();
    damping->parse_parameters(prm);
    quasi_static_end = std::make_unique<QuasiStaticEnd<dim>>();
    quasi_static_end->parse_parameters(prm);
    stage_plan = std::make_unique<StagePlan<dim>>();
    stage_plan->parse_parameters(prm,
                                 method->fixed_grid(),
                                 quasi_static_end->enabled());
    stage_plan->reserve_point_variables(*materials);
    end_time = stage_plan->stages().back().end_time;
    checkpoint->set_end_time(stage_plan->end_time_entry(), end_time);
  }



  template void
  Simulator<1>::declare_parameters(ParameterHandler &, const SubsectionNames &);
  template void
  Simulator<1>::parse_parameters(ParameterHandler &);
  template void
  Simulator<2>::declare_parameters(ParameterHandler &, const SubsectionNames &);
  template void
  Simulator<2>::parse_parameters(ParameterHandler &);
  template void
  Simulator<3>::declare_parameters(ParameterHandler &, const SubsectionNames &);
  template void
  Simulator<3>::parse_parameters(ParameterHandler &);
} // namespace MpmOtm
