#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid_system/consistent_mass_matrix.h>
#include <mpm_otm/grid_system/node_block_preconditioner.h>

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
            typename ParticleShapeData<dim>::Cursor functions(shape_data);
            for (unsigned int k = 0; k < particle_mass.size(); ++k)
              {
                const auto point        = functions.next();
                double     interpolated = 0.;
                for (unsigned int j = 0; j < point.n; ++j)
                  interpolated += point.values[j] * x[point.indices[j]];
                interpolated *= particle_mass[k];
                for (unsigned int j = 0; j < point.n; ++j)
                  y[point.indices[j]] += point.values[j] * interpolated;
              }
          });
      }

    private:
      const ParticleShapeData<dim>    &shape_data;
      const std::vector<double>       &particle_mass;
      const std::vector<unsigned int> &excluded;
    };

    /**
     * y = M x with the assembled matrix, and the identity on the excluded
     * coefficients (whose entries of x are zero, see
     * multiply_with_exclusions()).
     */
    template <typename VectorType>
    class MatrixMassOperator
    {
    public:
      MatrixMassOperator(const TrilinosWrappers::SparseMatrix &matrix,
                         const std::vector<unsigned int>      &excluded)
        : matrix(matrix)
        , excluded(excluded)
      {}

      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        matrix.vmult(dst, src);
        for (const unsigned int i : excluded)
          dst.local_element(i) = src.local_element(i);
      }

    private:
      const TrilinosWrappers::SparseMatrix &matrix;
      const std::vector<unsigned int>      &excluded;
    };



    /**
     * A preconditioner of the whole matrix applied to the coefficients that
     * are not excluded: its result is set to zero on the excluded ones,
     * which CG then keeps at zero. Symmetric and positive definite on the
     * others when the preconditioner is.
     */
    template <typename VectorType>
    class FreeCoefficientPreconditioner
    {
    public:
      FreeCoefficientPreconditioner(
        const TrilinosWrappers::PreconditionBase &preconditioner,
        const std::vector<unsigned int>          &excluded)
        : preconditioner(preconditioner)
        , excluded(excluded)
      {}

      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        preconditioner.vmult(dst, src);
        for (const unsigned int i : excluded)
          dst.local_element(i) = 0.;
      }

    private:
      const TrilinosWrappers::PreconditionBase &preconditioner;
      const std::vector<unsigned int>          &excluded;
    };
  } // namespace



  template <int dim>
  ConsistentMassMatrix<dim>::ConsistentMassMatrix() = default;



  template <int dim>
  ConsistentMassMatrix<dim>::~ConsistentMassMatrix() = default;



  template <int dim>
  void
  ConsistentMassMatrix<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Mass matrix preconditioner",
      "diagonal",
      Patterns::Selection("diagonal|direct per rank|algebraic multigrid"),
      "How conjugate gradients are preconditioned when the mass matrix is "
      "consistent or partially lumped. diagonal: the lumped masses, or, "
      "for families with several functions per node (Powell-Sabin), the "
      "inverses of the nodes' blocks of the matrix; cheap, and enough for "
      "the linear, B-spline and Powell-Sabin families. algebraic multigrid: "
      "Trilinos ML, set up from the matrix every step; for ill-conditioned "
      "matrices, as those of max-ent functions with a large 'Max-ent "
      "support factor' (2D, d_max = 3), on any number of ranks. direct per "
      "rank: a sparse direct factorisation of each rank's rows (Trilinos "
      "Ifpack with Amesos), set up every step: on one rank CG then needs "
      "few iterations, between ranks it is only block Jacobi.");
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::parse_parameters(ParameterHandler &prm)
  {
    const std::string name = prm.get("Mass matrix preconditioner");
    preconditioner_type =
      (name == "direct per rank") ?
        Preconditioner::direct_per_rank :
        ((name == "algebraic multigrid") ? Preconditioner::algebraic_multigrid :
                                           Preconditioner::diagonal);
  }



  template <int dim>
  bool
  ConsistentMassMatrix<dim>::find_groups(
    const ParticleShapeData<dim> &shape_data)
  {
    std::vector<unsigned int> previous_offsets;
    std::vector<unsigned int> previous_indices;
    previous_offsets.swap(group_offsets);
    previous_indices.swap(group_indices);
    group_offsets.assign(1, 0);
    group_indices.clear();
    group_first_point.clear();
    unsigned int group_start = 0;
    for (unsigned int b = 0; b < shape_data.n_batches(); ++b)
      {
        const unsigned int n = shape_data.n_functions(b);
        Assert(n > 0, ExcMessage("A point without shape functions."));
        const unsigned int *indices = shape_data.function_indices(b);
        const bool          same =
          b > 0 && group_indices.size() - group_start == n &&
          std::equal(indices, indices + n, group_indices.begin() + group_start);
        if (!same)
          {
            group_start = group_indices.size();
            group_first_point.push_back(shape_data.first_particle(b));
            group_indices.insert(group_indices.end(), indices, indices + n);
            group_offsets.push_back(group_indices.size());
          }
      }
    group_first_point.push_back(shape_data.n_particles());
    return group_offsets != previous_offsets ||
           group_indices != previous_indices;
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::assemble(const NodalSystem<dim>       &system,
                                      const ParticleShapeData<dim> &shape_data)
  {
    const bool groups_changed = find_groups(shape_data);

    // The matrix pays when a product with it (at most one entry per pair of
    // functions of a group) is cheaper than a point pass. All ranks decide
    // together: the products communicate differently.
    std::vector<double> local_counts(3, 0.);
    for (unsigned int g = 0; g + 1 < group_offsets.size(); ++g)
      local_counts[0] += Utilities::fixed_power<2>(
        double(group_offsets[g + 1] - group_offsets[g]));
    local_counts[1] = 2. * shape_data.values.size();
    local_counts[2] = groups_changed ? 1. : 0.;
    std::vector<double> counts(3);
    Utilities::MPI::sum(local_counts,
                        system.lumped_mass.get_mpi_communicator(),
                        counts);

    const bool preconditioner_needs_matrix =
      preconditioner_type != Preconditioner::diagonal ||
      system.functions_per_node() > 1;
    use_matrix = preconditioner_needs_matrix || counts[0] < counts[1];
    const bool pattern_changed = use_matrix && (!has_pattern || counts[2] > 0.);
    if (pattern_changed)
      build_sparsity(system);
    if (use_matrix)
      assemble_matrix(system, shape_data);
    else
      has_pattern = false;

    matrix_preconditioner.reset();
    node_blocks.clear();
    if (preconditioner_type != Preconditioner::diagonal)
      initialize_matrix_preconditioner(system, pattern_changed);
    else if (system.functions_per_node() > 1)
      extract_node_blocks(system);
    else
      {
        VectorType &inverse = inverse_lumped_mass.get_vector();
        inverse.reinit(system.lumped_mass, true);
        for (unsigned int i = 0; i < inverse.locally_owned_size(); ++i)
          {
            const double m           = system.lumped_mass.local_element(i);
            inverse.local_element(i) = (m > 0.) ? 1. / m : 1.;
          }
      }
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::build_sparsity(const NodalSystem<dim> &system)
  {
    const Utilities::MPI::Partitioner &partitioner = system.partitioner();
    const IndexSet &owned = partitioner.locally_owned_range();
    IndexSet        relevant(owned);
    relevant.add_indices(partitioner.ghost_indices());

    // Ghost rows are written here and sent to their owners in compress().
    TrilinosWrappers::SparsityPattern pattern(
      owned,
      owned,
      relevant,
      system.lumped_mass.get_mpi_communicator());
    std::vector<types::global_dof_index> global;
    for (unsigned int g = 0; g + 1 < group_offsets.size(); ++g)
      {
        global.clear();
        for (unsigned int a = group_offsets[g]; a < group_offsets[g + 1]; ++a)
          global.push_back(partitioner.local_to_global(group_indices[a]));
        for (const types::global_dof_index row : global)
          pattern.add_entries(row, global.begin(), global.end());
      }
    for (const types::global_dof_index row : owned)
      pattern.add(row, row);
    pattern.compress();

    if (!matrix)
      matrix = std::make_unique<TrilinosWrappers::SparseMatrix>();
    matrix->reinit(pattern);
    has_pattern = true;
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::assemble_matrix(
    const NodalSystem<dim>       &system,
    const ParticleShapeData<dim> &shape_data)
  {
    const Utilities::MPI::Partitioner &partitioner = system.partitioner();

    // Sum m_p phi_a phi_b over the points of each group into a dense block,
    // its upper triangle, then add the block to the matrix.
    *matrix = 0.;
    std::vector<double>                     block;
    std::vector<types::global_dof_index>    global;
    typename ParticleShapeData<dim>::Cursor functions(shape_data);
    for (unsigned int g = 0; g + 1 < group_offsets.size(); ++g)
      {
        const unsigned int n = group_offsets[g + 1] - group_offsets[g];
        block.assign(n * n, 0.);
        for (unsigned int k = group_first_point[g];
             k < group_first_point[g + 1];
             ++k)
          {
            const double  m   = system.particle_mass[k];
            const double *phi = functions.next().values;
            for (unsigned int a = 0; a < n; ++a)
              {
                const double m_phi = m * phi[a];
                double      *row   = &block[a * n];
                for (unsigned int b = a; b < n; ++b)
                  row[b] += m_phi * phi[b];
              }
          }
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < a; ++b)
            block[a * n + b] = block[b * n + a];

        global.resize(n);
        for (unsigned int a = 0; a < n; ++a)
          global[a] =
            partitioner.local_to_global(group_indices[group_offsets[g] + a]);
        for (unsigned int a = 0; a < n; ++a)
          matrix->add(global[a], n, global.data(), &block[a * n], false);
      }
    matrix->compress(VectorOperation::add);
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::extract_node_blocks(const NodalSystem<dim> &system)
  {
    const Utilities::MPI::Partitioner &partitioner = system.partitioner();
    const unsigned int                 n = system.functions_per_node();
    const unsigned int n_owned           = partitioner.locally_owned_size();
    AssertThrow(n_owned % n == 0 && partitioner.local_range().first % n == 0,
                ExcMessage("The functions of a node must have one owner."));
    node_blocks.resize(std::size_t(n_owned) * n);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const unsigned int node_start = i - i % n;
        for (unsigned int b = 0; b < n; ++b)
          node_blocks[std::size_t(i) * n + b] =
            matrix->el(partitioner.local_to_global(i),
                       partitioner.local_to_global(node_start + b));
      }
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::initialize_matrix_preconditioner(
    const NodalSystem<dim> &system,
    const bool              pattern_changed)
  {
    // The preconditioners factorise the matrix with the identity in the
    // rows and columns of the functions every solve prescribes: those
    // without material (lumped mass not positive, whose rows may be empty)
    // and the deactivated ones. For the others they then see M_ff.
    const Utilities::MPI::Partitioner &partitioner = system.partitioner();
    const IndexSet &owned        = partitioner.locally_owned_range();
    const MPI_Comm  communicator = system.lumped_mass.get_mpi_communicator();
    if (!preconditioner_matrix)
      preconditioner_matrix =
        std::make_unique<TrilinosWrappers::SparseMatrix>();
    if (pattern_changed)
      {
        // Every rank takes the same path in copy_from() below only if the
        // layouts are equal.
        preconditioner_matrix->reinit(*matrix);
        const Epetra_Map &column_map = matrix->trilinos_matrix().ColMap();
        IndexSet          columns(matrix->n());
        for (int c = 0; c < column_map.NumMyElements(); ++c)
          columns.add_index(column_map.GID(c));
        columns.compress();
        excluded_columns =
          std::make_unique<TrilinosWrappers::MPI::Vector>(owned,
                                                          columns,
                                                          communicator);
      }
    preconditioner_matrix->copy_from(*matrix);

    TrilinosWrappers::MPI::Vector excluded_owned(owned, communicator);
    for (unsigned int i = 0; i < partitioner.locally_owned_size(); ++i)
      if (!(system.lumped_mass.local_element(i) > 0.))
        excluded_owned[partitioner.local_to_global(i)] = 1.;
    for (const unsigned int i : system.deactivated_functions())
      excluded_owned[partitioner.local_to_global(i)] = 1.;
    excluded_owned.compress(VectorOperation::insert);
    *excluded_columns = excluded_owned;

    const Epetra_CrsMatrix &entries = preconditioner_matrix->trilinos_matrix();
    for (int row = 0; row < entries.NumMyRows(); ++row)
      {
        const types::global_dof_index global_row = entries.GRID(row);
        const bool row_excluded = (*excluded_columns)(global_row) != 0.;
        int        n_entries;
        double    *values;
        int       *columns;
        entries.ExtractMyRowView(row, n_entries, values, columns);
        for (int e = 0; e < n_entries; ++e)
          {
            const types::global_dof_index column = entries.GCID(columns[e]);
            if (row_excluded || (*excluded_columns)(column) != 0.)
              values[e] = (column == global_row) ? 1. : 0.;
          }
      }

    std::string failure;
    try
      {
        switch (preconditioner_type)
          {
            case Preconditioner::direct_per_rank:
              {
                auto direct = std::make_unique<
                  TrilinosWrappers::PreconditionBlockwiseDirect>();
                direct->initialize(*preconditioner_matrix);
                matrix_preconditioner = std::move(direct);
                break;
              }
            case Preconditioner::algebraic_multigrid:
              {
                auto multigrid =
                  std::make_unique<TrilinosWrappers::PreconditionAMG>();
                multigrid->initialize(*preconditioner_matrix);
                matrix_preconditioner = std::move(multigrid);
                break;
              }
            case Preconditioner::diagonal:
              Assert(false, ExcInternalError());
          }
      }
    catch (const std::exception &error)
      {
        failure = error.what();
      }
    const bool failed_somewhere =
      Utilities::MPI::max(failure.empty() ? 0 : 1,
                          system.lumped_mass.get_mpi_communicator()) == 1;
    AssertThrow(!failed_somewhere,
                ExcMessage("The preconditioner of the consistent mass matrix "
                           "('Mass matrix preconditioner') could not be set "
                           "up" +
                           (failure.empty() ? std::string(" on another rank") :
                                              ": " + failure) +
                           " Choose another 'Mass matrix preconditioner', or "
                           "'set Mass matrix = lumped'."));
  }



  template <int dim>
  bool
  ConsistentMassMatrix<dim>::is_consistent() const
  {
    return true;
  }



  template <int dim>
  void
  ConsistentMassMatrix<dim>::vmult(const NodalSystem<dim>       &system,
                                   const ParticleShapeData<dim> &shape_data,
                                   const VectorType             &vector,
                                   VectorType                   &product) const
  {
    const std::vector<unsigned int> none;
    product.zero_out_ghost_values();
    if (use_matrix)
      MatrixMassOperator<VectorType>(*matrix, none).vmult(product, vector);
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
    const auto           solve_with = [&](const auto &mass) {
      if (matrix_preconditioner)
        cg.solve(
          mass,
          solution,
          rhs,
          FreeCoefficientPreconditioner<VectorType>(*matrix_preconditioner,
                                                    prescribed));
      else if (system.functions_per_node() > 1)
        cg.solve(mass,
                 solution,
                 rhs,
                 NodeBlockPreconditioner(node_blocks,
                                         system.functions_per_node(),
                                         system.lumped_mass,
                                         prescribed));
      else
        cg.solve(mass, solution, rhs, inverse_lumped_mass);
    };
    try
      {
        if (use_matrix)
          solve_with(MatrixMassOperator<VectorType>(*matrix, prescribed));
        else
          solve_with(ParticleMassOperator<dim>(shape_data,
                                               system.particle_mass,
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
                   "support factor' in 2D and 3D. Use "
                << (preconditioner_type == Preconditioner::diagonal ?
                      "'set Mass matrix preconditioner = algebraic "
                      "multigrid', " :
                      "")
                << "'set Mass matrix = lumped', or a smaller 'Max-ent "
                   "support factor'.";
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
