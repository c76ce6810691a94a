#include <mpm_otm/algorithms/quasi_static_end.h>
#include <mpm_otm/grid_system/nodal_system.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace MpmOtm
{
  template <int dim>
  void
  QuasiStaticEnd<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Quasi-static end");
    prm.declare_entry(
      "Kinetic energy ratio",
      "0",
      Patterns::Double(0., 1.),
      "End the run when the body is at rest: when the kinetic energy of the "
      "grid's motion, sum_i m_i |v_i|^2 / 2, stays at or below this fraction "
      "of the largest it has had in the run (or of the work of the loads, "
      "if that is larger) for 'Checks' checks in a row, one every 10 steps "
      "(e.g. 1e-6). A run that reaches its end time still moving is "
      "reported with the trend of that energy (manual, 'Quasi-static "
      "end'). 0: off, the run goes to its end time.");
    prm.declare_entry("Checks",
                      "10",
                      Patterns::Integer(1),
                      "Number of consecutive checks (one every 10 steps) at "
                      "rest that end the run.");
    prm.leave_subsection();
  }



  template <int dim>
  void
  QuasiStaticEnd<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Quasi-static end");
    tolerance       = prm.get_double("Kinetic energy ratio");
    required_checks = prm.get_integer("Checks");
    prm.leave_subsection();
  }



  template <int dim>
  bool
  QuasiStaticEnd<dim>::enabled() const
  {
    return tolerance > 0.;
  }



  template <int dim>
  bool
  QuasiStaticEnd<dim>::check(const NodalSystem<dim> &system,
                             const double            time,
                             const double            supplied_work)
  {
    const double energy    = system.kinetic_energy();
    largest_kinetic_energy = std::max(largest_kinetic_energy, energy);
    work                   = supplied_work - work_at_start;
    history.emplace_back(time, energy);
    const double reference = std::max(largest_kinetic_energy, work);
    checks_at_rest = (energy <= tolerance * reference) ? checks_at_rest + 1 : 0;
    return at_rest();
  }



  template <int dim>
  void
  QuasiStaticEnd<dim>::restart(const double supplied_work)
  {
    checks_at_rest         = 0;
    largest_kinetic_energy = 0;
    work                   = 0;
    work_at_start          = supplied_work;
    history.clear();
  }



  template <int dim>
  bool
  QuasiStaticEnd<dim>::at_rest() const
  {
    return enabled() && checks_at_rest >= required_checks;
  }



  template <int dim>
  std::string
  QuasiStaticEnd<dim>::summary() const
  {
    std::ostringstream text;
    text << std::setprecision(3);
    if (history.empty())
      return "no step checked";
    const auto &[time, energy] = history.back();
    const double reference     = std::max(largest_kinetic_energy, work);
    const double ratio         = reference > 0. ? energy / reference : 0.;
    if (at_rest())
      {
        text << "at rest at t = " << time
             << ": the kinetic energy of the grid's motion, " << energy
             << " J, has stayed at or below " << tolerance
             << " x its reference " << reference << " J for " << required_checks
             << " checks";
        return text.str();
      }
    // The trend over the last tenth of the checks.
    const auto &[earlier_time, earlier_energy] =
      history[history.size() - 1 - history.size() / 10];
    text << "not at rest at t = " << time
         << ": the kinetic energy of the grid's motion is " << energy << " J, "
         << ratio << " x its reference " << reference
         << " J (the largest so far, or the work of the loads)";
    if (earlier_time < time)
      {
        text << "; since t = " << earlier_time << " it ";
        if (energy >= 0.5 * earlier_energy)
          text << "has not decayed (from " << earlier_energy
               << " J): the body is failing, or the run too short to stop "
                  "it";
        else
          text << "has fallen from " << earlier_energy
               << " J: the body is coming to rest; a longer End time may "
                  "reach it";
      }
    return text.str();
  }



  template <int dim>
  void
  QuasiStaticEnd<dim>::save(CheckpointState &state) const
  {
    std::vector<double> values = {double(checks_at_rest),
                                  largest_kinetic_energy,
                                  work,
                                  work_at_start};
    for (const auto &[time, energy] : history)
      values.insert(values.end(), {time, energy});
    state.set_shared("quasi-static end", values);
  }



  template <int dim>
  void
  QuasiStaticEnd<dim>::load(const CheckpointState &state)
  {
    const auto values      = state.shared("quasi-static end");
    checks_at_rest         = static_cast<unsigned int>(values.at(0));
    largest_kinetic_energy = values.at(1);
    work                   = values.at(2);
    work_at_start          = values.at(3);
    history.clear();
    for (std::size_t k = 4; k + 1 < values.size(); k += 2)
      history.emplace_back(values[k], values[k + 1]);
  }



  template class QuasiStaticEnd<1>;
  template class QuasiStaticEnd<2>;
  template class QuasiStaticEnd<3>;
} // namespace MpmOtm
