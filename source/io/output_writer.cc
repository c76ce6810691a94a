#include <deal.II/base/utilities.h>

#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/io/grid_patches.h>
#include <mpm_otm/io/output_directory.h>
#include <mpm_otm/io/output_writer.h>
#include <mpm_otm/io/particle_patches.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace MpmOtm
{
  namespace
  {
    std::string
    step_string(const unsigned int step)
    {
      return Utilities::int_to_string(step, 5);
    }



  } // namespace



  template <int dim>
  void
  OutputWriter<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::DirectoryName(),
                      "Directory for all output (created if missing).");
    prm.declare_entry(
      "Overwrite",
      "false",
      Patterns::Bool(),
      "Whether a run may write into a directory that holds another run's "
      "output (a statistics.csv, parameters.prm, .pvd or .xdmf file); it then "
      "first removes that run's step files (particles-NNNNN.csv, "
      "particles_NNNNN.*, grid_NNNNN.*, the .pvd and .xdmf files). false: such a "
      "directory stops the run before anything is written. The command "
      "line option --overwrite sets it.");
    prm.declare_entry("Interval",
                      "0",
                      Patterns::Integer(0),
                      "Write output every this many time steps (0: only at "
                      "the start and at the end time, or as Time interval "
                      "says).");
    prm.declare_entry("Time interval",
                      "0",
                      Patterns::Double(0),
                      "Also write output in every time step that reaches a "
                      "multiple of this time (s): every 0.01 s, say, "
                      "whatever the time step (0: no such output).");
    prm.declare_entry("Write particle CSV",
                      "false",
                      Patterns::Bool(),
                      "Also write particles-NNNNN.csv with one row per "
                      "material point.");
    prm.declare_entry(
      "Format",
      "vtu",
      Patterns::Selection("vtu|hdf5|none"),
      "Files of the particle and grid fields, which ParaView opens: vtu - "
      "per output step one file per rank (particles_NNNNN.R.vtu, "
      "grid_NNNNN.R.vtu) with the index particles_NNNNN.pvtu, over the "
      "steps particles.pvd and grid.pvd; hdf5 - per output step one file "
      "that all ranks write together (particles_NNNNN.h5, grid_NNNNN.h5), "
      "over the steps particles.xdmf and grid.xdmf (for runs on many ranks "
      "or with many points); none - no field files (statistics.csv and the "
      "CSV files only).");
    prm.declare_entry(
      "Powell-Sabin basis at",
      "",
      Patterns::List(Patterns::Double(), 0, 3),
      "A point (x, y): write powell-sabin-basis.vtu at the start with the "
      "three Powell-Sabin functions of the grid vertex nearest to it, on the "
      "Powell-Sabin refinement of the cells around it and their neighbours "
      "(Shape functions = Powell-Sabin only, serial runs only). Empty: not "
      "written.");
    prm.leave_subsection();
  }



  template <int dim>
  void
  OutputWriter<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    output_directory         = prm.get("Directory");
    interval                 = prm.get_integer("Interval");
    time_interval            = prm.get_double("Time interval");
    write_csv                = prm.get_bool("Write particle CSV");
    const std::string format = prm.get("Format");
    AssertThrow(dim > 1 || format != "hdf5",
                ExcMessage("Output/Format = hdf5 needs Dimension = 2 or 3 "
                           "(deal.II's XDMF index has no one-dimensional "
                           "geometry); use vtu or none in 1D."));
    write_fields = (format != "none");
    field_format =
      (format == "hdf5") ? TimeSeries::Format::hdf5 : TimeSeries::Format::vtu;
    overwrite                = prm.get_bool("Overwrite");
    powell_sabin_basis_point = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Powell-Sabin basis at")));
    prm.leave_subsection();
    AssertThrow(!output_directory.empty(),
                ExcMessage("Output/Directory must not be empty."));
  }



  template <int dim>
  void
  OutputWriter<dim>::initialize(const ParameterHandler &prm,
                                const bool              has_displacement_error,
                                const bool              has_stress_error,
                                const MPI_Comm          communicator,
                                const MaterialLibrary<dim> &material_library,
                                const std::vector<std::string> &boundary_names,
                                const bool                      has_gravity,
                                const unsigned int              resumed_step)
  {
    mpi_communicator           = communicator;
    materials                  = &material_library;
    write_gravitational_energy = has_gravity;
    if (resumed_step > 0)
      {
        std::string problem;
        if (Utilities::MPI::this_mpi_process(communicator) == 0)
          problem =
            OutputDirectory::trim_after_step(output_directory, resumed_step);
        stop_if_any_rank_failed(communicator,
                                problem,
                                "Cannot resume in <" + output_directory + ">: ",
                                "");
        return;
      }
    // Rank 0 creates the directory; every rank learns whether that worked,
    // so that all stop together instead of waiting for rank 0.
    std::string problem;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::error_code error;
        problem =
          OutputDirectory::clear_previous_run(output_directory, overwrite);
        if (problem.empty())
          std::filesystem::create_directories(output_directory, error);
        if (problem.empty() && error)
          problem = "Output/Directory: cannot create <" + output_directory +
                    ">: " + error.message() + ".";
        else if (problem.empty())
          problem = OutputDirectory::write_file_atomically(
            output_directory + "/parameters.prm",
            [&](std::ostream &out) {
              prm.print_parameters(out, ParameterHandler::PRM);
            });
      }
    problem = Utilities::MPI::broadcast(communicator, problem, 0);
    AssertThrow(problem.empty(), ExcMessage(problem));
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        const std::string name = output_directory + "/statistics.csv";
        std::ofstream     statistics(name);
        statistics << "step,time,kinetic_energy,strain_energy,total_energy";
        if (has_displacement_error)
          statistics << ",displacement_rms_error,displacement_l2_error";
        if (has_stress_error)
          statistics << ",stress_rms_error";
        if (has_gravity)
          statistics << ",gravitational_energy";
        for (const auto &name : boundary_names)
          for (const std::string quantity : {"force", "displacement"})
            for (unsigned int d = 0; d < dim; ++d)
              statistics << ',' << name << '_' << quantity << '_' << "xyz"[d];
        statistics << ",supplied_work,grid_kinetic_energy";
        if (dim == 2)
          statistics << ",angular_momentum";
        if (dim == 3)
          statistics << ",angular_momentum_x,angular_momentum_y,"
                        "angular_momentum_z";
        statistics << '\n';
        statistics.close();
        if (!statistics)
          problem = "Could not write <" + name +
                    ">: " + std::string(std::strerror(errno)) + ". ";
      }
    stop_if_any_rank_failed(
      communicator,
      problem,
      "",
      "Free space on the disk of Output/Directory or choose another one.");
  }



  template <int dim>
  void
  OutputWriter<dim>::save(CheckpointState &state) const
  {
    particle_series.save(state);
    grid_series.save(state);
  }



  template <int dim>
  void
  OutputWriter<dim>::load(const CheckpointState &state)
  {
    // A run resumed with another format starts new series.
    for (TimeSeries *series : {&particle_series, &grid_series})
      {
        series->load(state, field_format);
        if (write_fields)
          series->write_index(output_directory, field_format, mpi_communicator);
      }
  }



  template <int dim>
  bool
  OutputWriter<dim>::is_output_step(const unsigned int step,
                                    const double       time_before,
                                    const double       time_after,
                                    const bool         last) const
  {
    if (step == 0 || last || (interval > 0 && step % interval == 0))
      return true;
    if (time_interval == 0)
      return false;
    // The step reaches a multiple of the interval if it passes one or ends
    // on it; a millionth of the step absorbs the round-off of summed steps.
    const double tolerance = 1e-6 * (time_after - time_before);
    return std::floor((time_after + tolerance) / time_interval) >
           std::floor((time_before + tolerance) / time_interval);
  }



  template <int dim>
  void
  OutputWriter<dim>::write(const unsigned int         step,
                           const double               time,
                           const MaterialPoints<dim> &material_points,
                           const BackgroundGrid<dim> &grid,
                           const ShapeFunctions<dim> &shape_functions,
                           NodalSystem<dim>          &system,
                           const Statistics<dim>     &statistics)
  {
    if (write_fields)
      {
        write_particle_fields(step, time, material_points);
        write_grid_fields(step, time, grid, shape_functions, system);
      }
    std::string problem;
    if (write_csv)
      problem += write_particle_csv(step, material_points);
    problem += write_statistics(step, time, statistics);
    stop_if_any_rank_failed(
      mpi_communicator,
      problem,
      "",
      "Free space on the disk of Output/Directory or choose another one.");
  }



  template <int dim>
  const std::string &
  OutputWriter<dim>::directory() const
  {
    return output_directory;
  }



  template <int dim>
  void
  OutputWriter<dim>::write_particle_fields(
    const unsigned int         step,
    const double               time,
    const MaterialPoints<dim> &material_points)
  {
    // A 1D patch cannot hold a 3 x 3 tensor: components there too.
    ParticlePatches<dim> patches(material_points,
                                 *materials,
                                 dim == 1 ||
                                   field_format == TimeSeries::Format::hdf5);
    particle_series.write(patches,
                          output_directory,
                          field_format,
                          step,
                          time,
                          mpi_communicator);
  }



  template <int dim>
  void
  OutputWriter<dim>::write_grid_fields(
    const unsigned int         step,
    const double               time,
    const BackgroundGrid<dim> &grid,
    const ShapeFunctions<dim> &shape_functions,
    NodalSystem<dim>          &system)
  {
    grid_series.write(GridPatches<dim>(grid, shape_functions, system),
                      output_directory,
                      field_format,
                      step,
                      time,
                      mpi_communicator);
  }



  template <int dim>
  std::string
  OutputWriter<dim>::write_particle_csv(
    const unsigned int         step,
    const MaterialPoints<dim> &material_points) const
  {
    using Layout = PropertyLayout<dim>;
    // Stress columns in the order sxx, syy, szz, sxy, syz, sxz.
    std::vector<std::pair<unsigned int, unsigned int>> stress_columns;
    for (unsigned int d = 0; d < dim; ++d)
      stress_columns.emplace_back(d, d);
    if (dim >= 2)
      stress_columns.emplace_back(0, 1);
    if (dim == 3)
      {
        stress_columns.emplace_back(1, 2);
        stress_columns.emplace_back(0, 2);
      }

    std::vector<std::pair<types::particle_index, std::string>> rows;
    for (const auto &particle : material_points.particle_handler())
      {
        const auto       properties = particle.get_properties();
        const Point<dim> X(
          Layout::get_vector(properties, Layout::initial_position));
        const Point<dim>              x     = particle.get_location();
        const SymmetricTensor<2, dim> sigma = Layout::get_stress(properties);
        std::ostringstream            row;
        row << std::setprecision(12) << particle.get_id();
        for (unsigned int d = 0; d < dim; ++d)
          row << ',' << X[d];
        for (unsigned int d = 0; d < dim; ++d)
          row << ',' << x[d];
        for (unsigned int d = 0; d < dim; ++d)
          row << ',' << x[d] - X[d];
        for (unsigned int d = 0; d < dim; ++d)
          row << ',' << properties[Layout::velocity + d];
        for (const auto &[i, j] : stress_columns)
          row << ',' << sigma[i][j];
        row << ',' << Layout::volume(properties) << ','
            << properties[Layout::mass];
        if (dim < 3)
          row << ',' << Layout::get_out_of_plane_stress(properties);
        const unsigned int id    = Layout::get_material_id(properties);
        const unsigned int first = materials->first_internal_variable(id);
        row << ',' << id << ','
            << (*materials)[id].equivalent_plastic_strain(
                 ArrayView<const double>(properties.data() + first,
                                         materials->n_internal_variables(id)))
            << '\n';
        rows.emplace_back(particle.get_id(), row.str());
      }

    const auto all = Utilities::MPI::gather(mpi_communicator, rows, 0);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return "";
    std::vector<std::pair<types::particle_index, std::string>> sorted;
    for (const auto &part : all)
      sorted.insert(sorted.end(), part.begin(), part.end());
    std::sort(sorted.begin(), sorted.end());

    static const char *const header[3] = {
      "id,X,x,ux,vx,sxx,volume,mass,s_lateral,material,plastic_strain",
      "id,X,Y,x,y,ux,uy,vx,vy,sxx,syy,sxy,volume,mass,szz,material,"
      "plastic_strain",
      "id,X,Y,Z,x,y,z,ux,uy,uz,vx,vy,vz,sxx,syy,szz,sxy,syz,sxz,volume,mass,"
      "material,plastic_strain"};
    return OutputDirectory::write_file_atomically(
      output_directory + "/particles-" + step_string(step) + ".csv",
      [&](std::ostream &csv) {
        csv << header[dim - 1] << '\n';
        for (const auto &row : sorted)
          csv << row.second;
      });
  }



  template <int dim>
  std::string
  OutputWriter<dim>::write_statistics(const unsigned int     step,
                                      const double           time,
                                      const Statistics<dim> &statistics) const
  {
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return "";
    const std::string  name = output_directory + "/statistics.csv";
    std::ostringstream file;
    file << std::setprecision(12) << step << ',' << time << ','
         << statistics.kinetic_energy << ',' << statistics.strain_energy << ','
         << statistics.kinetic_energy + statistics.strain_energy +
              statistics.gravitational_energy;
    if (statistics.has_displacement_error)
      file << ',' << statistics.displacement_rms_error << ','
           << statistics.displacement_l2_error;
    if (statistics.has_stress_error)
      file << ',' << statistics.stress_rms_error;
    if (write_gravitational_energy)
      file << ',' << statistics.gravitational_energy;
    for (const auto &[force, displacement] : statistics.boundary_reactions)
      {
        for (unsigned int d = 0; d < dim; ++d)
          file << ',' << force[d];
        for (unsigned int d = 0; d < dim; ++d)
          file << ',' << displacement[d];
      }
    file << ',' << statistics.supplied_work << ','
         << statistics.grid_kinetic_energy;
    if (dim == 2)
      file << ',' << statistics.angular_momentum[2];
    if (dim == 3)
      for (unsigned int d = 0; d < 3; ++d)
        file << ',' << statistics.angular_momentum[d];
    file << '\n';
    return OutputDirectory::append_to_file(name, file.str());
  }



  template <int dim>
  void
  OutputWriter<dim>::check_basis_picture(
    const ShapeFunctions<dim> &shape_functions,
    const MPI_Comm             communicator) const
  {
    if (powell_sabin_basis_point.empty())
      return;
    AssertThrow(shape_functions.has_basis_picture(),
                ExcMessage("Output/Powell-Sabin basis at needs Shape "
                           "functions = Powell-Sabin; remove the entry or "
                           "change the shape functions."));
    AssertThrow(powell_sabin_basis_point.size() == dim,
                ExcMessage("Output/Powell-Sabin basis at needs a point with " +
                           std::to_string(dim) + " coordinates."));
    AssertThrow(Utilities::MPI::n_mpi_processes(communicator) == 1,
                ExcMessage("Output/Powell-Sabin basis at: the picture is "
                           "drawn in serial runs only (on more than one MPI "
                           "rank no rank holds the whole triangulation); run "
                           "without mpirun, or remove the entry."));
  }



  template <int dim>
  void
  OutputWriter<dim>::write_basis_picture(
    const ShapeFunctions<dim> &shape_functions) const
  {
    if (powell_sabin_basis_point.empty())
      return;
    Point<dim> point;
    for (unsigned int d = 0; d < dim; ++d)
      point[d] = powell_sabin_basis_point[d];
    shape_functions.write_basis_picture(point,
                                        output_directory +
                                          "/powell-sabin-basis.vtu");
  }



  template class OutputWriter<1>;
  template class OutputWriter<2>;
  template class OutputWriter<3>;
} // namespace MpmOtm
