// Output/Format = hdf5 on two ranks (issue 17, "Output that scales"): per
// output step one HDF5 file for all ranks and an XDMF index over the steps.
//
// A 1 x 1 block of 64 points (4 x 4 cells, 2 x 2 points each, density 1)
// translates at v = (1, 0) without stress, so after step k every point's
// displacement is (k dt, 0) exactly. Checked in particles_00004.h5, read
// back with deal.II's HDF5 interface: 64 points, each id once, the masses
// summing to density x area = 1, every displacement (4 dt, 0, 0) (vectors
// are stored with three components) in double precision (the VTU files
// hold single precision), stress_xx = 0 (to round-off: the
// velocity gradient of a uniform field is a sum of gradients that cancel).
// particles.xdmf and grid.xdmf index steps 0 to 4; the grid's nodal_velocity is
// a vector.
//
// The grid (grid_00004.h5, written patch by patch, GridPatches::write_hdf5):
// with linear functions 16 quadrilaterals of 4 own nodes each (64 nodes),
// with quadratic B-splines (their Bernstein form, each cell a patch of 3 x 3
// nodes subdivided twice) 64 quadrilaterals on 144 nodes, with linear
// functions on triangles (four per block around its centre; on one rank)
// 64 triangles of 3 own nodes each (192 nodes), with Powell-Sabin splines
// on the same triangles (on two ranks; FE_PowellSabin evaluated by DataOut
// at the corners and edge midpoints, each triangle written as the four
// triangles between them; Young's modulus halved for a stable time step)
// 256 triangles on 384 nodes;
// every cell's corners counter-clockwise with the area of a cell
// (shoelace formula), and the nodal velocity (1, 0, 0) at every node
// (every function carries mass, and the functions sum to one).
//
// The run writes a checkpoint at step 2 and is then resumed from it: the
// resumed run must continue the series it was written with, so the index
// again lists steps 0 to 4, each once.

#include <deal.II/base/hdf5.h>

#include <fstream>
#include <iterator>
#include <set>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

const std::string parameters = R"(
set Dimension = 2
set Problem = custom
subsection Time
  set End time = 4e-4
  set Time step = 1e-4
end
subsection Mesh
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 4, 4
end
subsection Material
  set Young's modulus = 1e6
  set Density = 1
end
subsection Custom problem
  set Initial velocity = 1; 0
end
subsection Checkpoint
  set Interval = 2
end
subsection Output
  set Directory = output-hdf5
  set Overwrite = true
  set Format = hdf5
  set Interval = 1
end
)";

std::string
read_text(const std::string &name)
{
  std::ifstream file("output-hdf5/" + name);
  check(static_cast<bool>(file), name + " was not written");
  return std::string((std::istreambuf_iterator<char>(file)),
                     std::istreambuf_iterator<char>());
}

unsigned int
count(const std::string &text, const std::string &what)
{
  unsigned int n = 0;
  for (auto at = text.find(what); at != std::string::npos;
       at      = text.find(what, at + 1))
    ++n;
  return n;
}

void
check_index(const std::string &when)
{
  for (const std::string series : {"particles", "grid"})
    {
      const std::string index = read_text(series + ".xdmf");
      check(count(index, "<Time Value=") == 5,
            when + ": " + series + ".xdmf must index 5 steps");
      for (unsigned int step = 0; step <= 4; ++step)
        check(count(index,
                    series + "_0000" + std::to_string(step) + ".h5:/nodes") ==
                1,
              when + ": " + series + ".xdmf must index step " +
                std::to_string(step) + " once");
    }
  const std::string particles = read_text("particles.xdmf");
  check(count(particles, "NumberOfElements=\"64\"") == 5,
        when + ": every step must hold the 64 points");
  check(count(read_text("grid.xdmf"),
              "Attribute Name=\"nodal_velocity\" AttributeType=\"Vector\"") ==
          5,
        when + ": the grid's nodal_velocity must be a vector");
  deallog << when << ": particles.xdmf and grid.xdmf index steps 0 to 4"
          << std::endl;
}

/**
 * Check grid_00004.h5 of the run with @p family: @p n_cells counter-clockwise
 * cells of @p n_vertices vertices and area 1 / n_cells on @p n_nodes nodes,
 * and the velocity (1, 0, 0) at every node.
 */
void
check_grid(const std::string &family,
           const unsigned int n_cells,
           const unsigned int n_nodes,
           const unsigned int n_vertices = 4)
{
  HDF5::File file("output-hdf5/grid_00004.h5",
                  HDF5::File::FileAccessMode::open);
  const auto nodes = file.open_dataset("nodes").read<std::vector<double>>();
  const auto cells =
    file.open_dataset("cells").read<std::vector<unsigned int>>();
  const auto velocity =
    file.open_dataset("nodal_velocity").read<std::vector<float>>();
  check(cells.size() == n_vertices * n_cells && nodes.size() == 2 * n_nodes &&
          velocity.size() == 3 * n_nodes,
        family + ": grid_00004.h5 must hold " + std::to_string(n_cells) +
          " cells of " + std::to_string(n_vertices) + " vertices on " +
          std::to_string(n_nodes) + " nodes");
  for (unsigned int c = 0; c < n_cells; ++c)
    {
      double area = 0;
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          const unsigned int i = cells[n_vertices * c + v],
                             j = cells[n_vertices * c + (v + 1) % n_vertices];
          area += 0.5 * (nodes[2 * i] * nodes[2 * j + 1] -
                         nodes[2 * j] * nodes[2 * i + 1]);
        }
      check(std::abs(area * n_cells - 1.) < 1e-12,
            family + ": grid cell " + std::to_string(c) + " has area " +
              std::to_string(area) + " or is not counter-clockwise");
    }
  for (unsigned int i = 0; i < nodes.size() / 2; ++i)
    check(std::abs(velocity[3 * i] - 1.f) < 1e-6f &&
            std::abs(velocity[3 * i + 1]) < 1e-6f && velocity[3 * i + 2] == 0.f,
          family + ": the nodal velocity at grid node " + std::to_string(i) +
            " is not (1, 0, 0)");
  deallog << family << ": grid_00004.h5 holds " << n_cells
          << " counter-clockwise cells of area 1/" << n_cells << " on "
          << n_nodes << " nodes, nodal velocity (1, 0, 0)" << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  simulator_from_text<2>(parameters)->run();
  if (root)
    {
      check_index("run");
      HDF5::File file("output-hdf5/particles_00004.h5",
                      HDF5::File::FileAccessMode::open);
      const auto mass = file.open_dataset("mass").read<std::vector<double>>();
      const auto id   = file.open_dataset("id").read<std::vector<double>>();
      const auto displacement =
        file.open_dataset("displacement").read<std::vector<double>>();
      const auto stress_xx =
        file.open_dataset("stress_xx").read<std::vector<double>>();
      check(mass.size() == 64 && id.size() == 64 &&
              displacement.size() == 3 * 64 && stress_xx.size() == 64,
            "particles_00004.h5 must hold 64 points");
      double total_mass = 0;
      for (const double m : mass)
        total_mass += m;
      check(std::abs(total_mass - 1.) < 1e-12, "the masses must sum to 1");
      check(std::set<double>(id.begin(), id.end()).size() == 64,
            "every point must be written once");
      for (unsigned int p = 0; p < 64; ++p)
        check(std::abs(displacement[3 * p] - 4e-4) < 1e-15 &&
                std::abs(displacement[3 * p + 1]) < 1e-15 &&
                displacement[3 * p + 2] == 0. && std::abs(stress_xx[p]) < 1e-6,
              "point " + std::to_string(p) + ": displacement (" +
                std::to_string(displacement[3 * p]) + ", " +
                std::to_string(displacement[3 * p + 1]) +
                "), stress_xx = " + std::to_string(stress_xx[p]) +
                "; must be (4 dt, 0) without stress");
      deallog << "particles_00004.h5: 64 points, total mass " << total_mass
              << ", displacement (4 dt, 0, 0), no stress" << std::endl;
      check_grid("linear", 16, 64);
    }

  simulator_from_text<2>(parameters, MPI_COMM_WORLD, true)->run();
  if (root)
    check_index("resumed from step 2");

  simulator_from_text<2>(parameters + "set Shape functions = B-spline\n"
                                      "set B-spline degree = 2\n")
    ->run();
  if (root)
    check_grid("quadratic B-splines", 64, 144);

  if (root)
    {
      simulator_from_text<2>(
        parameters + "subsection Mesh\n set Cell type = simplex\nend\n",
        MPI_COMM_SELF)
        ->run();
      check_grid("linear on triangles", 64, 192, 3);
    }

  simulator_from_text<2>(parameters +
                         "subsection Mesh\n set Cell type = simplex\nend\n"
                         "set Shape functions = Powell-Sabin\n"
                         // a softer material: dt = 1e-4 is stable
                         "subsection Material\n"
                         " set Young's modulus = 5e5\nend\n")
    ->run();
  if (root)
    check_grid("Powell-Sabin", 256, 384, 3);
}
