// The plane-strain biaxial test of prm/biaxial-softening.prm
// (biaxial_softening.h) as the prm file sets it up, quadratic B-splines
// whose strength softens with the nodal average of the plastic strain
// (Softening regularisation = nodal average), on 0.1 m cells (the prm
// file's are 0.05 m) to a platen displacement of 0.06 m. Asserted:
//  - the peak of the platen's load within 2 % of the exact
//    2 c cos(phi) / (1 - sin(phi)) x 1 m = 69.28 kN/m;
//  - the residual strength: the mean load at platen displacements above
//    0.045 m within 2 % of 2 c_r cos(phi_r) / (1 - sin(phi_r)) x 1 m =
//    10.91 kN/m, the least load that slides a block along a band with the
//    residual strength (local softening leaves it 6-11 % above:
//    doc/benchmarks.md);
//  - the points past the end of softening form a band across the
//    specimen.

#include "biaxial_softening.h"

int
main(int argc, char **argv)
{
  using namespace Biaxial;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const Result result = run(16,
                            22,
                            12.,
                            0.045,
                            "set Shape functions = B-spline\n"
                            "set B-spline degree = 2\n"
                            "set Softening regularisation = nodal average",
                            1.);
  check(std::abs(result.peak_load / peak - 1.) < 0.02,
        "the peak load is not within 2 % of the exact one");
  check(std::abs(result.late_load / residual - 1.) < 0.02,
        "the late load is not within 2 % of the residual strength");
  check(result.band_points >= 20 && result.band_left < 0.2 &&
          result.band_right > 0.8,
        "no shear band across the specimen");
}
