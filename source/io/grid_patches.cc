#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/io/collective_hdf5_file.h>
#include <mpm_otm/io/grid_patches.h>

namespace MpmOtm
{
  namespace
  {
    /**
     * The number of points of @p patch and of its sub-cells: a hypercube
     * patch subdivided n times has (n + 1)^dim points in lexicographic
     * order, a simplex patch its vertices, and a triangle patch of a
     * quadratic element (Powell-Sabin) its vertices and then its edges'
     * midpoints (VTK's quadratic triangle), written as four triangles.
     */
    template <int dim>
    std::pair<unsigned int, unsigned int>
    points_and_cells(const DataOutBase::Patch<dim, dim> &patch)
    {
      if (patch.reference_cell == ReferenceCells::get_hypercube<dim>())
        return {Utilities::fixed_power<dim>(patch.n_subdivisions + 1),
                Utilities::fixed_power<dim>(patch.n_subdivisions)};
      if (patch.reference_cell == ReferenceCells::Triangle &&
          patch.n_subdivisions == 2)
        return {6, 4};
      AssertThrow(patch.n_subdivisions == 1,
                  ExcMessage("Grid output: a subdivided simplex patch."));
      return {patch.reference_cell.n_vertices(), 1};
    }
  } // namespace



  template <int dim>
  GridPatches<dim>::GridPatches(const BackgroundGrid<dim> &grid,
                                const ShapeFunctions<dim> &shape_functions,
                                NodalSystem<dim>          &system)
    : subdomain(grid.triangulation().n_active_cells())
    , cell_kind(grid.triangulation().get_reference_cells()[0])
  {
    // zlib's fastest level: the best level took several times longer per
    // output for files a few percent smaller.
    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    this->set_flags(flags);
    this->attach_dof_handler(shape_functions.dof_handler());
    system.lumped_mass.update_ghost_values();
    shape_functions.to_cell_dofs(system.lumped_mass, fields[dim]);
    this->add_data_vector(fields[dim], "nodal_mass");
    const std::string names = "xyz";
    for (unsigned int c = 0; c < dim; ++c)
      {
        system.velocity[c].update_ghost_values();
        shape_functions.to_cell_dofs(system.velocity[c], fields[c]);
        this->add_data_vector(fields[c],
                              std::string("nodal_velocity_") + names[c]);
      }
    for (auto &value : subdomain)
      value = grid.triangulation().locally_owned_subdomain();
    this->add_data_vector(subdomain, "subdomain");
    this->build_patches(grid.mapping(),
                        shape_functions.dof_handler().get_fe().degree);
  }



  template <int dim>
  std::vector<
    std::tuple<unsigned int,
               unsigned int,
               std::string,
               DataComponentInterpretation::DataComponentInterpretation>>
  GridPatches<dim>::get_nonscalar_data_ranges() const
  {
    auto ranges = DataOut<dim>::get_nonscalar_data_ranges();
    if (dim > 1)
      ranges.emplace_back(
        1,
        dim,
        "nodal_velocity",
        DataComponentInterpretation::component_is_part_of_vector);
    return ranges;
  }



  template <int dim>
  std::uint64_t
  GridPatches<dim>::n_nodes() const
  {
    std::uint64_t n = 0;
    for (const auto &patch : this->get_patches())
      n += points_and_cells(patch).first;
    return n;
  }



  template <int dim>
  std::uint64_t
  GridPatches<dim>::n_cells() const
  {
    std::uint64_t n = 0;
    for (const auto &patch : this->get_patches())
      n += points_and_cells(patch).second;
    return n;
  }



  template <int dim>
  ReferenceCell
  GridPatches<dim>::reference_cell() const
  {
    return cell_kind;
  }



  template <int dim>
  std::vector<std::pair<std::string, unsigned int>>
  GridPatches<dim>::data_sets() const
  {
    return xdmf_data_sets(this->get_dataset_names(),
                          get_nonscalar_data_ranges());
  }



  template <int dim>
  void
  GridPatches<dim>::write_hdf5(const std::string &file_name,
                               const MPI_Comm     communicator) const
  {
    const auto        &patches = this->get_patches();
    const unsigned int n_data  = this->get_dataset_names().size();
    const std::size_t  n_local = n_nodes();

    // The points: their coordinates are the last dim data rows where the
    // mapping computed them, else multilinear in the patch's vertices
    // (numbered lexicographically, as the points).
    std::vector<double> nodes;
    nodes.reserve(n_local * dim);
    for (const auto &patch : patches)
      {
        const unsigned int n_points = points_and_cells(patch).first;
        const unsigned int n        = patch.n_subdivisions;
        for (unsigned int j = 0; j < n_points; ++j)
          if (patch.points_are_available)
            for (unsigned int d = 0; d < dim; ++d)
              nodes.push_back(patch.data(n_data + d, j));
          else if (patch.reference_cell != ReferenceCells::get_hypercube<dim>())
            for (unsigned int d = 0; d < dim; ++d)
              nodes.push_back(patch.vertices[j][d]);
          else
            {
              Point<dim> xi;
              for (unsigned int d = 0, rest = j; d < dim; ++d, rest /= n + 1)
                xi[d] = double(rest % (n + 1)) / n;
              Point<dim> x;
              for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell;
                   ++v)
                {
                  double weight = 1;
                  for (unsigned int d = 0; d < dim; ++d)
                    weight *= ((v >> d) & 1) ? xi[d] : 1. - xi[d];
                  x += weight * patch.vertices[v];
                }
              for (unsigned int d = 0; d < dim; ++d)
                nodes.push_back(x[d]);
            }
      }
    CollectiveHDF5File  file(file_name, communicator);
    const std::uint64_t first = file.write("nodes", nodes, dim);

    // The sub-cells, their vertices in XDMF's (VTK's) order: the corners of
    // a quadrilateral counter-clockwise, of a hexahedron its bottom then its
    // top face so; a simplex's as deal.II numbers them.
    const unsigned int        vertices_per_cell = cell_kind.n_vertices();
    std::vector<unsigned int> cells;
    cells.reserve(n_cells() * vertices_per_cell);
    std::uint64_t patch_start = first;
    for (const auto &patch : patches)
      {
        const auto [n_points, n_sub_cells] = points_and_cells(patch);
        const unsigned int n               = patch.n_subdivisions;
        if (patch.reference_cell == ReferenceCells::Triangle &&
            patch.n_subdivisions == 2)
          // Corners 0, 1, 2 and midpoints 3 (0-1), 4 (1-2), 5 (2-0).
          for (const unsigned int v : {0, 3, 5, 3, 1, 4, 5, 4, 2, 3, 4, 5})
            cells.push_back(patch_start + v);
        else if (patch.reference_cell != ReferenceCells::get_hypercube<dim>())
          for (unsigned int v = 0; v < n_points; ++v)
            cells.push_back(patch_start + v);
        else
          for (unsigned int c = 0; c < n_sub_cells; ++c)
            {
              // The sub-cell's lowest point, then its corners.
              unsigned int lowest = 0;
              for (unsigned int d = 0, rest = c, stride = 1; d < dim;
                   ++d, rest /= n, stride *= n + 1)
                lowest += (rest % n) * stride;
              const unsigned int stride_y = n + 1, stride_z = (n + 1) * (n + 1);
              const std::array<unsigned int, 4> face = {
                {0, 1, 1 + stride_y, stride_y}};
              for (unsigned int layer = 0; layer < (dim == 3 ? 2 : 1); ++layer)
                for (unsigned int k = 0; k < (dim == 1 ? 2 : 4); ++k)
                  cells.push_back(patch_start + lowest + layer * stride_z +
                                  face[k]);
            }
        patch_start += n_points;
      }
    file.write("cells", cells, vertices_per_cell);

    // The fields, point by point: the patches' data columns in order.
    std::vector<std::pair<unsigned int, unsigned int>> patch_and_column;
    patch_and_column.reserve(n_local);
    for (unsigned int k = 0; k < patches.size(); ++k)
      for (unsigned int j = 0; j < patches[k].data.n_cols(); ++j)
        patch_and_column.emplace_back(k, j);
    file.write_fields<float>(data_sets(),
                             n_local,
                             dim,
                             [&](const std::size_t  row,
                                 const unsigned int component) {
                               const auto [k, j] = patch_and_column[row];
                               return patches[k].data(component, j);
                             });
  }



  template class GridPatches<1>;
  template class GridPatches<2>;
  template class GridPatches<3>;
} // namespace MpmOtm
