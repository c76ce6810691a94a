#include <deal.II/base/bounding_box.h>
#include <deal.II/boost_adaptors/bounding_box.h>
#include <deal.II/boost_adaptors/point.h>
#include <deal.II/numerics/rtree.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid_system/background_grid.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/max_ent.h>

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



  namespace
  {
    /**
     * The cubic-spline prior of journal Eq. 89 and its derivative in r.
     */
    inline void
    cubic_spline(const double r, double &value, double &derivative)
    {
      if (r <= 0.5)
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
  } // namespace



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
  }



  template <int dim>
  MaxEnt<dim>::MaxEnt(const double support_factor)
    : support_factor(support_factor)
  {}



  template <int dim>
  MaxEnt<dim>::~MaxEnt() = default;



  template <int dim>
  void
  MaxEnt<dim>::parse_parameters(ParameterHandler &prm)
  {
    support_factor = prm.get_double("Max-ent support factor");
  }



  template <int dim>
  void
  MaxEnt<dim>::initialize(const BackgroundGrid<dim> &grid)
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(
                  grid.triangulation().get_communicator()) == 1,
                ExcMessage("Shape functions = max-ent run on one MPI rank "
                           "only so far: their supports reach beyond the "
                           "ghost cells. Run without mpirun."));
    vertex_numbering.initialize(grid);
    nodes.clear();
    update_nodes();
  }



  template <int dim>
  void
  MaxEnt<dim>::update_nodes() const
  {
    const DoFHandler<dim>  &dofs = vertex_numbering.dof_handler();
    std::vector<Point<dim>> current(dofs.n_dofs());
    for (const auto &cell : dofs.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        current[cell->vertex_dof_index(v, 0)] = cell->vertex(v);
    if (current == nodes && search_tree)
      return;
    nodes = std::move(current);

    // zeta_i: distance to the nearest other node.
    const auto point_tree = pack_rtree_of_indices(nodes);
    radii.resize(nodes.size());
    supports.resize(nodes.size());
    std::vector<unsigned int> nearest;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        nearest.clear();
        point_tree.query(bgi::nearest(nodes[i], 2),
                         std::back_inserter(nearest));
        double zeta = std::numeric_limits<double>::max();
        for (const unsigned int j : nearest)
          if (j != i)
            zeta = std::min(zeta, nodes[i].distance(nodes[j]));
        AssertThrow(zeta > 0. && zeta < std::numeric_limits<double>::max(),
                    ExcMessage("Max-ent shape functions need at least two "
                               "distinct nodes."));
        radii[i]         = support_factor * zeta;
        Point<dim> lower = nodes[i], upper = nodes[i];
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] -= radii[i];
            upper[d] += radii[i];
          }
        supports[i] = BoundingBox<dim>(std::make_pair(lower, upper));
      }
    search_tree = std::make_unique<SearchTree>(supports);
  }



  template <int dim>
  std::string
  MaxEnt<dim>::evaluate_at(const Point<dim>                     &x,
                           std::vector<types::global_dof_index> &indices,
                           std::vector<double>                  &values,
                           std::vector<Tensor<1, dim>> &gradients) const
  {
    // The nodes whose support contains x, their priors and prior gradients.
    candidates.clear();
    search_tree->tree.query(bgi::intersects(x), std::back_inserter(candidates));
    indices.clear();
    weights.clear();
    weight_gradients.clear();
    double length_scale = 0;
    for (const unsigned int i : candidates)
      {
        const Tensor<1, dim> offset   = x - nodes[i];
        const double         distance = offset.norm();
        const double         r        = distance / radii[i];
        if (r >= 1.)
          continue;
        double w, dw_dr;
        cubic_spline(r, w, dw_dr);
        indices.push_back(i);
        weights.push_back(w);
        weight_gradients.push_back(distance > 0. ?
                                     (dw_dr / (radii[i] * distance)) * offset :
                                     Tensor<1, dim>());
        length_scale = std::max(length_scale, radii[i]);
      }
    const unsigned int n = indices.size();
    if (n < dim + 1)
      {
        std::ostringstream message;
        message << "only " << n << " node(s) have x = (" << x
                << ") inside their support, fewer than dim + 1 = " << dim + 1
                << ": increase Max-ent support factor (now " << support_factor
                << ").";
        return message.str();
      }

    // Newton's method on ln Z(lambda) (Eq. 83) with a backtracking line
    // search; Z_i = w_i exp(lambda . (x - x_i)), shifted by the largest
    // exponent against overflow.
    values.resize(n);
    const auto ln_z = [&](const Tensor<1, dim> &lambda) {
      double largest = -std::numeric_limits<double>::max();
      for (unsigned int k = 0; k < n; ++k)
        largest = std::max(largest, lambda * (x - nodes[indices[k]]));
      double z = 0;
      for (unsigned int k = 0; k < n; ++k)
        {
          values[k] =
            weights[k] * std::exp(lambda * (x - nodes[indices[k]]) - largest);
          z += values[k];
        }
      for (unsigned int k = 0; k < n; ++k)
        values[k] /= z;
      return std::log(z) + largest;
    };

    const auto residual_of = [&]() {
      Tensor<1, dim> r;
      for (unsigned int k = 0; k < n; ++k)
        r += values[k] * (x - nodes[indices[k]]);
      return r;
    };

    // Start from the multipliers of the previous point (points come cell by
    // cell, so it is usually a neighbour) unless lambda = 0 is closer.
    Tensor<1, dim> lambda;
    double         objective = ln_z(lambda);
    Tensor<1, dim> residual  = residual_of();
    {
      const double         previous_objective = ln_z(previous_lambda);
      const Tensor<1, dim> previous_residual  = residual_of();
      if (previous_residual.norm() < residual.norm())
        {
          lambda    = previous_lambda;
          objective = previous_objective;
          residual  = previous_residual;
        }
      else
        objective = ln_z(lambda);
    }
    Tensor<2, dim> hessian;
    const double   tolerance = 1e-12 * length_scale;
    bool           converged = false;
    for (unsigned int iteration = 0; iteration < 100; ++iteration)
      {
        hessian = 0;
        for (unsigned int k = 0; k < n; ++k)
          {
            const Tensor<1, dim> offset = x - nodes[indices[k]];
            hessian += values[k] * outer_product(offset, offset);
          }
        hessian -= outer_product(residual, residual);
        if (residual.norm() <= tolerance)
          {
            converged = true;
            break;
          }
        if (!(determinant(hessian) > 0.))
          break;
        // Accept a step that decreases ln Z (Armijo) or, once ln Z is flat
        // to round-off, the residual; otherwise halve it.
        const Tensor<1, dim> step     = -(invert(hessian) * residual);
        const double         slope    = residual * step;
        double               alpha    = 1.;
        bool                 accepted = false;
        for (unsigned int halving = 0; halving < 40; ++halving, alpha *= 0.5)
          {
            const double         trial          = ln_z(lambda + alpha * step);
            const Tensor<1, dim> trial_residual = residual_of();
            if (trial <= objective + 1e-4 * alpha * slope ||
                trial_residual.norm() < residual.norm())
              {
                lambda += alpha * step;
                objective = trial;
                residual  = trial_residual;
                accepted  = true;
                break;
              }
          }
        if (!accepted)
          {
            objective = ln_z(lambda);
            residual  = residual_of();
            break;
          }
      }
    if (!converged)
      {
        std::ostringstream message;
        message << "the max-ent Lagrange multipliers at x = (" << x
                << ") did not converge (residual " << residual.norm()
                << "): x lies outside the convex hull of the " << n
                << " nodes that reach it, or on its boundary. Keep the "
                   "material inside the grid's nodes, or increase Max-ent "
                   "support factor (now "
                << support_factor << ").";
        return message.str();
      }

    previous_lambda = lambda;

    // Gradients (Eqs. 84-86 with the sign derived in the class
    // documentation).
    Tensor<1, dim> mean_log_gradient;
    Tensor<2, dim> A;
    for (unsigned int k = 0; k < n; ++k)
      {
        const Tensor<1, dim> log_gradient = weight_gradients[k] / weights[k];
        mean_log_gradient += values[k] * log_gradient;
        A += values[k] * outer_product(x - nodes[indices[k]], log_gradient);
      }
    const Tensor<2, dim> M =
      (unit_symmetric_tensor<dim>() + transpose(A)) * invert(hessian);
    gradients.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      gradients[k] =
        values[k] * (weight_gradients[k] / weights[k] - mean_log_gradient -
                     M * (x - nodes[indices[k]]));
    return "";
  }



  template <int dim>
  void
  MaxEnt<dim>::evaluate(const MaterialPoints<dim>         &material_points,
                        const Utilities::MPI::Partitioner &partitioner,
                        ParticleShapeData<dim>            &data) const
  {
    update_nodes();
    const auto &particles = material_points.particle_handler();
    data.offsets.resize(particles.n_locally_owned_particles() + 1);
    data.indices.clear();
    data.values.clear();
    data.gradients.clear();

    std::vector<types::global_dof_index> &indices   = point_indices;
    std::vector<double>                  &values    = point_values;
    std::vector<Tensor<1, dim>>          &gradients = point_gradients;
    unsigned int                          k         = 0;
    for (const auto &particle : particles)
      {
        data.offsets[k] = data.indices.size();
        const std::string failure =
          evaluate_at(particle.get_location(), indices, values, gradients);
        AssertThrow(failure.empty(),
                    ExcMessage("At material point " +
                               std::to_string(particle.get_id()) + ": " +
                               failure));
        for (unsigned int e = 0; e < indices.size(); ++e)
          {
            data.indices.push_back(partitioner.global_to_local(indices[e]));
            data.values.push_back(values[e]);
            data.gradients.push_back(gradients[e]);
          }
        ++k;
      }
    data.offsets[k] = data.indices.size();
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
    // Serial only: every function is relevant.
    return complete_index_set(n_functions());
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
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        // On the hull's boundary the multipliers are infinite (weak
        // Kronecker delta): evaluate 1e-6 of the way to the centroid of the
        // node's neighbours instead, which changes the value by O(1e-6 h).
        std::string failure =
          evaluate_at(nodes[i], point_indices, point_values, point_gradients);
        if (!failure.empty())
          {
            Point<dim> centroid;
            for (const auto j : point_indices)
              centroid += nodes[j] / double(point_indices.size());
            failure = evaluate_at(nodes[i] + 1e-6 * (centroid - nodes[i]),
                                  point_indices,
                                  point_values,
                                  point_gradients);
          }
        AssertThrow(failure.empty(), ExcMessage("At a node: " + failure));
        double value = 0;
        for (unsigned int e = 0; e < point_indices.size(); ++e)
          value += point_values[e] * coefficients(point_indices[e]);
        values(i) = value;
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
