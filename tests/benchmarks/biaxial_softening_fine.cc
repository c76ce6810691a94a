// The plane-strain biaxial test of prm/biaxial-softening.prm
// (biaxial_softening.h) on its 0.05 m cells, to a platen displacement of
// 0.06 m. Asserted:
//  - the peak of the platen's load within 2 % of the exact
//    2 c cos(phi) / (1 - sin(phi)) x 1 m = 69.28 kN/m;
//  - the mean load at platen displacements 0.045-0.06 m, once the band has
//    softened through, within 2 % of the residual strength
//    2 c_r cos(phi_r) / (1 - sin(phi_r)) x 1 m = 10.91 kN/m, the least load
//    that slides a block along a band at the residual strength (within 3 %
//    of it for any band between 41 and 54 deg; the block's value for the
//    band's angle and its contact shortened by the slip is printed);
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
  const Result result = run(32, 40, 12., 0.045);
  check(std::abs(result.peak_load / peak - 1.) < 0.02,
        "the peak load is not within 2 % of the exact one");
  check(std::abs(result.late_load / residual - 1.) < 0.02,
        "the residual load is not within 2 % of the residual strength");
  check(result.band_points >= 20 && result.band_left < 0.2 &&
          result.band_right > 0.8,
        "no shear band across the specimen");
}
