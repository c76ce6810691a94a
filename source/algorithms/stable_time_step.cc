#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/tridiagonal_matrix.h>

#include <mpm_otm/algorithms/stable_time_step.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace MpmOtm
{
  namespace
  {
    /**
     * A number in [-1, 1) that depends on @p key only (splitmix64).
     */
    double
    pseudo_random(std::uint64_t key)
    {
      key += 0x9e3779b97f4a7c15ULL;
      key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ULL;
      key = (key ^ (key >> 27)) * 0x94d049bb133111ebULL;
      key = key ^ (key >> 31);
      return 2. * static_cast<double>(key >> 11) / 9007199254740992. - 1.;
    }



    /**
     * A product with the identity on the @p excluded (locally owned, sorted)
     * entries and @p product elsewhere.
     */
    template <typename VectorType, typename Product>
    class ExcludingOperator
    {
    public:
      ExcludingOperator(const std::vector<unsigned int> &excluded,
                        const Product                   &product)
        : excluded(excluded)
        , product(product)
      {}

      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        product(src, dst);
        for (const unsigned int i : excluded)
          dst.local_element(i) = src.local_element(i);
      }

    private:
      const std::vector<unsigned int> &excluded;
      const Product                   &product;
    };
  } // namespace



  template <int dim>
  typename StableTimeStep<dim>::Estimate
  StableTimeStep<dim>::estimate(
    const MaterialPoints<dim>                        &material_points,
    const ShapeFunctions<dim>                        &shape_functions,
    NodalSystem<dim>                                 &system,
    MassMatrix<dim>                                  &mass_matrix,
    const MaterialLibrary<dim>                       &materials,
    const Problem<dim>                               &problem,
    const typename NodalUpdate<dim>::ParticleVelocity particle_velocity)
  {
    shape_functions.evaluate(material_points, system.partitioner(), data);
    system.assemble(material_points, data, problem, 0., true);
    system.finish_assembly();
    mass_matrix.assemble(system, data);

    // Lanczos for K q = lambda M q in the M inner product, with p = M q
    // carried along so that the consistent mass matrix needs only solves:
    // r = K q_j - alpha_j p_j - beta_(j-1) p_(j-1), w = M^-1 r,
    // beta_j = sqrt(w . r), q_(j+1) = w / beta_j, p_(j+1) = r / beta_j. The
    // largest eigenvalue of the tridiagonal matrix (alpha, beta) rises to
    // the largest of M^-1 K within a few dozen steps.
    // Functions whose mass is round-off (a point on the edge of their
    // support, where phi_i(x_p) = 1e-16 but its gradient is not) would
    // give omega_max ~ 1e10 h / c; the particle update multiplies their
    // accelerations by that phi_i, so they are left out of the estimate.
    double largest_point_mass = 0;
    for (const double m : system.particle_mass)
      largest_point_mass = std::max(largest_point_mass, m);
    largest_point_mass =
      Utilities::MPI::max(largest_point_mass,
                          system.lumped_mass.get_mpi_communicator());
    std::vector<unsigned int> negligible;
    for (unsigned int i = 0; i < system.lumped_mass.locally_owned_size(); ++i)
      if (system.lumped_mass.local_element(i) < 1e-6 * largest_point_mass)
        negligible.push_back(i);

    // What replaces M^-1 in Lanczos for the nodal update (see the class):
    // M^-1, 2 M^-1 - M^-1 M_C M^-1, or ((M + M_C) / 2)^-1.
    using Velocity  = typename NodalUpdate<dim>::ParticleVelocity;
    const bool flip = !mass_matrix.is_consistent() &&
                      particle_velocity == Velocity::from_acceleration;
    const bool carried_by_nodes =
      !mass_matrix.is_consistent() &&
      particle_velocity == Velocity::from_displacement;
    VectorType first_solve, consistent_product;
    first_solve.reinit(system.lumped_mass);
    consistent_product.reinit(system.lumped_mass);
    const auto apply_inverse_mass = [&](const unsigned int c,
                                        const VectorType  &right_hand_side,
                                        VectorType        &solution) {
      const auto &constraints = system.constraints()[c];
      if (flip)
        {
          mass_matrix.solve(system,
                            data,
                            right_hand_side,
                            first_solve,
                            constraints);
          for (const unsigned int i : negligible)
            first_solve.local_element(i) = 0.;
          apply_consistent_mass(system, first_solve, consistent_product);
          mass_matrix.solve(system,
                            data,
                            consistent_product,
                            solution,
                            constraints);
          solution.sadd(-1., 2., first_solve);
        }
      else if (carried_by_nodes)
        {
          std::vector<unsigned int> excluded = negligible;
          for (const auto &line : system.local_lines(constraints))
            excluded.push_back(line.first);
          std::sort(excluded.begin(), excluded.end());
          excluded.erase(std::unique(excluded.begin(), excluded.end()),
                         excluded.end());
          VectorType rhs(right_hand_side);
          for (const unsigned int i : excluded)
            rhs.local_element(i) = 0.;
          const auto averaged_mass = [&](const VectorType &x, VectorType &y) {
            mass_matrix.vmult(system, data, x, y);
            apply_consistent_mass(system, x, consistent_product);
            y += consistent_product;
            y *= 0.5;
          };
          const auto inverse_lumped_mass = [&](const VectorType &x,
                                               VectorType       &y) {
            for (unsigned int i = 0; i < y.locally_owned_size(); ++i)
              y.local_element(i) =
                x.local_element(i) / system.lumped_mass.local_element(i);
          };
          using Operator =
            ExcludingOperator<VectorType, decltype(averaged_mass)>;
          using Preconditioner =
            ExcludingOperator<VectorType, decltype(inverse_lumped_mass)>;
          solution          = 0.;
          const double norm = rhs.l2_norm();
          if (norm == 0.)
            return;
          SolverControl        control(1000, 1e-12 * norm, false, false);
          SolverCG<VectorType> cg(control);
          cg.solve(Operator(excluded, averaged_mass),
                   solution,
                   rhs,
                   Preconditioner(excluded, inverse_lumped_mass));
        }
      else
        mass_matrix.solve(system, data, right_hand_side, solution, constraints);
    };

    // The start vector r_i = sum_p phi_i(x_p) w_p, with a number w_p in
    // [-1, 1) that depends on the point's initial position only (rounded to
    // single precision): every partition starts from the same vector to
    // round-off, so that an estimate that has not converged is the same on
    // every number of ranks. (The global function numbers depend on the
    // partition.)
    std::array<VectorType, dim> q, q_old, p, p_old, r;
    for (unsigned int c = 0; c < dim; ++c)
      for (auto *vector : {&q[c], &q_old[c], &p[c], &p_old[c], &r[c]})
        vector->reinit(system.lumped_mass);
    {
      using Layout = PropertyLayout<dim>;
      typename ParticleShapeData<dim>::Cursor functions(data);
      for (const auto &particle : material_points.particle_handler())
        {
          const auto    point = functions.next();
          const auto    X     = Layout::get_vector(particle.get_properties(),
                                            Layout::initial_position);
          std::uint64_t key   = 0;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const float   coordinate = static_cast<float>(X[d]);
              std::uint32_t bits;
              std::memcpy(&bits, &coordinate, sizeof(bits));
              key = (key << 21) ^ (key >> 43) ^ bits;
            }
          for (unsigned int c = 0; c < dim; ++c)
            {
              const double weight = pseudo_random(dim * key + c);
              for (unsigned int j = 0; j < point.n; ++j)
                r[c].local_element(point.indices[j]) +=
                  point.values[j] * weight;
            }
        }
      for (unsigned int c = 0; c < dim; ++c)
        r[c].compress(VectorOperation::add);
    }
    std::vector<double> alpha, beta;
    double              eigenvalue = 0;
    Estimate            result;
    for (unsigned int j = 0; j < 60; ++j)
      {
        // q_j = M^-1 r / beta, p_j = r / beta.
        double r_norm_squared = 0;
        for (unsigned int c = 0; c < dim; ++c)
          {
            for (const unsigned int i : negligible)
              r[c].local_element(i) = 0.;
            apply_inverse_mass(c, r[c], q[c]);
            for (const unsigned int i : negligible)
              q[c].local_element(i) = 0.;
            r_norm_squared += q[c] * r[c];
          }
        if (!(r_norm_squared > 1e-24 * (eigenvalue * eigenvalue + 1e-300)))
          break;
        const double norm = std::sqrt(r_norm_squared);
        if (j > 0)
          beta.push_back(norm);
        for (unsigned int c = 0; c < dim; ++c)
          {
            q[c] /= norm;
            p[c] = r[c];
            p[c] /= norm;
            q[c].update_ghost_values();
          }
        apply_stiffness(material_points, materials, q, r);
        double a = 0;
        for (unsigned int c = 0; c < dim; ++c)
          a += q[c] * r[c];
        alpha.push_back(a);
        for (unsigned int c = 0; c < dim; ++c)
          {
            r[c].add(-a, p[c]);
            if (j > 0)
              r[c].add(-beta.back(), p_old[c]);
            q[c].zero_out_ghost_values();
            std::swap(q_old[c], q[c]);
            std::swap(p_old[c], p[c]);
          }

        TridiagonalMatrix<double> tridiagonal(alpha.size(), true);
        for (unsigned int k = 0; k < alpha.size(); ++k)
          {
            tridiagonal(k, k) = alpha[k];
            if (k + 1 < alpha.size())
              tridiagonal(k, k + 1) = beta[k];
          }
        tridiagonal.compute_eigenvalues();
        const double largest = tridiagonal.eigenvalue(alpha.size() - 1);
        result.iterations    = j + 1;
        result.last_change   = std::abs(largest - eigenvalue) / largest;
        result.converged     = j > 4 && result.last_change <= 1e-8;
        eigenvalue           = std::max(eigenvalue, largest);
        if (result.converged)
          break;
      }
    result.largest_frequency = std::sqrt(eigenvalue);
    result.time_step         = eigenvalue > 0. ?
                                 2. / result.largest_frequency :
                                 std::numeric_limits<double>::infinity();
    return result;
  }



  template <int dim>
  void
  StableTimeStep<dim>::apply_stiffness(
    const MaterialPoints<dim>         &material_points,
    const MaterialLibrary<dim>        &materials,
    const std::array<VectorType, dim> &x,
    std::array<VectorType, dim>       &stiffness_product) const
  {
    using Layout = PropertyLayout<dim>;
    std::vector<double> lambda(materials.n_materials()),
      mu(materials.n_materials());
    for (unsigned int id = 0; id < materials.n_materials(); ++id)
      {
        lambda[id] = materials[id].lambda();
        mu[id]     = materials[id].mu();
      }
    for (unsigned int c = 0; c < dim; ++c)
      stiffness_product[c] = 0.;
    typename ParticleShapeData<dim>::Cursor functions(data);
    for (const auto &particle : material_points.particle_handler())
      {
        const auto     properties = particle.get_properties();
        const auto     point      = functions.next();
        Tensor<2, dim> gradient;
        for (unsigned int j = 0; j < point.n; ++j)
          for (unsigned int c = 0; c < dim; ++c)
            gradient[c] +=
              x[c].local_element(point.indices[j]) * point.gradients[j];
        const unsigned int            id = Layout::get_material_id(properties);
        const SymmetricTensor<2, dim> strain = symmetrize(gradient);
        const SymmetricTensor<2, dim> stress =
          Layout::volume(properties) *
          (lambda[id] * trace(strain) * unit_symmetric_tensor<dim>() +
           2. * mu[id] * strain);
        for (unsigned int j = 0; j < point.n; ++j)
          {
            const Tensor<1, dim> force = stress * point.gradients[j];
            for (unsigned int c = 0; c < dim; ++c)
              stiffness_product[c].local_element(point.indices[j]) += force[c];
          }
      }
    for (unsigned int c = 0; c < dim; ++c)
      stiffness_product[c].compress(VectorOperation::add);
  }



  template <int dim>
  void
  StableTimeStep<dim>::apply_consistent_mass(const NodalSystem<dim> &system,
                                             const VectorType       &x,
                                             VectorType &product) const
  {
    x.update_ghost_values();
    product = 0.;
    typename ParticleShapeData<dim>::Cursor functions(data);
    for (const double mass : system.particle_mass)
      {
        const auto point        = functions.next();
        double     interpolated = 0.;
        for (unsigned int j = 0; j < point.n; ++j)
          interpolated += point.values[j] * x.local_element(point.indices[j]);
        interpolated *= mass;
        for (unsigned int j = 0; j < point.n; ++j)
          product.local_element(point.indices[j]) +=
            point.values[j] * interpolated;
      }
    product.compress(VectorOperation::add);
    x.zero_out_ghost_values();
  }



  template class StableTimeStep<1>;
  template class StableTimeStep<2>;
  template class StableTimeStep<3>;
} // namespace MpmOtm
