#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/base/subsection_names.h>
#include <mpm_otm/boundary_conditions/boundary_conditions.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/grid_system/mass_matrix.h>
#include <mpm_otm/grid_system/nodal_system.h>
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
    using Registry = PluginRegistry<Condition<dim>>;
    for (const auto &name : names)
      {
        prm.enter_subsection("Boundary " + name);
        prm.declare_entry("Type",
                          "fixed",
                          Patterns::Selection(Registry::selection()),
                          "What the condition does:" +
                            Registry::documentation());
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
        Registry::declare_parameters(prm);
        prm.leave_subsection();
      }
  }



  template <int dim>
  void
  BoundaryConditions<dim>::parse_parameters(ParameterHandler &prm)
  {
    conditions.clear();
    types.clear();
    for (const auto &name : SubsectionNames::names_in(prm, "Boundaries"))
      {
        const std::string path = "Boundary " + name + "/";
        prm.enter_subsection("Boundary " + name);
        const std::string type = prm.get("Type");
        auto condition         = PluginRegistry<Condition<dim>>::create(type);
        ConditionNodes<dim> &where = condition->where;
        where.name                 = name;
        for (const int id : Utilities::string_to_int(
               Utilities::split_string_list(prm.get("Boundary ids"))))
          where.boundary_ids.push_back(id);
        const auto lower = Utilities::string_to_double(
          Utilities::split_string_list(prm.get("Box lower corner")));
        const auto upper = Utilities::string_to_double(
          Utilities::split_string_list(prm.get("Box upper corner")));
        where.on_box = where.boundary_ids.empty();
        if (where.on_box)
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
            where.box = BoundingBox<dim>(std::make_pair(p1, p2));
            AssertThrow(!condition->needs_normal(),
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
        condition->parse_parameters(prm);
        prm.leave_subsection();
        conditions.push_back(std::move(condition));
        types.push_back(type);
      }
    reaction_sums.assign(conditions.size(), Tensor<1, dim>());
    loads.assign(conditions.size(), Tensor<1, dim>());
    n_steps.assign(conditions.size(), 0);
    acting.assign(conditions.size(), true);
  }



  template <int dim>
  void
  BoundaryConditions<dim>::check_method(const std::string &method_name,
                                        const bool         fixed_grid,
                                        const bool computes_accelerations,
                                        const bool lumped_mass)
  {
    AssertThrow(conditions.empty() || computes_accelerations,
                ExcMessage("Boundaries: Method = " + method_name +
                           " updates the nodal velocities in one solve "
                           "from the momenta and forces, without the nodal "
                           "accelerations from which the named conditions' "
                           "corrections and reactions come. Use Method = "
                           "Unified or MPM, or fix components with the "
                           "problem's own entries (Custom problem/Fixed "
                           "components)."));
    for (auto &condition : conditions)
      {
        ConditionNodes<dim> &where = condition->where;
        AssertThrow(fixed_grid || !where.on_box,
                    ExcMessage(where.path() +
                               "Box lower corner, Box upper corner: a "
                               "condition on the nodes in a box needs the "
                               "fixed grid of Method = MPM; Method = " +
                               method_name +
                               " moves the grid's nodes with the material, "
                               "so give Boundary ids (a side of the grid) "
                               "instead."));
        AssertThrow(lumped_mass || !condition->needs_lumped_mass(),
                    ExcMessage(where.path() +
                               "Type = " + types[&condition - &conditions[0]] +
                               " acts on each node with its own (lumped) "
                               "mass, which the solve with a consistent or "
                               "partially lumped Mass matrix would spread "
                               "over the neighbouring nodes, so that its "
                               "force could overshoot. Use Mass matrix = "
                               "lumped."));
        where.fixed_grid = fixed_grid;
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
    communicator         = grid.triangulation().get_communicator();
    functions            = &shape_functions;
    background_grid      = &grid;
    const IndexSet owned = shape_functions.locally_owned_functions();
    for (unsigned int b = 0; b < conditions.size(); ++b)
      {
        ConditionNodes<dim> &where = conditions[b]->where;
        where.functions.clear();
        if (where.on_box)
          {
            find_box_functions(where);
            AssertThrow(
              Utilities::MPI::sum(where.functions.size(), communicator) > 0,
              ExcMessage(where.path() +
                         "Box lower corner, Box upper corner: the box holds "
                         "no node of the grid (linear, max-ent: no vertex; "
                         "B-splines: no Greville point), so the condition "
                         "would act on nothing; enlarge the box to hold the "
                         "nodes it should act on."));
            refuse_nodes_on_box_sides(where);
          }
        else
          {
            for (const auto id : where.boundary_ids)
              for (const auto function : shape_functions.boundary_functions(id))
                if (owned.is_element(function))
                  where.functions.push_back(owned.index_within_set(function));
            find_normal(where, conditions[b]->needs_normal(), types[b]);
          }
        std::sort(where.functions.begin(), where.functions.end());
        where.functions.erase(std::unique(where.functions.begin(),
                                          where.functions.end()),
                              where.functions.end());
        where.displacement = Tensor<1, dim>();
        reaction_sums[b]   = Tensor<1, dim>();
        n_steps[b]         = 0;
        conditions[b]->initialize(shape_functions);
      }
  }



  template <int dim>
  void
  BoundaryConditions<dim>::find_normal(ConditionNodes<dim> &where,
                                       const bool           needs_normal,
                                       const std::string   &type) const
  {
    const BackgroundGrid<dim> &grid          = *background_grid;
    const auto                &triangulation = grid.triangulation();
    const std::string          path          = where.path();
    // The outward normal: the mean of the normals of the condition's
    // faces (on this rank, collected once), which must all be equal
    // for slip and friction.
    std::vector<Tensor<1, dim>> normals;
    std::vector<Point<dim>>     centers;
    double              cell_depth = std::numeric_limits<double>::infinity();
    std::vector<double> faces_per_id(where.boundary_ids.size(), 0.);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto id = std::find(where.boundary_ids.begin(),
                                        where.boundary_ids.end(),
                                        cell->face(f)->boundary_id());
              if (id == where.boundary_ids.end())
                continue;
              faces_per_id[id - where.boundary_ids.begin()] += 1.;
              normals.push_back(outward_normal<dim>(cell, f));
              centers.push_back(cell->face(f)->center());
              // Twice the distance from the face to the cell's
              // centre: the cell's depth for quadrilaterals and
              // hexahedra, two thirds (triangles) or a half
              // (tetrahedra) of it for simplices.
              cell_depth =
                std::min(cell_depth,
                         2. * std::abs(normals.back() *
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
                      ExcMessage(path +
                                 "Boundary ids: no face of the grid "
                                 "has the id " +
                                 std::to_string(where.boundary_ids[i]) +
                                 "; the grid's boundary ids are " + ids +
                                 " (box grids: the sides 0 to " +
                                 std::to_string(2 * dim - 1) +
                                 "; Mesh file: its physical tags, 0 on "
                                 "untagged faces)."));
        }
    // Faces that face each other (e.g. sides 0 and 1 in one
    // condition) have no mean normal: not planar.
    const bool has_normal = sum.norm() > 1e-8 * n_faces;
    where.normal =
      has_normal ? Tensor<1, dim>(sum / sum.norm()) : Tensor<1, dim>();
    double deviation = has_normal ? 0. : 1.;
    double offset    = 0.;
    for (const auto &normal : normals)
      deviation = std::max(deviation, (normal - where.normal).norm());
    for (const auto &center : centers)
      offset += where.normal * center;
    deviation         = Utilities::MPI::max(deviation, communicator);
    where.wall_offset = Utilities::MPI::sum(offset, communicator) / n_faces;
    where.cell_depth  = Utilities::MPI::min(cell_depth, communicator);
    AssertThrow(deviation < 1e-8 || !needs_normal,
                ExcMessage(path + "Type = " + type +
                           " needs a planar boundary, but the faces "
                           "of these Boundary ids have "
                           "different normals; give each "
                           "planar part its own id."));
  }



  template <int dim>
  void
  BoundaryConditions<dim>::check_run(const double end_time) const
  {
    for (const auto &condition : conditions)
      condition->check_run(end_time);
  }



  template <int dim>
  void
  BoundaryConditions<dim>::refuse_nodes_on_box_sides(
    const ConditionNodes<dim> &where) const
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
    const Point<dim> lower = where.box.get_boundary_points().first;
    const Point<dim> upper = where.box.get_boundary_points().second;
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
          message << "Boundary " << where.name
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
  BoundaryConditions<dim>::find_box_functions(ConditionNodes<dim> &where) const
  {
    IndexSet owned = functions->locally_owned_functions();
    owned.compress();
    Point<dim> lower = where.box.get_boundary_points().first;
    Point<dim> upper = where.box.get_boundary_points().second;
    lower += where.displacement;
    upper += where.displacement;
    const BoundingBox<dim>               box(std::make_pair(lower, upper));
    std::vector<types::global_dof_index> global;
    AssertThrow(functions->functions_in_box(box, global),
                ExcMessage("Boundary " + where.name +
                           "/Box lower corner: a condition on the nodes in "
                           "a box needs shape functions that belong to "
                           "points (linear, max-ent: vertices; B-splines: "
                           "Greville points); use Boundary ids instead."));
    where.functions.clear();
    for (const auto function : global)
      where.functions.push_back(owned.index_within_set(function));
  }



  template <int dim>
  std::vector<FixedComponents<dim>>
  BoundaryConditions<dim>::fixed_components() const
  {
    std::vector<FixedComponents<dim>> result;
    for (unsigned int b = 0; b < conditions.size(); ++b)
      if (acting[b] && !conditions[b]->where.on_box)
        for (const auto &fixed : conditions[b]->fixed_components())
          result.push_back(fixed);
    return result;
  }



  template <int dim>
  void
  BoundaryConditions<dim>::set_acting(const std::vector<bool> &acts)
  {
    AssertDimension(acts.size(), conditions.size());
    acting = acts;
  }



  template <int dim>
  std::vector<std::string>
  BoundaryConditions<dim>::acting_names() const
  {
    std::vector<std::string> result;
    for (unsigned int b = 0; b < conditions.size(); ++b)
      if (acting[b])
        result.push_back(conditions[b]->where.name);
    return result;
  }



  template <int dim>
  void
  BoundaryConditions<dim>::add_loads(NodalSystem<dim> &system,
                                     const double      time,
                                     const double      dt)
  {
    for (unsigned int b = 0; b < conditions.size(); ++b)
      loads[b] = acting[b] ? conditions[b]->add_loads(system, time, dt) :
                             Tensor<1, dim>();
  }



  template <int dim>
  void
  BoundaryConditions<dim>::make_acceleration_constraints(
    const NodalSystem<dim>                 &system,
    const double                            time,
    const double                            dt,
    typename NodalSystem<dim>::Constraints &constraints)
  {
    // A box that moves finds its nodes at its new place.
    for (unsigned int b = 0; b < conditions.size(); ++b)
      if (acting[b] && conditions[b]->where.on_box && conditions[b]->moves())
        find_box_functions(conditions[b]->where);
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
    for (unsigned int b = 0; b < conditions.size(); ++b)
      {
        if (!acting[b])
          continue;
        const auto                 &condition = conditions[b];
        const std::array<bool, dim> components =
          condition->constrained_components();
        if (std::none_of(components.begin(),
                         components.end(),
                         [](const bool fixed) {
                           return fixed;
                         }))
          continue;
        const std::vector<unsigned int> &nodes = condition->where.functions;
        node_values.resize(nodes.size());
        condition->target_velocities(time, node_values);
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            const unsigned int i = nodes[k];
            if (!(system.lumped_mass.local_element(i) > 0.))
              continue;
            const types::global_dof_index global =
              partitioner.local_to_global(i);
            for (unsigned int c = 0; c < dim; ++c)
              if (components[c])
                {
                  constraints[c].add_line(global);
                  constraints[c]
                    .set_inhomogeneity(global, value(i, c, node_values[k][c]));
                }
          }
      }
  }



  template <int dim>
  void
  BoundaryConditions<dim>::correct_accelerations(
    NodalSystem<dim>             &system,
    const MassMatrix<dim>        &mass_matrix,
    const MaterialPoints<dim>    &material_points,
    const ParticleShapeData<dim> &shape_data,
    const double                  time,
    const double                  dt)
  {
    if (conditions.empty())
      return;
    for (unsigned int b = 0; b < conditions.size(); ++b)
      if (acting[b])
        conditions[b]->prepare(material_points, shape_data, system);
    for (unsigned int b = 0; b < conditions.size(); ++b)
      if (acting[b])
        conditions[b]->correct_accelerations(system, time, dt);
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
    // A condition that does not act has no reaction (which counts in the
    // mean over the output's window) and stays where it is.
    for (unsigned int b = 0; b < conditions.size(); ++b)
      {
        ++n_steps[b];
        if (!acting[b])
          continue;
        node_values.clear();
        Tensor<1, dim> reaction;
        if (conditions[b]->holds_nodes())
          for (const unsigned int i : conditions[b]->where.functions)
            {
              Tensor<1, dim> node_reaction;
              for (unsigned int c = 0; c < dim; ++c)
                node_reaction[c] = inertia[c].local_element(i) -
                                   (system.force[c].local_element(i) -
                                    system.damping_force[c].local_element(i));
              node_values.push_back(node_reaction);
              reaction += node_reaction;
            }
        reaction += loads[b];
        reaction_sums[b] += reaction;
        work_of_prescribed_velocities +=
          conditions[b]->advance(node_values, time, dt);
      }
  }



  template <int dim>
  void
  BoundaryConditions<dim>::correct_velocities(NodalSystem<dim> &system,
                                              const double      time) const
  {
    for (unsigned int b = 0; b < conditions.size(); ++b)
      if (acting[b])
        conditions[b]->correct_velocities(system, time);
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
      result.push_back(condition->where.name);
    return result;
  }



  template <int dim>
  std::vector<std::pair<Tensor<1, dim>, Tensor<1, dim>>>
  BoundaryConditions<dim>::reactions_and_displacements(
    const bool start_new_window)
  {
    std::vector<std::pair<Tensor<1, dim>, Tensor<1, dim>>> result;
    for (unsigned int b = 0; b < conditions.size(); ++b)
      {
        const Tensor<1, dim> sum =
          Utilities::MPI::sum(reaction_sums[b], communicator);
        result.emplace_back(n_steps[b] > 0 ? sum / n_steps[b] : sum,
                            conditions[b]->where.displacement);
        if (start_new_window)
          {
            reaction_sums[b] = Tensor<1, dim>();
            n_steps[b]       = 0;
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
    for (unsigned int b = 0; b < conditions.size(); ++b)
      {
        shared.push_back(n_steps[b]);
        for (unsigned int d = 0; d < dim; ++d)
          {
            shared.push_back(conditions[b]->where.displacement[d]);
            own.push_back(reaction_sums[b][d]);
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
        n_steps[b] = static_cast<unsigned int>(shared[b * (dim + 1)]);
        for (unsigned int d = 0; d < dim; ++d)
          {
            conditions[b]->where.displacement[d] =
              shared[b * (dim + 1) + 1 + d];
            reaction_sums[b][d] = own[b * dim + d];
          }
      }
    work_of_prescribed_velocities = own.back();
  }



  template class BoundaryConditions<1>;
  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace MpmOtm
