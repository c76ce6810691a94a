#include <mpm_otm/base/plugins.h>
#include <mpm_otm/boundary_conditions/absorbing_condition.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/shape_functions/shape_functions.h>

namespace MpmOtm
{
  template <int dim>
  void
  AbsorbingCondition<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Density",
                      "0",
                      Patterns::Double(0.),
                      "Type = absorbing: the density rho of the material "
                      "at the side (kg/m^3), > 0.");
    prm.declare_entry("P-wave speed",
                      "0",
                      Patterns::Double(0.),
                      "Type = absorbing: c_p of the material at the side "
                      "(m/s), > 0; for an elastic material sqrt((lambda + "
                      "2 mu) / rho) = sqrt(E (1 - nu) / ((1 + nu) (1 - 2 "
                      "nu) rho)).");
    prm.declare_entry("S-wave speed",
                      "0",
                      Patterns::Double(0.),
                      "Type = absorbing: c_s of the material at the side "
                      "(m/s), >= 0; for an elastic material sqrt(mu / rho) "
                      "= sqrt(E / (2 (1 + nu) rho)).");
  }



  template <int dim>
  void
  AbsorbingCondition<dim>::parse_parameters(ParameterHandler &prm)
  {
    const std::string path = this->where.path();
    density                = prm.get_double("Density");
    p_wave_speed           = prm.get_double("P-wave speed");
    s_wave_speed           = prm.get_double("S-wave speed");
    AssertThrow(density > 0. && p_wave_speed > 0.,
                ExcMessage(path +
                           "Type = absorbing needs Density > 0 and P-wave "
                           "speed > 0 (the dashpots' impedance rho c_p); "
                           "given Density = " +
                           prm.get("Density") + ", P-wave speed = " +
                           prm.get("P-wave speed") + "."));
  }



  template <int dim>
  bool
  AbsorbingCondition<dim>::needs_normal() const
  {
    return true;
  }



  template <int dim>
  bool
  AbsorbingCondition<dim>::needs_lumped_mass() const
  {
    return true;
  }



  template <int dim>
  bool
  AbsorbingCondition<dim>::holds_nodes() const
  {
    return false;
  }



  template <int dim>
  void
  AbsorbingCondition<dim>::initialize(
    const ShapeFunctions<dim> &shape_functions)
  {
    functions = &shape_functions;
    shares.reinit(
      shape_functions.locally_owned_functions(),
      shape_functions.locally_relevant_functions(),
      shape_functions.dof_handler().get_triangulation().get_communicator());
    find_shares();
  }



  template <int dim>
  void
  AbsorbingCondition<dim>::find_shares()
  {
    shares = 0.;
    for (const auto id : this->where.boundary_ids)
      AssertThrow(functions->boundary_integrals(id, shares),
                  ExcMessage(this->where.path() +
                             "Type = absorbing needs the integrals of the "
                             "shape functions over the side, which this "
                             "family does not provide; use Shape functions "
                             "= linear, B-spline or max-ent."));
  }



  template <int dim>
  Tensor<1, dim>
  AbsorbingCondition<dim>::add_loads(NodalSystem<dim> &system,
                                     const double,
                                     const double dt)
  {
    const ConditionNodes<dim> &where = this->where;
    // The faces of a moving grid change in every step (collective on
    // every rank alike).
    if (!where.fixed_grid)
      find_shares();
    const Tensor<1, dim> &normal = where.normal;
    Tensor<1, dim>        load;
    for (const unsigned int i : where.functions)
      {
        const double m = system.lumped_mass.local_element(i);
        if (!(m > 0.))
          continue;
        Tensor<1, dim> momentum;
        for (unsigned int c = 0; c < dim; ++c)
          momentum[c] = system.momentum[c].local_element(i) +
                        dt * system.force[c].local_element(i);
        const double         impedance = shares.local_element(i) * density;
        const double         normal_momentum = momentum * normal;
        const Tensor<1, dim> tangential_momentum =
          momentum - normal_momentum * normal;
        const double normal_velocity =
          normal_momentum / (m + dt * impedance * p_wave_speed);
        const Tensor<1, dim> tangential_velocity =
          tangential_momentum / (m + dt * impedance * s_wave_speed);
        const Tensor<1, dim> force =
          -impedance * (p_wave_speed * normal_velocity * normal +
                        s_wave_speed * tangential_velocity);
        for (unsigned int c = 0; c < dim; ++c)
          system.force[c].local_element(i) += force[c];
        load += force;
      }
    return load;
  }



  template class AbsorbingCondition<1>;
  template class AbsorbingCondition<2>;
  template class AbsorbingCondition<3>;
} // namespace MpmOtm

MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<1>,
  MpmOtm::AbsorbingCondition<1>,
  "absorbing",
  "viscous (Lysmer-Kuhlemeyer) dashpots rho c_p v_n and rho c_s v_t that let "
  "waves leave through the side (planar), with 'Density', 'P-wave speed', "
  "'S-wave speed'")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<2>,
  MpmOtm::AbsorbingCondition<2>,
  "absorbing",
  "viscous (Lysmer-Kuhlemeyer) dashpots rho c_p v_n and rho c_s v_t that let "
  "waves leave through the side (planar), with 'Density', 'P-wave speed', "
  "'S-wave speed'")
MPM_OTM_REGISTER_PLUGIN(
  MpmOtm::Condition<3>,
  MpmOtm::AbsorbingCondition<3>,
  "absorbing",
  "viscous (Lysmer-Kuhlemeyer) dashpots rho c_p v_n and rho c_s v_t that let "
  "waves leave through the side (planar), with 'Density', 'P-wave speed', "
  "'S-wave speed'")
