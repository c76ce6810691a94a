// The energy balance that stops unstable runs (manual, "Instability").
//
// 1. Free fall: an elastic block 0.2 x 0.2 (rho = 1000, so M = 40 per unit
//    thickness) falls from rest under g = 10 for 0.1 s with no boundary
//    condition. Its kinetic energy is M (g t)^2 / 2 = 20 and its strain
//    energy zero; the work gravity did, sum_n dt M g v_n + dt^2 M g^2 / 2,
//    is the same 20 exactly. With Energy growth limit = 1e-9 the run must
//    finish, and the supplied work must equal the kinetic energy to 1e-9.
// 2. A platen (a box of grid nodes with a prescribed velocity of 1e-3
//    downwards) compresses a block on a fixed floor slowly. The work it
//    does must equal the kinetic plus strain energy of the block within
//    5 %, and the run must finish with the default limit.
// 3. The cantilever of G1 (coarse grid) with Update scheme = USL at 0.998
//    of its stable time step at the start (4.928e-5 s) gains energy no load
//    supplied as it deforms and blows up; the check must stop it, naming
//    the energy growth, the step and MUSL, before any value becomes
//    non-finite. With MUSL the same run must finish.

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  const std::string block_on_grid =
    "set Dimension = 2\n"
    "set Problem = custom\n"
    "set Method = MPM\n"
    "set Update scheme = MUSL\n"
    "set Mass matrix = lumped\n"
    "set Shape functions = linear\n"
    "set Bodies = block\n"
    "subsection Particles\n set Particles per cell = 2\nend\n"
    "subsection Mesh\n set Lower corner = 0, 0\n"
    " set Upper corner = 1, 1\n set Subdivisions = 20, 20\nend\n"
    "subsection Material\n set Model = hypo-elastic\n"
    " set Young's modulus = 1e6\n set Poisson's ratio = 0.3\n"
    " set Density = 1000\nend\n"
    "subsection Output\n set Interval = 100000\n"
    " set Write particle CSV = false\nend\n";
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  {
    auto simulator = make_simulator<2>(
      "",
      block_on_grid +
        "subsection Time\n set End time = 0.1\n set Time step = 1e-3\n"
        " set Energy growth limit = 1e-9\nend\n"
        "subsection Body block\n set Shape = box\n"
        " set Lower corner = 0.4, 0.6\n set Upper corner = 0.6, 0.8\nend\n"
        "subsection Gravity\n set Vector = 0, -10\nend\n",
      "output-energy_monitor");
    const auto   statistics = simulator->run();
    const double exact      = 0.5 * 40. * 1. * 1.;
    deallog << "free fall: kinetic energy "
            << rounded(statistics.kinetic_energy, 9) << ", supplied work "
            << rounded(statistics.supplied_work, 9) << " (exact " << exact
            << ")" << std::endl;
    check(std::abs(statistics.kinetic_energy - exact) < 1e-9 * exact,
          "the kinetic energy of free fall is not M (g t)^2 / 2");
    check(std::abs(statistics.supplied_work - exact) < 1e-9 * exact,
          "the work of gravity in free fall is not M (g t)^2 / 2");
  }

  {
    auto simulator = make_simulator<2>(
      "",
      block_on_grid +
        "set Boundaries = floor, platen\n"
        "subsection Time\n set End time = 0.2\n set Time step = auto\nend\n"
        "subsection Body block\n set Shape = box\n"
        " set Lower corner = 0.4, 0\n set Upper corner = 0.6, 0.2\nend\n"
        "subsection Boundary floor\n set Type = fixed\n"
        " set Boundary ids = 2\nend\n"
        "subsection Boundary platen\n set Type = velocity\n"
        " set Box lower corner = 0.39, 0.19\n"
        " set Box upper corner = 0.61, 0.21\n"
        " set Velocity = 0; -1e-2*min(t/0.05, 1)\n"
        " set Velocity components = y\nend\n",
      "output-energy_monitor");
    const auto   statistics = simulator->run();
    const double energy = statistics.kinetic_energy + statistics.strain_energy;
    deallog << "platen: energy " << rounded(energy, 2) << ", supplied work "
            << rounded(statistics.supplied_work, 2) << std::endl;
    check(std::abs(statistics.supplied_work - energy) < 0.02 * energy,
          "the work of the platen is not the energy of the block");
  }

  // The step in which a run stops (0 if it runs to its end), and why.
  const auto stop = [](Simulator<2> &simulator) {
    try
      {
        simulator.run();
      }
    catch (const std::exception &error)
      {
        const std::string message = error.what();
        const auto        where   = message.find("Stopped in time step ");
        check(where != std::string::npos, "no step in: " + message);
        return std::make_pair(static_cast<unsigned int>(
                                std::stoul(message.substr(where + 21))),
                              message);
      }
    return std::make_pair(0u, std::string());
  };
  const std::string coarse_cantilever =
    "subsection Mesh\n set Subdivisions = 48, 16\nend\n"
    "subsection Time\n set End time = 0.05\n set Time step = 4.92e-5\nend\n";
  auto usl = make_simulator<2>("G1-cantilever-vibration.prm",
                               coarse_cantilever + "set Update scheme = USL\n",
                               "output-energy_monitor");
  const auto [energy_stop, message] = stop(*usl);
  auto unchecked =
    make_simulator<2>("G1-cantilever-vibration.prm",
                      coarse_cantilever + "set Update scheme = USL\n"
                                          "subsection Time\n"
                                          " set Energy growth limit = 1e12\n"
                                          "end\n",
                      "output-energy_monitor");
  const unsigned int non_finite_stop = stop(*unchecked).first;
  deallog << "G1 with USL: stopped for its energy in step " << energy_stop
          << "; unchecked, a value is non-finite in step " << non_finite_stop
          << std::endl;
  check(energy_stop > 0 &&
          message.find("is above (1 + Time/Energy growth limit = 0.25)") !=
            std::string::npos &&
          message.find("Update scheme = MUSL") != std::string::npos,
        "USL on the cantilever was not stopped for its energy: " + message);
  check(non_finite_stop > energy_stop,
        "the energy check did not stop the run before a value was "
        "non-finite");
  auto musl = make_simulator<2>("G1-cantilever-vibration.prm",
                                coarse_cantilever,
                                "output-energy_monitor");
  check(stop(*musl).first == 0, "G1 with MUSL did not run to its end");
  deallog << "G1 with MUSL: runs to its end" << std::endl;
}
