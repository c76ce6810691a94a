#include <deal.II/base/mpi.h>

#include <mpm_otm/io/statistics.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/materials/point_energy.h>
#include <mpm_otm/problems/problem.h>

#include <cmath>

namespace MpmOtm
{
  template <int dim>
  void
  Statistics<dim>::compute(const MaterialPoints<dim>  &material_points,
                           const MaterialLibrary<dim> &materials,
                           const Problem<dim>         &problem,
                           const double                time)
  {
    using Layout           = PropertyLayout<dim>;
    has_displacement_error = problem.has_exact_solution();
    has_stress_error       = problem.has_exact_stress();

    // kinetic, strain, mass, momentum (3), squared errors (3), gravitational,
    // angular momentum (3)
    double               sums[13] = {};
    const Tensor<1, dim> gravity  = problem.gravity(time);
    for (const auto &particle : material_points.particle_handler())
      {
        const auto           properties = particle.get_properties();
        const double         m          = properties[Layout::mass];
        const double         volume     = Layout::volume(properties);
        const Tensor<1, dim> v =
          Layout::get_vector(properties, Layout::velocity);
        const Point<dim> X(
          Layout::get_vector(properties, Layout::initial_position));
        const SymmetricTensor<2, dim> sigma = Layout::get_stress(properties);

        const PointEnergy energy = point_energy(properties, materials);
        sums[0] += energy.kinetic;
        sums[1] += energy.strain;
        sums[2] += m;
        sums[9] -= m * (gravity * (particle.get_location() - X));
        for (unsigned int d = 0; d < dim; ++d)
          sums[3 + d] += m * v[d];
        const Point<dim> &x = particle.get_location();
        if constexpr (dim == 2)
          sums[12] += m * (x[0] * v[1] - x[1] * v[0]);
        if constexpr (dim == 3)
          for (unsigned int d = 0; d < 3; ++d)
            sums[10 + d] += m * (x[(d + 1) % 3] * v[(d + 2) % 3] -
                                 x[(d + 2) % 3] * v[(d + 1) % 3]);
        if (has_displacement_error)
          {
            const double error = ((particle.get_location() - X) -
                                  problem.exact_displacement(X, time))
                                   .norm_square();
            sums[6] += error;
            sums[7] += volume * error;
          }
        if (has_stress_error)
          {
            const double error = (sigma - problem.exact_stress(X, time)).norm();
            sums[8] += error * error;
          }
      }

    const MPI_Comm communicator = material_points.communicator();
    Utilities::MPI::sum(ArrayView<const double>(sums, 13),
                        communicator,
                        ArrayView<double>(sums, 13));
    const double n_points =
      static_cast<double>(material_points.n_global_points());

    kinetic_energy = sums[0];
    strain_energy  = sums[1];
    total_mass     = sums[2];
    for (unsigned int d = 0; d < 3; ++d)
      momentum[d] = sums[3 + d];
    displacement_rms_error = std::sqrt(sums[6] / n_points);
    displacement_l2_error  = std::sqrt(sums[7]);
    stress_rms_error       = std::sqrt(sums[8] / n_points);
    gravitational_energy   = sums[9];
    for (unsigned int d = 0; d < 3; ++d)
      angular_momentum[d] = sums[10 + d];
  }



  template struct Statistics<1>;
  template struct Statistics<2>;
  template struct Statistics<3>;
} // namespace MpmOtm
