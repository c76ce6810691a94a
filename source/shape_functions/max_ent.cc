#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/boost_adaptors/bounding_box.h>
#include <deal.II/boost_adaptors/point.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/rtree.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/base/plugins.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/max_ent.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
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
    find_node_cloud();
    nodes.clear();
    search_tree.reset();
    update_nodes();
  }



  namespace
  {
    /**
     * The squared distance from @p x to the box @p box (0 inside).
     */
    template <int dim>
    double
    squared_distance_to_box(const Point<dim> &x, const BoundingBox<dim> &box)
    {
      double result = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double outside = std::max(
            {box.lower_bound(d) - x[d], x[d] - box.upper_bound(d), 0.});
          result += outside * outside;
        }
      return result;
    }



    /**
     * @p box widened by @p margin on every side.
     */
    template <int dim>
    BoundingBox<dim>
    widened(const BoundingBox<dim> &box, const double margin)
    {
      auto corners = box.get_boundary_points();
      for (unsigned int d = 0; d < dim; ++d)
        {
          corners.first[d] -= margin;
          corners.second[d] += margin;
        }
      return BoundingBox<dim>(corners);
    }



    /**
     * A few boxes that together cover the locally owned cells of
     * @p dofs: the cells' bounding boxes merged per bin of a uniform
     * subdivision of their joint bounding box (at most 8^dim bins in 1D and
     * 2D, 4^3 in 3D).
     */
    template <int dim>
    std::vector<BoundingBox<dim>>
    covering_boxes(const DoFHandler<dim> &dofs)
    {
      std::vector<BoundingBox<dim>> cell_boxes;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          cell_boxes.push_back(cell->bounding_box());
      if (cell_boxes.empty())
        return {};
      BoundingBox<dim> all = cell_boxes[0];
      for (const auto &box : cell_boxes)
        all.merge_with(box);
      const unsigned int bins_per_direction = (dim == 3) ? 4 : 8;
      std::map<unsigned int, BoundingBox<dim>> bins;
      for (const auto &box : cell_boxes)
        {
          const Point<dim> centre = box.center();
          unsigned int     bin    = 0;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double width = all.side_length(d);
              const double t =
                width > 0. ? (centre[d] - all.lower_bound(d)) / width : 0.;
              bin = bin * bins_per_direction +
                    std::min(static_cast<unsigned int>(t * bins_per_direction),
                             bins_per_direction - 1);
            }
          const auto found = bins.find(bin);
          if (found == bins.end())
            bins.emplace(bin, box);
          else
            found->second.merge_with(box);
        }
      std::vector<BoundingBox<dim>> result;
      for (const auto &bin : bins)
        result.push_back(bin.second);
      return result;
    }
  } // namespace



  template <int dim>
  void
  MaxEnt<dim>::find_node_cloud()
  {
    const DoFHandler<dim> &dofs = vertex_numbering.dof_handler();
    const MPI_Comm communicator = dofs.get_triangulation().get_communicator();
    const IndexSet owned        = vertex_numbering.locally_owned_functions();
    const unsigned int n_ranks  = Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int this_rank =
      Utilities::MPI::this_mpi_process(communicator);
    if (n_ranks == 1)
      {
        complete_cloud = true;
        node_partition =
          std::make_shared<Utilities::MPI::Partitioner>(owned,
                                                        complete_index_set(
                                                          owned.size()),
                                                        communicator);
        return;
      }

    // The positions of the vertices this rank sees: its own and its ghost
    // cells'. An owned node's nearest vertex among them bounds its zeta
    // from above.
    const IndexSet ghost_cell_vertices =
      vertex_numbering.locally_relevant_functions();
    std::map<types::global_dof_index, Point<dim>> known;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        for (const unsigned int v : cell->vertex_indices())
          known.emplace(cell->vertex_dof_index(v, 0), cell->vertex(v));
    // Flatten the known nodes into known_indices and known_positions and
    // return the largest distance from an owned node to its nearest other
    // known node.
    std::vector<types::global_dof_index> known_indices;
    std::vector<Point<dim>>              known_positions;
    const auto                           largest_nearest_distance = [&]() {
      known_indices.clear();
      known_positions.clear();
      for (const auto &entry : known)
        {
          known_indices.push_back(entry.first);
          known_positions.push_back(entry.second);
        }
      double                    largest = 0;
      const auto                tree = pack_rtree_of_indices(known_positions);
      std::vector<unsigned int> nearest;
      for (unsigned int k = 0; k < known_indices.size(); ++k)
        if (owned.is_element(known_indices[k]))
          {
            nearest.clear();
            tree.query(bgi::nearest(known_positions[k], 2),
                       std::back_inserter(nearest));
            for (const unsigned int j : nearest)
              if (j != k)
                largest =
                  std::max(largest,
                           known_positions[k].distance(known_positions[j]));
          }
      return largest;
    };
    const double largest_zeta_bound =
      Utilities::MPI::max(largest_nearest_distance(), communicator);

    // Send each rank the owned nodes within reach of its cells' boxes:
    // halo_factor d_max times the bound, which holds both the nearest
    // neighbours of the rank's own nodes and the final halo.
    const std::vector<BoundingBox<dim>> my_boxes = covering_boxes(dofs);
    const auto                          all_boxes =
      GridTools::exchange_local_bounding_boxes(my_boxes, communicator);
    const double reach = halo_factor * support_factor * largest_zeta_bound;
    std::vector<BoundingBox<dim>> others_boxes;
    std::vector<unsigned int>     box_rank;
    for (unsigned int rank = 0; rank < n_ranks; ++rank)
      if (rank != this_rank)
        for (const auto &box : all_boxes[rank])
          {
            others_boxes.push_back(widened(box, reach));
            box_rank.push_back(rank);
          }
    std::map<unsigned int, std::vector<double>> sent;
    {
      const auto others_tree = pack_rtree_of_indices(others_boxes);
      std::vector<unsigned int> hits;
      for (unsigned int k = 0; k < known_indices.size(); ++k)
        if (owned.is_element(known_indices[k]))
          {
            hits.clear();
            others_tree.query(bgi::intersects(known_positions[k]),
                              std::back_inserter(hits));
            unsigned int last_rank = numbers::invalid_unsigned_int;
            std::sort(hits.begin(), hits.end());
            for (const unsigned int h : hits)
              if (box_rank[h] != last_rank)
                {
                  last_rank   = box_rank[h];
                  auto &entry = sent[last_rank];
                  entry.push_back(known_indices[k]);
                  for (unsigned int d = 0; d < dim; ++d)
                    entry.push_back(known_positions[k][d]);
                }
          }
    }
    const auto received = Utilities::MPI::some_to_some(communicator, sent);

    // The owned nodes' nearest neighbours are among the known and the
    // received nodes: their largest zeta sets the halo.
    for (const auto &message : received)
      for (unsigned int k = 0; k < message.second.size(); k += dim + 1)
        {
          Point<dim> x;
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = message.second[k + 1 + d];
          known.emplace(static_cast<types::global_dof_index>(message.second[k]),
                        x);
        }
    halo = halo_factor * support_factor *
           Utilities::MPI::max(largest_nearest_distance(), communicator);

    // The cloud: the received nodes within the halo of this rank's cells,
    // and the vertices of its ghost cells.
    IndexSet relevant = ghost_cell_vertices;
    relevant.add_indices(owned);
    const auto                my_tree = pack_rtree_of_indices(my_boxes);
    std::vector<unsigned int> hits;
    std::vector<types::global_dof_index> in_halo;
    for (unsigned int k = 0; k < known_indices.size(); ++k)
      if (!relevant.is_element(known_indices[k]))
        {
          hits.clear();
          Point<dim> lower = known_positions[k], upper = known_positions[k];
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] -= halo;
              upper[d] += halo;
            }
          my_tree.query(bgi::intersects(
                          BoundingBox<dim>(std::make_pair(lower, upper))),
                        std::back_inserter(hits));
          for (const unsigned int h : hits)
            if (squared_distance_to_box(known_positions[k], my_boxes[h]) <=
                halo * halo)
              {
                in_halo.push_back(known_indices[k]);
                break;
              }
        }
    relevant.add_indices(in_halo.begin(), in_halo.end());
    relevant.compress();
    complete_cloud = (relevant.n_elements() == owned.size());
    node_partition =
      std::make_shared<Utilities::MPI::Partitioner>(owned,
                                                    relevant,
                                                    communicator);
  }



  template <int dim>
  void
  MaxEnt<dim>::update_nodes(const MaterialPoints<dim> *material_points) const
  {
    const DoFHandler<dim> &dofs = vertex_numbering.dof_handler();
    const MPI_Comm communicator = node_partition->get_mpi_communicator();
    const bool     parallel = Utilities::MPI::n_mpi_processes(communicator) > 1;
    const unsigned int n_owned = node_partition->locally_owned_size();
    const unsigned int n_local = n_owned + node_partition->n_ghost_indices();
    const bool         first   = !search_tree;
    bool               moved   = first;
    if (first)
      {
        nodes.resize(n_local);
        radii.resize(n_local);
      }
    // The positions of the owned nodes, from the owned cells' vertices (in
    // one rank: all cells).
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const types::global_dof_index global = cell->vertex_dof_index(v, 0);
            if (!node_partition->in_local_range(global))
              continue;
            const unsigned int local = node_partition->global_to_local(global);
            if (!(nodes[local] == cell->vertex(v)))
              {
                nodes[local] = cell->vertex(v);
                moved        = true;
              }
          }
    if (parallel)
      moved = Utilities::MPI::max(moved ? 1 : 0, communicator) > 0;
    if (!moved)
      {
        // The nodes last moved before an update without the points (grid
        // output): check the points against that update now.
        if (parallel && material_points && points_unchecked)
          stop_if_cloud_too_small(material_points);
        return;
      }

    // Positions of the cloud, then the owned nodes' zeta (distance to the
    // nearest other node) and the cloud's radii.
    VectorType exchange(node_partition);
    if (parallel)
      for (unsigned int d = 0; d < dim; ++d)
        {
          for (unsigned int i = 0; i < n_owned; ++i)
            exchange.local_element(i) = nodes[i][d];
          exchange.update_ghost_values();
          for (unsigned int i = n_owned; i < n_local; ++i)
            nodes[i][d] = exchange.local_element(i);
        }
    {
      const auto                point_tree = pack_rtree_of_indices(nodes);
      std::vector<unsigned int> nearest;
      for (unsigned int i = 0; i < n_owned; ++i)
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
          radii[i] = support_factor * zeta;
        }
    }
    if (parallel)
      {
        for (unsigned int i = 0; i < n_owned; ++i)
          exchange.local_element(i) = radii[i];
        exchange.update_ghost_values();
        for (unsigned int i = n_owned; i < n_local; ++i)
          radii[i] = exchange.local_element(i);
      }
    inverse_radii.resize(n_local);
    supports.resize(n_local);
    for (unsigned int i = 0; i < n_local; ++i)
      {
        inverse_radii[i] = 1. / radii[i];
        supports[i] =
          widened(BoundingBox<dim>(std::make_pair(nodes[i], nodes[i])),
                  radii[i]);
      }
    search_tree = std::make_unique<SearchTree>(supports);

    // Each owned cell's candidates: the nodes whose support ball meets the
    // cell's bounding box.
    const Triangulation<dim> &triangulation = dofs.get_triangulation();
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

    if (!parallel)
      return;
    if (first)
      {
        initial_owned_nodes.assign(nodes.begin(), nodes.begin() + n_owned);
        initial_cell_boxes = cell_boxes;
      }
    // The largest radius on all ranks and the box of all nodes'
    // displacements since set-up (its upper corner and minus its lower one),
    // in one reduction.
    std::vector<double> extremes(1 + 2 * dim,
                                 -std::numeric_limits<double>::max());
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        extremes[0] = std::max(extremes[0], radii[i]);
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double u        = nodes[i][d] - initial_owned_nodes[i][d];
            extremes[1 + d]       = std::max(extremes[1 + d], u);
            extremes[1 + dim + d] = std::max(extremes[1 + dim + d], -u);
          }
      }
    {
      const std::vector<double> local_extremes = extremes;
      Utilities::MPI::max(local_extremes, communicator, extremes);
    }
    largest_radius      = extremes[0];
    displacement_spread = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        displacement_centre[d] =
          0.5 * (extremes[1 + d] - extremes[1 + dim + d]);
        const double width = 0.5 * (extremes[1 + d] + extremes[1 + dim + d]);
        displacement_spread += width * width;
      }
    displacement_spread = std::sqrt(displacement_spread);
    stop_if_cloud_too_small(material_points);
  }



  template <int dim>
  void
  MaxEnt<dim>::stop_if_cloud_too_small(
    const MaterialPoints<dim> *material_points) const
  {
    stop_if_any_rank_failed(
      node_partition->get_mpi_communicator(),
      complete_cloud ? std::string() : cloud_problem(material_points),
      "The max-ent nodes moved so far relative to each other that a rank "
      "could miss a node whose support reaches its material points: ",
      "Increase Max-ent halo factor (now " + Utilities::to_string(halo_factor) +
        "), or run on fewer MPI ranks.");
    points_unchecked = (material_points == nullptr);
  }



  template <int dim>
  std::string
  MaxEnt<dim>::cloud_problem(const MaterialPoints<dim> *material_points) const
  {
    // A node outside the cloud started at least the halo H from this
    // rank's cells and has moved by at most the spread from the centre of
    // all displacements; it cannot reach a point y of a cell whose box at
    // set-up, moved by that centre, lies within
    // H - spread - largest radius of y.
    const double allowed = halo - displacement_spread - largest_radius;
    const DoFHandler<dim>        &dofs = vertex_numbering.dof_handler();
    std::vector<BoundingBox<dim>> current(cell_boxes.size());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        current[cell->active_cell_index()] =
          cell_boxes[cell->active_cell_index()];
    if (material_points)
      for (const auto &particle : material_points->particle_handler())
        current[particle.get_surrounding_cell()->active_cell_index()]
          .merge_with(BoundingBox<dim>(
            std::make_pair(particle.get_location(), particle.get_location())));
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int      c     = cell->active_cell_index();
          const BoundingBox<dim> &box   = current[c];
          double                  worst = 0;
          for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell;
               ++v)
            {
              Point<dim> corner;
              for (unsigned int d = 0; d < dim; ++d)
                corner[d] =
                  ((v >> d) & 1) ? box.upper_bound(d) : box.lower_bound(d);
              worst =
                std::max(worst,
                         squared_distance_to_box(corner - displacement_centre,
                                                 initial_cell_boxes[c]));
            }
          if (std::sqrt(worst) > allowed)
            {
              std::ostringstream message;
              message << "on MPI rank "
                      << Utilities::MPI::this_mpi_process(
                           node_partition->get_mpi_communicator())
                      << ", the cell at (" << cell->center()
                      << ") with its points lies " << std::sqrt(worst)
                      << " outside its set-up box moved with the nodes' common "
                         "displacement, but the halo "
                      << halo << " less the spread " << displacement_spread
                      << " of the nodes' displacements and the largest support "
                         "radius "
                      << largest_radius << " allows " << allowed << ". ";
              return message.str();
            }
        }
    return "";
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
    unsigned int   *reached_candidate = reached.data();
    Tensor<1, dim> *offset            = offsets.data();
    double         *weight            = weights.data();
    Tensor<1, dim> *log_gradient      = log_weight_gradients.data();
    unsigned int    n                 = 0;
    double          length_scale      = 0;
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
          indices.push_back(node_partition->local_to_global(candidates[k]));
        }
    values.resize(indices.size());
    gradients.resize(indices.size());
    return failure;
  }



  template <int dim>
  const Point<dim> &
  MaxEnt<dim>::node(const types::global_dof_index i) const
  {
    return nodes[node_partition->global_to_local(i)];
  }



  template <int dim>
  double
  MaxEnt<dim>::support_radius(const types::global_dof_index i) const
  {
    return radii[node_partition->global_to_local(i)];
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
               node_partition->locally_owned_range() &&
             partitioner.ghost_indices() == node_partition->ghost_indices(),
           ExcInternalError());
    (void)partitioner;
    const auto &particles = material_points.particle_handler();
    data.offsets.resize(particles.n_locally_owned_particles() + 1);
    data.indices.clear();
    data.values.clear();
    data.gradients.clear();
    previous_lambda = Tensor<1, dim>();

    // A point inside its cell's bounding box gets the cell's candidates, so
    // that the points of a cell share their list of functions (the mass
    // matrix sums them as one block); a point outside it (OTM: the nodes
    // move with the material, but not as the cell's linear map) gets the
    // candidates from the search tree.
    typename Triangulation<dim>::active_cell_iterator current_cell;
    unsigned int                                      cell = 0;
    unsigned int                                      k    = 0;
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

        const unsigned int offset = data.indices.size();
        data.offsets[k]           = offset;
        data.indices.resize(offset + n_candidates);
        data.values.resize(offset + n_candidates);
        data.gradients.resize(offset + n_candidates);
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
        std::copy(candidate_nodes,
                  candidate_nodes + n_candidates,
                  data.indices.begin() + offset);
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
    IndexSet relevant = node_partition->ghost_indices();
    relevant.add_indices(node_partition->locally_owned_range());
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
      functions.push_back(node_partition->local_to_global(cell_nodes[k]));
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
    previous_lambda = Tensor<1, dim>();
    for (unsigned int i = 0; i < node_partition->locally_owned_size(); ++i)
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
