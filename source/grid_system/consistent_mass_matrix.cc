#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid_system/consistent_mass_matrix.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>


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
     * y = M x with the matrix in compressed rows on the locally stored
     * coefficients (ghosts included), and the identity on the excluded
     * coefficients.
     */
    template <int dim>
    class SparseMassOperator
    {
    public:
      using VectorType = typename NodalSystem<dim>::VectorType;

      SparseMassOperator(const std::vector<unsigned int> &row_offsets,
                         const std::vector<unsigned int> &columns,
                         const std::vector<double>       &entries,
                         const std::vector<unsigned int> &excluded)
        : row_offsets(row_offsets)
        , columns(columns)
        , entries(entries)
        , excluded(excluded)
      {}

      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        multiply_with_exclusions(dst,
                                 src,
                                 excluded,
                                 [&](const double *x, double *y) {
                                   for (unsigned int row = 0;
                                        row + 1 < row_offsets.size();
                                        ++row)
                                     {
                                       double sum = 0.;
                                       for (unsigned int e = row_offsets[row];
                                            e < row_offsets[row + 1];
                                            ++e)
                                         sum += entries[e] * x[columns[e]];
                                       y[row] += sum;
                                     }
                                 });
      }

    private:
      const std::vector<unsigned int> &row_offsets;
      const std::vector<unsigned int> &columns;
      const std::vector<double>       &entries;
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



    /**
     * Block Jacobi preconditioner for families with several functions per
     * node (ShapeFunctions::functions_per_node()): the inverse of each
     * node's diagonal block of the mass matrix, which holds the strong
     * coupling of functions with one support (a Powell-Sabin vertex's three
     * functions are far from orthogonal, and a diagonal preconditioner
     * leaves CG four times the iterations of the linear family). Excluded
     * coefficients get the identity; a block that is not numerically
     * positive definite gets its lumped masses.
     */
    template <int dim>
    class NodeBlockPreconditioner
    {
    public:
      using VectorType = typename NodalSystem<dim>::VectorType;

      /**
       * Factorize the blocks; @p block_entries[q] holds M_ij for every
       * function i and j the function q of i's node.
       */
      NodeBlockPreconditioner(const std::vector<VectorType>   &block_entries,
                              const VectorType                &lumped_mass,
                              const std::vector<unsigned int> &excluded)
        : block_size(block_entries.size())
        , factors(lumped_mass.locally_owned_size() * block_size)
      {
        const unsigned int n_owned = lumped_mass.locally_owned_size();
        Assert(n_owned % block_size == 0,
               ExcMessage("A node's functions must have one owner."));
        std::vector<bool> is_excluded(n_owned, false);
        for (const unsigned int i : excluded)
          is_excluded[i] = true;
        const unsigned int n = block_size;
        for (unsigned int start = 0; start < n_owned; start += n)
          {
            double *L = &factors[start * n];
            for (unsigned int a = 0; a < n; ++a)
              for (unsigned int b = 0; b < n; ++b)
                L[a * n + b] =
                  (is_excluded[start + a] || is_excluded[start + b]) ?
                    (a == b ? 1. : 0.) :
                    block_entries[b].local_element(start + a);
            if (!cholesky(L))
              for (unsigned int a = 0; a < n; ++a)
                for (unsigned int b = 0; b < n; ++b)
                  {
                    const double m = lumped_mass.local_element(start + a);
                    L[a * n + b] =
                      (a != b) ?
                        0. :
                        ((m > 0. && !is_excluded[start + a]) ? std::sqrt(m) :
                                                               1.);
                  }
          }
      }

      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        const unsigned int n = block_size;
        for (unsigned int start = 0; start < dst.locally_owned_size();
             start += n)
          {
            const double *L = &factors[start * n];
            double       *x = dst.get_values() + start;
            const double *y = src.get_values() + start;
            // L L^T x = y: forward, then backward substitution.
            for (unsigned int a = 0; a < n; ++a)
              {
                double sum = y[a];
                for (unsigned int b = 0; b < a; ++b)
                  sum -= L[a * n + b] * x[b];
                x[a] = sum / L[a * n + a];
              }
            for (unsigned int a = n; a-- > 0;)
              {
                double sum = x[a];
                for (unsigned int b = a + 1; b < n; ++b)
                  sum -= L[b * n + a] * x[b];
                x[a] = sum / L[a * n + a];
              }
          }
      }

    private:
      /**
       * Overwrite the lower triangle of the row-major block @p L with its
       * Cholesky factor; false if a pivot is not clearly positive.
       */
      bool
      cholesky(double *L) const
      {
        const unsigned int n                = block_size;
        double             largest_diagonal = 0.;
        for (unsigned int a = 0; a < n; ++a)
          largest_diagonal = std::max(largest_diagonal, L[a * n + a]);
        for (unsigned int a = 0; a < n; ++a)
          {
            for (unsigned int b = 0; b <= a; ++b)
              {
                double sum = L[a * n + b];
                for (unsigned int c = 0; c < b; ++c)
                  sum -= L[a * n + c] * L[b * n + c];
                if (a == b)
                  {
                    if (!(sum > 1e-12 * largest_diagonal))
                      return false;
                    L[a * n + a] = std::sqrt(sum);
                  }
                else
                  L[a * n + b] = sum / L[b * n + b];
              }
          }
        return true;
      }

      const unsigned int  block_size;
      std::vector<double> factors;
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
    const std::vector<unsigned int> previous_offsets = group_offsets;
    const std::vector<unsigned int> previous_indices = group_indices;
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

    // The matrix pays when a product with it (at most one entry per pair of
    // functions of a group) is cheaper than a point pass.
    use_matrix = block_cost < point_pass_cost;
    if (use_matrix)
      assemble_matrix(system, shape_data, previous_offsets, previous_indices);
    if (system.functions_per_node() > 1)
      assemble_node_blocks(system, shape_data);
    else
      node_block_entries.clear();
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::assemble_matrix(
    const NodalSystem<dim>          &system,
    const ParticleShapeData<dim>    &shape_data,
    const std::vector<unsigned int> &previous_offsets,
    const std::vector<unsigned int> &previous_indices)
  {
    if (group_offsets != previous_offsets || group_indices != previous_indices)
      build_sparsity(system.partitioner().locally_owned_size() +
                     system.partitioner().n_ghost_indices());

    // Sum m_p phi_a phi_b over the points of each group (a run of
    // consecutive points) into a dense block, its upper triangle, then add
    // the block to the matrix entries.
    entries.assign(columns.size(), 0.);
    for (unsigned int k = 0; k < shape_data.n_particles();)
      {
        const unsigned int group = group_of_point[k];
        const unsigned int n = group_offsets[group + 1] - group_offsets[group];
        group_block.assign(n * n, 0.);
        for (; k < shape_data.n_particles() && group_of_point[k] == group; ++k)
          {
            const double  m   = system.particle_mass[k];
            const double *phi = &shape_data.values[shape_data.offsets[k]];
            for (unsigned int a = 0; a < n; ++a)
              {
                const double m_phi = m * phi[a];
                double      *row   = &group_block[a * n];
                for (unsigned int b = a; b < n; ++b)
                  row[b] += m_phi * phi[b];
              }
          }
        const unsigned int *position = &entry_of_block[block_offsets[group]];
        for (unsigned int a = 0; a < n; ++a)
          {
            entries[position[a * n + a]] += group_block[a * n + a];
            for (unsigned int b = a + 1; b < n; ++b)
              {
                entries[position[a * n + b]] += group_block[a * n + b];
                entries[position[b * n + a]] += group_block[a * n + b];
              }
          }
      }
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::assemble_node_blocks(
    const NodalSystem<dim>       &system,
    const ParticleShapeData<dim> &shape_data)
  {
    const unsigned int                 n = system.functions_per_node();
    const Utilities::MPI::Partitioner &partitioner = system.partitioner();
    const unsigned int                 n_local =
      partitioner.locally_owned_size() + partitioner.n_ghost_indices();
    global_of_local.resize(n_local);
    for (unsigned int i = 0; i < n_local; ++i)
      global_of_local[i] = partitioner.local_to_global(i);

    node_block_entries.resize(n);
    for (VectorType &entries_q : node_block_entries)
      {
        if (entries_q.get_partitioner() != system.lumped_mass.get_partitioner())
          entries_q.reinit(system.lumped_mass.get_partitioner());
        entries_q = 0.;
      }
    const auto add =
      [&](const unsigned int i, const unsigned int j, const double value) {
        if (global_of_local[i] / n == global_of_local[j] / n)
          node_block_entries[global_of_local[j] % n].local_element(i) += value;
      };
    if (use_matrix)
      for (unsigned int row = 0; row + 1 < row_offsets.size(); ++row)
        for (unsigned int e = row_offsets[row]; e < row_offsets[row + 1]; ++e)
          add(row, columns[e], entries[e]);
    else
      for (unsigned int k = 0; k < shape_data.n_particles(); ++k)
        {
          const unsigned int  begin   = shape_data.offsets[k];
          const unsigned int  end     = shape_data.offsets[k + 1];
          const double        m       = system.particle_mass[k];
          const double       *phi     = &shape_data.values[0];
          const unsigned int *indices = &shape_data.indices[0];
          for (unsigned int a = begin; a < end; ++a)
            for (unsigned int b = begin; b < end; ++b)
              add(indices[a], indices[b], m * phi[a] * phi[b]);
        }
    for (VectorType &entries_q : node_block_entries)
      entries_q.compress(VectorOperation::add);
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::build_sparsity(const unsigned int n_rows)
  {
    const unsigned int n_groups = group_offsets.size() - 1;

    // The groups of each row (a row's function appears in them).
    std::vector<unsigned int> groups_of_row_offsets(n_rows + 1, 0);
    for (const unsigned int i : group_indices)
      ++groups_of_row_offsets[i + 1];
    for (unsigned int i = 0; i < n_rows; ++i)
      groups_of_row_offsets[i + 1] += groups_of_row_offsets[i];
    std::vector<unsigned int> groups_of_row(group_indices.size());
    std::vector<unsigned int> place_in_group(group_indices.size());
    {
      std::vector<unsigned int> next(groups_of_row_offsets.begin(),
                                     groups_of_row_offsets.end() - 1);
      for (unsigned int g = 0; g < n_groups; ++g)
        for (unsigned int a = group_offsets[g]; a < group_offsets[g + 1]; ++a)
          {
            const unsigned int slot = next[group_indices[a]]++;
            groups_of_row[slot]     = g;
            place_in_group[slot]    = a - group_offsets[g];
          }
    }

    block_offsets.resize(n_groups);
    std::size_t block_size = 0;
    for (unsigned int g = 0; g < n_groups; ++g)
      {
        block_offsets[g]    = block_size;
        const std::size_t n = group_offsets[g + 1] - group_offsets[g];
        block_size += n * n;
      }
    entry_of_block.resize(block_size);

    // Row by row: the columns are the union of the row's groups' functions;
    // each group's block entry (a, b) of this row points to its column.
    row_offsets.assign(1, 0);
    columns.clear();
    std::vector<unsigned int> entry_of_column(n_rows,
                                              numbers::invalid_unsigned_int);
    for (unsigned int row = 0; row < n_rows; ++row)
      {
        const unsigned int row_start = columns.size();
        for (unsigned int s = groups_of_row_offsets[row];
             s < groups_of_row_offsets[row + 1];
             ++s)
          {
            const unsigned int  g = groups_of_row[s];
            const unsigned int  n = group_offsets[g + 1] - group_offsets[g];
            const unsigned int *indices = &group_indices[group_offsets[g]];
            unsigned int       *position =
              &entry_of_block[block_offsets[g] + place_in_group[s] * n];
            for (unsigned int b = 0; b < n; ++b)
              {
                unsigned int &entry = entry_of_column[indices[b]];
                if (entry == numbers::invalid_unsigned_int || entry < row_start)
                  {
                    entry = columns.size();
                    columns.push_back(indices[b]);
                  }
                position[b] = entry;
              }
          }
        row_offsets.push_back(columns.size());
      }
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::vmult(const NodalSystem<dim>       &system,
                                   const ParticleShapeData<dim> &shape_data,
                                   const VectorType             &vector,
                                   VectorType                   &product) const
  {
    const std::vector<unsigned int> none;
    if (use_matrix)
      SparseMassOperator<dim>(row_offsets, columns, entries, none)
        .vmult(product, vector);
    else
      ParticleMassOperator<dim>(shape_data, system.particle_mass, none)
        .vmult(product, vector);
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::solve(
    const NodalSystem<dim>          &system,
    const ParticleShapeData<dim>    &shape_data,
    const VectorType                &right_hand_side,
    VectorType                      &solution,
    const AffineConstraints<double> &constraints) const
  {
    solve_prescribed(system,
                     shape_data,
                     right_hand_side,
                     solution,
                     system.local_lines(constraints));
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::solve_prescribed(
    const NodalSystem<dim>                             &system,
    const ParticleShapeData<dim>                       &shape_data,
    const VectorType                                   &right_hand_side,
    VectorType                                         &solution,
    const std::vector<std::pair<unsigned int, double>> &lines) const
  {
    // The prescribed indices, which the operators keep at the identity.
    std::vector<unsigned int> prescribed(lines.size());
    for (unsigned int k = 0; k < lines.size(); ++k)
      prescribed[k] = lines[k].first;
    const auto set_values = [&](VectorType &vector) {
      for (const auto &[i, value] : lines)
        vector.local_element(i) = value;
    };

    VectorType rhs(right_hand_side);
    rhs.zero_out_ghost_values();

    // b_f - M_fp x_p; the vector x_p is communicated, so every rank takes
    // part even without prescribed values of its own.
    const bool inhomogeneous =
      Utilities::MPI::max(std::any_of(lines.begin(),
                                      lines.end(),
                                      [](const auto &line) {
                                        return line.second != 0.;
                                      }) ?
                            1 :
                            0,
                          rhs.get_mpi_communicator()) == 1;
    if (inhomogeneous)
      {
        VectorType lifted, product;
        lifted.reinit(right_hand_side);
        product.reinit(right_hand_side, true);
        set_values(lifted);
        ConsistentMassMatrix<dim>::vmult(system, shape_data, lifted, product);
        rhs -= product;
      }
    for (const unsigned int i : prescribed)
      rhs.local_element(i) = 0.;
    const double norm = rhs.l2_norm();
    if (norm == 0.)
      {
        solution = 0.;
        set_values(solution);
        return;
      }

    // Start from the solution of the previous step (the same quantity a
    // time step earlier), which is close: CG then needs few iterations.
    solution.zero_out_ghost_values();
    for (const unsigned int i : prescribed)
      solution.local_element(i) = 0.;

    SolverControl        control(1000, 1e-13 * norm, false, false);
    SolverCG<VectorType> cg(control);
    const auto           solve_with = [&](const auto &preconditioner) {
      if (use_matrix)
        cg.solve(
          SparseMassOperator<dim>(row_offsets, columns, entries, prescribed),
          solution,
          rhs,
          preconditioner);
      else
        cg.solve(ParticleMassOperator<dim>(shape_data,
                                           system.particle_mass,
                                           prescribed),
                 solution,
                 rhs,
                 preconditioner);
    };
    try
      {
        if (node_block_entries.empty())
          solve_with(LumpedMassPreconditioner<dim>(system.lumped_mass));
        else
          solve_with(NodeBlockPreconditioner<dim>(node_block_entries,
                                                  system.lumped_mass,
                                                  prescribed));
      }
    catch (const SolverControl::NoConvergence &failure)
      {
        std::ostringstream message;
        message << "The consistent mass matrix could not be solved: "
                << failure.last_step << " CG iterations left the residual at "
                << std::scientific << std::setprecision(2)
                << failure.last_residual / norm
                << " of the right-hand side (tolerance 1e-13). The matrix is "
                   "nearly singular or badly conditioned. Two causes are "
                   "known: a shape function supported by almost no material "
                   "(thesis Ch. 5), and shape functions whose supports overlap "
                   "widely, as max-ent functions with a large 'Max-ent "
                   "support factor' in 2D and 3D. Use 'set Mass matrix = "
                   "lumped', or a smaller 'Max-ent support factor'.";
        AssertThrow(false, ExcMessage(message.str()));
      }
    set_values(solution);
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
