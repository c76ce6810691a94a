#include <deal.II/base/bounding_box.h>
#include <deal.II/boost_adaptors/bounding_box.h>
#include <deal.II/boost_adaptors/point.h>
#include <deal.II/numerics/rtree.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/max_ent.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace MpmOtm
{
  namespace bgi = boost::geometry::index;

  template <int dim>
  struct MaxEnt<dim>::SearchTree
  {
    using Tree = decltype(pack_rtree_of_indices(
      std::declval<const std::vector<BoundingBox<dim>> &>()));
    explicit SearchTree(const std::vector<BoundingBox<dim>> &boxes)
      : tree(pack_rtree_of_indices(boxes))
    {}
    Tree tree;
  };



  void
  cubic_spline_prior(const double r, double &value, double &derivative)
  {
    if (r >= 1.)
      {
        value      = 0.;
        derivative = 0.;
      }
    else if (r <= 0.5)
      {
        value      = 2. / 3. - 4. * r * r + 4. * r * r * r;
        derivative = -8. * r + 12. * r * r;
      }
    else
      {
        // 4/3 - 4 r + 4 r^2 - 4/3 r^3 = 4/3 (1 - r)^3, in the form that
        // stays positive up to r = 1 (no cancellation).
        const double s = 1. - r;
        value          = 4. / 3. * s * s * s;
        derivative     = -4. * s * s;
      }
  }



  template <int dim>
  void
  MaxEnt<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Max-ent support factor",
                      "2",
                      Patterns::Double(1.),
                      "Factor d_max of the support radius d_i = d_max zeta_i "
                      "of the max-ent prior (journal Eq. 88; zeta_i is the "
                      "distance from node i to its nearest other node). "
                      "Typical values 2 to 4; larger values smooth more and "
                      "cost more (Shape functions = max-ent).");
    prm.declare_entry(
      "Max-ent halo factor",
      "1.5",
      Patterns::Double(1.),
      "Under MPI, each rank keeps the nodes of other ranks within this "
      "factor times the largest support radius d_max zeta_i of all nodes at "
      "set-up from its cells (Shape functions = max-ent). 1 suffices on a "
      "fixed grid (MPM). When the nodes move with the material (OTM), the "
      "margin, (factor - 1) times that radius, must hold about twice the "
      "spread of all nodes' displacements (half the diagonal of their range "
      "over the whole body; a translation has none): beyond it a rank could "
      "miss a node that reaches its points, and the run stops and asks for "
      "a larger factor. Larger factors exchange more nodes.");
  }



  template <int dim>
  MaxEnt<dim>::MaxEnt(const double support_factor)
    : support_factor(support_factor)
    , halo_factor(1.5)
  {}



  template <int dim>
  MaxEnt<dim>::~MaxEnt() = default;



  template <int dim>
  void
  MaxEnt<dim>::parse_parameters(ParameterHandler &prm)
  {
    support_factor = prm.get_double("Max-ent support factor");
    halo_factor    = prm.get_double("Max-ent halo factor");
  }



  template <int dim>
  void
  MaxEnt<dim>::initialize(const BackgroundGrid<dim> &grid)
  {
    vertex_numbering.initialize(grid);
    cloud.initialize(vertex_numbering.dof_handler(),
                     vertex_numbering.locally_relevant_functions(),
                     support_factor,
                     halo_factor);
    search_tree.reset();
    update_nodes();
  }



  template <int dim>
  void
  MaxEnt<dim>::update_nodes(const MaterialPoints<dim> *material_points) const
  {
    if (!cloud.update(material_points) && search_tree)
      return;
    const std::vector<Point<dim>> &nodes   = cloud.positions();
    const std::vector<double>     &radii   = cloud.radii();
    const unsigned int             n_local = nodes.size();
    inverse_radii.resize(n_local);
    supports.resize(n_local);
    for (unsigned int i = 0; i < n_local; ++i)
      {
        inverse_radii[i] = 1. / radii[i];
        supports[i]      = BoundingBox<dim>(std::make_pair(nodes[i], nodes[i]));
        supports[i].extend(radii[i]);
      }
    search_tree = std::make_unique<SearchTree>(supports);

    // Each owned cell's candidates: the nodes whose support ball meets the
    // cell's bounding box.
    const Triangulation<dim> &triangulation =
      vertex_numbering.dof_handler().get_triangulation();
    cell_boxes.resize(triangulation.n_active_cells());
    cell_node_offsets.assign(triangulation.n_active_cells() + 1, 0);
    cell_nodes.clear();
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        cell_node_offsets[c] = cell_nodes.size();
        if (!cell->is_locally_owned())
          continue;
        const BoundingBox<dim> box = cell->bounding_box();
        cell_boxes[c]              = box;
        candidates.clear();
        search_tree->tree.query(bgi::intersects(box),
                                std::back_inserter(candidates));
        for (const unsigned int i : candidates)
          // Nodes whose support only touches the box (to round-off, as
          // on a uniform grid with integer d_max) have zero weight in it.
          if (squared_distance_to_box(nodes[i], box) <
              (1. - 1e-10) * radii[i] * radii[i])
            cell_nodes.push_back(i);
      }
    cell_node_offsets.back() = cell_nodes.size();
  }



  template <int dim>
  std::string
  MaxEnt<dim>::solve(const Point<dim>         &x,
                     const unsigned int *const candidate_nodes,
                     const unsigned int        n_candidates,
                     Tensor<1, dim>           &lambda,
                     double *const             values,
                     Tensor<1, dim> *const     gradients) const
  {
    // The candidates whose support contains x: their offsets x - x_i, priors
    // and logarithmic prior gradients grad w_i / w_i.
    // (Sized once for all candidates and filled through raw pointers: no
    // allocation once the arrays have grown.)
    if (reached.size() < n_candidates)
      {
        reached.resize(n_candidates);
        offsets.resize(n_candidates);
        weights.resize(n_candidates);
        log_weight_gradients.resize(n_candidates);
        phi_current.resize(n_candidates);
        phi_trial.resize(n_candidates);
      }
    const std::vector<Point<dim>> &nodes             = cloud.positions();
    const std::vector<double>     &radii             = cloud.radii();
    unsigned int                  *reached_candidate = reached.data();
    Tensor<1, dim>                *offset            = offsets.data();
    double                        *weight            = weights.data();
    Tensor<1, dim>                *log_gradient = log_weight_gradients.data();
    unsigned int                   n            = 0;
    double                         length_scale = 0;
    for (unsigned int k = 0; k < n_candidates; ++k)
      {
        values[k]               = 0.;
        gradients[k]            = Tensor<1, dim>();
        const unsigned int   i  = candidate_nodes[k];
        const Tensor<1, dim> dx = x - nodes[i];
        const double distance   = (dim == 1) ? std::abs(dx[0]) : dx.norm();
        const double r          = distance * inverse_radii[i];
        if (r >= 1.)
          continue;
        double w, dw_dr;
        cubic_spline_prior(r, w, dw_dr);
        reached_candidate[n] = k;
        offset[n]            = dx;
        weight[n]            = w;
        log_gradient[n]      = distance > 0. ?
                                 (dw_dr * inverse_radii[i] / (w * distance)) * dx :
                                 Tensor<1, dim>();
        length_scale         = std::max(length_scale, radii[i]);
        ++n;
      }
    n_reached = n;
    if (n < dim + 1)
      {
        std::ostringstream message;
        message << "only " << n << " node(s) have x = (" << x
                << ") inside their support, fewer than dim + 1 = " << dim + 1
                << ": increase Max-ent support factor (now " << support_factor
                << ").";
        return message.str();
      }

    // One pass at multipliers l: phi_k = w_k exp(l . (x - x_k)) / Z (shifted
    // by the largest exponent against overflow), ln Z, the residual
    // r = sum_k phi_k (x - x_k) = grad ln Z and the Hessian
    // H = sum_k phi_k (x - x_k) (x - x_k)^T - r r^T.
    struct State
    {
      /// Z = z exp(shift).
      double         z;
      double         shift;
      Tensor<1, dim> residual;
      Tensor<2, dim> hessian;
      double
      ln_z() const
      {
        return std::log(z) + shift;
      }
    };
    const auto pass = [&](const Tensor<1, dim> &l, double *const phi) {
      // |l . (x - x_k)| < |l| length_scale: shift only where exp could
      // overflow.
      State state{0., 0., {}, {}};
      if (l.norm() * length_scale > 300.)
        {
          state.shift = -std::numeric_limits<double>::max();
          for (unsigned int k = 0; k < n; ++k)
            state.shift = std::max(state.shift, l * offset[k]);
        }
      for (unsigned int k = 0; k < n; ++k)
        {
          phi[k] = weight[k] * std::exp(l * offset[k] - state.shift);
          state.z += phi[k];
        }
      const double inverse_z = 1. / state.z;
      for (unsigned int k = 0; k < n; ++k)
        {
          phi[k] *= inverse_z;
          const Tensor<1, dim> weighted = phi[k] * offset[k];
          state.residual += weighted;
          state.hessian += outer_product(weighted, offset[k]);
        }
      state.hessian -= outer_product(state.residual, state.residual);
      return state;
    };

    // Newton's method on ln Z (Eq. 83, convex) with a backtracking line
    // search: accept a step that decreases ln Z (Armijo) or, once ln Z is
    // flat to round-off, the residual; otherwise halve it. Converged means a
    // residual below the tolerance and a positive definite Hessian: at a
    // node on the boundary of the hull the residual vanishes only as the
    // multipliers tend to infinity, and multipliers far too large (a first
    // guess from elsewhere) make the other functions underflow to zero,
    // the residual exactly zero and H = 0, from which no gradient follows.
    const double tolerance = 1e-12 * length_scale;
    double      *phi       = phi_current.data();
    double      *trial_phi = phi_trial.data();
    State        state{0., 0., {}, {}};
    const auto   newton = [&]() {
      state = pass(lambda, phi);
      for (unsigned int iteration = 0; iteration < 100; ++iteration)
        {
          const double residual_norm    = state.residual.norm();
          const bool   positive_hessian = determinant(state.hessian) > 0.;
          if (residual_norm <= tolerance && positive_hessian)
            return true;
          if (!positive_hessian)
            return false;
          const Tensor<1, dim> step = -(invert(state.hessian) * state.residual);
          const double         slope    = state.residual * step;
          double               alpha    = 1.;
          bool                 accepted = false;
          for (unsigned int halving = 0; halving < 40; ++halving, alpha *= 0.5)
            {
              const State trial = pass(lambda + alpha * step, trial_phi);
              if (trial.residual.norm() < residual_norm ||
                  trial.ln_z() <= state.ln_z() + 1e-4 * alpha * slope)
                {
                  lambda += alpha * step;
                  state = trial;
                  std::swap(phi, trial_phi);
                  accepted = true;
                  break;
                }
            }
          if (!accepted)
            return false;
        }
      return false;
    };
    // The first guess (the multipliers of the point solved before) can lie
    // far from the solution, e.g. near the hull's
    // boundary; start again from zero if it fails.
    bool converged = newton();
    if (!converged && lambda.norm() > 0.)
      {
        lambda    = Tensor<1, dim>();
        converged = newton();
      }
    if (!converged)
      {
        std::ostringstream message;
        message << "the max-ent Lagrange multipliers at x = (" << x
                << ") did not converge (residual " << state.residual.norm()
                << "): x lies outside the convex hull of the " << n
                << " nodes that reach it. Keep the material inside the "
                   "grid's nodes, or increase Max-ent support factor (now "
                << support_factor << ").";
        lambda = Tensor<1, dim>();
        return message.str();
      }

    // Gradients (Eqs. 84-86 with the sign derived in the class
    // documentation), in the form that holds for the residual r that
    // Newton's method leaves: with the offsets from the phi-weighted mean
    // of the nodes, x - x_k - r, and (I + A^T - g r^T) H^-1 (g the mean of
    // grad w_k / w_k, H the centred Hessian), the gradients satisfy
    // sum_k grad phi_k = 0 and sum_k x_k (grad phi_k)^T = I exactly. This
    // matters near a node on the hull's boundary, where H ~ |r| / h: there
    // the printed form loses the node's own gradient (0 instead of -1/h
    // exactly on an end node in 1D, as the offset x - x_k vanishes).
    const Tensor<1, dim> &residual = state.residual;
    Tensor<1, dim>        mean_log_gradient;
    Tensor<2, dim>        A;
    for (unsigned int k = 0; k < n; ++k)
      {
        mean_log_gradient += phi[k] * log_gradient[k];
        A += outer_product(phi[k] * offset[k], log_gradient[k]);
      }
    const Tensor<2, dim> M = (unit_symmetric_tensor<dim>() + transpose(A) -
                              outer_product(mean_log_gradient, residual)) *
                             invert(state.hessian);
    for (unsigned int k = 0; k < n; ++k)
      {
        values[reached_candidate[k]] = phi[k];
        gradients[reached_candidate[k]] =
          phi[k] *
          (log_gradient[k] - mean_log_gradient - M * (offset[k] - residual));
      }
    return "";
  }



  template <int dim>
  std::string
  MaxEnt<dim>::evaluate_at(const Point<dim>                     &x,
                           std::vector<types::global_dof_index> &indices,
                           std::vector<double>                  &values,
                           std::vector<Tensor<1, dim>> &gradients) const
  {
    candidates.clear();
    search_tree->tree.query(bgi::intersects(x), std::back_inserter(candidates));
    values.resize(candidates.size());
    gradients.resize(candidates.size());
    const std::string failure = solve(x,
                                      candidates.data(),
                                      candidates.size(),
                                      previous_lambda,
                                      values.data(),
                                      gradients.data());
    // Keep the functions that do not vanish at x (on failure: those whose
    // support contains x, with value zero).
    indices.clear();
    for (unsigned int k = 0; k < candidates.size(); ++k)
      if (values[k] > 0. ||
          (!failure.empty() &&
           std::find(reached.begin(), reached.begin() + n_reached, k) !=
             reached.begin() + n_reached))
        {
          values[indices.size()]    = values[k];
          gradients[indices.size()] = gradients[k];
          indices.push_back(cloud.partition().local_to_global(candidates[k]));
        }
    values.resize(indices.size());
    gradients.resize(indices.size());
    return failure;
  }



  template <int dim>
  const Point<dim> &
  MaxEnt<dim>::node(const types::global_dof_index i) const
  {
    return cloud.positions()[cloud.partition().global_to_local(i)];
  }



  template <int dim>
  bool
  MaxEnt<dim>::function_points(const Utilities::MPI::Partitioner &partitioner,
                               std::vector<Point<dim>>           &points) const
  {
    Assert(partitioner.locally_owned_range() ==
               cloud.partition().locally_owned_range() &&
             partitioner.ghost_indices() == cloud.partition().ghost_indices(),
           ExcInternalError());
    (void)partitioner;
    points = cloud.positions();
    return true;
  }



  template <int dim>
  double
  MaxEnt<dim>::support_radius(const types::global_dof_index i) const
  {
    return cloud.radii()[cloud.partition().global_to_local(i)];
  }



  template <int dim>
  void
  MaxEnt<dim>::evaluate(const MaterialPoints<dim>         &material_points,
                        const Utilities::MPI::Partitioner &partitioner,
                        ParticleShapeData<dim>            &data) const
  {
    update_nodes(&material_points);
    // The local numbers of the nodes are those of the partition the nodal
    // system builds from locally_owned_functions() and
    // locally_relevant_functions().
    Assert(partitioner.locally_owned_range() ==
               cloud.partition().locally_owned_range() &&
             partitioner.ghost_indices() == cloud.partition().ghost_indices(),
           ExcInternalError());
    (void)partitioner;
    const auto &particles = material_points.particle_handler();
    data.reinit(particles.n_locally_owned_particles(), 0);
    previous_lambda = Tensor<1, dim>();

    // A point inside its cell's bounding box gets the cell's candidates, so
    // that the points of a cell share their list of functions (one batch,
    // which the mass matrix sums as one block); a point outside it (OTM: the
    // nodes move with the material, but not as the cell's linear map) gets
    // the candidates from the search tree, in a batch of its own.
    typename Triangulation<dim>::active_cell_iterator current_cell;
    unsigned int                                      cell        = 0;
    const unsigned int                               *batch_nodes = nullptr;
    for (const auto &particle : particles)
      {
        if (particle.get_surrounding_cell() != current_cell)
          {
            current_cell = particle.get_surrounding_cell();
            cell         = current_cell->active_cell_index();
          }
        const Point<dim>   &x = particle.get_location();
        const unsigned int *candidate_nodes;
        unsigned int        n_candidates;
        if (cell_boxes[cell].point_inside(x))
          {
            candidate_nodes = cell_nodes.data() + cell_node_offsets[cell];
            n_candidates =
              cell_node_offsets[cell + 1] - cell_node_offsets[cell];
          }
        else
          {
            candidates.clear();
            search_tree->tree.query(bgi::intersects(x),
                                    std::back_inserter(candidates));
            candidate_nodes = candidates.data();
            n_candidates    = candidates.size();
          }
        if (candidate_nodes != batch_nodes ||
            candidate_nodes == candidates.data())
          {
            data.start_batch(candidate_nodes, n_candidates);
            batch_nodes = candidate_nodes;
          }

        const std::size_t offset  = data.add_particle();
        const std::string failure = solve(x,
                                          candidate_nodes,
                                          n_candidates,
                                          previous_lambda,
                                          &data.values[offset],
                                          &data.gradients[offset]);
        AssertThrow(failure.empty(),
                    ExcMessage("At material point " +
                               std::to_string(particle.get_id()) + ": " +
                               failure));
      }
    data.finish();
  }



  template <int dim>
  types::global_dof_index
  MaxEnt<dim>::n_functions() const
  {
    return vertex_numbering.n_functions();
  }



  template <int dim>
  IndexSet
  MaxEnt<dim>::locally_owned_functions() const
  {
    return vertex_numbering.locally_owned_functions();
  }



  template <int dim>
  IndexSet
  MaxEnt<dim>::locally_relevant_functions() const
  {
    IndexSet relevant = cloud.partition().ghost_indices();
    relevant.add_indices(cloud.partition().locally_owned_range());
    return relevant;
  }



  template <int dim>
  IndexSet
  MaxEnt<dim>::boundary_functions(const types::boundary_id boundary_id) const
  {
    return vertex_numbering.boundary_functions(boundary_id);
  }



  template <int dim>
  bool
  MaxEnt<dim>::is_linearly_complete() const
  {
    return true;
  }



  template <int dim>
  void
  MaxEnt<dim>::functions_on_cell(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    std::vector<types::global_dof_index>                    &functions) const
  {
    // The cell's candidates: the nodes whose support meets its bounding box
    // (for a simplex a few more than those that reach the cell itself).
    Assert(cell->is_locally_owned(), ExcInternalError());
    const unsigned int c = cell->active_cell_index();
    functions.clear();
    for (unsigned int k = cell_node_offsets[c]; k < cell_node_offsets[c + 1];
         ++k)
      functions.push_back(cloud.partition().local_to_global(cell_nodes[k]));
  }



  template <int dim>
  types::global_dof_index
  MaxEnt<dim>::vertex_function(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const unsigned int                                       v) const
  {
    return vertex_numbering.vertex_function(cell, v);
  }



  template <int dim>
  const DoFHandler<dim> &
  MaxEnt<dim>::dof_handler() const
  {
    return vertex_numbering.dof_handler();
  }



  template <int dim>
  void
  MaxEnt<dim>::to_cell_dofs(const VectorType &coefficients,
                            VectorType       &values) const
  {
    update_nodes();
    values.reinit(coefficients.get_partitioner());
    previous_lambda                      = Tensor<1, dim>();
    const std::vector<Point<dim>> &nodes = cloud.positions();
    for (unsigned int i = 0; i < cloud.partition().locally_owned_size(); ++i)
      {
        // On the hull's boundary the multipliers grow until the functions of
        // the nodes off the boundary fall below Newton's tolerance (weak
        // Kronecker delta). Should that fail (a node cloud distorted by the
        // motion), evaluate 1e-6 of the way to the centroid of the node's
        // neighbours instead, which changes the value by O(1e-6 h).
        std::string failure =
          evaluate_at(nodes[i], point_indices, point_values, point_gradients);
        if (!failure.empty())
          {
            Point<dim> centroid;
            for (const auto j : point_indices)
              centroid += node(j) / double(point_indices.size());
            failure = evaluate_at(nodes[i] + 1e-6 * (centroid - nodes[i]),
                                  point_indices,
                                  point_values,
                                  point_gradients);
          }
        AssertThrow(failure.empty(), ExcMessage("At a node: " + failure));
        double value = 0;
        for (unsigned int e = 0; e < point_indices.size(); ++e)
          value += point_values[e] * coefficients(point_indices[e]);
        values.local_element(i) = value;
      }
    values.update_ghost_values();
  }



  template class MaxEnt<1>;
  template class MaxEnt<2>;
  template class MaxEnt<3>;
} // namespace MpmOtm

#define MPM_OTM_MAX_ENT_DESCRIPTION                                       \
  "local maximum-entropy functions on the grid's vertices (cubic-spline " \
  "prior, 'Max-ent support factor')"
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<1>,
                        MpmOtm::MaxEnt<1>,
                        "max-ent",
                        MPM_OTM_MAX_ENT_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<2>,
                        MpmOtm::MaxEnt<2>,
                        "max-ent",
                        MPM_OTM_MAX_ENT_DESCRIPTION)
MPM_OTM_REGISTER_PLUGIN(MpmOtm::ShapeFunctions<3>,
                        MpmOtm::MaxEnt<3>,
                        "max-ent",
                        MPM_OTM_MAX_ENT_DESCRIPTION)
