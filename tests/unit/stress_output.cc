// The stress and strain fields of the particle output, read back from the
// VTU and the HDF5 files as a ParaView user gets them (manual, "Viewing the
// results in ParaView"): a von Mises block with linear hardening H in
// plane-strain uniaxial-strain compression. The unit square (4 x 4 cells,
// 2 x 2 points per cell) has its sides on rollers and its base fixed; the
// top moves down at 5e-3 / 0.95 m/s (ramped over 0.1 s) to a compression
// of 5e-3 at t = 1 s. E = 1e7, nu = 0.3, rho = 1 (quasi-static: the
// inertia is below 1e-4 of the stress), sigma_y = 1e4, H = 2e6; every point
// has F = diag(1, 1 - u), u the top's displacement (statistics.csv).
// Exact (small strain, K bulk and G shear modulus, eps = -ln(1 - u) the
// compressive logarithmic strain): the elastic sigma_yy = -(K + 4 G / 3) eps
// up to yield at eps_y = sigma_y / (2 G), after it the tangent
// d sigma_yy / d eps = -(K + 4 G H / (3 (3 G + H))), sigma_xx = sigma_zz
// (the 3 x 3 tensor holds sigma_zz in its place), the mean stress
// p = tr(sigma) / 3, the von Mises stress q = |sigma_yy - sigma_xx| =
// sigma_y + H eps_p, the principal stresses sigma_1 = sigma_2 = sigma_xx >=
// sigma_3 = sigma_yy, and the logarithmic strain tensor
// diag(0, ln(1 - u), 0). Asserted at every output after the ramp, in both
// formats, each within 1 % (the strain within 0.5 %: the ramp leaves elastic
// waves of about 1e-6 in strain ringing in the undamped block).

#include <deal.II/base/hdf5.h>
#include <deal.II/base/utilities.h>

#include <array>
#include <map>
#include <zlib.h>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  const double E = 1e7, nu = 0.3, yield = 1e4, H = 2e6;
  const double K = E / (3. * (1. - 2. * nu)), G = E / (2. * (1. + nu));

  /**
   * The fields of one output: name -> values, point after point (a tensor
   * with its 9 components, row by row).
   */
  using Fields = std::map<std::string, std::vector<double>>;

  /**
   * Read the data arrays @p names of a VTU file as deal.II writes it: each
   * array base64-encoded as a zlib-compressed block behind a base64-encoded
   * header of four 32-bit numbers (blocks, block size, last block size,
   * compressed size).
   */
  Fields
  read_vtu(const std::string &file_name, const std::vector<std::string> &names)
  {
    std::ifstream     file(file_name);
    std::stringstream contents;
    contents << file.rdbuf();
    const std::string text = contents.str();
    Fields            fields;
    for (const auto &name : names)
      {
        const std::size_t tag = text.find("Name=\"" + name + "\"");
        check(tag != std::string::npos, file_name + " has no field " + name);
        const std::size_t start = text.find('>', tag) + 1;
        const std::size_t end   = text.find('<', start);
        std::string       data  = text.substr(start, end - start);
        data.erase(std::remove_if(data.begin(), data.end(), ::isspace),
                   data.end());
        // 16 bytes of header are 24 base64 characters.
        const auto    header = Utilities::decode_base64(data.substr(0, 24));
        std::uint32_t sizes[4];
        std::memcpy(sizes, header.data(), sizeof(sizes));
        const auto compressed = Utilities::decode_base64(data.substr(24));
        std::vector<float> values(sizes[1] / sizeof(float));
        uLongf             length = sizes[1];
        check(uncompress(reinterpret_cast<Bytef *>(values.data()),
                         &length,
                         compressed.data(),
                         sizes[3]) == Z_OK,
              "cannot decompress " + name + " of " + file_name);
        fields[name].assign(values.begin(), values.end());
      }
    return fields;
  }

  /**
   * Read the datasets @p names of an HDF5 file of the particle output.
   */
  Fields
  read_hdf5(const std::string &file_name, const std::vector<std::string> &names)
  {
    HDF5::File file(file_name, HDF5::File::FileAccessMode::open, MPI_COMM_SELF);
    Fields     fields;
    for (const auto &name : names)
      fields[name] = file.open_dataset(name).read<std::vector<double>>();
    return fields;
  }

  void
  check_close(const double       value,
              const double       exact,
              const double       scale,
              const double       tolerance,
              const std::string &what)
  {
    std::ostringstream message;
    message << std::setprecision(8) << what << ": " << value << " against "
            << exact;
    check(std::abs(value - exact) <= tolerance * std::abs(scale),
          message.str());
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string parameters      = R"(
set Dimension = 2
set Problem = custom
set Bodies = block
set Boundaries = left, right, base, top
subsection Mesh
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 4, 4
end
subsection Material
  set Model = von Mises
  set Young's modulus = 1e7
  set Poisson's ratio = 0.3
  set Density = 1
  subsection von Mises
    set Yield stress = 1e4
    set Hardening modulus = 2e6
  end
end
subsection Body block
  set Lower corner = 0, 0
  set Upper corner = 1, 1
end
subsection Boundary left
  set Type = slip
  set Boundary ids = 0
end
subsection Boundary right
  set Type = slip
  set Boundary ids = 1
end
subsection Boundary base
  set Type = fixed
  set Boundary ids = 2
end
subsection Boundary top
  set Type = velocity
  set Boundary ids = 3
  set Velocity = 0; -5e-3/0.95*min(t/0.1, 1)
  set Velocity components = y
end
subsection Time
  set End time = 1
  set Time step = auto
end
)";
  const double      elastic_modulus = K + 4. * G / 3.;
  const double      plastic_modulus = K + 4. * G * H / (3. * (3. * G + H));
  const double      yield_strain    = yield / (2. * G);
  for (const std::string format : {"vtu", "hdf5"})
    {
      const std::string directory = "output-stress-" + format;
      auto              simulator = simulator_from_text<2>(
        parameters + "subsection Output\n set Directory = " + directory +
          "\n set Format = " + format +
          "\n set Time interval = 0.05\n set Overwrite = true\nend\n",
        MPI_COMM_WORLD,
        false);
      // Time, step and the top's displacement (its prescribed motion, as
      // the time steps integrated it) at every output.
      std::vector<std::array<double, 3>> steps;
      simulator->run(
        [&](const unsigned int step, const Statistics<2> &statistics) {
          steps.push_back({{simulator->time(),
                            double(step),
                            -statistics.boundary_reactions[3].second[1]}});
        });

      const bool vtu = format == "vtu";
      const auto tensor_names =
        vtu ? std::vector<std::string>{"stress", "log_strain"} :
              std::vector<std::string>{"stress_xx",
                                       "stress_yy",
                                       "stress_zz",
                                       "stress_xy",
                                       "log_strain_xx",
                                       "log_strain_yy",
                                       "log_strain_zz",
                                       "log_strain_xy"};
      std::vector<std::string> names = {"mean_stress",
                                        "von_mises_stress",
                                        "principal_stress_1",
                                        "principal_stress_2",
                                        "principal_stress_3",
                                        "plastic_strain"};
      names.insert(names.end(), tensor_names.begin(), tensor_names.end());
      double       previous_strain = 0, previous_stress = 0;
      unsigned int n_elastic = 0, n_plastic = 0;
      double       worst_elastic = 0, worst_tangent = 0;
      for (const auto &[time, step, u] : steps)
        {
          const std::string base =
            directory + "/particles_" +
            Utilities::int_to_string(static_cast<unsigned int>(step), 5);
          const Fields fields    = vtu ? read_vtu(base + ".0.vtu", names) :
                                         read_hdf5(base + ".h5", names);
          const auto   component = [&](const std::string &name,
                                     const unsigned int i,
                                     const unsigned int j,
                                     const unsigned int p) {
            return vtu ? fields.at(name)[9 * p + 3 * i + j] :
                           fields.at(name + "_" + "xyz"[std::min(i, j)] +
                                   "xyz"[std::max(i, j)])[p];
          };
          const double strain = -std::log(1. - u);
          if (time < 0.1 + 1e-9)
            continue;
          const unsigned int n_points = fields.at("mean_stress").size();
          double             sigma_yy = 0;
          for (unsigned int p = 0; p < n_points; ++p)
            {
              const double xx      = component("stress", 0, 0, p),
                           yy      = component("stress", 1, 1, p),
                           zz      = component("stress", 2, 2, p),
                           xy      = component("stress", 0, 1, p);
              const std::string at = format + ", t = " + std::to_string(time);
              check_close(zz, xx, yy, 0.01, at + ": sigma_zz against sigma_xx");
              check_close(xy, 0, yy, 1e-4, at + ": sigma_xy");
              check_close(fields.at("mean_stress")[p],
                          (xx + yy + zz) / 3.,
                          yy,
                          1e-5,
                          at + ": mean stress");
              check_close(fields.at("von_mises_stress")[p],
                          std::abs(yy - xx),
                          yy,
                          0.01,
                          at + ": von Mises stress");
              check_close(fields.at("principal_stress_1")[p],
                          xx,
                          yy,
                          0.01,
                          at + ": sigma_1");
              check_close(fields.at("principal_stress_2")[p],
                          xx,
                          yy,
                          0.01,
                          at + ": sigma_2");
              check_close(fields.at("principal_stress_3")[p],
                          yy,
                          yy,
                          1e-5,
                          at + ": sigma_3");
              check_close(component("log_strain", 1, 1, p),
                          -strain,
                          strain,
                          5e-3,
                          at + ": log strain yy");
              check_close(component("log_strain", 0, 0, p),
                          0,
                          strain,
                          5e-3,
                          at + ": log strain xx");
              check_close(component("log_strain", 2, 2, p),
                          0,
                          strain,
                          5e-3,
                          at + ": log strain zz");
              const double plastic = fields.at("plastic_strain")[p];
              if (plastic > 0)
                check_close(fields.at("von_mises_stress")[p],
                            yield + H * plastic,
                            yield,
                            0.01,
                            at + ": q against sigma_y + H eps_p");
              sigma_yy += yy / n_points;
            }
          if (strain < 0.9 * yield_strain)
            {
              worst_elastic =
                std::max(worst_elastic,
                         std::abs(sigma_yy / (-elastic_modulus * strain) - 1.));
              ++n_elastic;
            }
          if (previous_strain > 1.2 * yield_strain)
            {
              const double tangent =
                (sigma_yy - previous_stress) / (strain - previous_strain);
              worst_tangent =
                std::max(worst_tangent,
                         std::abs(-tangent / plastic_modulus - 1.));
              ++n_plastic;
            }
          previous_strain = strain;
          previous_stress = sigma_yy;
        }
      check(n_elastic >= 2 && n_plastic >= 5, "too few outputs on a branch");
      check(worst_elastic < 0.01,
            format + ": sigma_yy is not (K + 4 G / 3) eps within 1 %");
      check(worst_tangent < 0.01,
            format + ": the tangent after yield is not within 1 %");
      deallog << format << ": " << n_elastic << " elastic outputs, sigma_yy "
              << "within " << std::fixed << std::setprecision(3)
              << 100. * worst_elastic << " % of (K + 4 G / 3) eps; "
              << n_plastic << " plastic, tangent within "
              << 100. * worst_tangent
              << " % of K + 4 G H / (3 (3 G + H)); sigma_xx = sigma_zz, p, q, "
              << "principal stresses and log strain as exact"
              << std::defaultfloat << std::endl;
    }
}
