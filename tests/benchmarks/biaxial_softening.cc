// The plane-strain biaxial test of prm/biaxial-softening.prm
// (biaxial_softening.h) with linear functions and local softening
// (Softening regularisation = none) on 0.1 m cells (the prm file's are
// quadratic B-splines with the nodal average on 0.05 m cells, run by
// doc/scripts/reproduce_user_problems.sh; biaxial_softening_regularised
// runs them on 0.1 m cells) to a platen displacement of 0.03 m. Asserted:
//  - the peak of the platen's load within 2 % of the exact
//    2 c cos(phi) / (1 - sin(phi)) x 1 m = 69.28 kN/m;
//  - the load softens: at platen displacements 0.025-0.03 m below 30 % of
//    the peak, and above the residual strength 10.91 kN/m, the least load
//    that slides a block along a band (on these cells the band is two
//    cells, a fifth of the specimen, wide, and the load stays 17 %
//    above it at 0.025-0.03 m: doc/benchmarks.md);
//  - the points past the end of softening form a band across the
//    specimen; its angle to the horizontal is printed beside Roscoe's
//    45 + psi / 2 = 45 deg and Coulomb's 45 + phi / 2 = 60 deg
//    (doc/benchmarks.md discusses it).

#include "biaxial_softening.h"

int
main(int argc, char **argv)
{
  using namespace Biaxial;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const Result result = run(16,
                            22,
                            6.,
                            0.025,
                            "set Shape functions = linear\n"
                            "set Softening regularisation = none",
                            0.5);
  check(std::abs(result.peak_load / peak - 1.) < 0.02,
        "the peak load is not within 2 % of the exact one");
  check(result.late_load < 0.3 * result.peak_load &&
          result.late_load > residual,
        "the load has not softened towards the residual strength");
  check(result.band_points >= 20 && result.band_left < 0.2 &&
          result.band_right > 0.8,
        "no shear band across the specimen");
}
