#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid_system/consistent_mass_matrix.h>

#include <algorithm>


namespace MpmOtm
{
  namespace
  {
    /**
     * y = M x for a matrix whose product on the locally stored entries
     * (ghosts included) is @p local_product(x, y), summed over the ranks,
     * with the identity on the excluded coefficients. The excluded
     * coefficients of x are zero (right-hand side and initial guess are),
     * so they do not couple to the others.
     */
    template <typename VectorType, typename LocalProduct>
    void
    multiply_with_exclusions(VectorType                      &dst,
                             const VectorType                &src,
                             const std::vector<unsigned int> &excluded,
                             const LocalProduct              &local_product)
    {
      src.update_ghost_values();
      dst = 0.;
      local_product(src.get_values(), dst.get_values());
      dst.compress(VectorOperation::add);
      src.zero_out_ghost_values();
      for (const unsigned int i : excluded)
        dst.local_element(i) = src.local_element(i);
    }



    /**
     * y = M x with M_ij = sum_p m_p phi_i(x_p) phi_j(x_p), and the identity
     * on the excluded coefficients.
     */
    template <int dim>
    class ParticleMassOperator
    {
    public:
      using VectorType = typename NodalSystem<dim>::VectorType;

      ParticleMassOperator(const ParticleShapeData<dim>    &shape_data,
                           const std::vector<double>       &particle_mass,
                           const std::vector<unsigned int> &excluded)
        : shape_data(shape_data)
        , particle_mass(particle_mass)
        , excluded(excluded)
      {}

      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        multiply_with_exclusions(
          dst,
          src,
          excluded,
          [&](const double *x, double *y) {
            for (unsigned int k = 0; k < particle_mass.size(); ++k)
              {
                double interpolated = 0.;
                for (unsigned int e = shape_data.offsets[k];
                     e < shape_data.offsets[k + 1];
                     ++e)
                  interpolated +=
                    shape_data.values[e] * x[shape_data.indices[e]];
                interpolated *= particle_mass[k];
                for (unsigned int e = shape_data.offsets[k];
                     e < shape_data.offsets[k + 1];
                     ++e)
                  y[shape_data.indices[e]] +=
                    shape_data.values[e] * interpolated;
              }
          });
      }

    private:
      const ParticleShapeData<dim>    &shape_data;
      const std::vector<double>       &particle_mass;
      const std::vector<unsigned int> &excluded;
    };

    /**
     * y = M x from the dense blocks of groups of points with the same
     * functions, and the identity on the excluded coefficients.
     */
    template <int dim>
    class GroupMassOperator
    {
    public:
      using VectorType = typename NodalSystem<dim>::VectorType;

      GroupMassOperator(const std::vector<unsigned int> &group_offsets,
                        const std::vector<unsigned int> &group_indices,
                        const std::vector<std::size_t>  &block_offsets,
                        const std::vector<double>       &group_blocks,
                        const std::vector<unsigned int> &excluded)
        : group_offsets(group_offsets)
        , group_indices(group_indices)
        , block_offsets(block_offsets)
        , group_blocks(group_blocks)
        , excluded(excluded)
      {}

      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        multiply_with_exclusions(
          dst,
          src,
          excluded,
          [&](const double *x, double *y) {
            for (unsigned int g = 0; g + 1 < group_offsets.size(); ++g)
              {
                const unsigned int *indices = &group_indices[group_offsets[g]];
                const unsigned int  n = group_offsets[g + 1] - group_offsets[g];
                const double       *block = &group_blocks[block_offsets[g]];
                for (unsigned int a = 0; a < n; ++a)
                  {
                    double sum = 0.;
                    for (unsigned int b = 0; b < n; ++b)
                      sum += block[a * n + b] * x[indices[b]];
                    y[indices[a]] += sum;
                  }
              }
          });
      }

    private:
      const std::vector<unsigned int> &group_offsets;
      const std::vector<unsigned int> &group_indices;
      const std::vector<std::size_t>  &block_offsets;
      const std::vector<double>       &group_blocks;
      const std::vector<unsigned int> &excluded;
    };



    /**
     * Jacobi preconditioner with the lumped masses.
     */
    template <int dim>
    class LumpedMassPreconditioner
    {
    public:
      using VectorType = typename NodalSystem<dim>::VectorType;

      explicit LumpedMassPreconditioner(const VectorType &lumped_mass)
        : lumped_mass(lumped_mass)
      {}

      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        for (unsigned int i = 0; i < dst.locally_owned_size(); ++i)
          {
            const double m = lumped_mass.local_element(i);
            dst.local_element(i) =
              (m > 0.) ? src.local_element(i) / m : src.local_element(i);
          }
      }

    private:
      const VectorType &lumped_mass;
    };
  } // namespace



  template <int dim>
  void
  ConsistentMassMatrix<dim>::declare_parameters(ParameterHandler &)
  {}



  template <int dim>
  void
  ConsistentMassMatrix<dim>::assemble(const NodalSystem<dim>       &system,
                                      const ParticleShapeData<dim> &shape_data)
  {
    // Consecutive points with the same function indices form a group.
    group_offsets.assign(1, 0);
    group_indices.clear();
    group_of_point.resize(shape_data.n_particles());
    std::size_t  point_pass_cost = 0;
    std::size_t  block_cost      = 0;
    unsigned int group_start     = 0;
    for (unsigned int k = 0; k < shape_data.n_particles(); ++k)
      {
        const unsigned int  begin   = shape_data.offsets[k];
        const unsigned int  n       = shape_data.offsets[k + 1] - begin;
        const unsigned int *indices = &shape_data.indices[begin];
        Assert(n > 0, ExcMessage("A point without shape functions."));
        point_pass_cost += 2 * n;
        const bool same =
          k > 0 && group_indices.size() - group_start == n &&
          std::equal(indices, indices + n, group_indices.begin() + group_start);
        if (!same)
          {
            group_start = group_indices.size();
            group_indices.insert(group_indices.end(), indices, indices + n);
            group_offsets.push_back(group_indices.size());
            block_cost += std::size_t(n) * n;
          }
        group_of_point[k] = group_offsets.size() - 2;
      }

    // Blocks pay when a product over them is cheaper than a point pass.
    use_groups = block_cost < point_pass_cost;
    block_offsets.clear();
    group_blocks.clear();
    if (!use_groups)
      return;
    block_offsets.resize(group_offsets.size() - 1);
    std::size_t size = 0;
    for (unsigned int g = 0; g + 1 < group_offsets.size(); ++g)
      {
        block_offsets[g]    = size;
        const std::size_t n = group_offsets[g + 1] - group_offsets[g];
        size += n * n;
      }
    group_blocks.assign(size, 0.);
    for (unsigned int k = 0; k < shape_data.n_particles(); ++k)
      {
        const unsigned int begin = shape_data.offsets[k];
        const unsigned int n     = shape_data.offsets[k + 1] - begin;
        double       *block = &group_blocks[block_offsets[group_of_point[k]]];
        const double  m     = system.particle_mass[k];
        const double *phi   = &shape_data.values[begin];
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            block[a * n + b] += m * phi[a] * phi[b];
      }
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::solve(const NodalSystem<dim>       &system,
                                   const ParticleShapeData<dim> &shape_data,
                                   const VectorType  &right_hand_side,
                                   VectorType        &solution,
                                   const unsigned int component) const
  {
    const std::vector<unsigned int> excluded =
      system.excluded_functions(component);
    VectorType rhs(right_hand_side);
    rhs.zero_out_ghost_values();
    for (const unsigned int i : excluded)
      rhs.local_element(i) = 0.;

    const double norm = rhs.l2_norm();
    if (norm == 0.)
      {
        solution = 0.;
        return;
      }

    // Start from the solution of the previous step (the same quantity a
    // time step earlier), which is close: CG then needs few iterations.
    solution.zero_out_ghost_values();
    for (const unsigned int i : excluded)
      solution.local_element(i) = 0.;

    const LumpedMassPreconditioner<dim> preconditioner(system.lumped_mass);
    SolverControl        control(1000, 1e-13 * norm, false, false);
    SolverCG<VectorType> cg(control);
    try
      {
        if (use_groups)
          cg.solve(GroupMassOperator<dim>(group_offsets,
                                          group_indices,
                                          block_offsets,
                                          group_blocks,
                                          excluded),
                   solution,
                   rhs,
                   preconditioner);
        else
          cg.solve(ParticleMassOperator<dim>(shape_data,
                                             system.particle_mass,
                                             excluded),
                   solution,
                   rhs,
                   preconditioner);
      }
    catch (const SolverControl::NoConvergence &failure)
      {
        AssertThrow(false,
                    ExcMessage(
                      "The consistent mass matrix could not be solved (" +
                      std::to_string(failure.last_step) +
                      " CG iterations, residual " +
                      std::to_string(failure.last_residual) +
                      "): it is nearly singular, which happens when a "
                      "shape function is supported by almost no material "
                      "(thesis Ch. 5). Use 'set Mass matrix = lumped'."));
      }
  }



  template class ConsistentMassMatrix<1>;
  template class ConsistentMassMatrix<2>;
  template class ConsistentMassMatrix<3>;
} // namespace MpmOtm

#define MPM_OTM_CONSISTENT_DESCRIPTION \
  "consistent, solved with CG (journal Eq. 19)"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::MassMatrix<1>,
                        MpmOtm::ConsistentMassMatrix<1>,
                        "consistent",
                        MPM_OTM_CONSISTENT_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::MassMatrix<2>,
                        MpmOtm::ConsistentMassMatrix<2>,
                        "consistent",
                        MPM_OTM_CONSISTENT_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::MassMatrix<3>,
                        MpmOtm::ConsistentMassMatrix<3>,
                        "consistent",
                        MPM_OTM_CONSISTENT_DESCRIPTION)
