// The particle-velocity rules on two MPI ranks: the spinning disk of
// prm/spinning-disk.prm (100 steps, 8 x 8 cells on the square [0, 4]^2, so
// the disk spans both ranks' cells) with PIC, blend and APIC (USL) and APIC
// with MUSL, linear
// functions and quadratic B-splines, once on MPI_COMM_WORLD and once on
// rank 0 alone. The energies and the angular momentum (statistics.csv's,
// summed over the ranks, with APIC's affine part) agree to round-off, and
// APIC with USL conserves the angular momentum to 1e-10 of its start on two
// ranks as on one (its points of the functions x_i of the ghost functions come
// from the ghost cells, or the Greville points of the relevant B-splines).

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  Statistics<2>
  spin(const std::string &family,
       const std::string &scheme,
       const std::string &rule,
       const std::string &directory,
       const MPI_Comm     communicator,
       double            &initial_angular_momentum)
  {
    auto simulator =
      make_simulator<2>("spinning-disk.prm",
                        family + "set Particle velocity = " + rule + R"(
subsection Mesh
  set Subdivisions = 8, 8
end
subsection Time
  set End time = 0.1
end
subsection Output
  set Interval = 0
end
)",
                        directory,
                        communicator);
    return simulator->run(
      [&](const unsigned int step, const Statistics<2> &statistics) {
        if (step == 0)
          initial_angular_momentum = statistics.angular_momentum[2];
      });
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const MPI_Comm world = MPI_COMM_WORLD;
  for (const auto &[family_name, family] :
       std::vector<std::pair<std::string, std::string>>{
         {"linear", "set Shape functions = linear\n"},
         {"quadratic B-splines",
          "set Shape functions = B-spline\nset B-spline degree = 2\n"}})
    for (const auto &[scheme, rule] :
         std::vector<std::pair<std::string, std::string>>{{"USL", "PIC"},
                                                          {"USL", "blend"},
                                                          {"USL", "APIC"},
                                                          {"MUSL", "APIC"}})
      {
        const std::string label = family_name + ", " + scheme + " " + rule;
        double            L0    = 0;
        const auto        parallel =
          spin(family, scheme, rule, "output-parallel", world, L0);
        double serial_values[3] = {0, 0, 0};
        if (Utilities::MPI::this_mpi_process(world) == 0)
          {
            double     serial_L0 = 0;
            const auto serial    = spin(family,
                                     scheme,
                                     rule,
                                     "output-serial",
                                     MPI_COMM_SELF,
                                     serial_L0);
            serial_values[0]     = serial.kinetic_energy;
            serial_values[1]     = serial.strain_energy;
            serial_values[2]     = serial.angular_momentum[2];
          }
        const double parallel_values[3] = {parallel.kinetic_energy,
                                           parallel.strain_energy,
                                           parallel.angular_momentum[2]};
        for (unsigned int i = 0; i < 3; ++i)
          {
            const double serial =
              Utilities::MPI::broadcast(world, serial_values[i], 0);
            check(std::abs(parallel_values[i] - serial) <=
                    1e-10 * std::abs(serial),
                  label + ": 2 ranks differ from 1 rank in " +
                    std::vector<std::string>{"the kinetic energy",
                                             "the strain energy",
                                             "the angular momentum"}[i] +
                    ", relative difference " +
                    Utilities::to_string(std::abs(parallel_values[i] - serial) /
                                         std::abs(serial)));
          }
        const double drift = parallel.angular_momentum[2] / L0 - 1.;
        const bool   exact = (scheme == "USL" && rule == "APIC");
        if (exact)
          check(std::abs(drift) < 1e-10,
                label + ": the angular momentum changed by " +
                  std::to_string(drift) + " of its start on 2 ranks");
        deallog << label << ": 1 and 2 ranks agree; angular momentum after "
                << "100 steps ";
        if (exact)
          deallog << "conserved to 1e-10" << std::endl;
        else if (rule == "APIC")
          {
            // MUSL moves the points with the projected velocities: O(dt)
            // of their difference, 5e-14 here.
            check(std::abs(drift) < 1e-8,
                  label + ": the angular momentum changed by " +
                    std::to_string(drift));
            deallog << "changed by less than 1e-8" << std::endl;
          }
        else
          deallog << "changed by " << rounded(drift, 2) << " of its start"
                  << std::endl;
      }
}
