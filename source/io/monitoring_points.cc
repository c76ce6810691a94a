#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/utilities.h>

#include <mpm_otm/base/checkpoint_state.h>
#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/base/read_point.h>
#include <mpm_otm/io/monitoring_points.h>
#include <mpm_otm/io/output_directory.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/materials/material_library.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace MpmOtm
{
  namespace
  {
    /**
     * @p value with three significant digits, for messages.
     */
    std::string
    rounded(const double value)
    {
      std::ostringstream text;
      text << std::setprecision(3) << value;
      return text.str();
    }


    /**
     * The names of the stress columns: sxx, syy, szz, sxy, syz, sxz in 3D,
     * the four of plane strain in 2D, sxx and the lateral stress in 1D.
     */
    std::vector<std::string>
    stress_column_names(const unsigned int dim)
    {
      if (dim == 1)
        return {"sxx", "s_lateral"};
      if (dim == 2)
        return {"sxx", "syy", "szz", "sxy"};
      return {"sxx", "syy", "szz", "sxy", "syz", "sxz"};
    }
  } // namespace



  template <int dim>
  void
  MonitoringPoints<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Monitoring");
    prm.declare_entry(
      "Points",
      "",
      Patterns::Anything(),
      "Named points whose material point is followed through the run, as "
      "NAME: x, y[, z] separated by ';' (e.g. crest: 5, 10; toe: 15, 0). "
      "Each follows the material point whose initial position is nearest to "
      "its coordinates; monitoring.csv in the output directory gets, per "
      "point, its position, displacement, velocity, stress (sxx, syy, szz, "
      "sxy in 2D; tension positive), mean_stress (trace / 3), "
      "von_mises_stress and plastic_strain. A point outside every body "
      "stops the run before the first step. Empty: no monitoring.");
    prm.declare_entry(
      "Interval",
      "0",
      Patterns::Integer(0),
      "Write monitoring.csv every this many time steps (and at the first "
      "and the last); 0: at the steps of the field output (Output/Interval, "
      "Output/Time interval).");
    prm.leave_subsection();
  }



  template <int dim>
  void
  MonitoringPoints<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Monitoring");
    const std::string entry = "Monitoring/Points";
    for (const auto &item :
         Utilities::split_string_list(prm.get("Points"), ';'))
      {
        if (item.empty())
          continue;
        const auto colon = item.find(':');
        AssertThrow(colon != std::string::npos,
                    ExcMessage(entry + ": <" + item +
                               "> must be NAME: coordinates, e.g. crest: " +
                               (dim == 1 ? "5" :
                                dim == 2 ? "5, 10" :
                                           "5, 10, 2") +
                               "."));
        const std::string name = Utilities::trim(item.substr(0, colon));
        AssertThrow(!name.empty() &&
                      std::all_of(name.begin(),
                                  name.end(),
                                  [](const char c) {
                                    return std::isalnum(
                                             static_cast<unsigned char>(c)) ||
                                           c == '_' || c == '-';
                                  }),
                    ExcMessage(entry + ": the name <" + name + "> of <" + item +
                               "> must be letters, digits, '_' or '-' (it "
                               "names the point's columns)."));
        AssertThrow(std::find(names.begin(), names.end(), name) == names.end(),
                    ExcMessage(entry + ": the name <" + name +
                               "> is given twice; every point needs its own."));
        names.push_back(name);
        locations.push_back(
          read_point<dim>(item.substr(colon + 1), entry + " (" + name + ")"));
      }
    interval = prm.get_integer("Interval");
    prm.leave_subsection();
  }



  template <int dim>
  bool
  MonitoringPoints<dim>::enabled() const
  {
    return !names.empty();
  }



  template <int dim>
  unsigned int
  MonitoringPoints<dim>::n_values()
  {
    return 3 * dim + stress_column_names(dim).size() + 3;
  }



  template <int dim>
  std::string
  MonitoringPoints<dim>::locate(const MaterialPoints<dim> &material_points,
                                const MPI_Comm             communicator)
  {
    using Layout = PropertyLayout<dim>;
    // Per monitoring point: this rank's nearest material point as distance,
    // id, its reach (the diagonal of its initial share of the body) and its
    // initial position; the nearest over the ranks, the smaller id on a tie.
    const unsigned int  n_points = names.size();
    std::vector<double> nearest(n_points * (3 + dim),
                                std::numeric_limits<double>::infinity());
    for (const auto &particle : material_points.particle_handler())
      {
        const auto       properties = particle.get_properties();
        const Point<dim> X(
          Layout::get_vector(properties, Layout::initial_position));
        for (unsigned int k = 0; k < n_points; ++k)
          {
            double *const candidate = &nearest[k * (3 + dim)];
            const double  distance  = X.distance(locations[k]);
            const double  id        = particle.get_id();
            if (distance < candidate[0] ||
                (distance == candidate[0] && id < candidate[1]))
              {
                candidate[0] = distance;
                candidate[1] = id;
                candidate[2] =
                  std::sqrt(double(dim)) *
                  std::pow(properties[Layout::initial_volume], 1. / dim);
                for (unsigned int d = 0; d < dim; ++d)
                  candidate[3 + d] = X[d];
              }
          }
      }
    const auto all = Utilities::MPI::all_gather(communicator, nearest);

    ids.clear();
    std::string        problem;
    std::ostringstream log;
    for (unsigned int k = 0; k < n_points; ++k)
      {
        const double *best = nullptr;
        for (const auto &part : all)
          {
            const double *candidate = &part[k * (3 + dim)];
            if (best == nullptr || candidate[0] < best[0] ||
                (candidate[0] == best[0] && candidate[1] < best[1]))
              best = candidate;
          }
        std::ostringstream where;
        where << std::setprecision(6) << names[k] << " (";
        for (unsigned int d = 0; d < dim; ++d)
          where << (d > 0 ? ", " : "") << locations[k][d];
        where << ")";
        if (!(best[0] <= best[2]))
          {
            problem += "Monitoring/Points: " + where.str() +
                       (std::isfinite(best[0]) ?
                          " is outside every body: the nearest material "
                          "point is " +
                            rounded(best[0]) + " away, more than its spacing " +
                            rounded(best[2]) + ". " :
                          " cannot be followed: there are no material "
                          "points. ");
            ids.push_back(0);
            continue;
          }
        ids.push_back(static_cast<types::particle_index>(best[1]));
        Point<dim> X;
        for (unsigned int d = 0; d < dim; ++d)
          X[d] = best[3 + d];
        log << "monitoring point " << where.str() << ": material point "
            << ids.back() << " at (";
        for (unsigned int d = 0; d < dim; ++d)
          log << (d > 0 ? ", " : "") << X[d];
        log << "), " << rounded(best[0]) << " away\n";
      }
    AssertThrow(problem.empty(),
                ExcMessage(problem + "Give coordinates inside a body."));
    return log.str();
  }



  template <int dim>
  std::string
  MonitoringPoints<dim>::header() const
  {
    std::ostringstream header;
    header << "step,time";
    for (const auto &point : names)
      {
        for (const std::string quantity : {"", "u", "v"})
          for (unsigned int d = 0; d < dim; ++d)
            header << ',' << point << '_' << quantity << "xyz"[d];
        for (const auto &column : stress_column_names(dim))
          header << ',' << point << '_' << column;
        for (const std::string column :
             {"mean_stress", "von_mises_stress", "plastic_strain"})
          header << ',' << point << '_' << column;
      }
    return header.str();
  }



  template <int dim>
  void
  MonitoringPoints<dim>::write_header(const std::string &directory,
                                      const bool         resumed,
                                      const MPI_Comm     communicator) const
  {
    std::string problem;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        const std::string name = directory + "/monitoring.csv";
        std::ifstream     existing(name);
        std::string       first_line;
        if (resumed && existing && std::getline(existing, first_line))
          {
            if (first_line != header())
              problem = "Monitoring/Points: <" + name +
                        "> of the run being resumed follows other points "
                        "(its columns are " +
                        first_line +
                        "). Resume with the monitoring points it was written "
                        "with. ";
          }
        else
          {
            problem =
              OutputDirectory::write_file_atomically(name,
                                                     [&](std::ostream &out) {
                                                       out << header() << '\n';
                                                     });
            if (!problem.empty())
              problem += "Free space on the disk of Output/Directory or "
                         "choose another one.";
          }
      }
    stop_if_any_rank_failed(communicator, problem, "", "");
  }



  template <int dim>
  bool
  MonitoringPoints<dim>::is_due(const unsigned int step,
                                const bool         output_step,
                                const bool         last) const
  {
    if (!enabled())
      return false;
    if (step == 0 || last)
      return true;
    return interval == 0 ? output_step : step % interval == 0;
  }



  template <int dim>
  void
  MonitoringPoints<dim>::save(CheckpointState &state) const
  {
    state.set_shared("monitoring/ids",
                     std::vector<double>(ids.begin(), ids.end()));
  }



  template <int dim>
  void
  MonitoringPoints<dim>::load(const CheckpointState &state)
  {
    const auto &stored = state.shared("monitoring/ids");
    AssertThrow(stored.size() == names.size(),
                ExcMessage("The checkpoint follows " +
                           std::to_string(stored.size()) +
                           " monitoring points, the parameters name " +
                           std::to_string(names.size()) + "."));
    ids.assign(stored.begin(), stored.end());
  }



  template <int dim>
  void
  MonitoringPoints<dim>::write(const unsigned int          step,
                               const double                time,
                               const MaterialPoints<dim>  &material_points,
                               const MaterialLibrary<dim> &materials,
                               const std::string          &directory,
                               const MPI_Comm              communicator) const
  {
    if (!enabled())
      return;
    using Layout           = PropertyLayout<dim>;
    const unsigned int n   = n_values();
    const unsigned int n_k = names.size();
    // Each monitored point's values on the rank that owns it, zeros
    // elsewhere, and a count of its owners: summed over the ranks, every
    // point has its values and a count of 1 (0 once it is gone).
    std::vector<double> values(n_k * (n + 1), 0.);
    for (const auto &particle : material_points.particle_handler())
      {
        const auto k = std::find(ids.begin(), ids.end(), particle.get_id());
        if (k == ids.end())
          continue;
        double *row                 = &values[(k - ids.begin()) * (n + 1)];
        row[n]                      = 1.;
        const auto       properties = particle.get_properties();
        const Point<dim> X(
          Layout::get_vector(properties, Layout::initial_position));
        const Point<dim> &x = particle.get_location();
        for (unsigned int d = 0; d < dim; ++d)
          {
            row[d]           = x[d];
            row[dim + d]     = x[d] - X[d];
            row[2 * dim + d] = properties[Layout::velocity + d];
          }
        const SymmetricTensor<2, 3> full = Layout::get_full_stress(properties);
        unsigned int                c    = 3 * dim;
        if (dim == 1)
          {
            row[c++] = full[0][0];
            row[c++] = full[1][1];
          }
        else
          {
            for (unsigned int d = 0; d < 3; ++d)
              row[c++] = full[d][d];
            row[c++] = full[0][1];
            if (dim == 3)
              {
                row[c++] = full[1][2];
                row[c++] = full[0][2];
              }
          }
        row[c++]                 = trace(full) / 3.;
        row[c++]                 = std::sqrt(1.5) * deviator(full).norm();
        const unsigned int id    = Layout::get_material_id(properties);
        const unsigned int first = materials.first_internal_variable(id);
        row[c++]                 = materials[id].equivalent_plastic_strain(
          ArrayView<const double>(properties.data() + first,
                                  materials.n_internal_variables(id)));
        AssertDimension(c, n);
      }
    Utilities::MPI::sum(values, communicator, values);

    std::string problem;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        const std::string  name = directory + "/monitoring.csv";
        std::ostringstream file;
        file << std::setprecision(12) << step << ',' << time;
        for (unsigned int k = 0; k < n_k; ++k)
          for (unsigned int v = 0; v < n; ++v)
            {
              // A point no rank holds any more (it left the grid) is nan.
              file << ',';
              if (values[k * (n + 1) + n] == 1.)
                file << values[k * (n + 1) + v];
              else
                file << "nan";
            }
        file << '\n';
        problem = OutputDirectory::append_to_file(name, file.str());
      }
    stop_if_any_rank_failed(
      communicator,
      problem,
      "",
      "Free space on the disk of Output/Directory or choose another one.");
  }



  template class MonitoringPoints<1>;
  template class MonitoringPoints<2>;
  template class MonitoringPoints<3>;
} // namespace MpmOtm
