// The data of doc/figures/max-ent-functions-1d.png, the counterpart of
// journal Fig. 4: the cubic-spline priors w_i of Eq. 89 and the local
// max-ent shape functions phi_i of Eqs. 80-83 on n uniform nodes of [0, 1]
// (default 11; the caption gives only d_max = 2, not the nodes) with their
// derivatives, evaluated by the project's MaxEnt<1> class - the functions
// the simulations use, gradients at the end nodes included.
//
// Usage: max-ent-functions-1d [nodes [d_max [samples]]]
// Prints one row per sample point x in [0, 1]: x, then w_i, dw_i/dx,
// phi_i and dphi_i/dx for i = 0 ... n - 1 (4 n + 1 columns).

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/shape_functions/max_ent.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;

  /**
   * Print the priors, the max-ent functions and their derivatives on
   * @p n_nodes uniform nodes of [0, 1] with support factor @p d_max at
   * @p n_samples + 1 equally spaced points.
   */
  void
  print_functions(const unsigned int n_nodes,
                  const double       d_max,
                  const unsigned int n_samples)
  {
    // The nodes are the vertices of a 1D grid, as in the simulations.
    ParameterHandler prm;
    MpmOtm::BackgroundGrid<1>::declare_parameters(prm);
    prm.parse_input_from_string("subsection Mesh\n"
                                " set Lower corner = 0\n"
                                " set Upper corner = 1\n"
                                " set Subdivisions = " +
                                std::to_string(n_nodes - 1) + "\nend\n");
    MpmOtm::BackgroundGrid<1> grid;
    grid.parse_parameters(prm);
    grid.create(MPI_COMM_WORLD);
    MpmOtm::MaxEnt<1> functions(d_max);
    functions.initialize(grid);
    const unsigned int n = functions.n_functions();

    // The functions are numbered like the vertices; print them by position.
    std::vector<unsigned int> by_position(n);
    for (unsigned int i = 0; i < n; ++i)
      by_position[static_cast<unsigned int>(
        std::lround(functions.node(i)[0] * (n - 1)))] = i;

    std::cout << "# local max-ent functions, journal Sect. 6.3 and Fig. 4: "
              << n << " uniform nodes on [0, 1], d_max = " << d_max
              << ", cubic-spline prior (Eq. 89)\n"
              << "# columns: x, w_i (i = 0.." << n - 1 << "), dw_i/dx, phi_i, "
              << "dphi_i/dx\n";
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    std::vector<Tensor<1, 1>>            gradients;
    std::vector<double> prior(n), prior_slope(n), phi(n), phi_slope(n);
    std::cout << std::setprecision(10);
    for (unsigned int s = 0; s <= n_samples; ++s)
      {
        const double x = double(s) / n_samples;
        for (unsigned int j = 0; j < n; ++j)
          {
            // Eq. 87: r = |x - x_i| / d_i, so dw/dx = dw/dr sign(x - x_i) /
            // d_i.
            const unsigned int i      = by_position[j];
            const double       offset = x - functions.node(i)[0];
            const double       radius = functions.support_radius(i);
            double             dw_dr  = 0;
            MpmOtm::cubic_spline_prior(std::abs(offset) / radius,
                                       prior[j],
                                       dw_dr);
            prior_slope[j] =
              (offset == 0.) ? 0. : dw_dr * (offset > 0. ? 1. : -1.) / radius;
            phi[j]       = 0.;
            phi_slope[j] = 0.;
          }
        const std::string failure =
          functions.evaluate_at(Point<1>(x), indices, values, gradients);
        AssertThrow(failure.empty(), ExcMessage(failure));
        for (unsigned int k = 0; k < indices.size(); ++k)
          for (unsigned int j = 0; j < n; ++j)
            if (by_position[j] == indices[k])
              {
                phi[j]       = values[k];
                phi_slope[j] = gradients[k][0];
              }
        std::cout << x;
        for (const auto *column : {&prior, &prior_slope, &phi, &phi_slope})
          for (const double value : *column)
            std::cout << ' ' << (std::abs(value) < 1e-14 ? 0. : value);
        std::cout << '\n';
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const unsigned int n_nodes   = argc > 1 ? std::stoi(argv[1]) : 11;
      const double       d_max     = argc > 2 ? std::stod(argv[2]) : 2.;
      const unsigned int n_samples = argc > 3 ? std::stoi(argv[3]) : 400;
      AssertThrow(n_nodes >= 2 && d_max >= 1. && n_samples >= 1,
                  ExcMessage("Usage: max-ent-functions-1d [nodes >= 2 "
                             "[d_max >= 1 [samples >= 1]]]"));
      print_functions(n_nodes, d_max, n_samples);
    }
  catch (const std::exception &error)
    {
      std::cerr << "max-ent-functions-1d stopped with an error:\n"
                << error.what() << std::endl;
      return 1;
    }
  return 0;
}
