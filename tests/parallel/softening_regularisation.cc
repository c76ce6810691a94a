// The nodal average of Softening regularisation on one and on two ranks
// (the same program writes softening_regularisation.output on one rank and
// softening_regularisation.mpirun=2.output on two; both hold the same
// digits): the biaxial test of prm/biaxial-softening.prm (quadratic
// B-splines, whose functions reach over the ranks' boundary, so that the
// nodal sums of the plastic strain are exchanged) on 0.1 m cells to a
// platen displacement of 0.025 m, through the peak and the softening.
// Printed: the peak load and the load at the end (the mean over the last
// 0.05 s), to 6 digits; asserted: the peak within 2 % of the exact
// 2 c cos(phi) / (1 - sin(phi)) x 1 m = 69.28 kN/m, and the end load below
// 30 % of it and above the residual strength 10.91 kN/m.

#include "../benchmarks/biaxial_softening.h"

using namespace Biaxial;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  auto simulator =
    make_simulator<2>("biaxial-softening.prm",
                      "set Softening regularisation = nodal average\n"
                      "subsection Mesh\n set Subdivisions = 16, 22\nend\n"
                      "subsection Boundary platen\n"
                      " set Box lower corner = -0.3, 1.9\n"
                      " set Box upper corner = 1.3, 2.1\nend\n"
                      "subsection Time\n set End time = 5\nend\n"
                      "subsection Output\n set Time interval = 0.05\nend\n",
                      "output-softening-regularisation");
  double largest = 0, last = 0;
  simulator->run([&](const unsigned int, const Statistics<2> &statistics) {
    last    = -statistics.boundary_reactions[0].first[1];
    largest = std::max(largest, last);
  });
  deallog << "peak load " << std::setprecision(6) << largest << " N/m (exact "
          << peak << "), load at a platen displacement of "
          << "0.025 m " << last << " N/m (residual strength " << residual << ")"
          << std::endl;
  check(std::abs(largest / peak - 1.) < 0.02,
        "the peak load is not within 2 % of the exact one");
  check(last < 0.3 * peak && last > residual,
        "the load has not softened towards the residual strength");
}
