// The runs of the biaxial tests (prm/biaxial-softening.prm): a 1 m x 2 m
// Mohr-Coulomb specimen (phi = 30 deg, psi = 0, c = 20 kPa) without
// confinement, compressed by a smooth platen at 0.005 m/s, whose strength
// softens to phi_r = 5 deg, c_r = 5 kPa between the equivalent plastic
// strains 0.01 and 0.05; the exact strengths and the measurements of the
// load and of the shear band.

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/materials/material_library.h>

#include "../tests.h"

namespace Biaxial
{
  using namespace MpmOtm;
  using namespace MpmOtmTests;

  const double phi = numbers::PI / 6., c = 20e3;
  const double phi_r = 5. * numbers::PI / 180., c_r = 5e3;
  /// 2 c cos(phi) / (1 - sin(phi)) on the 1 m wide specimen (N/m).
  const double peak = 2. * c * std::cos(phi) / (1. - std::sin(phi));
  /// The least load that slides a block along a band at the residual
  /// strength, at Coulomb's angle 45 + phi_r / 2 (N/m).
  const double residual = 2. * c_r * std::cos(phi_r) / (1. - std::sin(phi_r));

  /**
   * The load that slides a block along a band at @p angle (radians) to the
   * horizontal with the residual strength, per unit of the band's
   * horizontal length: c_r / (sin cos - cos^2 tan(phi_r)) (Pa).
   */
  inline double
  sliding_stress(const double angle)
  {
    return c_r / (std::sin(angle) * std::cos(angle) -
                  std::pow(std::cos(angle), 2) * std::tan(phi_r));
  }

  struct Result
  {
    /// The largest platen load (N/m; each the mean over 0.05 s).
    double peak_load = 0;
    /// The mean platen load at platen displacements in the window.
    double late_load = 0;
    /// The band: its points and its angle to the horizontal (degrees).
    unsigned int band_points = 0;
    double       band_angle  = 0;
    /// The band's extent: its leftmost and rightmost initial x (m).
    double band_left  = 1;
    double band_right = 0;
    /// The horizontal slip of the specimen's top over its bottom at the end
    /// (m), by which the band's contact has shortened.
    double slip = 0;
  };

  /**
   * Run the specimen on @p nx x @p ny cells of the prm file's grid (1.6 m x
   * 2.2 m) to the time @p end, with the entries @p settings (shape
   * functions, regularisation) and the platen's box reaching
   * @p platen_cells cells above and below the specimen's top; the late load
   * is the mean at platen displacements above @p window_start. The band is made
   * of the points whose plastic strain has passed the end of softening, between
   * 0.1 m above the base and 0.1 m below the platen, its angle that of their
   * least-squares line (initial positions).
   */
  inline Result
  run(const unsigned int nx,
      const unsigned int ny,
      const double       end,
      const double       window_start,
      const std::string &settings,
      const double       platen_cells)
  {
    // The platen: the functions whose nodes (or control points) lie within
    // platen_cells cells of the specimen's top (the grid reaches 0.2 m
    // above it).
    const double       h = 2.2 / ny;
    std::ostringstream changes;
    changes << settings << "\nsubsection Mesh\n set Subdivisions = " << nx
            << ", " << ny
            << "\nend\nsubsection Boundary platen\n set Box lower corner = "
            << "-0.3, " << 2. - platen_cells * h
            << "\n set Box upper corner = 1.3, " << 2. + platen_cells * h
            << "\nend\nsubsection Time\n set End time = " << end
            << "\nend\nsubsection Output\n set Time interval = 0.05\nend\n";
    auto         simulator = make_simulator<2>("biaxial-softening.prm",
                                       changes.str(),
                                       "output-biaxial");
    Result       result;
    unsigned int samples = 0;
    simulator->run(
      [&](const unsigned int step, const Statistics<2> &statistics) {
        if (step == 0)
          return;
        const double load = -statistics.boundary_reactions[0].first[1];
        result.peak_load  = std::max(result.peak_load, load);
        if (-statistics.boundary_reactions[0].second[1] > window_start)
          {
            result.late_load += load;
            ++samples;
          }
      });
    result.late_load /= samples;

    const auto  &library = simulator->material_library();
    double       sx = 0, sy = 0, sxx = 0, sxy = 0, top = 0, bottom = 0;
    unsigned int n_top = 0, n_bottom = 0;
    for (const auto &particle : simulator->material_points().particle_handler())
      {
        const auto     properties = particle.get_properties();
        const Point<2> X(
          PropertyLayout<2>::get_vector(properties,
                                        PropertyLayout<2>::initial_position));
        const double displacement = particle.get_location()[0] - X[0];
        if (X[1] > 1.9)
          {
            top += displacement;
            ++n_top;
          }
        if (X[1] < 0.1)
          {
            bottom += displacement;
            ++n_bottom;
          }
        const double plastic_strain =
          properties[library.first_internal_variable(
            PropertyLayout<2>::get_material_id(properties))];
        if (plastic_strain > 0.05 && X[1] > 0.1 && X[1] < 1.9)
          {
            ++result.band_points;
            result.band_left  = std::min(result.band_left, X[0]);
            result.band_right = std::max(result.band_right, X[0]);
            sx += X[0];
            sy += X[1];
            sxx += X[0] * X[0];
            sxy += X[0] * X[1];
          }
      }
    const double n     = result.band_points;
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    result.band_angle  = std::atan(std::abs(slope)) * 180. / numbers::PI;
    result.slip        = std::abs(top / n_top - bottom / n_bottom);

    deallog << std::fixed << std::setprecision(2) << "peak load "
            << result.peak_load / 1e3 << " kN/m (exact " << peak / 1e3 << ", "
            << 100. * (result.peak_load / peak - 1.) << " %)" << std::endl;
    deallog << "mean load at platen displacements above "
            << std::setprecision(3) << window_start
            << " m: " << std::setprecision(2) << result.late_load / 1e3
            << " kN/m (residual strength " << residual / 1e3 << " kN/m, "
            << 100. * (result.late_load / residual - 1.) << " %)" << std::endl;
    deallog << "shear band of " << result.band_points
            << " points from x = " << result.band_left << " to "
            << result.band_right << " m at " << std::setprecision(1)
            << result.band_angle
            << " deg (Roscoe 45, Coulomb 60); a block sliding on it with the "
            << "contact shortened by the slip " << std::setprecision(3)
            << result.slip << " m: " << std::setprecision(2)
            << sliding_stress(result.band_angle * numbers::PI / 180.) *
                 (1. - result.slip) / 1e3
            << " kN/m" << std::endl;
    return result;
  }
} // namespace Biaxial
