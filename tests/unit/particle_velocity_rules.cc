// The rules of "Particle velocity" on a free elastic disk that spins as a
// rigid body (radius 1, omega = 1 about its centre, no gravity, no
// boundary condition; USL, lumped mass), with linear functions and with
// quadratic B-splines, 200 steps:
//  - APIC (Jiang et al. 2015): both transfers conserve the angular momentum
//    sum_p m_p (x_p x v_p + B_p,yx - B_p,xy) exactly, and the internal
//    forces of a symmetric stress have no moment, so it must not change by
//    more than 1e-10 of its start from one output (every 10 steps) to the
//    next (round-off);
//  - every rule conserves the linear momentum (1e-12 of the rotation's
//    scale m omega R);
//  - PIC's transfers lose kinetic energy (Jensen's inequality: the velocity
//    at a point is a weighted mean of the nodal velocities, and the nodal
//    velocity of the points'), most at the disk's rim, where the nodes see
//    points on one side only: on these 4 cells per radius the rotation
//    stops within the 200 steps (angular momentum below 1 % of its start),
//    while APIC carries it;
//  - a blend 0.99 FLIP + 0.01 PIC ends with a kinetic energy between PIC's
//    and FLIP's (FLIP's total energy, kinetic and strain, is printed: it
//    loses about 1 % to the points that cross cells at the rim).
// The angular momentum after 200 steps is printed relative to its start
// for FLIP, PIC, blend 0.99 and APIC (doc/benchmarks.md copies them).

#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/materials/material_library.h>

#include <algorithm>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  struct History
  {
    double initial_angular_momentum = 0;
    double final_angular_momentum   = 0;
    double largest_step_change      = 0;
    double largest_momentum         = 0;
    double initial_kinetic_energy   = 0;
    double final_kinetic_energy     = 0;
    double final_total_energy       = 0;
  };

  /**
   * The angular momentum about the origin of the points of @p simulator,
   * with the affine part of APIC if the points carry B_p, and their
   * kinetic energy 1/2 m v^2.
   */
  std::pair<double, double>
  angular_momentum_and_energy(const Simulator<2> &simulator)
  {
    using Layout      = PropertyLayout<2>;
    const auto names  = simulator.material_library().internal_variable_names();
    const auto found  = std::find(names.begin(), names.end(), "apic_B_00");
    const bool affine = (found != names.end());
    const unsigned int first =
      Layout::n_fixed_properties + (found - names.begin());
    double L = 0, energy = 0;
    for (const auto &particle : simulator.material_points().particle_handler())
      {
        const auto         properties = particle.get_properties();
        const double       m          = properties[Layout::mass];
        const Point<2>     x          = particle.get_location();
        const Tensor<1, 2> v = Layout::get_vector(properties, Layout::velocity);
        L += m * (x[0] * v[1] - x[1] * v[0]);
        if (affine)
          L += m * (properties[first + 2] - properties[first + 1]);
        energy += 0.5 * m * v.norm_square();
      }
    return {L, energy};
  }

  History
  spin(const std::string &family,
       const std::string &rule,
       const std::string &scheme = "USL")
  {
    auto    simulator = make_simulator<2>("",
                                       R"(
set Dimension = 2
set Problem = custom
set Update scheme = )" + scheme + R"(
set Particle velocity = )" + rule + R"(
set Bodies = disk
)" + family + R"(
subsection Mesh
  set Lower corner = 0, 0
  set Upper corner = 4, 4
  set Subdivisions = 16, 16
end
subsection Particles
  set Particles per cell = 2
end
subsection Material
  set Model = neo-Hookean
  set Young's modulus = 1e3
  set Poisson's ratio = 0.3
  set Density = 1
end
subsection Body disk
  set Shape = ball
  set Centre = 2, 2
  set Radius = 1
  set Initial velocity = -(y-2); x-2
end
subsection Time
  set End time = 0.2
  set Time step = 1e-3
end
subsection Output
  set Interval = 10
end
)",
                                       "output-particle-velocity");
    History history;
    double  previous                 = 0;
    const auto [L0, E0]              = angular_momentum_and_energy(*simulator);
    history.initial_angular_momentum = L0;
    history.initial_kinetic_energy   = E0;
    previous                         = L0;
    simulator->run([&](const unsigned int, const Statistics<2> &statistics) {
      const auto [L, E] = angular_momentum_and_energy(*simulator);
      check(std::abs(statistics.angular_momentum[2] - L) <
              1e-12 * std::abs(history.initial_angular_momentum),
            "Statistics::angular_momentum " +
              std::to_string(statistics.angular_momentum[2]) +
              " is not the points' " + std::to_string(L));
      history.largest_step_change =
        std::max(history.largest_step_change, std::abs(L - previous));
      history.largest_momentum       = std::max({history.largest_momentum,
                                                 std::abs(statistics.momentum[0]),
                                                 std::abs(statistics.momentum[1])});
      previous                       = L;
      history.final_angular_momentum = L;
      history.final_kinetic_energy   = E;
      history.final_total_energy =
        statistics.kinetic_energy + statistics.strain_energy;
    });
    return history;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (const auto &[family_name, family] :
       std::vector<std::pair<std::string, std::string>>{
         {"linear", "set Shape functions = linear\n"},
         {"quadratic B-splines",
          "set Shape functions = B-spline\nset B-spline degree = 2\n"}})
    {
      std::map<std::string, History> histories;
      for (const std::string rule : {"FLIP", "PIC", "blend", "APIC"})
        {
          const History h = spin(family, rule);
          histories[rule] = h;
          const double L0 = h.initial_angular_momentum;
          // The rotation's momentum scale: total mass pi, speed 1 at r = 1.
          check(h.largest_momentum < 1e-12 * M_PI,
                family_name + ", " + rule + ": linear momentum " +
                  std::to_string(h.largest_momentum));
          // PIC stops the rotation within the 200 steps: what is left is
          // round-off of a decayed state, checked below and not printed.
          if (rule != "PIC")
            deallog
              << family_name << ", " << rule
              << ": angular momentum after 200 steps "
              << rounded(h.final_angular_momentum / L0, 3)
              << " of its start, kinetic energy "
              << rounded(h.final_kinetic_energy / h.initial_kinetic_energy, 3)
              << ", total energy "
              << rounded(h.final_total_energy / h.initial_kinetic_energy, 3)
              << std::endl;
        }
      const History &apic = histories["APIC"];
      check(apic.largest_step_change <
              1e-10 * std::abs(apic.initial_angular_momentum),
            family_name + ", APIC: the angular momentum changed by " +
              std::to_string(apic.largest_step_change /
                             std::abs(apic.initial_angular_momentum)) +
              " of its start in 10 steps (1e-10 allowed)");
      deallog << family_name
              << ", APIC: angular momentum conserved to 1e-10 every 10 steps"
              << std::endl;
      const History &pic = histories["PIC"];
      check(std::abs(pic.final_angular_momentum) <
              0.01 * std::abs(pic.initial_angular_momentum),
            family_name + ": PIC kept " +
              std::to_string(pic.final_angular_momentum /
                             pic.initial_angular_momentum) +
              " of the angular momentum");
      deallog << family_name
              << ", PIC: angular momentum after 200 steps below 0.01 of its "
                 "start"
              << std::endl;
      const History &flip = histories["FLIP"];
      check(pic.final_kinetic_energy < apic.final_kinetic_energy &&
              pic.final_kinetic_energy < 0.99 * pic.initial_kinetic_energy,
            family_name + ": PIC's kinetic energy " +
              std::to_string(pic.final_kinetic_energy) +
              " is not below APIC's " +
              std::to_string(apic.final_kinetic_energy) +
              " and 0.99 of its start");
      const History &blend = histories["blend"];
      check(blend.final_kinetic_energy > pic.final_kinetic_energy &&
              blend.final_kinetic_energy < flip.final_kinetic_energy,
            family_name + ": the blend's kinetic energy " +
              std::to_string(blend.final_kinetic_energy) +
              " is not between PIC's and FLIP's");

      // MUSL: PIC's part comes from the grid's own velocities before the
      // projection, which adds APIC's affine momenta. The points then move
      // with the projected velocities, not with those of their momenta, so
      // APIC's angular momentum changes by O(dt) of the difference: it
      // must stay within 1e-3 of FLIP's change (FLIP loses 1-3 %).
      const History musl_apic = spin(family, "APIC", "MUSL");
      const History musl_pic  = spin(family, "PIC", "MUSL");
      const double  flip_loss = std::abs(
        flip.final_angular_momentum / flip.initial_angular_momentum - 1.);
      const double apic_loss = std::abs(musl_apic.final_angular_momentum /
                                          musl_apic.initial_angular_momentum -
                                        1.);
      check(apic_loss < 1e-3 * flip_loss &&
              musl_apic.largest_momentum < 1e-12 * M_PI &&
              musl_pic.largest_momentum < 1e-12 * M_PI,
            family_name + ", MUSL: APIC changed the angular momentum by " +
              std::to_string(apic_loss) + " (FLIP with USL " +
              std::to_string(flip_loss) + "), or momentum was not conserved");
      check(std::abs(musl_pic.final_angular_momentum) <
              0.05 * std::abs(musl_pic.initial_angular_momentum),
            family_name + ", MUSL: PIC kept " +
              std::to_string(musl_pic.final_angular_momentum /
                             musl_pic.initial_angular_momentum) +
              " of the rotation");
      deallog << family_name
              << ", MUSL: APIC keeps the angular momentum to 1e-3 of FLIP's "
                 "loss, PIC stops the rotation (below 0.05 of its start)"
              << std::endl;
    }
}
