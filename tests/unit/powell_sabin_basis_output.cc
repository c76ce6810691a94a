// Output/Powell-Sabin basis at: powell-sabin-basis.vtu shows the three
// functions of the vertex nearest to the point on the Powell-Sabin
// refinement of its cells and their neighbours, each sub-triangle divided
// into 36 triangles. On the 1 x 8 blocks of
// prm/B6-soil-column-small-powell-sabin.prm (2 m x 3.125 m blocks of four
// triangles around the block centre), the vertex nearest to (0.1, 12.4) is
// the corner (0, 12.5) between blocks 4 and 5. Its functions live on four
// triangles (the left and top one of block 4, the left and bottom one of
// block 5); the triangles sharing a vertex with those are all eight of the
// two blocks and two each of blocks 3 and 6 (at the corners (0, 9.375) and
// (0, 15.625)): 12 cells, 12 * 6 * 36 = 2592 output triangles.

#include <fstream>
#include <iterator>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  make_simulator<2>("B6-soil-column-small-powell-sabin.prm",
                    "subsection Output\n"
                    " set Powell-Sabin basis at = 0.1, 12.4\nend\n",
                    "output-basis");
  std::ifstream     file("output-basis/powell-sabin-basis.vtu");
  const std::string text((std::istreambuf_iterator<char>(file)),
                         std::istreambuf_iterator<char>());
  check(!text.empty(), "powell-sabin-basis.vtu was not written");
  check(text.find("NumberOfCells=\"2592\"") != std::string::npos,
        "powell-sabin-basis.vtu must have 2592 triangles");
  for (const std::string name : {"phi_0", "phi_1", "phi_2"})
    check(text.find("Name=\"" + name + "\"") != std::string::npos,
          "powell-sabin-basis.vtu must hold " + name);
  deallog << "powell-sabin-basis.vtu: 2592 triangles with phi_0, phi_1, phi_2"
          << std::endl;
}
