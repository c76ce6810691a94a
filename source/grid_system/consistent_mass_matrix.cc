#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid_system/consistent_mass_matrix.h>


namespace MpmOtm
{
  namespace
  {
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
        // The excluded coefficients of src are zero (right-hand side and
        // initial guess are), so they do not couple to the others.
        src.update_ghost_values();
        dst             = 0.;
        const double *x = src.get_values();
        double       *y = dst.get_values();
        for (unsigned int k = 0; k < particle_mass.size(); ++k)
          {
            double interpolated = 0.;
            for (unsigned int e = shape_data.offsets[k];
                 e < shape_data.offsets[k + 1];
                 ++e)
              interpolated += shape_data.values[e] * x[shape_data.indices[e]];
            interpolated *= particle_mass[k];
            for (unsigned int e = shape_data.offsets[k];
                 e < shape_data.offsets[k + 1];
                 ++e)
              y[shape_data.indices[e]] += shape_data.values[e] * interpolated;
          }
        dst.compress(VectorOperation::add);
        src.zero_out_ghost_values();
        for (const unsigned int i : excluded)
          dst.local_element(i) = src.local_element(i);
      }

    private:
      const ParticleShapeData<dim>    &shape_data;
      const std::vector<double>       &particle_mass;
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

    const ParticleMassOperator<dim>     mass_operator(shape_data,
                                                  system.particle_mass,
                                                  excluded);
    const LumpedMassPreconditioner<dim> preconditioner(system.lumped_mass);
    SolverControl        control(1000, 1e-13 * norm, false, false);
    SolverCG<VectorType> cg(control);
    try
      {
        cg.solve(mass_operator, solution, rhs, preconditioner);
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
