// A block of material that starts inside one rank's part of the grid and
// falls freely under gravity (issue 16, item 1): in every step its points
// change cell on that rank while the other rank owns no point, and later
// they move to the other rank. Both ranks must reach the same collective
// calls in every step (the run used to hang in the point location), and
// every point must follow the discrete free fall of MPM (USL, lumped mass,
// no stress): v_n = n g dt, x_n = X + g dt^2 n (n + 1) / 2, to round-off.
// Linear functions in 1D, 2D and 3D, quadratic B-splines in 1D and 2D. In
// 1D and on triangles and tetrahedra (fully distributed grids, partitioned
// by METIS, so the block need not start on one rank) some points change
// rank, and on simplices every point also lies in its cell, with
// barycentric coordinates in [0, 1].

#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>

#include <set>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

template <int dim>
void
test(const std::string &shape_functions,
     const unsigned int cells,
     const bool         simplex = false)
{
  const MPI_Comm world = MPI_COMM_WORLD;
  // p4est orders the cells along a Z curve, so rank 0 owns the lower half
  // (in the last coordinate) and rank 1 the upper half, where the block
  // starts; it falls 0.2 in 0.2 s, into the lower half. METIS cuts a grid
  // of simplices along a jagged line somewhere through its middle: there
  // the block spans the grid's width and falls from its upper to its lower
  // half. A 1D grid is cut by METIS too, into two halves.
  std::string lower = "0", upper = "1", blocks = std::to_string(cells),
              body_lower = dim == 1 ? "0.6" :
                           simplex  ? "0.125" :
                                      "0.1",
              body_upper = dim == 1 ? "0.85" :
                           simplex  ? "0.875" :
                                      "0.4",
              gravity    = dim == 1 ? "-10" : "0";
  for (unsigned int d = 1; d < dim; ++d)
    {
      lower += ", 0";
      upper += ", 1";
      blocks += ", " + std::to_string(cells);
      body_lower += (d + 1 < dim) ? (simplex ? ", 0.125" : ", 0.1") : ", 0.6";
      body_upper += (d + 1 < dim) ? (simplex ? ", 0.875" : ", 0.4") : ", 0.85";
      gravity += (d + 1 < dim) ? ", 0" : ", -10";
    }
  const double dt        = 1e-3;
  auto         simulator = make_simulator<dim>(
    "",
    "set Dimension = " + std::to_string(dim) +
      "\nset Problem = custom\nset Update scheme = USL\n"
              "set Shape functions = " +
      shape_functions + "\nsubsection Mesh\n set Lower corner = " + lower +
      "\n set Upper corner = " + upper + "\n set Subdivisions = " + blocks +
      "\n set Cell type = " + (simplex ? "simplex" : "hypercube") +
      "\nend\n"
              "subsection Particles\n set Particles per cell = 2\n"
              "end\n"
              "subsection Material\n set Young's modulus = 1e3\n"
              " set Density = 1\nend\n"
              "set Bodies = block\nsubsection Body block\n"
              " set Lower corner = " +
      body_lower + "\n set Upper corner = " + body_upper +
      "\nend\n"
              "subsection Gravity\n set Vector = " +
      gravity +
      "\nend\n"
              "subsection Time\n set End time = 0.25\n"
              " set Time step = 1e-3\nend\n"
              "subsection Output\n set Interval = 10\nend\n",
    "output-falling-" + shape_functions + "-" + std::to_string(dim) + "d" +
      (simplex ? "-simplex" : ""));
  const std::string label = std::to_string(dim) + "D, " + shape_functions +
                            (simplex ? ", simplex" : "");

  using Layout          = PropertyLayout<dim>;
  const auto &points    = simulator->material_points();
  const auto  n_points  = points.n_global_points();
  const bool  on_rank_0 = Utilities::MPI::this_mpi_process(world) == 0;
  const types::particle_index n_initial =
    points.particle_handler().n_locally_owned_particles();
  types::particle_index           n_final = 0;
  double                          largest = 0, outside = 0;
  std::set<types::particle_index> initial_ids, final_ids;
  const auto &mapping = simulator->background_grid().mapping();
  simulator->run([&](const unsigned int step, const Statistics<dim> &) {
    Tensor<1, dim> fall;
    fall[dim - 1] = -10. * dt * dt * step * (step + 1.) / 2.;
    final_ids.clear();
    for (const auto &particle : points.particle_handler())
      {
        const Point<dim> X(Layout::get_vector(particle.get_properties(),
                                              Layout::initial_position));
        largest =
          std::max(largest, (particle.get_location() - X - fall).norm());
        final_ids.insert(particle.get_id());
        if (simplex)
          {
            // Barycentric coordinates 1 - sum xi and xi in [0, 1], and the
            // cell's map of xi is the point.
            const Point<dim> xi  = particle.get_reference_location();
            double           sum = 0;
            for (unsigned int d = 0; d < dim; ++d)
              {
                outside = std::max(outside, -xi[d]);
                sum += xi[d];
              }
            outside = std::max(outside, sum - 1.);
            largest = std::max(largest,
                               (mapping.transform_unit_to_real_cell(
                                  particle.get_surrounding_cell(),
                                  xi) -
                                particle.get_location())
                                 .norm());
          }
      }
    if (step == 0)
      initial_ids = final_ids;
    n_final = points.particle_handler().n_locally_owned_particles();
  });
  largest                   = Utilities::MPI::max(largest, world);
  outside                   = Utilities::MPI::max(outside, world);
  unsigned int changed_rank = 0;
  for (const auto id : initial_ids)
    if (final_ids.count(id) == 0)
      ++changed_rank;
  changed_rank = Utilities::MPI::sum(changed_rank, world);
  check(points.n_global_points() == n_points, label + ": points were lost");
  if (!simplex && dim > 1)
    {
      check(Utilities::MPI::sum(on_rank_0 ? n_initial : 0, world) == 0,
            label + ": the block did not start on rank 1 alone");
      check(Utilities::MPI::sum(on_rank_0 ? n_final : 0, world) > 0,
            label + ": no point fell onto rank 0");
    }
  check(changed_rank > 0, label + ": no point changed rank");
  check(outside < 1e-12,
        label + ": a point lies outside its simplex by " +
          std::to_string(outside));
  check(largest < 1e-12,
        label + ": free-fall error " + std::to_string(largest));
  deallog << label << ": " << n_points << " points fell"
          << (simplex  ? ", some across ranks, each in its simplex," :
              dim == 1 ? ", some across ranks," :
                         " from rank 1 onto rank 0")
          << " as the discrete free fall" << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  test<2>("linear", 8);
  test<2>("B-spline", 8);
  test<3>("linear", 4);
  test<2>("linear", 8, true);
  test<3>("linear", 4, true);
  test<1>("linear", 16);
  test<1>("B-spline", 16);
}
