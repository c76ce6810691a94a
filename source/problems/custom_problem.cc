#include <mpm_otm/base/plugins.h>
#include <mpm_otm/base/read_point.h>
#include <mpm_otm/base/subsection_names.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/grid/gmsh_file.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/problems/custom_problem.h>
#include <mpm_otm/problems/mesh_groups.h>

#include <algorithm>
#include <cmath>

namespace MpmOtm
{



  template <int dim>
  void
  CustomProblem<dim>::declare_parameters(ParameterHandler &prm)
  {
    const std::string zeros = (dim == 1 ? "0" : dim == 2 ? "0; 0" : "0; 0; 0");
    prm.enter_subsection("Custom problem");
    prm.declare_entry("Initial velocity",
                      zeros,
                      Patterns::Anything(),
                      "dim expressions in the initial position (x, y, z), "
                      "separated by ';' (without Bodies; a body has its "
                      "own).");
    prm.declare_entry("Body force",
                      zeros,
                      Patterns::Anything(),
                      "Body force per unit mass: dim expressions in the "
                      "initial position (x, y, z) and time t, separated by "
                      "';'.");
    prm.declare_entry("Material lower corner",
                      "",
                      Patterns::List(Patterns::Double(), 0, dim),
                      "Lower corner of the box filled with the default "
                      "material at t = 0 when no Bodies are given (empty: "
                      "the whole grid, for a Mesh file the cells of the "
                      "file).");
    prm.declare_entry("Material upper corner",
                      "",
                      Patterns::List(Patterns::Double(), 0, dim),
                      "Upper corner of the box filled with material at t = 0 "
                      "(empty: the whole grid).");
    prm.declare_entry("Fixed components",
                      "",
                      Patterns::Anything(),
                      "Velocity components fixed to zero per boundary id, "
                      "e.g. '0: x, y; 2: y' (box grids: 0 x_min, 1 x_max, 2 "
                      "y_min, 3 y_max, 4 z_min, 5 z_max; Mesh file: its "
                      "physical tags).");
    prm.declare_entry("Traction boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 5)),
                      "Boundary ids whose outermost material points carry "
                      "the traction below (box grids only).");
    prm.declare_entry("Traction",
                      zeros,
                      Patterns::Anything(),
                      "Traction (force per unit boundary measure): dim "
                      "expressions in t, separated by ';'.");
    prm.declare_entry("Exact displacement",
                      "",
                      Patterns::Anything(),
                      "Optional exact displacement: dim expressions in "
                      "(x, y, z, t); when given, errors are reported.");
    prm.leave_subsection();
  }



  template <int dim>
  void
  CustomProblem<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Custom problem");
    const std::string path = "Custom problem/";
    velocity =
      std::make_unique<ParsedExpression<dim>>(prm.get("Initial velocity"),
                                              dim,
                                              false,
                                              path + "Initial velocity");
    force = std::make_unique<ParsedExpression<dim>>(prm.get("Body force"),
                                                    dim,
                                                    true,
                                                    path + "Body force");
    fixed = this->parse_fixed_components(prm.get("Fixed components"),
                                         path + "Fixed components");
    traction_ids.clear();
    for (const int id : Utilities::string_to_int(
           Utilities::split_string_list(prm.get("Traction boundary ids"))))
      {
        AssertThrow(id < static_cast<int>(2 * dim),
                    ExcMessage(path + "Traction boundary ids: id " +
                               std::to_string(id) + " must be below " +
                               std::to_string(2 * dim) + "."));
        traction_ids.push_back(id);
      }
    traction_function =
      std::make_unique<ParsedExpression<dim>>(prm.get("Traction"),
                                              dim,
                                              true,
                                              path + "Traction");
    region.reset();
    if (!prm.get("Material lower corner").empty() ||
        !prm.get("Material upper corner").empty())
      {
        const Point<dim> p1 =
          read_point<dim>(prm.get("Material lower corner"),
                          "Custom problem/Material lower corner");
        const Point<dim> p2 =
          read_point<dim>(prm.get("Material upper corner"),
                          "Custom problem/Material upper corner");
        for (unsigned int d = 0; d < dim; ++d)
          AssertThrow(p2[d] > p1[d],
                      ExcMessage("Custom problem/Material upper corner must be "
                                 "above Material lower corner."));
        region = BoundingBox<dim>(std::make_pair(p1, p2));
      }
    displacement.reset();
    if (!prm.get("Exact displacement").empty())
      displacement =
        std::make_unique<ParsedExpression<dim>>(prm.get("Exact displacement"),
                                                dim,
                                                true,
                                                path + "Exact displacement");
    prm.leave_subsection();

    bodies.clear();
    for (const auto &name : SubsectionNames::names_in(prm, "Bodies"))
      {
        prm.enter_subsection("Body " + name);
        bodies.emplace_back();
        bodies.back().parse_parameters(prm, name, *this->materials);
        prm.leave_subsection();
      }
    AssertThrow(bodies.empty() || traction_ids.empty(),
                ExcMessage("Custom problem/Traction boundary ids: tractions "
                           "act on the sides of the box material region, "
                           "which Bodies replace; remove the Bodies or the "
                           "tractions (a prescribed velocity or a body force "
                           "may do instead)."));
    for (const auto &body : bodies)
      if (body.has_geostatic_stress())
        AssertThrow(this->has_gravity(),
                    ExcMessage("Body " + body.name() +
                               "/Initial stress = geostatic needs gravity: "
                               "set Gravity/Vector."));
  }



  template <int dim>
  bool
  CustomProblem<dim>::runs_on_any_grid() const
  {
    return true;
  }



  template <int dim>
  bool
  CustomProblem<dim>::defines_bodies() const
  {
    return true;
  }



  template <int dim>
  CustomProblem<dim>::~CustomProblem() = default;



  template <int dim>
  void
  CustomProblem<dim>::initialize(const Material<dim>       &material,
                                 const BackgroundGrid<dim> &grid)
  {
    Problem<dim>::initialize(material, grid);
    // Each Mesh file is read once, however many bodies are its groups.
    mesh_groups.clear();
    if constexpr (dim > 1)
      for (const auto &body : bodies)
        if (body.is_mesh_group() &&
            mesh_groups.find(body.group_mesh_file()) == mesh_groups.end())
          {
            const std::string &file = body.group_mesh_file();
            if (!file.empty())
              mesh_groups[file] = std::make_unique<MeshGroups<dim>>(
                GmshFile(file, dim, "Body " + body.name() + "/Mesh file"));
            else if (grid.gmsh_file() != nullptr)
              mesh_groups[file] =
                std::make_unique<MeshGroups<dim>>(*grid.gmsh_file());
          }
    for (auto &body : bodies)
      {
        const auto groups = mesh_groups.find(body.group_mesh_file());
        body.check_on_grid(grid,
                           groups == mesh_groups.end() ? nullptr :
                                                         groups->second.get());
      }
  }



  template <int dim>
  BoundingBox<dim>
  CustomProblem<dim>::material_region() const
  {
    AssertThrow(bodies.empty(),
                ExcMessage("This set-up needs the box material region of "
                           "'Custom problem/Material lower corner' and "
                           "'Material upper corner' (Method = OTM and "
                           "Unified mesh only the material, tractions act on "
                           "the region's sides), which Bodies replace: use "
                           "Method = MPM with Bodies, or no Bodies."));
    return region ? *region : this->grid_box;
  }



  template <int dim>
  Tensor<1, dim>
  CustomProblem<dim>::initial_velocity(const Point<dim> &X) const
  {
    if (bodies.empty())
      return velocity->vector_value(X);
    const unsigned int body = body_containing(X);
    Assert(body < bodies.size(), ExcInternalError());
    return bodies[body].initial_velocity(X);
  }



  template <int dim>
  unsigned int
  CustomProblem<dim>::n_bodies() const
  {
    return bodies.empty() ? 1 : bodies.size();
  }



  template <int dim>
  std::string
  CustomProblem<dim>::body_name(const unsigned int body) const
  {
    return bodies.empty() ? Problem<dim>::body_name(body) :
                            "Body " + bodies[body].name();
  }



  template <int dim>
  unsigned int
  CustomProblem<dim>::body_containing(const Point<dim> &X) const
  {
    if (bodies.empty())
      return Problem<dim>::body_containing(X);
    unsigned int found = numbers::invalid_unsigned_int;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if ((b >= present_bodies.size() || present_bodies[b]) &&
          bodies[b].contains(X))
        {
          AssertThrow(
            found == numbers::invalid_unsigned_int,
            ExcMessage(
              "Body " + bodies[found].name() + " and Body " + bodies[b].name() +
              " overlap at (" + Utilities::to_string(X[0]) +
              (dim > 1 ? ", " + Utilities::to_string(X[1]) : std::string()) +
              (dim > 2 ? ", " + Utilities::to_string(X[2]) : std::string()) +
              "): a material point can belong to one body "
              "only; change their shapes so that they do "
              "not overlap."));
          found = b;
        }
    return found;
  }



  template <int dim>
  unsigned int
  CustomProblem<dim>::material_id(const unsigned int body) const
  {
    return bodies.empty() ? 0 : bodies[body].material_id();
  }



  template <int dim>
  double
  CustomProblem<dim>::vertical_stress(const Point<dim> &X) const
  {
    // The density along the line is piecewise constant: integrate it in
    // steps, locating every change of body by bisection.
    // On the boundary between two bodies both contain x: the first counts
    // (a point of measure zero), where body_containing() would call it an
    // overlap.
    const auto density = [&](const Point<dim> &x) {
      unsigned int body = numbers::invalid_unsigned_int;
      for (unsigned int b = 0;
           b < bodies.size() && body == numbers::invalid_unsigned_int;
           ++b)
        if ((b >= present_bodies.size() || present_bodies[b]) &&
            bodies[b].contains(x))
          body = b;
      return body == numbers::invalid_unsigned_int ?
               0. :
               (*this->materials)[bodies[body].material_id()].density();
    };
    const double top = this->grid_box.get_boundary_points().second[dim - 1];
    const unsigned int n_steps = 400;
    const double       step    = std::max(top - X[dim - 1], 0.) / n_steps;
    double             weight  = 0;
    Point<dim>         lower   = X;
    double             rho     = density(lower);
    for (unsigned int k = 0; k < n_steps; ++k)
      {
        Point<dim> upper       = X;
        upper[dim - 1]         = X[dim - 1] + (k + 1) * step;
        const double rho_upper = density(upper);
        if (rho_upper == rho)
          weight += rho * step;
        else
          {
            double a = lower[dim - 1], b = upper[dim - 1];
            for (unsigned int i = 0; i < 50 && b - a > 1e-14 * step; ++i)
              {
                Point<dim> middle                = X;
                middle[dim - 1]                  = 0.5 * (a + b);
                (density(middle) == rho ? a : b) = middle[dim - 1];
              }
            weight +=
              rho * (a - lower[dim - 1]) + rho_upper * (upper[dim - 1] - a);
            rho = rho_upper;
          }
        lower = upper;
      }
    return this->gravity_vector[dim - 1] * weight;
  }



  template <int dim>
  std::pair<SymmetricTensor<2, dim>, double>
  CustomProblem<dim>::initial_stress(const Point<dim>  &X,
                                     const unsigned int body) const
  {
    if (bodies.empty())
      return Problem<dim>::initial_stress(X, body);
    if (!bodies[body].has_geostatic_stress())
      return bodies[body].initial_stress(X);
    const double            sigma_v = vertical_stress(X);
    const double            K0      = bodies[body].lateral_stress_ratio();
    SymmetricTensor<2, dim> sigma;
    for (unsigned int d = 0; d + 1 < dim; ++d)
      sigma[d][d] = K0 * sigma_v;
    sigma[dim - 1][dim - 1] = sigma_v;
    return {sigma, K0 * sigma_v};
  }



  template <int dim>
  void
  CustomProblem<dim>::set_present_bodies(const std::vector<bool> &present)
  {
    present_bodies = present;
  }



  template <int dim>
  bool
  CustomProblem<dim>::has_body_force() const
  {
    return !force->is_zero();
  }



  template <int dim>
  Tensor<1, dim>
  CustomProblem<dim>::body_force(const Point<dim> &X, const double time) const
  {
    return force->vector_value(X, time);
  }



  template <int dim>
  std::vector<FixedComponents<dim>>
  CustomProblem<dim>::fixed_components() const
  {
    return fixed;
  }



  template <int dim>
  std::vector<types::boundary_id>
  CustomProblem<dim>::traction_boundaries() const
  {
    return traction_ids;
  }



  template <int dim>
  Tensor<1, dim>
  CustomProblem<dim>::traction(const types::boundary_id,
                               const double time) const
  {
    return traction_function->vector_value(Point<dim>(), time);
  }



  template <int dim>
  bool
  CustomProblem<dim>::has_exact_solution() const
  {
    return displacement != nullptr;
  }



  template <int dim>
  bool
  CustomProblem<dim>::has_exact_stress() const
  {
    return false;
  }



  template <int dim>
  Tensor<1, dim>
  CustomProblem<dim>::exact_displacement(const Point<dim> &X,
                                         const double      time) const
  {
    return displacement->vector_value(X, time);
  }



  template class CustomProblem<1>;
  template class CustomProblem<2>;
  template class CustomProblem<3>;
} // namespace MpmOtm

#define MPM_OTM_CUSTOM_DESCRIPTION \
  "conditions given as expressions in subsection 'Custom problem'"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<1>,
                        MpmOtm::CustomProblem<1>,
                        "custom",
                        MPM_OTM_CUSTOM_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<2>,
                        MpmOtm::CustomProblem<2>,
                        "custom",
                        MPM_OTM_CUSTOM_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::Problem<3>,
                        MpmOtm::CustomProblem<3>,
                        "custom",
                        MPM_OTM_CUSTOM_DESCRIPTION)
