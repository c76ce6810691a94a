// B-spline functions belong to the rank that owns their anchor cell (issue
// 17, item 3): the cell of the spans a(i_d) = i_d - floor(p / 2), clamped
// to the spans of direction d, the middle of the function's support. On
// two ranks of a p4est grid, for degrees 1 to 3 in 2D (12 x 10 cells) and
// 3D (5 x 4 x 6 cells):
// - the ranks' owned functions are contiguous, disjoint and number all
//   functions;
// - every owned function's anchor cell is one of the rank's own cells;
// - the global index maps to the multi-index and back (functions_on_cell
//   and multi_index() agree on every own cell);
// - a function on a rank's cells that another rank owns (a ghost) is
//   counted: with the anchor rule there are no more ghosts than with the
//   former contiguous lexicographic blocks [r N / P, (r + 1) N / P), and
//   the numbers of both are printed.

#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/shape_functions/b_splines.h>

#include <set>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

template <int dim>
void
test(const unsigned int degree, const std::string &subdivisions)
{
  const MPI_Comm world = MPI_COMM_WORLD;
  std::string    lower = "0", upper = "1";
  for (unsigned int d = 1; d < dim; ++d)
    {
      lower += ", 0";
      upper += ", 1";
    }
  auto simulator = make_simulator<dim>(
    "",
    "set Dimension = " + std::to_string(dim) +
      "\nset Problem = custom\nset Shape functions = B-spline\n"
      "set B-spline degree = " +
      std::to_string(degree) + "\nsubsection Mesh\n set Lower corner = " +
      lower + "\n set Upper corner = " + upper + "\n set Subdivisions = " +
      subdivisions + "\nend\nsubsection Time\n set Time step = 1e-5\nend\n",
    "output-b-spline-ownership");
  const auto &splines =
    dynamic_cast<const BSplines<dim> &>(simulator->shape_function_family());
  const types::global_dof_index n     = splines.n_functions();
  const IndexSet                owned = splines.locally_owned_functions();
  const unsigned int            rank  = Utilities::MPI::this_mpi_process(world);
  const unsigned int n_ranks          = Utilities::MPI::n_mpi_processes(world);

  // Contiguous, disjoint, all numbered.
  check(owned.is_contiguous(), "owned functions contiguous");
  const auto sizes  = Utilities::MPI::all_gather(world, owned.n_elements());
  const auto firsts = Utilities::MPI::all_gather(world,
                                                 owned.n_elements() > 0 ?
                                                   owned.nth_index_in_set(0) :
                                                   numbers::invalid_dof_index);
  types::global_dof_index next = 0;
  for (unsigned int r = 0; r < n_ranks; ++r)
    if (sizes[r] > 0)
      {
        check(firsts[r] == next, "ranks number their functions in turn");
        next += sizes[r];
      }
  check(next == n, "every function has one owner");

  // Every owned function's anchor cell is an own cell; the numbering of
  // functions_on_cell() and multi_index() agree.
  std::set<std::array<unsigned int, dim>> own_spans;
  std::vector<types::global_dof_index>    functions;
  std::set<types::global_dof_index>       on_own_cells;
  const unsigned int                      q = degree + 1;
  for (const auto &cell :
       simulator->background_grid().triangulation().active_cell_iterators())
    if (cell->is_locally_owned())
      {
        const auto &first = splines.first_function(cell);
        own_spans.insert(first);
        splines.functions_on_cell(cell, functions);
        for (unsigned int local = 0; local < functions.size(); ++local)
          {
            const auto   i    = splines.multi_index(functions[local]);
            unsigned int rest = local;
            for (unsigned int d = 0; d < dim; ++d, rest /= q)
              check(i[d] == first[d] + rest % q,
                    "multi_index() inverts functions_on_cell()");
            on_own_cells.insert(functions[local]);
          }
      }
  for (const auto global : owned)
    {
      const auto                    i = splines.multi_index(global);
      std::array<unsigned int, dim> anchor;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const unsigned int n_spans = splines.breakpoints(d).size() - 1;
          anchor[d] = std::min(i[d] - std::min(i[d], degree / 2), n_spans - 1);
        }
      check(own_spans.count(anchor) == 1,
            "an owned function's anchor cell is an own cell");
    }

  // Ghosts: functions on own cells owned elsewhere, now and with the
  // lexicographic blocks.
  std::uint64_t ghosts = 0, block_ghosts = 0;
  const auto    begin = static_cast<std::uint64_t>(rank) * n / n_ranks;
  const auto    end   = static_cast<std::uint64_t>(rank + 1) * n / n_ranks;
  for (const auto global : on_own_cells)
    {
      ghosts += owned.is_element(global) ? 0 : 1;
      const auto    i             = splines.multi_index(global);
      std::uint64_t lexicographic = 0;
      for (unsigned int d = dim; d-- > 0;)
        lexicographic =
          lexicographic * splines.n_functions_in_direction(d) + i[d];
      block_ghosts += (lexicographic >= begin && lexicographic < end) ? 0 : 1;
    }
  ghosts       = Utilities::MPI::sum(ghosts, world);
  block_ghosts = Utilities::MPI::sum(block_ghosts, world);
  check(ghosts <= block_ghosts, "no more ghosts than lexicographic blocks");
  if (rank == 0)
    deallog << dim << "D, degree " << degree << ", " << n
            << " functions: owned by anchor cell, " << ghosts
            << " ghosts on all ranks (lexicographic blocks: " << block_ghosts
            << ")" << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (unsigned int degree = 1; degree <= 3; ++degree)
    {
      test<2>(degree, "12, 10");
      test<3>(degree, "5, 4, 6");
    }
}
