#include <mpm_otm/grid_system/local_damping.h>
#include <mpm_otm/grid_system/nodal_system.h>

#include <cmath>
#include <limits>

namespace MpmOtm
{
  template <int dim>
  void
  LocalDamping<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Damping");
    prm.declare_entry("Local damping coefficient",
                      "0",
                      Patterns::Double(0., 1.),
                      "alpha in [0, 1) of local (Cundall) damping: each nodal "
                      "force component is reduced by alpha |f| against the "
                      "nodal velocity. 0: no damping. About 0.1-0.8 brings a "
                      "body to static equilibrium in a few of its periods.");
    prm.declare_entry("End time",
                      "1e300",
                      Patterns::Double(0.),
                      "Damping acts while t < End time (s); afterwards the "
                      "run is undamped (a dynamic phase after reaching "
                      "equilibrium).");
    prm.leave_subsection();
  }



  template <int dim>
  void
  LocalDamping<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Damping");
    coefficient = prm.get_double("Local damping coefficient");
    end_time    = prm.get_double("End time");
    prm.leave_subsection();
    AssertThrow(coefficient < 1.,
                ExcMessage("Damping/Local damping coefficient must be below "
                           "1 (at 1 the force would vanish)."));
  }



  template <int dim>
  bool
  LocalDamping<dim>::is_active(const double time) const
  {
    return coefficient > 0. && time < end_time;
  }



  template <int dim>
  void
  LocalDamping<dim>::set_coefficient(const double alpha)
  {
    AssertThrow(alpha >= 0. && alpha < 1., ExcInternalError());
    coefficient = alpha;
  }



  template <int dim>
  void
  LocalDamping<dim>::apply(NodalSystem<dim> &system) const
  {
    for (unsigned int i = 0; i < system.lumped_mass.locally_owned_size(); ++i)
      for (unsigned int c = 0; c < dim; ++c)
        {
          const double momentum = system.momentum[c].local_element(i);
          double      &force    = system.force[c].local_element(i);
          if (momentum != 0.)
            {
              const double damping_force =
                -coefficient * std::abs(force) * (momentum > 0. ? 1. : -1.);
              force += damping_force;
              system.damping_force[c].local_element(i) = damping_force;
            }
        }
  }



  template class LocalDamping<1>;
  template class LocalDamping<2>;
  template class LocalDamping<3>;
} // namespace MpmOtm
