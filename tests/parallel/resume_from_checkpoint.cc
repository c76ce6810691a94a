// Checkpoint and restart (issue 16; manual, "Safety"): a run with
// checkpoints goes to its end; the same run is then resumed from its newest
// checkpoint (mpm-otm --resume) and goes to the end again. Resumed on the
// number of ranks that wrote the checkpoint, every point's position and
// every property must equal the uninterrupted run's bit by bit: the
// checkpoint holds every state that a step carries to the next (points in
// their summation order, moved vertices or knots, the starting values of
// the consistent-mass solves and of the max-ent Newton iterations, the
// boundary displacements and reaction sums, the energy reference). Resumed
// on another number of ranks, the sums over points are split differently,
// so the results must agree to round-off: relative to the largest value of
// each quantity, to 1e-9.
//
// Serially: MPM with linear functions (G1, damping and gravity; G3,
// Mohr-Coulomb under a footing with a prescribed velocity; G2, a friction
// wall), the unified approach with quadratic B-splines and a consistent
// mass (B3), OTM with max-ent functions (B1b), MPM with Powell-Sabin
// splines (B5) and a 3D block. On two ranks: G3, the 3D block and OTM (B3)
// on triangles on two ranks, and G3 and OTM (B3, on quadrilaterals and on
// triangles) from one rank to two and from two to one.

#include <mpm_otm/material_points/material_points.h>

#include <algorithm>
#include <map>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  using PointValues = std::map<types::particle_index, std::vector<double>>;

  /**
   * Position and properties of every point of @p simulator (none on a rank
   * that is not in its communicator), gathered on every rank of the world.
   */
  template <int dim>
  PointValues
  gather_points(const Simulator<dim> *simulator)
  {
    PointValues local;
    if (simulator != nullptr)
      for (const auto &particle :
           simulator->material_points().particle_handler())
        {
          std::vector<double> values;
          for (unsigned int d = 0; d < dim; ++d)
            values.push_back(particle.get_location()[d]);
          const auto properties = particle.get_properties();
          values.insert(values.end(), properties.begin(), properties.end());
          local[particle.get_id()] = values;
        }
    PointValues all;
    for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, local))
      all.insert(part.begin(), part.end());
    return all;
  }

  /**
   * Run prm/@p prm with @p changes and checkpoints every @p interval steps
   * on @p first, resume it on @p second and compare the two ends.
   */
  template <int dim>
  void
  test(const std::string &name,
       const std::string &prm,
       const std::string &changes,
       const unsigned int interval,
       const MPI_Comm     first,
       const MPI_Comm     second)
  {
    const std::string directory = "output-resume-" + name;
    const std::string checkpoints =
      "\nsubsection Checkpoint\n set Interval = " + std::to_string(interval) +
      "\nend\n";
    PointValues uninterrupted, resumed;
    double      end_time = 0;
    {
      std::unique_ptr<Simulator<dim>> simulator;
      if (first != MPI_COMM_NULL)
        {
          simulator =
            make_simulator<dim>(prm, changes + checkpoints, directory, first);
          simulator->run();
          end_time = simulator->time();
        }
      uninterrupted = gather_points<dim>(simulator.get());
    }
    end_time = Utilities::MPI::max(end_time, MPI_COMM_WORLD);
    {
      std::unique_ptr<Simulator<dim>> simulator;
      if (second != MPI_COMM_NULL)
        {
          simulator = make_simulator<dim>(prm,
                                          changes + checkpoints,
                                          directory,
                                          second,
                                          true);
          simulator->run();
          check(simulator->time() == end_time,
                name + ": the resumed run ends at another time");
        }
      resumed = gather_points<dim>(simulator.get());
    }

    check(!uninterrupted.empty() && resumed.size() == uninterrupted.size(),
          name + ": the resumed run has " + std::to_string(resumed.size()) +
            " points, the uninterrupted one " +
            std::to_string(uninterrupted.size()));
    const unsigned int  n_values = uninterrupted.begin()->second.size();
    std::vector<double> largest(n_values, 0.);
    for (const auto &[id, values] : uninterrupted)
      for (unsigned int k = 0; k < n_values; ++k)
        largest[k] = std::max(largest[k], std::abs(values[k]));
    unsigned int n_different  = 0;
    double       worst_change = 0;
    for (const auto &[id, values] : uninterrupted)
      {
        const auto other = resumed.find(id);
        check(other != resumed.end(),
              name + ": point " + std::to_string(id) + " is missing");
        for (unsigned int k = 0; k < n_values; ++k)
          if (other->second[k] != values[k])
            {
              ++n_different;
              worst_change =
                std::max(worst_change,
                         std::abs(other->second[k] - values[k]) / largest[k]);
            }
      }
    int n_first = 0, n_second = 0;
    if (first != MPI_COMM_NULL)
      MPI_Comm_size(first, &n_first);
    if (second != MPI_COMM_NULL)
      MPI_Comm_size(second, &n_second);
    n_first  = Utilities::MPI::max(n_first, MPI_COMM_WORLD);
    n_second = Utilities::MPI::max(n_second, MPI_COMM_WORLD);
    deallog << name << ", " << n_first << " rank(s), resumed on " << n_second
            << ": " << uninterrupted.size() << " points, ";
    if (n_first == n_second)
      {
        deallog << (n_different == 0 ? "bit-identical" : "NOT identical")
                << std::endl;
        check(n_different == 0,
              name + ": " + std::to_string(n_different) +
                " values differ from the uninterrupted run's");
      }
    else
      {
        deallog << "relative difference "
                << (worst_change < 1e-9 ? "below 1e-9" : "TOO LARGE")
                << std::endl;
        check(worst_change < 1e-9,
              name +
                ": resumed on another number of ranks, a value changed "
                "by " +
                std::to_string(worst_change) + " of its largest");
      }
  }

  const std::string g1 = "subsection Time\n set End time = 0.005\nend\n"
                         "subsection Mesh\n set Subdivisions = 24, 8\nend\n";
  const std::string g3 = "subsection Time\n set End time = 0.06\nend\n"
                         "subsection Mesh\n set Subdivisions = 10, 12\nend\n";
  const std::string g2 = "subsection Time\n set End time = 0.05\nend\n";
  const std::string b3 = "subsection Mesh\n set Subdivisions = 8, 8\nend\n";
  const std::string b5 = "subsection Time\n set End time = 0.005\nend\n";
  const std::string block_3d =
    "set Dimension = 3\nset Problem = custom\nset Update scheme = MUSL\n"
    "set Bodies = block\nset Boundaries = floor\n"
    "subsection Mesh\n set Lower corner = 0, 0, 0\n"
    " set Upper corner = 1, 1, 1\n set Subdivisions = 4, 4, 4\nend\n"
    "subsection Material\n set Young's modulus = 1e4\n"
    " set Poisson's ratio = 0.3\n set Density = 1\nend\n"
    "subsection Body block\n set Lower corner = 0, 0, 0\n"
    " set Upper corner = 1, 1, 0.5\nend\n"
    "subsection Boundary floor\n set Type = fixed\n set Boundary ids = 4\n"
    "end\n"
    "subsection Gravity\n set Vector = 0, 0, -10\nend\n"
    "subsection Time\n set End time = 0.02\n set Time step = 1e-3\nend\n";
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const MPI_Comm world = MPI_COMM_WORLD;

  if (Utilities::MPI::n_mpi_processes(world) == 1)
    {
      test<2>("G1", "G1-cantilever-static.prm", g1, 70, world, world);
      test<2>("G2", "G2-friction-block.prm", g2, 100, world, world);
      test<2>("G3", "G3-prandtl-footing.prm", g3, 50, world, world);
      test<2>("B3-unified",
              "B3-plate-manufactured-unified.prm",
              b3,
              10,
              world,
              world);
      test<1>("B1b-OTM-max-ent",
              "B1b-bar-fixed-ends-otm-maxent.prm",
              "",
              30,
              world,
              world);
      test<2>("B5-Powell-Sabin",
              "B5-bar-2d-small-powell-sabin.prm",
              b5,
              300,
              world,
              world);
      test<3>("block-3d", "", block_3d, 7, world, world);
    }
  else
    {
      MPI_Comm single = first_rank_only();
      test<2>("G3", "G3-prandtl-footing.prm", g3, 50, world, world);
      test<2>("G3", "G3-prandtl-footing.prm", g3, 50, single, world);
      test<2>("G3", "G3-prandtl-footing.prm", g3, 50, world, single);
      test<2>("B3-OTM", "B3-plate-manufactured-otm.prm", b3, 10, world, world);
      test<2>("B3-OTM", "B3-plate-manufactured-otm.prm", b3, 10, single, world);
      test<2>("B3-OTM", "B3-plate-manufactured-otm.prm", b3, 10, world, single);
      test<3>("block-3d", "", block_3d, 7, world, world);
      // A fully distributed grid of triangles, whose ranks number their
      // vertices each in their own way.
      const std::string b3_simplex =
        b3 + "subsection Mesh\n set Cell type = simplex\nend\n";
      const std::string b3_otm = "B3-plate-manufactured-otm.prm";
      test<2>("B3-OTM-simplex", b3_otm, b3_simplex, 10, world, world);
      test<2>("B3-OTM-simplex", b3_otm, b3_simplex, 10, single, world);
      test<2>("B3-OTM-simplex", b3_otm, b3_simplex, 10, world, single);
      if (single != MPI_COMM_NULL)
        MPI_Comm_free(&single);
    }
}
