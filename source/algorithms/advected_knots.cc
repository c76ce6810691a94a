#include <mpm_otm/algorithms/advected_knots.h>
#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/problems/problem.h>
#include <mpm_otm/shape_functions/b_splines.h>

#include <algorithm>
#include <sstream>

namespace MpmOtm
{
  template <int dim>
  AdvectedKnots<dim>::AdvectedKnots(BSplines<dim> &splines)
    : splines(splines)
  {}



  template <int dim>
  bool
  AdvectedKnots<dim>::moves_vertices() const
  {
    return true;
  }



  template <int dim>
  bool
  AdvectedKnots<dim>::tractions_on_grid_faces() const
  {
    return true;
  }



  template <int dim>
  double
  AdvectedKnots<dim>::integral(const unsigned int d, const unsigned int i) const
  {
    // Function i spans U_i .. U_{i+p+1} of the open knot vector U, whose
    // entry k is the distinct knot k - p clamped to the ends.
    const auto        &knots = splines.breakpoints(d);
    const unsigned int p     = splines.degree();
    const auto         U     = [&](const int k) {
      return knots[std::clamp<int>(k - static_cast<int>(p),
                                   0,
                                   static_cast<int>(knots.size()) - 1)];
    };
    return (U(i + p + 1) - U(i)) / (p + 1);
  }



  template <int dim>
  void
  AdvectedKnots<dim>::add_face_tractions(const Problem<dim> &problem,
                                         const double        time,
                                         NodalSystem<dim>   &system) const
  {
    const auto  &partitioner = system.partitioner();
    const auto   owned       = partitioner.locally_owned_range();
    unsigned int n[dim];
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = splines.n_functions_in_direction(d);
    // The power of the tractions at the nodal velocities of the previous
    // step (the knots move with them).
    double power = 0.;
    for (const auto id : problem.traction_boundaries())
      {
        AssertThrow(id < 2 * dim, ExcInternalError());
        const Tensor<1, dim> traction  = problem.traction(id, time);
        const unsigned int   direction = id / 2;
        const unsigned int   layer     = (id % 2 == 0) ? 0 : n[direction] - 1;
        for (const auto global : owned)
          {
            const auto i       = splines.multi_index(global);
            double     weight  = 1.;
            bool       on_face = true;
            for (unsigned int d = 0; d < dim; ++d)
              if (d == direction)
                on_face = (i[d] == layer);
              else
                weight *= integral(d, i[d]);
            if (!on_face)
              continue;
            const unsigned int local = partitioner.global_to_local(global);
            for (unsigned int c = 0; c < dim; ++c)
              {
                system.force[c].local_element(local) += weight * traction[c];
                power += weight * traction[c] *
                         system.velocity[c].local_element(local);
              }
          }
      }
    system.add_external_power(power);
  }



  template <int dim>
  void
  AdvectedKnots<dim>::initialize(BackgroundGrid<dim> &grid,
                                 const ShapeFunctions<dim> &,
                                 const NodalSystem<dim> &,
                                 const double stable_cell_size)
  {
    stable_size   = stable_cell_size;
    triangulation = &grid.triangulation();
    vertices.clear();
    knot_of_vertex.clear();
    std::vector<bool> seen(triangulation->n_vertices(), false);
    // Every rank knows every knot, so it moves all vertices it holds: in
    // 2D and 3D all cells of the box grid, those of artificial cells
    // included (deal.II's point search must not see stale positions), in 1D
    // (fully distributed) its own and its ghost cells.
    for (const auto &cell : triangulation->active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (!seen[cell->vertex_index(v)])
          {
            seen[cell->vertex_index(v)] = true;
            vertices.push_back(&cell->vertex(v));
            std::array<unsigned int, dim> knot;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const auto  &knots = splines.breakpoints(d);
                const double x     = cell->vertex(v)[d];
                // The nearest knot (the vertex sits on one).
                const auto above =
                  std::lower_bound(knots.begin(), knots.end(), x);
                unsigned int k = above - knots.begin();
                if (k == knots.size() ||
                    (k > 0 && x - knots[k - 1] < knots[k] - x))
                  --k;
                knot[d] = k;
              }
            knot_of_vertex.push_back(knot);
          }
  }



  template <int dim>
  void
  AdvectedKnots<dim>::advance(const NodalSystem<dim> &system,
                              MaterialPoints<dim>    &material_points,
                              const double            dt)
  {
    const auto        &partitioner = system.partitioner();
    const unsigned int p           = splines.degree();
    const MPI_Comm     comm        = triangulation->get_communicator();
    unsigned int       n[dim];
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = splines.n_functions_in_direction(d);

    // Control-point velocities v_d averaged over the other directions.
    std::array<std::vector<double>, dim> mean;
    for (unsigned int d = 0; d < dim; ++d)
      mean[d].assign(n[d], 0.);
    for (const auto global : partitioner.locally_owned_range())
      {
        const unsigned int local = partitioner.global_to_local(global);
        const auto         i     = splines.multi_index(global);
        for (unsigned int d = 0; d < dim; ++d)
          mean[d][i[d]] += system.velocity[d].local_element(local);
      }
    const double n_total = splines.n_functions();
    for (unsigned int d = 0; d < dim; ++d)
      {
        Utilities::MPI::sum(mean[d], comm, mean[d]);
        for (double &value : mean[d])
          value /= n_total / n[d];
      }

    // New knots xi_k + dt w_d(xi_k), checked before anything moves.
    std::array<std::vector<double>, dim> moved;
    std::vector<double>                  values(p + 1), derivatives(p + 1);
    std::string                          problem;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const auto        &knots   = splines.breakpoints(d);
        const unsigned int n_spans = knots.size() - 1;
        moved[d].resize(knots.size());
        for (unsigned int k = 0; k <= n_spans; ++k)
          {
            const unsigned int span = std::min(k, n_spans - 1);
            splines.values_1d(d,
                              span,
                              k == n_spans ? 1. : 0.,
                              values.data(),
                              derivatives.data());
            double velocity = 0.;
            for (unsigned int a = 0; a <= p; ++a)
              velocity += values[a] * mean[d][span + a];
            moved[d][k] = knots[k] + dt * velocity;
          }
        for (unsigned int k = 0; k < n_spans && problem.empty(); ++k)
          {
            const double size = moved[d][k + 1] - moved[d][k];
            if (!(size >= stable_size))
              {
                std::ostringstream message;
                message << "knot span " << k << " of direction " << d
                        << " (from " << moved[d][k] << " to " << moved[d][k + 1]
                        << " after the step) would ";
                if (size <= 0.)
                  message << "invert. ";
                else
                  message << "be compressed below h_min dt / dt_stable = "
                          << stable_size
                          << ", the size at which the time step reaches the "
                             "stable one (found at the start for the "
                             "smallest span h_min; it scales with the span). ";
                problem = message.str();
              }
          }
      }
    stop_if_any_rank_failed(
      comm,
      problem,
      "The moving knots became invalid: ",
      "The grid is left at the start of the step. Reduce Time/Time step; if "
      "the material deforms more than knots that move with it can follow, "
      "use Method = MPM (fixed grid).");

    for (unsigned int k = 0; k < vertices.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        (*vertices[k])[d] = moved[d][knot_of_vertex[k][d]];
    triangulation->signals.mesh_movement();
    splines.move_breakpoints(moved);
    material_points.locate();
  }



  template <int dim>
  void
  AdvectedKnots<dim>::save(CheckpointState &state) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      state.set_shared("moving knots/direction " + std::to_string(d),
                       splines.breakpoints(d));
  }



  template <int dim>
  void
  AdvectedKnots<dim>::load(const CheckpointState &state)
  {
    std::array<std::vector<double>, dim> saved;
    for (unsigned int d = 0; d < dim; ++d)
      {
        saved[d] = state.shared("moving knots/direction " + std::to_string(d));
        AssertThrow(saved[d].size() == splines.breakpoints(d).size(),
                    ExcMessage("The checkpoint's knots do not fit this "
                               "run's grid."));
      }
    for (unsigned int k = 0; k < vertices.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        (*vertices[k])[d] = saved[d][knot_of_vertex[k][d]];
    triangulation->signals.mesh_movement();
    splines.move_breakpoints(saved);
  }



  template class AdvectedKnots<1>;
  template class AdvectedKnots<2>;
  template class AdvectedKnots<3>;
} // namespace MpmOtm
