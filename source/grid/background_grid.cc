#include <deal.II/base/utilities.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_cartesian.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/base/node_memory.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/grid/gmsh_file.h>

#include <algorithm>
#include <boost/crc.hpp>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace MpmOtm
{
  namespace
  {
    /**
     * Read a comma-separated list with one value per direction; a single
     * value is used for every direction.
     */
    template <typename T>
    std::vector<T>
    per_direction(const std::vector<T> &values,
                  const unsigned int    dim,
                  const std::string    &entry)
    {
      AssertThrow(values.size() == 1 || values.size() == dim,
                  ExcMessage("Mesh/" + entry + " needs one value or " +
                             std::to_string(dim) +
                             " comma-separated values (one per direction), "
                             "but has " +
                             std::to_string(values.size()) + "."));
      if (values.size() == dim)
        return values;
      return std::vector<T>(dim, values[0]);
    }
  } // namespace



  template <int dim>
  BackgroundGrid<dim>::BackgroundGrid() = default;



  template <int dim>
  BackgroundGrid<dim>::~BackgroundGrid() = default;



  template <int dim>
  void
  BackgroundGrid<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      prm.declare_entry(
        "Mesh file",
        "",
        Patterns::FileName(Patterns::FileName::input),
        "A Gmsh .msh file (ASCII, format 2.2 or 4.1; a relative path starts "
        "in the working directory) whose cells, all quadrilaterals or all "
        "triangles in 2D and all hexahedra or all tetrahedra in 3D, form the "
        "grid, with the physical tags of the boundary lines (2D) or "
        "surfaces (3D) as boundary ids (0 where a boundary face has none); "
        "empty: the box grid of Lower corner, Upper corner and "
        "Subdivisions.");
      prm.declare_entry("Cell type",
                        "hypercube",
                        Patterns::Selection("hypercube|simplex"),
                        "hypercube: one quadrilateral/hexahedron per block; "
                        "simplex: four triangles around the block centre in "
                        "2D (thesis Fig. 4.2), tetrahedra in 3D (ignored "
                        "with a Mesh file, whose cells decide).");
      prm.declare_entry("Lower corner",
                        "0",
                        Patterns::List(Patterns::Double()),
                        "Lower corner of the background box, one value per "
                        "direction (one value: the same in every direction; "
                        "ignored with a Mesh file).");
      prm.declare_entry("Upper corner",
                        "1",
                        Patterns::List(Patterns::Double()),
                        "Upper corner of the background box (ignored with a "
                        "Mesh file).");
      prm.declare_entry("Subdivisions",
                        "31",
                        Patterns::List(Patterns::Integer(1)),
                        "Number of blocks per direction (nodes per direction "
                        "minus one for linear shape functions; ignored with "
                        "a Mesh file).");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  BackgroundGrid<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    file = prm.get("Mesh file");
    if (!file.empty())
      {
        prm.leave_subsection();
        gmsh    = std::make_unique<GmshFile>(file, dim);
        simplex = gmsh->is_simplex();
        blocks.clear();
        return;
      }
    gmsh.reset();
    simplex = (prm.get("Cell type") == "simplex");
    const auto lower =
      per_direction(Utilities::string_to_double(
                      Utilities::split_string_list(prm.get("Lower corner"))),
                    dim,
                    "Lower corner");
    const auto upper =
      per_direction(Utilities::string_to_double(
                      Utilities::split_string_list(prm.get("Upper corner"))),
                    dim,
                    "Upper corner");
    const auto n =
      per_direction(Utilities::string_to_int(
                      Utilities::split_string_list(prm.get("Subdivisions"))),
                    dim,
                    "Subdivisions");
    prm.leave_subsection();

    Point<dim> p1, p2;
    blocks.resize(dim);
    for (unsigned int d = 0; d < dim; ++d)
      {
        AssertThrow(upper[d] > lower[d],
                    ExcMessage("Mesh/Upper corner must be larger than "
                               "Mesh/Lower corner in every direction."));
        p1[d]     = lower[d];
        p2[d]     = upper[d];
        blocks[d] = n[d];
      }
    bounding_box = BoundingBox<dim>(std::make_pair(p1, p2));
    AssertThrow(!(simplex && dim == 1),
                ExcMessage("Mesh/Cell type = simplex needs Dimension 2 or "
                           "3; in 1D use hypercube (intervals)."));
  }



  template <int dim>
  void
  BackgroundGrid<dim>::create(const MPI_Comm communicator,
                              const bool     vertices_move)
  {
    if (gmsh)
      {
        create_from_file(communicator);
        return;
      }
    check_memory(communicator);
    if (dim > 1 && !simplex)
      tria = std::make_unique<parallel::distributed::Triangulation<dim>>(
        communicator);
    else
      tria = std::make_unique<Triangulation<dim>>();

    if (!simplex)
      {
        GridGenerator::subdivided_hyper_rectangle(
          *tria,
          blocks,
          bounding_box.get_boundary_points().first,
          bounding_box.get_boundary_points().second);
        if (vertices_move)
          map = std::make_unique<MappingQ<dim>>(1);
        else
          map = std::make_unique<MappingCartesian<dim>>();
      }
    else
      {
        if constexpr (dim == 2)
          create_simplex_blocks_2d();
        else
          GridGenerator::subdivided_hyper_rectangle_with_simplices(
            *tria,
            blocks,
            bounding_box.get_boundary_points().first,
            bounding_box.get_boundary_points().second);
        map = std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
      }
    set_boundary_ids();
    compute_fingerprint();
    if (simplex || dim == 1)
      distribute(communicator);
  }



  template <int dim>
  void
  BackgroundGrid<dim>::compute_fingerprint()
  {
    boost::crc_32_type crc;
    for (const auto &cell : tria->cell_iterators_on_level(0))
      {
        for (const unsigned int v : cell->vertex_indices())
          crc.process_bytes(&cell->vertex(v)[0], dim * sizeof(double));
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              const types::boundary_id id = cell->face(f)->boundary_id();
              crc.process_bytes(&id, sizeof(id));
            }
      }
    grid_fingerprint = crc.checksum();
  }



  template <int dim>
  std::uint32_t
  BackgroundGrid<dim>::fingerprint() const
  {
    return grid_fingerprint;
  }



  template <int dim>
  void
  BackgroundGrid<dim>::create_from_file(const MPI_Comm communicator)
  {
    if constexpr (dim > 1)
      {
        if (!simplex)
          tria = std::make_unique<parallel::distributed::Triangulation<dim>>(
            communicator);
        else
          tria = std::make_unique<Triangulation<dim>>();
        check_memory(communicator);
        gmsh->read(*tria);
        if (simplex)
          map = std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
        else
          map = std::make_unique<MappingQ<dim>>(1);

        // Every rank has the whole coarse mesh.
        Point<dim> lower, upper;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = std::numeric_limits<double>::max();
            upper[d] = -std::numeric_limits<double>::max();
          }
        const auto &used = tria->get_used_vertices();
        for (unsigned int v = 0; v < tria->n_vertices(); ++v)
          if (used[v])
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = std::min(lower[d], tria->get_vertices()[v][d]);
                upper[d] = std::max(upper[d], tria->get_vertices()[v][d]);
              }
        bounding_box = BoundingBox<dim>(std::make_pair(lower, upper));
        compute_fingerprint();
        if (simplex)
          distribute(communicator);
      }
    else
      {
        (void)communicator;
        AssertThrow(false, ExcInternalError());
      }
  }



  template <int dim>
  void
  BackgroundGrid<dim>::distribute(const MPI_Comm communicator)
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    if (n_ranks == 1)
      return;
    // Every rank partitions the same coarse mesh with METIS, so all agree
    // on the owners without communication.
    const std::unique_ptr<Triangulation<dim>> serial = std::move(tria);
    // Every rank needs cells of its own (deal.II would give a rank without
    // any a placeholder cell that is not part of the grid).
    std::vector<unsigned int> cells_of_rank(n_ranks, 0);
    if (serial->n_active_cells() >= n_ranks)
      {
        GridTools::partition_triangulation(n_ranks, *serial);
        for (const auto &cell : serial->active_cell_iterators())
          ++cells_of_rank[cell->subdomain_id()];
      }
    AssertThrow(std::find(cells_of_rank.begin(), cells_of_rank.end(), 0u) ==
                  cells_of_rank.end(),
                ExcMessage(
                  (gmsh ? "Mesh/Mesh file: the mesh of <" + file + ">" :
                          std::string("Mesh/Subdivisions: the grid")) +
                  " has " + std::to_string(serial->n_active_cells()) +
                  (serial->n_active_cells() == 1 ? " cell" : " cells") +
                  "; partitioned for " + std::to_string(n_ranks) +
                  " MPI ranks, it leaves a rank without a cell. Run on "
                  "fewer ranks or use more cells."));
    auto distributed =
      std::make_unique<parallel::fullydistributed::Triangulation<dim>>(
        communicator);
    distributed->create_triangulation(
      TriangulationDescription::Utilities::
        create_description_from_triangulation(*serial, communicator));

    // The faces between the ghost layer and the cells a rank does not hold
    // are boundary faces of its triangulation, with boundary id 0: they get
    // an id of their own, which no condition names.
    coarse_vertex.assign(distributed->n_vertices(),
                         numbers::invalid_unsigned_int);
    for (const auto &cell : distributed->active_cell_iterators())
      {
        const auto coarse_cell = serial->create_cell_iterator(cell->id());
        for (const unsigned int v : cell->vertex_indices())
          coarse_vertex[cell->vertex_index(v)] = coarse_cell->vertex_index(v);
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              !coarse_cell->face(f)->at_boundary())
            cell->face(f)->set_boundary_id(ghost_layer_boundary_id);
      }
    tria = std::move(distributed);
  }



  template <int dim>
  unsigned int
  BackgroundGrid<dim>::coarse_vertex_index(const unsigned int vertex) const
  {
    return coarse_vertex.empty() ? vertex : coarse_vertex[vertex];
  }



  template <int dim>
  void
  BackgroundGrid<dim>::check_memory(const MPI_Comm communicator) const
  {
    // A lower bound of the bytes per cell: deal.II 9.4 with p4est takes
    // 850 per quadrilateral and 2000 per hexahedron (doc/performance.md,
    // "Memory"); the bound for a line is a guess.
    const double bytes_per_cell[] = {0., 200., 800., 1800.};
    double       n_cells          = 1.;
    if (gmsh)
      n_cells = gmsh->n_cells();
    else
      {
        for (unsigned int d = 0; d < dim; ++d)
          n_cells *= blocks[d];
        if (simplex)
          n_cells *= (dim == 2 ? 4. : 5.);
      }
    const double needed = bytes_per_cell[dim] * n_cells;

    // Every rank holds all cells of the coarse mesh.
    const NodeMemory   memory(communicator);
    const std::string  shortage = memory.shortage(memory.sum_on_node(needed));
    std::ostringstream message;
    if (!shortage.empty())
      message << std::setprecision(3)
              << (gmsh ? "Mesh/Mesh file: the mesh of <" + file + "> with " :
                         std::string("Mesh/Subdivisions: the grid of "))
              << n_cells << " cells needs at least " << needed / 1e9
              << " GB on every MPI rank (each holds all cells of the coarse "
              << "mesh): at least " << shortage;
    stop_if_any_rank_failed(communicator,
                            message.str(),
                            "",
                            gmsh ? "Use a coarser mesh, or fewer ranks per "
                                   "node." :
                                   "Use fewer Subdivisions, or fewer ranks "
                                   "per node.");
  }



  template <int dim>
  void
  BackgroundGrid<dim>::create_simplex_blocks_2d()
  {
    if constexpr (dim == 2)
      {
        const Point<2>     lower = bounding_box.get_boundary_points().first;
        const Point<2>     upper = bounding_box.get_boundary_points().second;
        const unsigned int nx = blocks[0], ny = blocks[1];
        const double       hx = (upper[0] - lower[0]) / nx;
        const double       hy = (upper[1] - lower[1]) / ny;

        std::vector<Point<2>> vertices;
        for (unsigned int j = 0; j <= ny; ++j)
          for (unsigned int i = 0; i <= nx; ++i)
            vertices.emplace_back(lower[0] + i * hx, lower[1] + j * hy);
        const unsigned int first_centre = vertices.size();
        for (unsigned int j = 0; j < ny; ++j)
          for (unsigned int i = 0; i < nx; ++i)
            vertices.emplace_back(lower[0] + (i + 0.5) * hx,
                                  lower[1] + (j + 0.5) * hy);

        std::vector<CellData<2>> cells;
        for (unsigned int j = 0; j < ny; ++j)
          for (unsigned int i = 0; i < nx; ++i)
            {
              const unsigned int corner[4] = {j * (nx + 1) + i,
                                              j * (nx + 1) + i + 1,
                                              (j + 1) * (nx + 1) + i + 1,
                                              (j + 1) * (nx + 1) + i};
              const unsigned int centre    = first_centre + j * nx + i;
              // Four counter-clockwise triangles: bottom, right, top, left.
              for (unsigned int k = 0; k < 4; ++k)
                {
                  CellData<2> cell(3);
                  cell.vertices = {corner[k], corner[(k + 1) % 4], centre};
                  cells.push_back(cell);
                }
            }
        tria->create_triangulation(vertices, cells, SubCellData());
      }
  }



  template <int dim>
  void
  BackgroundGrid<dim>::set_boundary_ids()
  {
    const Point<dim> lower = bounding_box.get_boundary_points().first;
    const Point<dim> upper = bounding_box.get_boundary_points().second;
    for (const auto &cell : tria->active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const Point<dim> centre = cell->face(f)->center();
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double tolerance = 1e-10 * (upper[d] - lower[d]);
                if (std::abs(centre[d] - lower[d]) < tolerance)
                  cell->face(f)->set_boundary_id(2 * d);
                else if (std::abs(centre[d] - upper[d]) < tolerance)
                  cell->face(f)->set_boundary_id(2 * d + 1);
              }
          }
  }



  template <int dim>
  Triangulation<dim> &
  BackgroundGrid<dim>::triangulation()
  {
    return *tria;
  }



  template <int dim>
  const Triangulation<dim> &
  BackgroundGrid<dim>::triangulation() const
  {
    return *tria;
  }



  template <int dim>
  const Mapping<dim> &
  BackgroundGrid<dim>::mapping() const
  {
    return *map;
  }



  template <int dim>
  bool
  BackgroundGrid<dim>::is_simplex() const
  {
    return simplex;
  }



  template <int dim>
  bool
  BackgroundGrid<dim>::is_box() const
  {
    return file.empty();
  }



  template <int dim>
  const std::string &
  BackgroundGrid<dim>::mesh_file() const
  {
    return file;
  }



  template <int dim>
  const GmshFile *
  BackgroundGrid<dim>::gmsh_file() const
  {
    return gmsh.get();
  }



  template <int dim>
  const BoundingBox<dim> &
  BackgroundGrid<dim>::box() const
  {
    return bounding_box;
  }



  template <int dim>
  const std::vector<unsigned int> &
  BackgroundGrid<dim>::subdivisions() const
  {
    Assert(is_box(), ExcMessage("Only box grids have blocks."));
    return blocks;
  }



  template <int dim>
  double
  BackgroundGrid<dim>::minimal_cell_size() const
  {
    double h = std::numeric_limits<double>::max();
    for (const auto &cell : tria->active_cell_iterators())
      if (cell->is_locally_owned())
        h = std::min(h, cell->minimum_vertex_distance());
    return Utilities::MPI::min(h, tria->get_communicator());
  }



  template <int dim>
  std::vector<types::boundary_id>
  BackgroundGrid<dim>::boundary_ids() const
  {
    std::vector<types::boundary_id> ids;
    for (const auto &cell : tria->active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            ids.push_back(cell->face(f)->boundary_id());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    ids = Utilities::MPI::compute_set_union(ids, tria->get_communicator());
    std::sort(ids.begin(), ids.end());
    return ids;
  }



  template class BackgroundGrid<1>;
  template class BackgroundGrid<2>;
  template class BackgroundGrid<3>;
} // namespace MpmOtm
