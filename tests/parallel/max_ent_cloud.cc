// Max-ent functions on a grid distributed over two MPI ranks are those of
// one rank. Max-ent supports reach d_max zeta beyond a cell, further than the
// ghost layer, so each rank keeps a cloud of other ranks' nodes (the halo
// of its cells). Checked on a 16 x 16 box with d_max = 3, on quadrilaterals
// (p4est) and on triangles (a fully distributed grid):
// - every node whose support reaches a locally owned cell, found by brute
//   force over all nodes of a serial copy of the grid, is in the rank's
//   cloud with the same support radius (zeta computed by its owner alone
//   equals the serial zeta);
// - the cloud is more than the ghost layer and less than the whole grid
//   (on quadrilaterals its size is printed);
// - at random points of each rank's cells, values and gradients, matched by
//   node position, equal the serial ones to 1e-12.

#include <deal.II/dofs/dof_tools.h>

#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/shape_functions/max_ent.h>

#include <map>
#include <random>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  /**
   * A key that identifies a node by its position (the grids are generated
   * alike, so positions agree to round-off).
   */
  std::pair<long, long>
  key(const Point<2> &x)
  {
    return {std::lround(x[0] * 1e9), std::lround(x[1] * 1e9)};
  }



  void
  compare(const std::string &label, const std::string &mesh)
  {
    const MPI_Comm     world          = MPI_COMM_WORLD;
    const double       support_factor = 3.;
    const std::string  changes        = R"(
set Dimension = 2
set Problem = custom
subsection Mesh
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 16, 16
)" + mesh + R"(
end
subsection Time
  set Time step = 1e-6
end
)";
    const unsigned int rank           = Utilities::MPI::this_mpi_process(world);
    auto               distributed_run =
      make_simulator<2>("", changes, "output-" + label, world);
    auto serial_run =
      make_simulator<2>("",
                        changes,
                        "output-" + label + "-serial-" + std::to_string(rank),
                        MPI_COMM_SELF);
    MaxEnt<2> distributed(support_factor), serial(support_factor);
    distributed.initialize(distributed_run->background_grid());
    serial.initialize(serial_run->background_grid());

    // The cloud by position, with the radii.
    const IndexSet relevant = distributed.locally_relevant_functions();
    std::map<std::pair<long, long>, double> cloud;
    for (const auto i : relevant)
      cloud[key(distributed.node(i))] = distributed.support_radius(i);

    // Brute force: every serial node whose support meets an owned cell.
    unsigned int                         missing = 0, needed = 0;
    double                               radius_difference = 0;
    std::vector<types::global_dof_index> reaching;
    for (const auto &cell : distributed.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const BoundingBox<2> box = cell->bounding_box();
          for (types::global_dof_index j = 0; j < serial.n_functions(); ++j)
            {
              const Point<2> &x                = serial.node(j);
              double          squared_distance = 0;
              for (unsigned int d = 0; d < 2; ++d)
                {
                  const double outside = std::max(
                    {box.lower_bound(d) - x[d], x[d] - box.upper_bound(d), 0.});
                  squared_distance += outside * outside;
                }
              if (squared_distance >=
                  serial.support_radius(j) * serial.support_radius(j))
                continue;
              ++needed;
              const auto found = cloud.find(key(x));
              if (found == cloud.end())
                ++missing;
              else
                radius_difference =
                  std::max(radius_difference,
                           std::abs(found->second - serial.support_radius(j)));
            }
        }
    check(missing == 0, label + ": a node that reaches a cell is missing");
    check(radius_difference < 1e-14,
          label + ": support radii differ from the serial ones");
    check(needed > 0, label + ": no node reaches the owned cells");

    IndexSet ghost_layer;
    DoFTools::extract_locally_relevant_dofs(distributed.dof_handler(),
                                            ghost_layer);
    check(relevant.n_elements() > ghost_layer.n_elements() &&
            relevant.n_elements() < distributed.n_functions(),
          label + ": the cloud is not between the ghost layer and the grid");

    // Values and gradients at random points of the owned cells.
    std::mt19937                         random(rank + 1);
    std::uniform_real_distribution<>     uniform(0., 1.);
    std::vector<types::global_dof_index> indices, serial_indices;
    std::vector<double>                  values, serial_values;
    std::vector<Tensor<1, 2>>            gradients, serial_gradients;
    double                               difference = 0;
    unsigned int                         n_points   = 0;
    for (const auto &cell : distributed.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (unsigned int sample = 0; sample < 3; ++sample)
          {
            // A random convex combination of the vertices.
            std::vector<double> weights(cell->n_vertices());
            double              sum = 0;
            for (auto &w : weights)
              sum += (w = uniform(random) + 0.01);
            Point<2> x;
            for (const unsigned int v : cell->vertex_indices())
              x += weights[v] / sum * cell->vertex(v);
            check(
              distributed.evaluate_at(x, indices, values, gradients).empty() &&
                serial
                  .evaluate_at(x,
                               serial_indices,
                               serial_values,
                               serial_gradients)
                  .empty(),
              label + ": evaluation failed");
            std::map<std::pair<long, long>, std::pair<double, Tensor<1, 2>>>
              by_position;
            for (unsigned int k = 0; k < serial_indices.size(); ++k)
              by_position[key(serial.node(serial_indices[k]))] =
                {serial_values[k], serial_gradients[k]};
            check(indices.size() == serial_indices.size(),
                  label + ": the number of functions at a point differs");
            for (unsigned int k = 0; k < indices.size(); ++k)
              {
                const auto found =
                  by_position.find(key(distributed.node(indices[k])));
                check(found != by_position.end(),
                      label + ": a function at a point is not a serial one");
                difference =
                  std::max({difference,
                            std::abs(values[k] - found->second.first),
                            (gradients[k] - found->second.second).norm()});
              }
            ++n_points;
          }
    difference = Utilities::MPI::max(difference, world);
    check(difference < 1e-12,
          label + ": values or gradients differ from the serial ones by " +
            rounded(difference));
    if (label == "quadrilaterals")
      deallog << label << ": clouds of "
              << Utilities::MPI::sum(relevant.n_elements(), world)
              << " nodes on the two ranks together, ghost layers of "
              << Utilities::MPI::sum(ghost_layer.n_elements(), world) << ", of "
              << distributed.n_functions() << " nodes" << std::endl;
    deallog << label << ": " << Utilities::MPI::sum(n_points, world)
            << " points, every reaching node in the cloud, values and "
               "gradients equal the serial ones to 1e-12"
            << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  compare("quadrilaterals", "");
  compare("triangles", "set Cell type = simplex");
}
