#include <deal.II/grid/grid_tools.h>

#include <mpm_otm/algorithms/advected_grid.h>
#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/problems/problem.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <limits>
#include <map>
#include <sstream>

namespace MpmOtm
{
  template <int dim>
  AdvectedGrid<dim>::AdvectedGrid(ShapeFunctions<dim> *rebuilt_functions)
    : rebuilt_functions(rebuilt_functions)
  {}



  template <int dim>
  bool
  AdvectedGrid<dim>::moves_vertices() const
  {
    return true;
  }



  template <int dim>
  bool
  AdvectedGrid<dim>::tractions_on_grid_faces() const
  {
    return true;
  }



  template <int dim>
  double
  AdvectedGrid<dim>::measure(
    const unsigned int n_vertices,
    const std::array<unsigned int, GeometryInfo<dim>::vertices_per_face>
      &vertices) const
  {
    const auto corner = [&](const unsigned int v) -> const Point<dim> & {
      return *vertex_positions[vertices[v]];
    };
    if constexpr (dim == 1)
      return 1.;
    else if constexpr (dim == 2)
      return (corner(1) - corner(0)).norm();
    else
      {
        // Triangle: half the cross product of two edges; quadrilateral
        // (vertices in deal.II's lexicographic order): half the cross
        // product of its diagonals.
        if (n_vertices == 3)
          return 0.5 *
                 cross_product_3d(corner(1) - corner(0), corner(2) - corner(0))
                   .norm();
        return 0.5 *
               cross_product_3d(corner(3) - corner(0), corner(2) - corner(1))
                 .norm();
      }
  }



  template <int dim>
  void
  AdvectedGrid<dim>::add_face_tractions(const Problem<dim> &problem,
                                        const double        time,
                                        NodalSystem<dim>   &system) const
  {
    constexpr unsigned int              n_sides = 2 * dim;
    std::array<bool, n_sides>           loaded{};
    std::array<Tensor<1, dim>, n_sides> traction;
    for (const auto id : problem.traction_boundaries())
      {
        AssertThrow(id < n_sides, ExcInternalError());
        loaded[id]   = true;
        traction[id] = problem.traction(id, time);
      }
    // The power of the tractions at the nodal velocities of the previous
    // step (the grid moves with them).
    double       *force[dim];
    const double *velocity[dim];
    for (unsigned int c = 0; c < dim; ++c)
      {
        force[c]    = system.force[c].get_values();
        velocity[c] = system.velocity[c].get_values();
      }
    double power = 0.;
    for (const auto &face : boundary_faces)
      if (face.boundary_id < n_sides && loaded[face.boundary_id])
        {
          const Tensor<1, dim> share = traction[face.boundary_id] *
                                       measure(face.n_vertices, face.vertices) /
                                       face.n_vertices;
          for (unsigned int v = 0; v < face.n_vertices; ++v)
            for (unsigned int e = vertex_offsets[face.vertices[v]];
                 e < vertex_offsets[face.vertices[v] + 1];
                 ++e)
              {
                const unsigned int i = vertex_functions[e];
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    force[c][i] += vertex_weights[e] * share[c];
                    power += vertex_weights[e] * share[c] * velocity[c][i];
                  }
              }
        }
    system.add_external_power(power);
  }



  template <int dim>
  void
  AdvectedGrid<dim>::initialize(BackgroundGrid<dim>       &grid,
                                const ShapeFunctions<dim> &shape_functions,
                                const NodalSystem<dim>    &system,
                                const double               stable_cell_size)
  {
    stable_size       = stable_cell_size;
    vertices_per_cell = grid.triangulation().begin_active()->n_vertices();

    triangulation                                  = &grid.triangulation();
    background                                     = &grid;
    const Utilities::MPI::Partitioner &partitioner = system.partitioner();
    position_of_vertex.assign(triangulation->n_vertices(),
                              numbers::invalid_unsigned_int);
    of_owned_cell.clear();
    std::vector<types::global_dof_index> functions;
    std::vector<double>                  weights;
    vertex_positions.clear();
    vertex_cells.clear();
    vertex_offsets.assign(1, 0);
    vertex_functions.clear();
    vertex_weights.clear();
    owned_cell_vertices.clear();
    owned_cells.clear();
    orientations.clear();
    boundary_faces.clear();

    for (const auto &cell : grid.triangulation().active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        for (const unsigned int v : cell->vertex_indices())
          {
            unsigned int &position = position_of_vertex[cell->vertex_index(v)];
            if (position == numbers::invalid_unsigned_int)
              {
                position = vertex_positions.size();
                vertex_positions.push_back(&cell->vertex(v));
                vertex_cells.emplace_back(cell, v);
                shape_functions.vertex_interpolation(cell,
                                                     v,
                                                     functions,
                                                     weights);
                for (const auto function : functions)
                  {
                    AssertThrow(function != numbers::invalid_dof_index,
                                ExcMessage(
                                  "Method = OTM or Unified moves the grid's "
                                  "vertices with the coefficients of the "
                                  "shape functions, which needs functions "
                                  "that belong to the vertices "
                                  "(Shape functions = linear)."));
                    vertex_functions.push_back(
                      partitioner.global_to_local(function));
                  }
                vertex_weights.insert(vertex_weights.end(),
                                      weights.begin(),
                                      weights.end());
                vertex_offsets.push_back(vertex_functions.size());
                of_owned_cell.push_back(false);
              }
            if (cell->is_locally_owned())
              {
                owned_cell_vertices.push_back(position);
                of_owned_cell[position] = true;
              }
          }
        if (cell->is_locally_owned())
          {
            owned_cells.emplace_back(triangulation,
                                     cell->level(),
                                     cell->index());
            const Point<dim> *corners[GeometryInfo<dim>::vertices_per_cell];
            for (unsigned int v = 0; v < vertices_per_cell; ++v)
              corners[v] = &cell->vertex(v);
            orientations.push_back(
              smallest_vertex_jacobian(corners, vertices_per_cell, 1.) > 0 ?
                1. :
                -1.);
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                {
                  BoundaryFace face;
                  face.boundary_id = cell->face(f)->boundary_id();
                  face.n_vertices  = cell->face(f)->n_vertices();
                  for (unsigned int v = 0; v < face.n_vertices; ++v)
                    face.vertices[v] =
                      position_of_vertex[cell->face(f)->vertex_index(v)];
                  boundary_faces.push_back(face);
                }
          }
      }
    moved_positions.resize(vertex_positions.size());
  }



  template <int dim>
  double
  AdvectedGrid<dim>::smallest_vertex_jacobian(const Point<dim> *const corners[],
                                              const unsigned int      n_corners,
                                              const double orientation)
  {
    Tensor<2, dim> jacobian;
    if (n_corners != GeometryInfo<dim>::vertices_per_cell)
      {
        // Simplex: constant Jacobian with columns x_{d+1} - x_0.
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int a = 0; a < dim; ++a)
            jacobian[a][d] = (*corners[d + 1])[a] - (*corners[0])[a];
        return orientation * determinant(jacobian);
      }

    // Hypercube: at vertex i the column for direction d is the edge from the
    // vertex with bit d cleared to the one with bit d set.
    double smallest = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < n_corners; ++i)
      {
        for (unsigned int d = 0; d < dim; ++d)
          {
            const Point<dim> &upper = *corners[i | (1u << d)];
            const Point<dim> &lower = *corners[i & ~(1u << d)];
            for (unsigned int a = 0; a < dim; ++a)
              jacobian[a][d] = upper[a] - lower[a];
          }
        smallest = std::min(smallest, orientation * determinant(jacobian));
      }
    return smallest;
  }



  template <int dim>
  void
  AdvectedGrid<dim>::advance(const NodalSystem<dim> &system,
                             MaterialPoints<dim>    &material_points,
                             const double            dt)
  {
    const double *velocity[dim];
    for (unsigned int c = 0; c < dim; ++c)
      velocity[c] = system.velocity[c].get_values();
    for (unsigned int k = 0; k < vertex_positions.size(); ++k)
      {
        moved_positions[k] = *vertex_positions[k];
        for (unsigned int e = vertex_offsets[k]; e < vertex_offsets[k + 1]; ++e)
          for (unsigned int c = 0; c < dim; ++c)
            moved_positions[k][c] +=
              dt * vertex_weights[e] * velocity[c][vertex_functions[e]];
      }
    if (rebuilt_functions != nullptr &&
        Utilities::MPI::n_mpi_processes(triangulation->get_communicator()) > 1)
      take_ghost_vertices_from_owners();

    std::string inverted;
    for (unsigned int k = 0; k < owned_cells.size() && inverted.empty(); ++k)
      {
        const Point<dim> *corners[GeometryInfo<dim>::vertices_per_cell];
        Point<dim>        centre;
        for (unsigned int v = 0; v < vertices_per_cell; ++v)
          {
            corners[v] =
              &moved_positions[owned_cell_vertices[k * vertices_per_cell + v]];
            centre += *corners[v] / vertices_per_cell;
          }
        if (smallest_vertex_jacobian(corners,
                                     vertices_per_cell,
                                     orientations[k]) <= 0.)
          {
            std::ostringstream message;
            message << "cell " << owned_cells[k]->id() << " (centre (" << centre
                    << ") after the step) would invert: its Jacobian would be "
                    << "non-positive at a vertex. ";
            inverted = message.str();
            continue;
          }
        double size = std::numeric_limits<double>::max();
        for (unsigned int v = 0; v < vertices_per_cell; ++v)
          for (unsigned int w = v + 1; w < vertices_per_cell; ++w)
            size = std::min(size, corners[v]->distance(*corners[w]));
        if (size < stable_size)
          {
            std::ostringstream message;
            message << "cell " << owned_cells[k]->id() << " (centre (" << centre
                    << ") after the step) would be compressed to a vertex "
                    << "distance of " << size
                    << ", below h_min dt / dt_stable = " << stable_size
                    << ", the size at which the time step reaches the "
                    << "stable one (found at the start for the smallest "
                    << "cell size h_min; it scales with the cell size). ";
            inverted = message.str();
          }
      }
    stop_if_any_rank_failed(
      triangulation->get_communicator(),
      inverted,
      "The moving grid became invalid: ",
      "The grid is left at the start of the step. Reduce Time/Time step; if "
      "the material deforms more than a grid that moves with it can follow, "
      "use Method = MPM (fixed grid).");

    for (unsigned int k = 0; k < vertex_positions.size(); ++k)
      std::swap(*vertex_positions[k], moved_positions[k]);
    triangulation->signals.mesh_movement();
    if (rebuilt_functions != nullptr)
      {
        // moved_positions now holds the vertices before the step.
        rebuild_functions(moved_positions);
        material_points.locate();
      }
  }



  template <int dim>
  void
  AdvectedGrid<dim>::take_ghost_vertices_from_owners()
  {
    using Cell = typename Triangulation<dim>::active_cell_iterator;
    GridTools::exchange_cell_data_to_ghosts<std::vector<double>,
                                            Triangulation<dim>>(
      *triangulation,
      [&](const Cell &cell) {
        std::vector<double> corners;
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            corners.push_back(
              moved_positions[position_of_vertex[cell->vertex_index(v)]][d]);
        return std_cxx17::optional<std::vector<double>>(corners);
      },
      [&](const Cell &cell, const std::vector<double> &corners) {
        for (const unsigned int v : cell->vertex_indices())
          {
            const unsigned int k = position_of_vertex[cell->vertex_index(v)];
            if (!of_owned_cell[k])
              for (unsigned int d = 0; d < dim; ++d)
                moved_positions[k][d] = corners[v * dim + d];
          }
      });
  }



  template <int dim>
  void
  AdvectedGrid<dim>::read_vertex_weights()
  {
    std::vector<types::global_dof_index> functions;
    std::vector<double>                  weights;
    for (unsigned int k = 0; k < vertex_cells.size(); ++k)
      {
        rebuilt_functions->vertex_interpolation(vertex_cells[k].first,
                                                vertex_cells[k].second,
                                                functions,
                                                weights);
        AssertDimension(weights.size(),
                        vertex_offsets[k + 1] - vertex_offsets[k]);
        std::copy(weights.begin(),
                  weights.end(),
                  vertex_weights.begin() + vertex_offsets[k]);
      }
  }



  template <int dim>
  void
  AdvectedGrid<dim>::rebuild_functions(const std::vector<Point<dim>> &previous)
  {
    const MPI_Comm    comm    = triangulation->get_communicator();
    const std::string problem = rebuilt_functions->rebuild_on_moved_grid();
    if (Utilities::MPI::max(problem.empty() ? 0 : 1, comm) == 1)
      {
        for (unsigned int k = 0; k < vertex_positions.size(); ++k)
          *vertex_positions[k] = previous[k];
        triangulation->signals.mesh_movement();
        rebuilt_functions->rebuild_on_moved_grid();
      }
    read_vertex_weights();
    stop_if_any_rank_failed(
      comm,
      problem,
      "The shape functions cannot be rebuilt on the moved grid: ",
      "The grid is left at the start of the step. Reduce Time/Time step; if "
      "the material deforms more than a grid that moves with it can follow, "
      "use Method = MPM (fixed grid).");
  }



  template <int dim>
  unsigned int
  AdvectedGrid<dim>::vertex_index(const unsigned int k) const
  {
    return background->coarse_vertex_index(
      vertex_positions[k] - triangulation->get_vertices().data());
  }



  template <int dim>
  void
  AdvectedGrid<dim>::save(CheckpointState &state) const
  {
    // This rank's vertices with their numbers in the coarse mesh.
    std::vector<double> vertices;
    vertices.reserve(vertex_positions.size() * (dim + 1));
    for (unsigned int k = 0; k < vertex_positions.size(); ++k)
      {
        vertices.push_back(vertex_index(k));
        for (unsigned int d = 0; d < dim; ++d)
          vertices.push_back((*vertex_positions[k])[d]);
      }
    state.set_own("moving grid/vertices", vertices);
  }



  template <int dim>
  void
  AdvectedGrid<dim>::load(const CheckpointState &state)
  {
    std::map<unsigned int, Point<dim>> saved;
    for (const auto &part : state.parts("moving grid/vertices"))
      for (unsigned int k = 0; k + dim < part.size(); k += dim + 1)
        {
          Point<dim> &position = saved[static_cast<unsigned int>(part[k])];
          for (unsigned int d = 0; d < dim; ++d)
            position[d] = part[k + 1 + d];
        }
    for (unsigned int k = 0; k < vertex_positions.size(); ++k)
      {
        const unsigned int index = vertex_index(k);
        const auto         found = saved.find(index);
        AssertThrow(found != saved.end(),
                    ExcMessage("The checkpoint lacks vertex " +
                               std::to_string(index) + " of the moving grid."));
        *vertex_positions[k] = found->second;
      }
    triangulation->signals.mesh_movement();
    if (rebuilt_functions != nullptr)
      {
        // Collective, so that a rank that meets a problem does not leave the
        // others waiting.
        stop_if_any_rank_failed(triangulation->get_communicator(),
                                rebuilt_functions->rebuild_on_moved_grid(),
                                "The shape functions cannot be rebuilt on the "
                                "grid of the checkpoint: ",
                                "");
        read_vertex_weights();
      }
  }



  template class AdvectedGrid<1>;
  template class AdvectedGrid<2>;
  template class AdvectedGrid<3>;
} // namespace MpmOtm
