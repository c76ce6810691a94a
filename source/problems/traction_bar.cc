#include <deal.II/base/numbers.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/materials/material.h>
#include <mpm_otm/problems/traction_bar.h>

#include <cmath>
#include <sstream>

namespace MpmOtm
{
  template <int dim>
  void
  TractionBar<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Traction bar");
    prm.declare_entry("Bar length",
                      "1",
                      Patterns::Double(0),
                      "Initial length l of the bar (m): the material fills "
                      "[0, l] in x, so Mesh/Lower corner must be 0 in x, "
                      "Mesh/Upper corner at least l, and l must lie on a "
                      "block boundary of the grid (Mesh/Subdivisions).");
    prm.declare_entry("Amplitude",
                      "1",
                      Patterns::Double(),
                      "Factor A on the stress of journal Eq. 103 and so on "
                      "the traction and the exact solution. A = 1 is Eq. 103 "
                      "as printed: the pulse compresses the bar first and its "
                      "free end moves inward. A = -1 pulls the free end "
                      "outward first, into the grid's empty cells (the "
                      "set-up in which the journal's BSMPM breaks down).");
    prm.leave_subsection();
  }



  template <int dim>
  void
  TractionBar<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Traction bar");
    length    = prm.get_double("Bar length");
    amplitude = prm.get_double("Amplitude");
    prm.leave_subsection();
    AssertThrow(length > 0.,
                ExcMessage("Traction bar/Bar length must be positive."));
  }



  template <int dim>
  void
  TractionBar<dim>::initialize(const Material<dim>       &material,
                               const BackgroundGrid<dim> &grid)
  {
    Problem<dim>::initialize(material, grid);
    const BoundingBox<dim> &box       = grid.box();
    const double            lower     = box.get_boundary_points().first[0];
    const double            upper     = box.get_boundary_points().second[0];
    const double            tolerance = 1e-10 * length;
    {
      std::ostringstream message;
      message << "The traction bar is fixed at X = 0 and its material starts "
                 "at the grid's lower corner: set Mesh/Lower corner to 0 in x "
                 "(it is "
              << lower << ").";
      AssertThrow(std::abs(lower) <= tolerance, ExcMessage(message.str()));
    }
    {
      std::ostringstream message;
      message << "The grid must contain the bar [0, l], l = Traction "
                 "bar/Bar length = "
              << length << ": set Mesh/Upper corner to at least " << length
              << " in x (it is " << upper << ").";
      AssertThrow(upper >= length - tolerance, ExcMessage(message.str()));
    }
    c       = material.wave_speed();
    modulus = material.density() * c * c;
    omega   = numbers::PI / length;
    lateral = material.lambda() / (material.lambda() + 2. * material.mu());
  }



  template <int dim>
  BoundingBox<dim>
  TractionBar<dim>::material_region() const
  {
    auto corners      = this->grid_box.get_boundary_points();
    corners.first[0]  = 0.;
    corners.second[0] = length;
    return BoundingBox<dim>(corners);
  }



  template <int dim>
  Tensor<1, dim>
  TractionBar<dim>::initial_velocity(const Point<dim> &) const
  {
    return Tensor<1, dim>();
  }



  template <int dim>
  std::vector<FixedComponents<dim>>
  TractionBar<dim>::fixed_components() const
  {
    std::vector<FixedComponents<dim>> result{FixedComponents<dim>::all(0)};
    // The sides of a 2D or 3D bar: fixed in their normal direction only.
    for (unsigned int side = 2; side < 2 * dim; ++side)
      result.push_back(FixedComponents<dim>::normal(side));
    return result;
  }



  template <int dim>
  std::vector<types::boundary_id>
  TractionBar<dim>::traction_boundaries() const
  {
    return {1};
  }



  template <int dim>
  Tensor<1, dim>
  TractionBar<dim>::traction(const types::boundary_id boundary_id,
                             const double             time) const
  {
    Assert(boundary_id == 1, ExcInternalError());
    (void)boundary_id;
    Tensor<1, dim> tau;
    tau[0] = axial_stress(length, time);
    return tau;
  }



  template <int dim>
  bool
  TractionBar<dim>::has_exact_solution() const
  {
    return true;
  }



  template <int dim>
  double
  TractionBar<dim>::pulse(const double s) const
  {
    return (s >= length && s < 3. * length) ? std::sin(omega * s) : 0.;
  }



  template <int dim>
  double
  TractionBar<dim>::pulse_integral(const double s) const
  {
    // int_l^s sin(w r) dr = (cos(w l) - cos(w s)) / w, cos(w l) = -1; it
    // returns to 0 at s = 3l, so g is continuous.
    return (s >= length && s < 3. * length) ?
             -(1. + std::cos(omega * s)) / omega :
             0.;
  }



  template <int dim>
  double
  TractionBar<dim>::axial_stress(const double X, const double time) const
  {
    // Eq. 103: the pulse entering from X = l, f(c t + X), plus its
    // reflection at the fixed end, f(c t - X).
    return amplitude * (pulse(c * time + X) + pulse(c * time - X));
  }



  template <int dim>
  Tensor<1, dim>
  TractionBar<dim>::exact_displacement(const Point<dim> &X,
                                       const double      time) const
  {
    // (1/M) int_0^X (f(c t + s) + f(c t - s)) ds
    //   = (1/M) [(g(c t + X) - g(c t)) - (g(c t - X) - g(c t))].
    Tensor<1, dim> u;
    u[0] = amplitude *
           (pulse_integral(c * time + X[0]) - pulse_integral(c * time - X[0])) /
           modulus;
    return u;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  TractionBar<dim>::exact_stress(const Point<dim> &X, const double time) const
  {
    SymmetricTensor<2, dim> sigma;
    sigma[0][0] = axial_stress(X[0], time);
    for (unsigned int d = 1; d < dim; ++d)
      sigma[d][d] = lateral * sigma[0][0];
    return sigma;
  }



  template class TractionBar<1>;
  template class TractionBar<2>;
  template class TractionBar<3>;
} // namespace MpmOtm

#define MPM_OTM_TRACTION_BAR_DESCRIPTION \
  "bar fixed at X = 0, sine traction on its free end X = l (B2)"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<1>,
                        MpmOtm::TractionBar<1>,
                        "traction bar",
                        MPM_OTM_TRACTION_BAR_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<2>,
                        MpmOtm::TractionBar<2>,
                        "traction bar",
                        MPM_OTM_TRACTION_BAR_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<3>,
                        MpmOtm::TractionBar<3>,
                        "traction bar",
                        MPM_OTM_TRACTION_BAR_DESCRIPTION)
