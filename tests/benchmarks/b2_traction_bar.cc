// B2 (journal Sect. 8.2, Fig. 7, MPM-P1, OTM-P1, unified, MPM-maxent and
// OTM-maxent curves) from
// prm/B2-traction-bar-{mpm,otm,unified,mpm-maxent,otm-maxent}.prm: neo-Hookean
// bar fixed at X = 0, traction -sin(pi t) on its free end, 68 material nodes
// (in an 85-node grid for MPM; the moving material grid alone for OTM), 4
// points per cell, T = 0.4. Errors at T against the small-strain exact
// solution of Eq. 103, for both methods:
// - RMS displacement error below 0.5 % of the largest exact displacement.
//   The exact solution is small-strain linear wave theory while the material
//   is neo-Hookean at strains of 1 / E = 1 %: the constitutive difference
//   alone is about half the strain, 0.5 %, in the pulse (measured: 0.09 %
//   for the same run at strain 1e-4, E = rho = 1e4, where only the
//   discretisation error is left; 0.13 % at the benchmark's 1 %). The RMS
//   of the exact displacement itself is 30 % of its maximum (60 % of the
//   bar is still at rest), so a traction 2 % too large or too small, let
//   alone one of the wrong sign or on the wrong points, fails the check.
// - RMS stress error below 5 % of the traction amplitude 1 (measured 2.8 %:
//   the grid-crossing noise of MPM-P1 that Fig. 7 shows; 1.7 % at strain
//   1e-4).
// - Kinetic plus strain energy within 3 % of the energy the traction has put
//   in, int_0^l sigma^2 / E dX (measured 0.8 % below).
// Published behaviour: OTM-P1 follows the exact solution without MPM-P1's
// grid-crossing noise, so its RMS stress error and its largest pointwise
// stress deviation must be below MPM-P1's (measured for OTM-P1, whose grid
// carries the traction on its moving end vertex: 0.05 % displacement, 0.75 %
// stress, energy within 0.2 %). The unified approach with quadratic
// B-splines on moving knots and a consistent mass matrix
// (prm/B2-traction-bar-unified.prm) stays stable and has the lowest errors
// of the three (Figs. 7-8): its stress errors must be below OTM-P1's. It
// also stays stable and accurate when the pulse has the opposite sign and
// pulls the free end outward, where BSMPM breaks down.
// Max-ent (d_max = 2), published behaviour: MPM-maxent misses the exact
// solution at the free end, OTM-maxent follows it and is far more accurate
// than its MPM equivalent. Mechanism: on the fixed grid the nodes beyond
// the free end get the mass-weighted mean velocity of the points in their
// support (lumped mass, v_i = sum phi_i m_p v_p / sum phi_i m_p), a constant
// extrapolation into the empty cells that flattens the velocity gradient
// of the outermost points by a fraction of order one, so the largest stress
// deviation of MPM-maxent must lie in the last cell of the bar and exceed
// 10 % of the traction amplitude (measured 36 %; the published "incomplete
// set of maxent basis functions" on inactive elements). OTM-maxent's nodes
// end at the moving free end, whose function is 1 there (weak Kronecker
// delta) and carries the traction: its largest stress deviation must stay
// below the P1 stress's own error, half the change of the exact stress over
// a cell, pi h / 2 = 2.3 % at h = 1/67 (measured 0.8 %), and its RMS and
// largest stress deviations must be at least five times below
// MPM-maxent's (measured 20 and 43 times).

#include <deal.II/base/numbers.h>

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/problems/problem.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  struct Errors
  {
    double stress_rms   = 0;
    double stress_worst = 0;
    /// The largest deviation among the points of the bar's last cell.
    double stress_last_cell = 0;
  };

  Errors
  run(const std::string &prm,
      const std::string &directory,
      const std::string &changes = "")
  {
    auto simulator = make_simulator<1>(
      prm,
      "subsection Output\n set Write particle CSV = false\nend\n" + changes,
      directory);
    const auto   statistics = simulator->run();
    const double T          = simulator->time();
    check(std::abs(T - 0.4) < 1e-12, "the run must end at T = 0.4");

    using Layout            = PropertyLayout<1>;
    double       max_exact  = 0;
    unsigned int n_in_pulse = 0;
    for (const auto &particle : simulator->material_points().particle_handler())
      {
        const Point<1> X(Layout::get_vector(particle.get_properties(),
                                            Layout::initial_position));
        const double   u = simulator->problem().exact_displacement(X, T)[0];
        max_exact        = std::max(max_exact, std::abs(u));
        if (X[0] > 1. - T)
          ++n_in_pulse;
      }
    // The free end's displacement (1 + cos(1.4 pi)) / (100 pi), less a little
    // because the outermost point lies h/8 inside.
    check(max_exact > 2.1e-3 && max_exact < 2.2e-3,
          "largest exact displacement not near (1 + cos(1.4 pi)) / (100 pi)");

    // Energy of the pulse that has entered by T (c = 1, l = 1, E = 100):
    // int_1^(1+T) sin^2(pi s) ds / E.
    const double exact_energy =
      (0.5 * T -
       (std::sin(2. * numbers::PI * (1. + T)) - std::sin(2. * numbers::PI)) /
         (4. * numbers::PI)) /
      100.;
    const double energy = statistics.kinetic_energy + statistics.strain_energy;

    const double relative_displacement =
      statistics.displacement_rms_error / max_exact;
    deallog << prm << (changes.empty() ? "" : ", Amplitude = -1") << std::endl;
    deallog << "material points in the pulse at T: " << n_in_pulse << std::endl;
    deallog << "largest exact displacement at T: " << rounded(max_exact)
            << std::endl;
    deallog << "RMS displacement error: "
            << rounded(statistics.displacement_rms_error, 2) << " ("
            << std::fixed << std::setprecision(2)
            << 100. * relative_displacement << " % of the largest displacement)"
            << std::defaultfloat << std::endl;
    deallog << "RMS stress error: " << rounded(statistics.stress_rms_error, 2)
            << std::endl;
    deallog << "energy: " << rounded(energy, 2)
            << " (put in by the traction: " << rounded(exact_energy, 2) << ")"
            << std::endl;

    check(relative_displacement < 0.005,
          "RMS displacement error above 0.5 % of the largest displacement: " +
            std::to_string(relative_displacement));
    check(statistics.stress_rms_error < 0.05,
          "RMS stress error above 5 % of the traction amplitude: " +
            std::to_string(statistics.stress_rms_error));
    check(std::abs(energy / exact_energy - 1.) < 0.03,
          "energy more than 3 % from the work of the traction: " +
            std::to_string(energy) + " vs " + std::to_string(exact_energy));

    // All prm files put 67 cells on the bar.
    const double h = 1. / 67.;
    Errors       errors;
    errors.stress_rms = statistics.stress_rms_error;
    for (const auto &particle : simulator->material_points().particle_handler())
      {
        const auto     properties = particle.get_properties();
        const Point<1> X(
          Layout::get_vector(properties, Layout::initial_position));
        const double deviation =
          std::abs(Layout::get_stress(properties)[0][0] -
                   simulator->problem().exact_stress(X, T)[0][0]);
        errors.stress_worst = std::max(errors.stress_worst, deviation);
        if (X[0] > 1. - h)
          errors.stress_last_cell =
            std::max(errors.stress_last_cell, deviation);
      }
    deallog << "largest stress deviation: " << rounded(errors.stress_worst, 2)
            << " (in the last cell: " << rounded(errors.stress_last_cell, 2)
            << ")" << std::endl;
    return errors;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const Errors mpm = run("B2-traction-bar-mpm.prm", "output-B2-mpm");
  const Errors otm = run("B2-traction-bar-otm.prm", "output-B2-otm");
  check(otm.stress_rms < mpm.stress_rms,
        "OTM-P1 RMS stress error should be below MPM-P1's");
  check(otm.stress_worst < 0.5 * mpm.stress_worst,
        "OTM-P1 should be free of MPM-P1's grid-crossing stress noise");
  const Errors unified =
    run("B2-traction-bar-unified.prm", "output-B2-unified");
  check(unified.stress_rms < otm.stress_rms &&
          unified.stress_worst < otm.stress_worst,
        "the unified approach should have the lowest stress errors");

  // The pulse with the opposite sign pulls the free end into the grid's
  // empty cells: BSMPM with 81 nodes breaks down there
  // (tests/bad_input, b2_bsmpm_breakdown), the unified approach stays
  // stable and as accurate (Sect. 8.2).
  run("B2-traction-bar-unified.prm",
      "output-B2-unified-pulled",
      "subsection Traction bar\n set Amplitude = -1\nend\n");

  // Max-ent, d_max = 2: MPM-maxent misses the free end, OTM-maxent does not.
  const Errors mpm_maxent =
    run("B2-traction-bar-mpm-maxent.prm", "output-B2-mpm-maxent");
  check(mpm_maxent.stress_last_cell == mpm_maxent.stress_worst,
        "MPM-maxent's largest stress deviation should lie at the free end");
  check(mpm_maxent.stress_last_cell > 0.1,
        "MPM-maxent should miss the exact stress at the free end by more "
        "than 10 % of the amplitude");
  const Errors otm_maxent =
    run("B2-traction-bar-otm-maxent.prm", "output-B2-otm-maxent");
  check(otm_maxent.stress_worst < numbers::PI / (2. * 67.),
        "OTM-maxent stress deviation above the P1 bound pi h / 2");
  check(5. * otm_maxent.stress_rms < mpm_maxent.stress_rms &&
          5. * otm_maxent.stress_worst < mpm_maxent.stress_worst,
        "OTM-maxent should be far more accurate than MPM-maxent");
}
