// The F-bar remedy (FBar) against averages computed by hand, on the unit
// square with 2 x 2 cells and 2 x 2 points per cell (V^0 = 1/16 each,
// F = I at the start), two bodies: "soil" x < 0.7 and "block" x > 0.7, so
// that the right cells hold points of two materials. Each point gets a
// velocity gradient with its own volume change and shear; dt = 0.1; after
// the stress update each point has a stress of its own.
//  - every point's new J = det(I + dt Lbar) equals the
//    mean of the trial J of its cell's points of its material (equal
//    weights), the isochoric part (I + dt L) / J^(1/2) is unchanged, and so
//    each cell keeps the volume of each material; after the stress update
//    every point's mean stress tr(sigma) / 3 (with sigma_zz) is the linear
//    least-squares fit of its group's, and its deviator is unchanged.
//  - a point that has lost contact (Drucker-Prager's separation open)
//    keeps its own J, and the other points of its cell average without it;
//  - with one point per cell F-bar changes nothing.

#include <mpm_otm/algorithms/f_bar.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <map>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  const double dt = 0.1;

  std::string
  parameters(const unsigned int points_per_cell)
  {
    return R"(
set Dimension = 2
set Problem = custom
set Materials = block
set Bodies = soil, block
subsection Material
  set Model = Drucker-Prager
end
subsection Mesh
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 2, 2
end
subsection Particles
  set Particles per cell = )" +
           std::to_string(points_per_cell) + R"(
end
subsection Material block
  set Young's modulus = 1
end
subsection Body soil
  set Shape = box
  set Lower corner = 0, 0
  set Upper corner = 0.7, 1
end
subsection Body block
  set Shape = box
  set Lower corner = 0.7, 0
  set Upper corner = 1, 1
  set Material = block
end
subsection Time
  set Time step = 1e-6
end
)";
  }

  /// A velocity gradient with a volume change and a shear that vary from
  /// point to point.
  Tensor<2, 2>
  gradient_at(const Point<2> &x)
  {
    Tensor<2, 2> L;
    const double volume = 0.5 * x[0] - 0.8 * x[1] * x[1];
    L[0][0]             = volume + 0.3 * x[1];
    L[1][1]             = volume - 0.3 * x[1];
    L[0][1]             = 0.7 * x[0];
    L[1][0]             = -0.2;
    return L;
  }

  Tensor<2, 2>
  increment(const Tensor<2, 2> &L)
  {
    return unit_symmetric_tensor<2>() + dt * L;
  }

  /// The isochoric part of the increment I + dt L.
  Tensor<2, 2>
  isochoric(const Tensor<2, 2> &L)
  {
    return increment(L) / std::sqrt(determinant(increment(L)));
  }

  struct Run
  {
    std::unique_ptr<Simulator<2>> simulator;
    ParticleShapeData<2>          data;
    std::vector<Tensor<2, 2>>     original;
    std::vector<Tensor<2, 2>>     corrected;
    std::vector<Point<2>>         locations;
    std::vector<unsigned int>     materials;
    /// The three-dimensional stresses given to the points, and what
    /// FBar::after_stress_update() made of them.
    std::vector<SymmetricTensor<2, 3>> stress_before, stress_after;
  };

  SymmetricTensor<2, 3>
  stress_3d(const ArrayView<const double> &properties)
  {
    using Layout                      = PropertyLayout<2>;
    const SymmetricTensor<2, 2> sigma = Layout::get_stress(properties);
    SymmetricTensor<2, 3>       result;
    result[0][0] = sigma[0][0];
    result[1][1] = sigma[1][1];
    result[0][1] = sigma[0][1];
    result[2][2] = Layout::get_out_of_plane_stress(properties);
    return result;
  }

  Run
  correct(const unsigned int points_per_cell, const bool disconnect = false)
  {
    Run run;
    run.simulator =
      simulator_from_text<2>(parameters(points_per_cell) +
                               "subsection Output\n set Directory = "
                               "output-f-bar\n set Format = none\n set "
                               "Overwrite = true\nend\n",
                             MPI_COMM_WORLD,
                             false);
    const auto &points = run.simulator->material_points();
    run.simulator->shape_function_family()
      .evaluate(points, run.simulator->nodal_system().partitioner(), run.data);
    for (const auto &particle : points.particle_handler())
      {
        run.locations.push_back(particle.get_location());
        run.original.push_back(gradient_at(particle.get_location()));
        run.materials.push_back(
          PropertyLayout<2>::get_material_id(particle.get_properties()));
      }
    // With @p disconnect, the soil point nearest the origin has lost
    // contact: its separation (Drucker-Prager's last internal variable) is
    // open.
    if (disconnect)
      for (auto &particle :
           const_cast<MaterialPoints<2> &>(points).particle_handler())
        if (particle.get_location().distance(Point<2>(0.125, 0.125)) < 1e-12)
          {
            const auto &library = run.simulator->material_library();
            particle.get_properties()[library.first_internal_variable(0) +
                                      library.n_internal_variables(0) - 1] =
              1e-3;
          }
    ParameterHandler prm;
    FBar<2>          f_bar;
    f_bar.parse_parameters(prm);
    f_bar.initialize(run.simulator->shape_function_family(),
                     run.simulator->nodal_system(),
                     run.simulator->material_library());
    run.corrected = run.original;
    f_bar.correct(const_cast<MaterialPoints<2> &>(points),
                  run.data,
                  dt,
                  run.corrected);

    // Stresses with a mean and a deviator that vary from point to point
    // (written into the points as the models would).
    using Layout         = PropertyLayout<2>;
    auto &mutable_points = const_cast<MaterialPoints<2> &>(points);
    for (auto &particle : mutable_points.particle_handler())
      {
        const Point<2>        x          = particle.get_location();
        const auto            properties = particle.get_properties();
        SymmetricTensor<2, 2> sigma;
        sigma[0][0] = -1e3 * (1. + x[0]) + 40. * x[1];
        sigma[1][1] = -2e3 * (1. + x[1] * x[0]);
        sigma[0][1] = 300. * x[0] - 70.;
        Layout::set_stress(properties, sigma);
        properties[Layout::out_of_plane_stress] = -500. * (2. - x[1]);
        run.stress_before.push_back(stress_3d(properties));
      }
    f_bar.after_stress_update(mutable_points);
    for (const auto &particle : points.particle_handler())
      run.stress_after.push_back(stress_3d(particle.get_properties()));
    return run;
  }

  double
  largest_isochoric_change(const Run &run)
  {
    double change = 0;
    for (unsigned int p = 0; p < run.original.size(); ++p)
      change = std::max(
        change,
        (isochoric(run.corrected[p]) - isochoric(run.original[p])).norm());
    return change;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  {
    const Run run = correct(2);
    // The mean trial J of each cell and material, by hand.
    std::map<std::pair<unsigned int, unsigned int>, std::pair<double, int>>
               sums;
    const auto group = [](const Point<2> &x, const unsigned int material) {
      return std::make_pair(static_cast<unsigned int>(x[0] / 0.5) +
                              2 * static_cast<unsigned int>(x[1] / 0.5) +
                              4 * material,
                            0u);
    };
    for (unsigned int p = 0; p < run.original.size(); ++p)
      {
        auto &sum = sums[group(run.locations[p], run.materials[p])];
        sum.first += determinant(increment(run.original[p]));
        ++sum.second;
      }
    double       error = 0, spread = 0;
    unsigned int mixed = 0;
    for (unsigned int p = 0; p < run.original.size(); ++p)
      {
        const auto  &sum  = sums[group(run.locations[p], run.materials[p])];
        const double mean = sum.first / sum.second;
        error =
          std::max(error,
                   std::abs(determinant(increment(run.corrected[p])) - mean));
        spread =
          std::max(spread,
                   std::abs(determinant(increment(run.original[p])) - mean));
      }
    for (const auto &sum : sums)
      mixed += (sum.first.first % 4 == 1 || sum.first.first % 4 == 3);
    deallog << run.original.size() << " points in " << sums.size()
            << " groups of a cell and a material (" << mixed
            << " in the two cells that hold both materials); largest "
            << "difference of the trial J from its group's mean "
            << rounded(spread) << std::endl;
    check(sums.size() == 6, "the grid has not 6 groups");
    check(spread > 1e-3, "the trial J do not differ");
    check(error < 1e-14, "a point's J is not its group's mean");
    check(largest_isochoric_change(run) < 1e-14, "the isochoric part changed");

    // The linear fit of the mean stresses of each group, by hand (equal
    // volumes): four points at (x_c +- h / 4, y_c +- h / 4) keep their
    // mean and gradient and lose their checkerboard part
    // c s_p, s_p = sign(x_p - x_c) sign(y_p - y_c), c = sum_q s_q p_q / 4;
    // the two points of a material in a mixed cell lie on a vertical line
    // and take their mean.
    std::map<std::pair<unsigned int, unsigned int>, std::vector<unsigned int>>
      members;
    for (unsigned int p = 0; p < run.original.size(); ++p)
      members[group(run.locations[p], run.materials[p])].push_back(p);
    const auto pressure = [](const SymmetricTensor<2, 3> &sigma) {
      return trace(sigma) / 3.;
    };
    double mean_error = 0, deviator_change = 0, mean_spread = 0;
    for (const auto &[key, points] : members)
      {
        Point<2> centre;
        double   mean = 0, checkerboard = 0;
        for (const auto p : points)
          {
            centre += run.locations[p] / double(points.size());
            mean += pressure(run.stress_before[p]) / double(points.size());
          }
        const auto sign = [&](const unsigned int p) {
          return (run.locations[p][0] > centre[0] ? 1. : -1.) *
                 (run.locations[p][1] > centre[1] ? 1. : -1.);
        };
        if (points.size() == 4)
          for (const auto p : points)
            checkerboard += sign(p) * pressure(run.stress_before[p]) / 4.;
        for (const auto p : points)
          {
            const double exact =
              points.size() == 4 ?
                pressure(run.stress_before[p]) - checkerboard * sign(p) :
                mean;
            mean_error =
              std::max(mean_error,
                       std::abs(pressure(run.stress_after[p]) - exact));
            mean_spread =
              std::max(mean_spread,
                       std::abs(pressure(run.stress_before[p]) - exact));
            deviator_change = std::max(deviator_change,
                                       (deviator(run.stress_after[p]) -
                                        deviator(run.stress_before[p]))
                                         .norm());
          }
      }
    check(mean_spread > 10., "the fit does not change the mean stresses");
    check(mean_error < 1e-9,
          "a point's mean stress is not its group's linear fit");
    check(deviator_change < 1e-10, "a deviator changed");
    deallog << "J equals its group's mean and the isochoric part is "
               "kept, to 1e-14; after the stress update each point's mean "
               "stress is its group's linear fit (it changed by up to "
            << rounded(mean_spread) << " Pa) and its deviator is kept"
            << std::endl;
  }

  {
    // A point that has lost contact keeps its J; the other three of its
    // cell take their own mean.
    const Run    run = correct(2, true);
    double       own = 1, error = 0, mean = 0;
    unsigned int n = 0;
    for (unsigned int p = 0; p < run.original.size(); ++p)
      if (run.locations[p][0] < 0.5 && run.locations[p][1] < 0.5 &&
          run.locations[p].distance(Point<2>(0.125, 0.125)) > 1e-12)
        {
          mean += determinant(increment(run.original[p]));
          ++n;
        }
    mean /= n;
    for (unsigned int p = 0; p < run.original.size(); ++p)
      if (run.locations[p].distance(Point<2>(0.125, 0.125)) < 1e-12)
        own = (run.corrected[p] - run.original[p]).norm();
      else if (run.locations[p][0] < 0.5 && run.locations[p][1] < 0.5)
        error =
          std::max(error,
                   std::abs(determinant(increment(run.corrected[p])) - mean));
    check(n == 3 && own == 0., "a point that lost contact was averaged");
    check(error < 1e-14, "the points in contact do not take their mean");
    deallog << "a point that has lost contact keeps its J; the other three "
               "of its cell take their mean"
            << std::endl;
  }

  {
    const Run run    = correct(1);
    double    change = 0;
    for (unsigned int p = 0; p < run.original.size(); ++p)
      change = std::max(change, (run.corrected[p] - run.original[p]).norm());
    check(change == 0., "one point per cell: the velocity gradient changed");
    deallog << "one point per cell: F-bar changes nothing" << std::endl;
  }
}
