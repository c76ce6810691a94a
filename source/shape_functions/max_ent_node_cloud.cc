#include <deal.II/base/mpi.h>
#include <deal.II/boost_adaptors/bounding_box.h>
#include <deal.II/boost_adaptors/point.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/numerics/rtree.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/max_ent_node_cloud.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace MpmOtm
{
  namespace bgi = boost::geometry::index;

  template <int dim>
  double
  squared_distance_to_box(const Point<dim> &x, const BoundingBox<dim> &box)
  {
    double result = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double outside =
          std::max({box.lower_bound(d) - x[d], x[d] - box.upper_bound(d), 0.});
        result += outside * outside;
      }
    return result;
  }



  namespace
  {
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
  MaxEntNodeCloud<dim>::initialize(const DoFHandler<dim> &vertex_dofs,
                                   const IndexSet        &ghost_cell_vertices,
                                   const double           support_factor,
                                   const double           halo_factor)
  {
    dofs                 = &vertex_dofs;
    this->support_factor = support_factor;
    this->halo_factor    = halo_factor;
    node_positions.clear();
    node_radii.clear();
    const MPI_Comm communicator = dofs->get_triangulation().get_communicator();
    const IndexSet owned        = dofs->locally_owned_dofs();
    const unsigned int n_ranks  = Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int this_rank =
      Utilities::MPI::this_mpi_process(communicator);
    if (n_ranks == 1)
      {
        complete = true;
        node_partition =
          std::make_shared<Utilities::MPI::Partitioner>(owned,
                                                        complete_index_set(
                                                          owned.size()),
                                                        communicator);
        update(nullptr);
        return;
      }

    // The positions of the vertices this rank sees: its own and its ghost
    // cells'. An owned node's nearest vertex among them bounds its zeta
    // from above.
    std::map<types::global_dof_index, Point<dim>> known;
    for (const auto &cell : dofs->active_cell_iterators())
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
    const std::vector<BoundingBox<dim>> my_boxes = covering_boxes(*dofs);
    const auto                          all_boxes =
      GridTools::exchange_local_bounding_boxes(my_boxes, communicator);
    const double reach = halo_factor * support_factor * largest_zeta_bound;
    std::vector<BoundingBox<dim>> others_boxes;
    std::vector<unsigned int>     box_rank;
    for (unsigned int rank = 0; rank < n_ranks; ++rank)
      if (rank != this_rank)
        for (const auto &box : all_boxes[rank])
          {
            others_boxes.push_back(box);
            others_boxes.back().extend(reach);
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
    complete = (relevant.n_elements() == owned.size());
    node_partition =
      std::make_shared<Utilities::MPI::Partitioner>(owned,
                                                    relevant,
                                                    communicator);
    update(nullptr);
  }



  template <int dim>
  bool
  MaxEntNodeCloud<dim>::update(const MaterialPoints<dim> *material_points)
  {
    const MPI_Comm communicator = node_partition->get_mpi_communicator();
    const bool     parallel = Utilities::MPI::n_mpi_processes(communicator) > 1;
    const unsigned int n_owned = node_partition->locally_owned_size();
    const unsigned int n_local = n_owned + node_partition->n_ghost_indices();
    const bool         first   = node_positions.empty() && n_local > 0;
    bool               moved   = first;
    if (first)
      {
        node_positions.resize(n_local);
        node_radii.resize(n_local);
      }
    // The positions of the owned nodes, from the owned cells' vertices (in
    // one rank: all cells).
    for (const auto &cell : dofs->active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const types::global_dof_index global = cell->vertex_dof_index(v, 0);
            if (!node_partition->in_local_range(global))
              continue;
            const unsigned int local = node_partition->global_to_local(global);
            if (!(node_positions[local] == cell->vertex(v)))
              {
                node_positions[local] = cell->vertex(v);
                moved                 = true;
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
        return false;
      }

    // Positions of the cloud, then the owned nodes' zeta (distance to the
    // nearest other node) and the cloud's radii.
    LinearAlgebra::distributed::Vector<double> exchange(node_partition);
    if (parallel)
      for (unsigned int d = 0; d < dim; ++d)
        {
          for (unsigned int i = 0; i < n_owned; ++i)
            exchange.local_element(i) = node_positions[i][d];
          exchange.update_ghost_values();
          for (unsigned int i = n_owned; i < n_local; ++i)
            node_positions[i][d] = exchange.local_element(i);
        }
    {
      const auto point_tree = pack_rtree_of_indices(node_positions);
      std::vector<unsigned int> nearest;
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          nearest.clear();
          point_tree.query(bgi::nearest(node_positions[i], 2),
                           std::back_inserter(nearest));
          double zeta = std::numeric_limits<double>::max();
          for (const unsigned int j : nearest)
            if (j != i)
              zeta =
                std::min(zeta, node_positions[i].distance(node_positions[j]));
          AssertThrow(zeta > 0. && zeta < std::numeric_limits<double>::max(),
                      ExcMessage("Max-ent shape functions need at least two "
                                 "distinct nodes."));
          node_radii[i] = support_factor * zeta;
        }
    }
    if (!parallel)
      return true;
    for (unsigned int i = 0; i < n_owned; ++i)
      exchange.local_element(i) = node_radii[i];
    exchange.update_ghost_values();
    for (unsigned int i = n_owned; i < n_local; ++i)
      node_radii[i] = exchange.local_element(i);

    if (first)
      {
        initial_owned_nodes.assign(node_positions.begin(),
                                   node_positions.begin() + n_owned);
        initial_cell_boxes.resize(dofs->get_triangulation().n_active_cells());
        for (const auto &cell : dofs->active_cell_iterators())
          if (cell->is_locally_owned())
            initial_cell_boxes[cell->active_cell_index()] =
              cell->bounding_box();
      }
    // The largest radius on all ranks and the box of all nodes'
    // displacements since set-up (its upper corner and minus its lower one),
    // in one reduction.
    std::vector<double> extremes(1 + 2 * dim,
                                 -std::numeric_limits<double>::max());
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        extremes[0] = std::max(extremes[0], node_radii[i]);
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double u  = node_positions[i][d] - initial_owned_nodes[i][d];
            extremes[1 + d] = std::max(extremes[1 + d], u);
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
    return true;
  }



  template <int dim>
  void
  MaxEntNodeCloud<dim>::stop_if_cloud_too_small(
    const MaterialPoints<dim> *material_points)
  {
    stop_if_any_rank_failed(
      node_partition->get_mpi_communicator(),
      complete ? std::string() : cloud_problem(material_points),
      "The max-ent nodes moved so far relative to each other that a rank "
      "could miss a node whose support reaches its material points: ",
      "Increase Max-ent halo factor (now " + Utilities::to_string(halo_factor) +
        "), or run on fewer MPI ranks.");
    points_unchecked = (material_points == nullptr);
  }



  template <int dim>
  std::string
  MaxEntNodeCloud<dim>::cloud_problem(
    const MaterialPoints<dim> *material_points) const
  {
    // A node outside the cloud started at least the halo H from this
    // rank's cells and has moved by at most the spread from the centre of
    // all displacements; it cannot reach a point y of a cell whose box at
    // set-up, moved by that centre, lies within
    // H - spread - largest radius of y.
    const double allowed = halo - displacement_spread - largest_radius;
    std::vector<BoundingBox<dim>> current(initial_cell_boxes.size());
    for (const auto &cell : dofs->active_cell_iterators())
      if (cell->is_locally_owned())
        current[cell->active_cell_index()] = cell->bounding_box();
    if (material_points)
      for (const auto &particle : material_points->particle_handler())
        current[particle.get_surrounding_cell()->active_cell_index()]
          .merge_with(BoundingBox<dim>(
            std::make_pair(particle.get_location(), particle.get_location())));
    for (const auto &cell : dofs->active_cell_iterators())
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
  const Utilities::MPI::Partitioner &
  MaxEntNodeCloud<dim>::partition() const
  {
    return *node_partition;
  }



  template <int dim>
  const std::vector<Point<dim>> &
  MaxEntNodeCloud<dim>::positions() const
  {
    return node_positions;
  }



  template <int dim>
  const std::vector<double> &
  MaxEntNodeCloud<dim>::radii() const
  {
    return node_radii;
  }



  template double
  squared_distance_to_box(const Point<1> &, const BoundingBox<1> &);
  template double
  squared_distance_to_box(const Point<2> &, const BoundingBox<2> &);
  template double
  squared_distance_to_box(const Point<3> &, const BoundingBox<3> &);
  template class MaxEntNodeCloud<1>;
  template class MaxEntNodeCloud<2>;
  template class MaxEntNodeCloud<3>;
} // namespace MpmOtm
