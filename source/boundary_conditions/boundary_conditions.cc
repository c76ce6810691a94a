#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <mpm_otm/base/subsection_names.h>
#include <mpm_otm/boundary_conditions/boundary_conditions.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/grid_system/mass_matrix.h>
#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/particle_shape_data.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace MpmOtm
{
  namespace
  {
    /**
     * The unit normal of boundary face @p f of @p cell, pointing out of the
     * cell.
     */
    template <int dim>
    Tensor<1, dim>
    outward_normal(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      const unsigned int                                       f)
    {
      const auto     face = cell->face(f);
      Tensor<1, dim> normal;
      if constexpr (dim == 1)
        normal[0] = 1.;
      else if constexpr (dim == 2)
        {
          const Tensor<1, 2> tangent = face->vertex(1) - face->vertex(0);
          normal[0]                  = tangent[1];
          normal[1]                  = -tangent[0];
        }
      else
        {
          const Tensor<1, 3> a = face->vertex(1) - face->vertex(0);
          const Tensor<1, 3> b =
            face->vertex(face->n_vertices() - 1) - face->vertex(0);
          normal = cross_product_3d(a, b);
        }
      normal /= normal.norm();
      if ((face->center() - cell->center()) * normal < 0.)
        normal = -normal;
      return normal;
    }
  } // namespace



  template <int dim>
  void
  BoundaryConditions<dim>::declare_parameters(
    ParameterHandler               &prm,
    const std::vector<std::string> &names)
  {
    const std::string zeros = (dim == 1 ? "0" : dim == 2 ? "0; 0" : "0; 0; 0");
    for (const auto &name : names)
      {
        prm.enter_subsection("Boundary " + name);
        prm.declare_entry(
          "Type",
          "fixed",
          Patterns::Selection("fixed|slip|friction|velocity"),
          "fixed: velocity zero; slip: normal velocity zero, tangential "
          "free (the boundary must be planar); friction: Coulomb friction "
          "with 'Friction coefficient' (the material may separate from the "
          "wall; planar boundary); velocity: the components 'Velocity "
          "components' prescribed to 'Velocity', the others free.");
        prm.declare_entry("Boundary ids",
                          "",
                          Patterns::List(Patterns::Integer(0)),
                          "Boundary ids the condition acts on (box grids: 0 "
                          "x_min, 1 x_max, 2 y_min, 3 y_max, 4 z_min, 5 "
                          "z_max; Mesh file: its physical tags, 0 on "
                          "untagged faces); empty: the grid vertices in the "
                          "box below.");
        prm.declare_entry("Box lower corner",
                          "",
                          Patterns::List(Patterns::Double(), 0, dim),
                          "With no Boundary ids: the condition acts on the "
                          "functions of the grid vertices in this box (e.g. "
                          "a footing or a platen; Type = fixed or "
                          "velocity).");
        prm.declare_entry("Box upper corner",
                          "",
                          Patterns::List(Patterns::Double(), 0, dim),
                          "Upper corner of that box.");
        prm.declare_entry("Friction coefficient",
                          "0",
                          Patterns::Double(),
                          "Type = friction: Coulomb coefficient mu >= 0.");
        prm.declare_entry("Velocity",
                          zeros,
                          Patterns::Anything(),
                          "Type = velocity: dim expressions in t (m/s), "
                          "separated by ';'.");
        prm.declare_entry("Velocity components",
                          std::string("xyz").substr(0, 1) +
                            (dim > 1 ? ", y" : "") + (dim > 2 ? ", z" : ""),
                          Patterns::List(Patterns::Selection("x|y|z")),
                          "Type = velocity: the components prescribed; the "
                          "others are free.");
        prm.leave_subsection();
      }
  }



  template <int dim>
  void
  BoundaryConditions<dim>::parse_parameters(ParameterHandler &prm)
  {
    conditions.clear();
    for (const auto &name : SubsectionNames::names_in(prm, "Boundaries"))
      {
        const std::string path = "Boundary " + name + "/";
        prm.enter_subsection("Boundary " + name);
        Condition condition;
        condition.name         = name;
        const std::string type = prm.get("Type");
        condition.type         = type == "fixed"    ? Type::fixed :
                                 type == "slip"     ? Type::slip :
                                 type == "friction" ? Type::friction :
                                                      Type::velocity;
        for (const int id : Utilities::string_to_int(
               Utilities::split_string_list(prm.get("Boundary ids"))))
          condition.boundary_ids.push_back(id);
        const auto lower = Utilities::string_to_double(
          Utilities::split_string_list(prm.get("Box lower corner")));
        const auto upper = Utilities::string_to_double(
          Utilities::split_string_list(prm.get("Box upper corner")));
        condition.on_box = condition.boundary_ids.empty();
        if (condition.on_box)
          {
            AssertThrow(lower.size() == dim && upper.size() == dim,
                        ExcMessage(path +
                                   "Boundary ids is empty, so Box lower "
                                   "corner and Box upper corner must give " +
                                   std::to_string(dim) + " values each."));
            Point<dim> p1, p2;
            for (unsigned int d = 0; d < dim; ++d)
              {
                p1[d] = lower[d];
                p2[d] = upper[d];
                AssertThrow(p2[d] >= p1[d],
                            ExcMessage(path + "Box upper corner must not be "
                                              "below Box lower corner."));
              }
            condition.box = BoundingBox<dim>(std::make_pair(p1, p2));
            AssertThrow(condition.type == Type::fixed ||
                          condition.type == Type::velocity,
                        ExcMessage(path + "Type = " + type +
                                   " needs a boundary with a normal: give "
                                   "Boundary ids (a box of nodes takes "
                                   "Type = fixed or velocity)."));
          }
        else
          AssertThrow(lower.empty() && upper.empty(),
                      ExcMessage(path + "give either Boundary ids or a box "
                                        "(Box lower/upper corner), not "
                                        "both."));
        condition.friction_coefficient = prm.get_double("Friction coefficient");
        AssertThrow(condition.friction_coefficient >= 0.,
                    ExcMessage(path + "Friction coefficient = " +
                               prm.get("Friction coefficient") +
                               " must be >= 0."));
        condition.components.fill(condition.type != Type::velocity);
        if (condition.type == Type::velocity)
          {
            for (const auto &component :
                 Utilities::split_string_list(prm.get("Velocity components")))
              {
                const unsigned int c = component[0] - 'x';
                AssertThrow(c < dim,
                            ExcMessage(path + "Velocity components: <" +
                                       component + "> is not a direction in " +
                                       std::to_string(dim) + "D."));
                condition.components[c] = true;
              }
            // The velocity is a function of time only (the condition's
            // nodes move as one).
            condition.velocity =
              std::make_unique<ParsedExpression<dim>>(prm.get("Velocity"),
                                                      dim,
                                                      true,
                                                      path + "Velocity",
                                                      false);
            condition.velocity->vector_value(Point<dim>(), 0.);
          }
        prm.leave_subsection();
        conditions.push_back(std::move(condition));
      }
  }



  template <int dim>
  bool
  BoundaryConditions<dim>::empty() const
  {
    return conditions.empty();
  }



  template <int dim>
  void
  BoundaryConditions<dim>::setup(const ShapeFunctions<dim> &shape_functions,
                                 const BackgroundGrid<dim> &grid)
  {
    const auto &triangulation = grid.triangulation();
    communicator              = triangulation.get_communicator();
    functions                 = &shape_functions;
    background_grid           = &grid;
    const IndexSet owned      = shape_functions.locally_owned_functions();
    for (auto &condition : conditions)
      {
        const std::string path = "Boundary " + condition.name + "/";
        condition.functions.clear();
        if (condition.on_box)
          {
            find_box_functions(condition);
            AssertThrow(
              Utilities::MPI::sum(condition.functions.size(), communicator) > 0,
              ExcMessage(path +
                         "Box lower corner, Box upper corner: the box holds "
                         "no node of the grid (linear, max-ent: no vertex; "
                         "B-splines: no Greville point), so the condition "
                         "would act on nothing; enlarge the box to hold the "
                         "nodes it should act on."));
            refuse_nodes_on_box_sides(condition);
          }
        else
          {
            for (const auto id : condition.boundary_ids)
              for (const auto function : shape_functions.boundary_functions(id))
                if (owned.is_element(function))
                  condition.functions.push_back(
                    owned.index_within_set(function));

            // The outward normal: the mean of the normals of the condition's
            // faces (on this rank, collected once), which must all be equal
            // for slip and friction.
            std::vector<Tensor<1, dim>> normals;
            std::vector<Point<dim>>     centers;
            double cell_depth = std::numeric_limits<double>::infinity();
            std::vector<double> faces_per_id(condition.boundary_ids.size(), 0.);
            for (const auto &cell : triangulation.active_cell_iterators())
              if (cell->is_locally_owned())
                for (const unsigned int f : cell->face_indices())
                  if (cell->face(f)->at_boundary())
                    {
                      const auto id = std::find(condition.boundary_ids.begin(),
                                                condition.boundary_ids.end(),
                                                cell->face(f)->boundary_id());
                      if (id == condition.boundary_ids.end())
                        continue;
                      faces_per_id[id - condition.boundary_ids.begin()] += 1.;
                      normals.push_back(outward_normal<dim>(cell, f));
                      centers.push_back(cell->face(f)->center());
                      // Twice the distance from the face to the cell's
                      // centre: the cell's depth for quadrilaterals and
                      // hexahedra, two thirds (triangles) or a half
                      // (tetrahedra) of it for simplices.
                      cell_depth =
                        std::min(cell_depth,
                                 2. *
                                   std::abs(normals.back() *
                                            (cell->center() - centers.back())));
                    }
            Tensor<1, dim> sum;
            for (const auto &normal : normals)
              sum += normal;
            double n_faces = normals.size();
            sum            = Utilities::MPI::sum(sum, communicator);
            n_faces        = Utilities::MPI::sum(n_faces, communicator);
            Utilities::MPI::sum(faces_per_id, communicator, faces_per_id);
            // Every listed id must have faces: one without any would be
            // a condition acting on nothing.
            for (unsigned int i = 0; i < faces_per_id.size(); ++i)
              if (!(faces_per_id[i] > 0))
                {
                  std::string ids;
                  for (const auto id : grid.boundary_ids())
                    ids += (ids.empty() ? "" : ", ") + std::to_string(id);
                  AssertThrow(false,
                              ExcMessage(
                                path +
                                "Boundary ids: no face of the grid "
                                "has the id " +
                                std::to_string(condition.boundary_ids[i]) +
                                "; the grid's boundary ids are " + ids +
                                " (box grids: the sides 0 to " +
                                std::to_string(2 * dim - 1) +
                                "; Mesh file: its physical tags, 0 on "
                                "untagged faces)."));
                }
            // Faces that face each other (e.g. sides 0 and 1 in one
            // condition) have no mean normal: not planar.
            const bool has_normal = sum.norm() > 1e-8 * n_faces;
            condition.normal =
              has_normal ? Tensor<1, dim>(sum / sum.norm()) : Tensor<1, dim>();
            double deviation = has_normal ? 0. : 1.;
            double offset    = 0.;
            for (const auto &normal : normals)
              deviation =
                std::max(deviation, (normal - condition.normal).norm());
            for (const auto &center : centers)
              offset += condition.normal * center;
            deviation = Utilities::MPI::max(deviation, communicator);
            condition.wall_offset =
              Utilities::MPI::sum(offset, communicator) / n_faces;
            condition.cell_depth =
              Utilities::MPI::min(cell_depth, communicator);
            AssertThrow(deviation < 1e-8 || condition.type == Type::fixed ||
                          condition.type == Type::velocity,
                        ExcMessage(path + "Type = slip and friction need a "
                                          "planar boundary, but the faces "
                                          "of these Boundary ids have "
                                          "different normals; give each "
                                          "planar part its own id."));
          }
        std::sort(condition.functions.begin(), condition.functions.end());
        condition.functions.erase(std::unique(condition.functions.begin(),
                                              condition.functions.end()),
                                  condition.functions.end());
        condition.reaction_sum = Tensor<1, dim>();
        condition.displacement = Tensor<1, dim>();
        condition.n_steps      = 0;
      }
  }



  template <int dim>
  void
  BoundaryConditions<dim>::check_travel_into_grid(const double end_time) const
  {
    for (const auto &condition : conditions)
      {
        if (condition.type != Type::velocity || condition.on_box ||
            condition.normal.norm() == 0.)
          continue;
        // The displacement of the prescribed components against the outward
        // normal, by the trapezoidal rule, and its largest value in the run.
        const auto inward_velocity = [&](const double t) {
          const Tensor<1, dim> velocity =
            condition.velocity->vector_value(Point<dim>(), t);
          double inward = 0.;
          for (unsigned int d = 0; d < dim; ++d)
            if (condition.components[d])
              inward -= velocity[d] * condition.normal[d];
          return inward;
        };
        const unsigned int n_intervals = 10000;
        const double       dt          = end_time / n_intervals;
        double previous = inward_velocity(0.), travel = 0., largest = 0.;
        for (unsigned int i = 1; i <= n_intervals; ++i)
          {
            const double current = inward_velocity(i * dt);
            travel += 0.5 * dt * (previous + current);
            largest  = std::max(largest, travel);
            previous = current;
          }
        std::ostringstream message;
        message << "Boundary " << condition.name
                << "/Velocity moves the grid side of its Boundary ids "
                << largest
                << " m into the grid before the End time, more than half the "
                   "depth of the cells along that side ("
                << 0.5 * condition.cell_depth
                << " m). MPM's grid stays where it is: once the material "
                   "has moved that far from the side, the side's nodes hold "
                   "less and less of it, and the condition's reaction stops "
                   "being the load on it (a platen loses its specimen). Give "
                   "the condition Box lower corner and Box upper corner "
                   "instead of Boundary ids (the box follows the "
                   "displacement: manual, 'Boundary conditions'), or a "
                   "shorter Time/End time.";
        AssertThrow(!(largest > 0.5 * condition.cell_depth),
                    ExcMessage(message.str()));
      }
  }



  template <int dim>
  void
  BoundaryConditions<dim>::refuse_nodes_on_box_sides(
    const Condition &condition) const
  {
    // Move each side of the box in and out by a margin far above round-off
    // and far below any placement a user means; if that changes the nodes
    // it holds, nodes lie on that side. Sides on or beyond the grid's own
    // sides hold the grid's boundary nodes without ambiguity.
    const double     margin = 1e-9 * background_grid->minimal_cell_size();
    const Point<dim> grid_lower =
      background_grid->box().get_boundary_points().first;
    const Point<dim> grid_upper =
      background_grid->box().get_boundary_points().second;
    const Point<dim> lower = condition.box.get_boundary_points().first;
    const Point<dim> upper = condition.box.get_boundary_points().second;
    for (unsigned int d = 0; d < dim; ++d)
      for (const bool upper_side : {false, true})
        {
          const double side = upper_side ? upper[d] : lower[d];
          if (upper_side ? !(side < grid_upper[d] - margin) :
                           !(side > grid_lower[d] + margin))
            continue;
          std::vector<types::global_dof_index> inside, outside;
          for (const double shift : {-margin, margin})
            {
              Point<dim> moved_lower = lower, moved_upper = upper;
              (upper_side ? moved_upper : moved_lower)[d] += shift;
              functions->functions_in_box(
                BoundingBox<dim>(std::make_pair(moved_lower, moved_upper)),
                (shift < 0.) == upper_side ? inside : outside);
            }
          const unsigned int on_side =
            Utilities::MPI::sum(static_cast<unsigned int>(outside.size() -
                                                          inside.size()),
                                communicator);
          std::ostringstream message;
          message << "Boundary " << condition.name
                  << "/Box lower corner, Box upper corner: " << on_side
                  << " node(s) of the grid lie on the box's side "
                  << static_cast<char>('x' + d) << " = " << side
                  << ", inside the grid, so round-off decides whether the "
                     "condition holds them (linear, max-ent: the vertices; "
                     "B-splines: the Greville points, at the centres of the "
                     "cells away from the grid's sides). Move that side off "
                     "the row of nodes, e.g. by a tenth of a cell.";
          AssertThrow(on_side == 0, ExcMessage(message.str()));
        }
  }



  template <int dim>
  void
  BoundaryConditions<dim>::find_box_functions(Condition &condition) const
  {
    IndexSet owned = functions->locally_owned_functions();
    owned.compress();
    Point<dim> lower = condition.box.get_boundary_points().first;
    Point<dim> upper = condition.box.get_boundary_points().second;
    lower += condition.displacement;
    upper += condition.displacement;
    const BoundingBox<dim>               box(std::make_pair(lower, upper));
    std::vector<types::global_dof_index> global;
    AssertThrow(functions->functions_in_box(box, global),
                ExcMessage("Boundary " + condition.name +
                           "/Box lower corner: a condition on the nodes in "
                           "a box needs shape functions that belong to "
                           "points (linear, max-ent: vertices; B-splines: "
                           "Greville points); use Boundary ids instead."));
    condition.functions.clear();
    for (const auto function : global)
      condition.functions.push_back(owned.index_within_set(function));
  }



  template <int dim>
  std::vector<FixedComponents<dim>>
  BoundaryConditions<dim>::fixed_components() const
  {
    std::vector<FixedComponents<dim>> result;
    for (const auto &condition : conditions)
      if (!condition.on_box)
        for (const auto id : condition.boundary_ids)
          {
            if (condition.type == Type::fixed)
              result.push_back(FixedComponents<dim>::all(id));
            else if (condition.type == Type::slip)
              for (unsigned int d = 0; d < dim; ++d)
                if (std::abs(std::abs(condition.normal[d]) - 1.) < 1e-12)
                  {
                    FixedComponents<dim> fixed{id, {}};
                    fixed.fixed.fill(false);
                    fixed.fixed[d] = true;
                    result.push_back(fixed);
                  }
          }
    return result;
  }



  template <int dim>
  Tensor<1, dim>
  BoundaryConditions<dim>::corrected_velocity(const Condition      &condition,
                                              const Tensor<1, dim> &v,
                                              const double          time) const
  {
    const double normal_velocity = v * condition.normal;
    switch (condition.type)
      {
        case Type::fixed:
          return Tensor<1, dim>();
        case Type::slip:
          return v - normal_velocity * condition.normal;
        case Type::friction:
          {
            if (normal_velocity <= 0.)
              return v;
            const Tensor<1, dim> tangential =
              v - normal_velocity * condition.normal;
            const double speed = tangential.norm();
            const double reduction =
              std::min(condition.friction_coefficient * normal_velocity, speed);
            return speed > 0. ? tangential * (1. - reduction / speed) :
                                tangential;
          }
        default:
          {
            Tensor<1, dim>       result = v;
            const Tensor<1, dim> prescribed =
              condition.velocity->vector_value(Point<dim>(), time);
            for (unsigned int d = 0; d < dim; ++d)
              if (condition.components[d])
                result[d] = prescribed[d];
            return result;
          }
      }
  }



  template <int dim>
  void
  BoundaryConditions<dim>::measure_gaps(
    const MaterialPoints<dim>    &material_points,
    const ParticleShapeData<dim> &data,
    const NodalSystem<dim>       &system)
  {
    for (auto &condition : conditions)
      {
        if (condition.type != Type::friction)
          continue;
        const auto &partitioner = system.lumped_mass.get_partitioner();
        if (condition.gap.get_partitioner() != partitioner)
          condition.gap.reinit(partitioner);
        double *const gap = condition.gap.get_values();
        std::fill(gap,
                  gap + partitioner->locally_owned_size() +
                    partitioner->n_ghost_indices(),
                  std::numeric_limits<double>::max());
        typename ParticleShapeData<dim>::Cursor functions(data);
        for (const auto &particle : material_points.particle_handler())
          {
            const auto   point = functions.next();
            const double half_size =
              0.5 *
              std::pow(PropertyLayout<dim>::volume(particle.get_properties()),
                       1. / dim);
            const double point_gap =
              condition.wall_offset -
              condition.normal * particle.get_location() - half_size;
            for (unsigned int j = 0; j < point.n; ++j)
              if (point.values[j] != 0.)
                gap[point.indices[j]] =
                  std::min(gap[point.indices[j]], point_gap);
          }
        condition.gap.compress(VectorOperation::min);
      }
  }



  template <int dim>
  std::array<bool, dim>
  BoundaryConditions<dim>::constrained_components(
    const Condition &condition) const
  {
    std::array<bool, dim> result{};
    switch (condition.type)
      {
        case Type::fixed:
          result.fill(true);
          break;
        case Type::slip:
          for (unsigned int d = 0; d < dim; ++d)
            result[d] = std::abs(std::abs(condition.normal[d]) - 1.) < 1e-12;
          break;
        case Type::velocity:
          result = condition.components;
          break;
        default:
          break;
      }
    return result;
  }



  template <int dim>
  void
  BoundaryConditions<dim>::make_acceleration_constraints(
    const NodalSystem<dim>                 &system,
    const double                            time,
    const double                            dt,
    typename NodalSystem<dim>::Constraints &constraints)
  {
    // A box of prescribed velocity moves with its displacement.
    for (auto &condition : conditions)
      if (condition.on_box && condition.type == Type::velocity)
        find_box_functions(condition);
    add_prescribed_lines(
      system,
      time + dt,
      [&](const unsigned int i, const unsigned int c, const double target) {
        return (target - system.momentum[c].local_element(i) /
                           system.lumped_mass.local_element(i)) /
               dt;
      },
      constraints);
  }



  template <int dim>
  void
  BoundaryConditions<dim>::make_velocity_constraints(
    const NodalSystem<dim>                 &system,
    const double                            time,
    typename NodalSystem<dim>::Constraints &constraints) const
  {
    add_prescribed_lines(
      system,
      time,
      [](const unsigned int, const unsigned int, const double target) {
        return target;
      },
      constraints);
  }



  template <int dim>
  void
  BoundaryConditions<dim>::add_prescribed_lines(
    const NodalSystem<dim>                                          &system,
    const double                                                     time,
    const std::function<double(unsigned int, unsigned int, double)> &value,
    typename NodalSystem<dim>::Constraints &constraints) const
  {
    for (unsigned int c = 0; c < dim; ++c)
      constraints[c].copy_from(system.constraints()[c]);
    const Utilities::MPI::Partitioner &partitioner = system.partitioner();
    for (const auto &condition : conditions)
      {
        const std::array<bool, dim> components =
          constrained_components(condition);
        if (std::none_of(components.begin(), components.end(), [](bool b) {
              return b;
            }))
          continue;
        const Tensor<1, dim> target =
          corrected_velocity(condition, Tensor<1, dim>(), time);
        for (const unsigned int i : condition.functions)
          {
            if (!(system.lumped_mass.local_element(i) > 0.))
              continue;
            const types::global_dof_index global =
              partitioner.local_to_global(i);
            for (unsigned int c = 0; c < dim; ++c)
              if (components[c])
                {
                  constraints[c].add_line(global);
                  constraints[c].set_inhomogeneity(global,
                                                   value(i, c, target[c]));
                }
          }
      }
  }



  template <int dim>
  void
  BoundaryConditions<dim>::constrain_accelerations(
    NodalSystem<dim>             &system,
    const MassMatrix<dim>        &mass_matrix,
    const ParticleShapeData<dim> &shape_data,
    const double                  time,
    const double                  dt)
  {
    if (conditions.empty())
      return;
    for (auto &condition : conditions)
      {
        condition.in_contact.assign(condition.functions.size(), false);
        if (condition.type != Type::friction && condition.type != Type::slip)
          continue;
        const std::array<bool, dim> components =
          constrained_components(condition);
        if (std::any_of(components.begin(), components.end(), [](bool b) {
              return b;
            }))
          continue;
        for (unsigned int k = 0; k < condition.functions.size(); ++k)
          {
            const unsigned int i = condition.functions[k];
            const double       m = system.lumped_mass.local_element(i);
            if (!(m > 0.))
              continue;
            Tensor<1, dim> v, a;
            for (unsigned int c = 0; c < dim; ++c)
              {
                v[c] = system.momentum[c].local_element(i) / m;
                a[c] = system.acceleration[c].local_element(i);
              }
            if (condition.type == Type::friction)
              {
                const double normal_velocity = (v + dt * a) * condition.normal;
                if (!(normal_velocity > 0. &&
                      condition.gap.local_element(i) <= dt * normal_velocity))
                  continue;
                condition.in_contact[k] = true;
              }
            const Tensor<1, dim> corrected =
              corrected_velocity(condition, v + dt * a, time + dt);
            for (unsigned int c = 0; c < dim; ++c)
              system.acceleration[c].local_element(i) =
                (corrected[c] - v[c]) / dt;
          }
      }
    // The reactions once every condition has acted (a node shared by two
    // conditions counts in both).
    for (unsigned int c = 0; c < dim; ++c)
      {
        if (inertia[c].get_partitioner() !=
            system.acceleration[c].get_partitioner())
          inertia[c].reinit(system.acceleration[c].get_partitioner());
        mass_matrix.vmult(system,
                          shape_data,
                          system.acceleration[c],
                          inertia[c]);
      }
    for (auto &condition : conditions)
      {
        Tensor<1, dim> reaction;
        for (const unsigned int i : condition.functions)
          for (unsigned int c = 0; c < dim; ++c)
            reaction[c] += inertia[c].local_element(i) -
                           (system.force[c].local_element(i) -
                            system.damping_force[c].local_element(i));
        condition.reaction_sum += reaction;
        if (condition.type == Type::velocity)
          {
            const Tensor<1, dim> prescribed =
              condition.velocity->vector_value(Point<dim>(), time + dt);
            double work = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              if (condition.components[d])
                {
                  condition.displacement[d] += dt * prescribed[d];
                  work += dt * reaction[d] * prescribed[d];
                }
            work_of_prescribed_velocities += std::max(work, 0.);
          }
        ++condition.n_steps;
      }
  }



  template <int dim>
  void
  BoundaryConditions<dim>::constrain_velocities(NodalSystem<dim> &system,
                                                const double      time) const
  {
    for (const auto &condition : conditions)
      {
        if (condition.type != Type::friction && condition.type != Type::slip)
          continue;
        const std::array<bool, dim> components =
          constrained_components(condition);
        if (std::any_of(components.begin(), components.end(), [](bool b) {
              return b;
            }))
          continue;
        for (unsigned int k = 0; k < condition.functions.size(); ++k)
          {
            const unsigned int i = condition.functions[k];
            if (!(system.lumped_mass.local_element(i) > 0.) ||
                (condition.type == Type::friction && !condition.in_contact[k]))
              continue;
            Tensor<1, dim> v;
            for (unsigned int c = 0; c < dim; ++c)
              v[c] = system.velocity[c].local_element(i);
            const Tensor<1, dim> corrected =
              condition.type == Type::friction ?
                v - (v * condition.normal) * condition.normal :
                corrected_velocity(condition, v, time);
            for (unsigned int c = 0; c < dim; ++c)
              system.velocity[c].local_element(i) = corrected[c];
          }
      }
  }



  template <int dim>
  double
  BoundaryConditions<dim>::take_work_of_prescribed_velocities()
  {
    const double work             = work_of_prescribed_velocities;
    work_of_prescribed_velocities = 0.;
    return work;
  }



  template <int dim>
  std::vector<std::string>
  BoundaryConditions<dim>::names() const
  {
    std::vector<std::string> result;
    for (const auto &condition : conditions)
      result.push_back(condition.name);
    return result;
  }



  template <int dim>
  std::vector<std::pair<Tensor<1, dim>, Tensor<1, dim>>>
  BoundaryConditions<dim>::reactions_and_displacements(
    const bool start_new_window)
  {
    std::vector<std::pair<Tensor<1, dim>, Tensor<1, dim>>> result;
    for (auto &condition : conditions)
      {
        const Tensor<1, dim> sum =
          Utilities::MPI::sum(condition.reaction_sum, communicator);
        result.emplace_back(condition.n_steps > 0 ? sum / condition.n_steps :
                                                    sum,
                            condition.displacement);
        if (start_new_window)
          {
            condition.reaction_sum = Tensor<1, dim>();
            condition.n_steps      = 0;
          }
      }
    return result;
  }



  template <int dim>
  void
  BoundaryConditions<dim>::save(CheckpointState &state) const
  {
    // Shared: per condition the number of steps summed and the
    // displacement; own: per condition this rank's reaction sum, then the
    // work not yet taken.
    std::vector<double> shared, own;
    for (const auto &condition : conditions)
      {
        shared.push_back(condition.n_steps);
        for (unsigned int d = 0; d < dim; ++d)
          {
            shared.push_back(condition.displacement[d]);
            own.push_back(condition.reaction_sum[d]);
          }
      }
    own.push_back(work_of_prescribed_velocities);
    state.set_shared("boundary conditions/steps and displacements", shared);
    state.set_own("boundary conditions/reactions and work", own);
  }



  template <int dim>
  void
  BoundaryConditions<dim>::load(const CheckpointState &state)
  {
    const auto &shared =
      state.shared("boundary conditions/steps and displacements");
    const auto own =
      state.share_of_sums("boundary conditions/reactions and work");
    AssertThrow(shared.size() == conditions.size() * (dim + 1) &&
                  own.size() == conditions.size() * dim + 1,
                ExcMessage("The checkpoint's boundary conditions are not "
                           "those of this run (Boundaries)."));
    for (unsigned int b = 0; b < conditions.size(); ++b)
      {
        conditions[b].n_steps =
          static_cast<unsigned int>(shared[b * (dim + 1)]);
        for (unsigned int d = 0; d < dim; ++d)
          {
            conditions[b].displacement[d] = shared[b * (dim + 1) + 1 + d];
            conditions[b].reaction_sum[d] = own[b * dim + d];
          }
      }
    work_of_prescribed_velocities = own.back();
  }



  template class BoundaryConditions<1>;
  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace MpmOtm
