// Monitoring points (issue 36; manual, "Monitoring points"): G3's footing
// on a coarse grid (with a yield stress of 3 kPa, so that the soil yields
// within the short run) with two named points, one below the footing's edge and
// one beside it. Checked against the particle CSV of the same run, which
// is written by another path:
//  - each point follows the material point whose initial position is
//    nearest to its coordinates (found again here from particles-00000.csv,
//    the smaller id on a tie);
//  - at every output step its row of monitoring.csv holds that point's
//    position, displacement, velocity, stress (sxx, syy, szz, sxy) and
//    plastic strain as the particle CSV prints them, and the mean stress
//    trace / 3 and the von Mises stress sqrt(3 J2) of those stresses to
//    1e-9 of the largest stress;
//  - with Interval = 7 its rows are the steps 0, 7, ..., 147 and the last;
//  - a run resumed from its newest checkpoint, after a cut-off row was left
//    at the end of the file, writes the same file byte by byte as the run
//    that was not interrupted (the same number of ranks);
//  - a run without monitoring points writes no monitoring.csv.
// On one and on two ranks, with the same output.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  /**
   * A CSV file as its header's column names and its rows.
   */
  struct CsvTable
  {
    std::map<std::string, unsigned int> column;
    std::vector<std::vector<double>>    rows;

    double
    get(const unsigned int row, const std::string &name) const
    {
      const auto found = column.find(name);
      check(found != column.end(), "no column " + name);
      return rows.at(row).at(found->second);
    }
  };

  CsvTable
  read_table(const std::string &name)
  {
    std::ifstream file(name);
    check(static_cast<bool>(file), "cannot read " + name);
    CsvTable    table;
    std::string line;
    std::getline(file, line);
    {
      std::istringstream header(line);
      std::string        entry;
      while (std::getline(header, entry, ','))
        table.column.emplace(entry, table.column.size());
    }
    while (std::getline(file, line))
      {
        std::istringstream  row(line);
        std::string         entry;
        std::vector<double> values;
        while (std::getline(row, entry, ','))
          values.push_back(std::stod(entry));
        check(values.size() == table.column.size(),
              name + ": a row has " + std::to_string(values.size()) +
                " values for " + std::to_string(table.column.size()) +
                " columns");
        table.rows.push_back(values);
      }
    return table;
  }

  std::string
  contents(const std::string &name)
  {
    std::ifstream     file(name);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
  }

  const std::string g3 =
    "subsection Time\n set End time = 0.06\nend\n"
    "subsection Mesh\n set Subdivisions = 10, 12\nend\n"
    "subsection Material\n subsection von Mises\n"
    "  set Yield stress = 3000\n end\nend\n"
    "subsection Monitoring\n"
    " set Points = below: 0.47, 2.45; beside: 1.2, 2.45\nend\n";

  const std::vector<std::pair<std::string, Point<2>>> monitored =
    {{"below", Point<2>(0.47, 2.45)}, {"beside", Point<2>(1.2, 2.45)}};
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  // Every output step against the particle CSV.
  const std::string directory = "output-monitoring";
  make_simulator<2>("G3-prandtl-footing.prm",
                    g3 + "subsection Output\n set Write particle CSV = "
                         "true\nend\n",
                    directory)
    ->run();
  const CsvTable      monitoring = read_table(directory + "/monitoring.csv");
  const CsvTable      start = read_table(directory + "/particles-00000.csv");
  std::vector<double> ids;
  for (const auto &[name, location] : monitored)
    {
      unsigned int nearest = 0;
      for (unsigned int p = 1; p < start.rows.size(); ++p)
        {
          const auto distance = [&](const unsigned int q) {
            return location.distance(
              Point<2>(start.get(q, "X"), start.get(q, "Y")));
          };
          if (distance(p) < distance(nearest))
            nearest = p;
        }
      ids.push_back(start.get(nearest, "id"));
      deallog << name << ": material point "
              << static_cast<unsigned int>(ids.back()) << std::endl;
    }
  std::vector<unsigned int> steps;
  for (unsigned int row = 0; row < monitoring.rows.size(); ++row)
    steps.push_back(monitoring.get(row, "step"));
  check(steps == std::vector<unsigned int>({0, 50, 100, 150}),
        "with Interval = 0 the rows are not those of the output steps");
  double largest_plastic_strain = 0;
  for (unsigned int row = 0; row < monitoring.rows.size(); ++row)
    {
      std::ostringstream file;
      file << directory << "/particles-" << std::setw(5) << std::setfill('0')
           << steps[row] << ".csv";
      const CsvTable particles = read_table(file.str());
      for (unsigned int k = 0; k < monitored.size(); ++k)
        {
          unsigned int p = 0;
          while (p < particles.rows.size() && particles.get(p, "id") != ids[k])
            ++p;
          check(p < particles.rows.size(), "the monitored point is gone");
          const std::string prefix = monitored[k].first + "_";
          for (const auto &[own, csv] :
               std::vector<std::pair<std::string, std::string>>{
                 {"x", "x"},
                 {"y", "y"},
                 {"ux", "ux"},
                 {"uy", "uy"},
                 {"vx", "vx"},
                 {"vy", "vy"},
                 {"sxx", "sxx"},
                 {"syy", "syy"},
                 {"szz", "szz"},
                 {"sxy", "sxy"},
                 {"plastic_strain", "plastic_strain"}})
            check(monitoring.get(row, prefix + own) == particles.get(p, csv),
                  "step " + std::to_string(steps[row]) + ": " + prefix + own +
                    " differs from the particle CSV");
          SymmetricTensor<2, 3> sigma;
          sigma[0][0]        = particles.get(p, "sxx");
          sigma[1][1]        = particles.get(p, "syy");
          sigma[2][2]        = particles.get(p, "szz");
          sigma[0][1]        = particles.get(p, "sxy");
          const double scale = std::max(1., sigma.norm());
          check(std::abs(monitoring.get(row, prefix + "mean_stress") -
                         trace(sigma) / 3.) < 1e-9 * scale &&
                  std::abs(monitoring.get(row, prefix + "von_mises_stress") -
                           std::sqrt(1.5) * deviator(sigma).norm()) <
                    1e-9 * scale,
                "step " + std::to_string(steps[row]) +
                  ": mean or von Mises stress differs from the stresses'");
          largest_plastic_strain =
            std::max(largest_plastic_strain,
                     monitoring.get(row, prefix + "plastic_strain"));
        }
    }
  deallog << "rows at steps 0, 50, 100, 150 equal the particle CSV's; "
          << "plastic strain "
          << (largest_plastic_strain > 0 ? "above 0" : "0 (NOT PLASTIC)")
          << std::endl;
  check(largest_plastic_strain > 0,
        "the point below the footing's edge never yielded: the plastic "
        "strain column is not exercised");

  // Every seventh step, with checkpoints; then resumed after a cut-off row.
  const std::string every_seventh =
    g3 + "subsection Monitoring\n set Interval = 7\nend\n"
         "subsection Checkpoint\n set Interval = 40\nend\n";
  const std::string resume_directory = "output-monitoring-resume";
  make_simulator<2>("G3-prandtl-footing.prm", every_seventh, resume_directory)
    ->run();
  const std::string         name = resume_directory + "/monitoring.csv";
  const std::string         uninterrupted = contents(name);
  const CsvTable            seventh       = read_table(name);
  std::vector<unsigned int> expected;
  for (unsigned int step = 0; step < 150; step += 7)
    expected.push_back(step);
  expected.push_back(150);
  steps.clear();
  for (unsigned int row = 0; row < seventh.rows.size(); ++row)
    steps.push_back(seventh.get(row, "step"));
  check(steps == expected, "with Interval = 7 the rows are not every 7th");
  deallog << "Interval = 7: " << steps.size()
          << " rows, steps 0, 7, ..., 147, 150" << std::endl;
  MPI_Barrier(MPI_COMM_WORLD);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::ofstream(name, std::ios::app) << "15";
  MPI_Barrier(MPI_COMM_WORLD);
  make_simulator<2>("G3-prandtl-footing.prm",
                    every_seventh,
                    resume_directory,
                    MPI_COMM_WORLD,
                    true)
    ->run();
  const bool same = contents(name) == uninterrupted;
  deallog << "resumed after a cut-off row: monitoring.csv "
          << (same ? "identical" : "DIFFERENT") << std::endl;
  check(same, "the resumed run's monitoring.csv differs");

  // Without monitoring points, no monitoring.csv.
  make_simulator<2>("G3-prandtl-footing.prm",
                    "subsection Time\n set End time = 0.0008\nend\n"
                    "subsection Mesh\n set Subdivisions = 10, 12\nend\n",
                    "output-monitoring-none")
    ->run();
  const bool none = !std::ifstream("output-monitoring-none/monitoring.csv");
  deallog << "without monitoring points: "
          << (none ? "no monitoring.csv" : "A monitoring.csv") << std::endl;
  check(none, "a run without monitoring points wrote monitoring.csv");
}
