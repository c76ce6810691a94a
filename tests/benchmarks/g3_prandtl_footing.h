// The footing runs of the G3 tests (BENCHMARKS.md G3): the smooth strip
// footing of prm/G3-prandtl-footing.prm (linear functions) or
// prm/G3-prandtl-footing-bspline.prm (quadratic B-splines) on n x 1.2 n
// cells (n / 5 per footing half-width), 2 x 2 points per cell, the footing
// at 0.1 m/s (ramped over 0.1 s, as in the prm files), dt = 0.83 of the CFL
// bound h / c, and the mean load at settlements in (0.03, upper].

#include "../tests.h"

namespace G3
{
  using namespace MpmOtm;
  using namespace MpmOtmTests;

  /// Prandtl's limit load (2 + pi) c B / 2 on the half model (N/m).
  const double prandtl = (2. + numbers::PI) * 10e3 * 0.5;

  /**
   * Mean footing load (N/m) at settlements in (0.03, @p upper] on a grid
   * of @p n x 1.2 n cells, with the functions of @p prm_file and the
   * entry "Volumetric locking remedy" = @p remedy. The footing box holds
   * the row of vertices (linear) or of Greville points (B-splines: the
   * rows half a cell on either side) around the soil surface.
   */
  inline double
  mean_load(const std::string &prm_file,
            const unsigned int n,
            const std::string &remedy,
            const double       upper)
  {
    const double       h       = 2.5 / n;
    const bool         splines = prm_file.find("bspline") != std::string::npos;
    const double       half    = splines ? h : 0.5 * h;
    const double       end     = 0.06 + upper / 0.1;
    const unsigned int steps   = std::ceil(end / (0.83 * h / 86.5));
    std::ostringstream changes;
    changes << std::setprecision(10)
            << "set Volumetric locking remedy = " << remedy
            << "\nsubsection Mesh\n set Subdivisions = " << n << ", "
            << 6 * n / 5 << "\nend\nsubsection Time\n"
            << " set Time step = " << end / steps << "\n set End time = " << end
            << "\nend\nsubsection Boundary footing\n"
            << " set Box lower corner = 0, " << 2.5 - half + 1e-6
            << "\n set Box upper corner = 0.5001, " << 2.5 + half - 1e-6
            << "\nend\nsubsection Output\n set Interval = " << steps / 100
            << "\nend\n";
    auto   simulator = make_simulator<2>(prm_file, changes.str(), "output-G3");
    double sum       = 0;
    unsigned int samples = 0;
    simulator->run(
      [&](const unsigned int step, const Statistics<2> &statistics) {
        // The reaction is the mean over the steps since the last output.
        const double settlement = -statistics.boundary_reactions[0].second[1];
        if (step > 0 && settlement > 0.03 && settlement <= upper + 1e-9)
          {
            sum -= statistics.boundary_reactions[0].first[1];
            ++samples;
          }
      });
    return sum / samples;
  }

  /**
   * Print and return the excess of @p load over Prandtl's (%).
   */
  inline double
  report(const std::string &name, const double load)
  {
    const double excess = 100. * (load / prandtl - 1.);
    deallog << name << ": load " << rounded(load) << " N/m, " << std::fixed
            << std::setprecision(1) << excess << " % from Prandtl's "
            << rounded(prandtl) << std::defaultfloat << std::endl;
    return excess;
  }
} // namespace G3
