#ifndef mpm_otm_grid_background_grid_h
#define mpm_otm_grid_background_grid_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * The background grid, either a box grid or the mesh of a Gmsh file.
   *
   * Box grid (Mesh/Mesh file empty): a coordinate-parallel box split into
   * blocks, each block a quadrilateral/hexahedral cell ("hypercube") or, for
   * "simplex", four triangles around the block's centre vertex in 2D (as in
   * the thesis, Fig. 4.2) and tetrahedra in 3D; intervals in 1D. Boundary
   * ids per side: 2 d for the lower and 2 d + 1 for the upper side in
   * direction d (0: x = x_min, 1: x = x_max, 2: y = y_min, ...).
   *
   * Mesh file (2D and 3D): the cells of a Gmsh file, all quadrilaterals or
   * all triangles (all hexahedra or all tetrahedra in 3D), read by
   * GmshFile; boundary ids are the file's physical tags of boundary lines
   * (2D) or surfaces (3D), 0 where a face has none.
   *
   * Quadrilateral and hexahedral grids in 2D and 3D are p4est-distributed
   * (a file's cells are p4est's trees). Simplex grids and 1D grids on more
   * than one MPI rank are parallel::fullydistributed: every rank builds the
   * coarse mesh, METIS partitions it, and each rank keeps its cells and one
   * layer of ghost cells.
   */
  class GmshFile;

  template <int dim>
  class BackgroundGrid
  {
  public:
    BackgroundGrid();

    ~BackgroundGrid();

    /**
     * Declare subsection "Mesh".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read and check subsection "Mesh"; a Mesh file is opened and checked
     * here (GmshFile), before anything is written.
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Build the triangulation and the mapping. With @p vertices_move (OTM and
     * the unified approach advect the vertices) quadrilaterals and hexahedra
     * of a box grid get the bilinear/trilinear MappingQ(1) instead of
     * MappingCartesian, because moved cells are no longer axis-parallel
     * boxes; those of a Mesh file always have MappingQ(1). Simplices have
     * MappingFE(FE_SimplexP(1)).
     */
    void
    create(const MPI_Comm communicator, const bool vertices_move = false);

    /**
     * The triangulation (distributed or serial).
     */
    Triangulation<dim> &
    triangulation();

    /**
     * The triangulation (distributed or serial).
     */
    const Triangulation<dim> &
    triangulation() const;

    /**
     * The mapping from reference to real cells.
     */
    const Mapping<dim> &
    mapping() const;

    /**
     * True for triangles/tetrahedra.
     */
    bool
    is_simplex() const;

    /**
     * True for the box grid of Mesh/Lower corner, Upper corner and
     * Subdivisions, false for a Mesh file (known after parse_parameters()).
     * Only box grids have blocks (subdivisions()).
     */
    bool
    is_box() const;

    /**
     * The Mesh file (empty for a box grid).
     */
    const std::string &
    mesh_file() const;

    /**
     * The checked Mesh file (nullptr for a box grid).
     */
    const GmshFile *
    gmsh_file() const;

    /**
     * The box covered by the grid: for a Mesh file, the bounding box of its
     * vertices (known after create()).
     */
    const BoundingBox<dim> &
    box() const;

    /**
     * Number of blocks per direction (box grids only).
     */
    const std::vector<unsigned int> &
    subdivisions() const;

    /**
     * Smallest distance between two vertices of one cell over the whole
     * (global) grid: the h of the CFL bound, thesis Eq. 2.48.
     */
    double
    minimal_cell_size() const;

    /**
     * The boundary ids of the grid's boundary faces on all ranks, sorted
     * (collective).
     */
    std::vector<types::boundary_id>
    boundary_ids() const;

    /**
     * The boundary id of the faces between a rank's ghost cells and the
     * cells it does not hold on a fully distributed triangulation (deal.II
     * gives them boundary id 0), so that no condition on a side applies to
     * them.
     */
    static constexpr types::boundary_id ghost_layer_boundary_id =
      numbers::internal_face_boundary_id - 1;

    /**
     * The number in the coarse mesh (the same on every rank) of the vertex
     * with index @p vertex in this rank's triangulation. The two differ only
     * on a fully distributed triangulation, which numbers its vertices per
     * rank.
     */
    unsigned int
    coarse_vertex_index(const unsigned int vertex) const;

    /**
     * A CRC-32 of the grid as created, the same on every rank and for every
     * number of ranks: of its cells' vertices and its boundary faces' ids,
     * in the order of the coarse mesh. A checkpoint records it, so that a
     * run resumed on another grid (a changed Mesh file) is refused.
     */
    std::uint32_t
    fingerprint() const;

  private:
    /**
     * Build the triangulation and mapping of the Mesh file.
     */
    void
    create_from_file(const MPI_Comm communicator);

    void
    create_simplex_blocks_2d();

    /**
     * Stop, on every rank and before the triangulation is filled, if the
     * cells of the box grid or of the Mesh file need more memory than the
     * node has available for its ranks: each rank holds every cell of the
     * coarse mesh. Collective; does nothing where /proc/meminfo is missing.
     */
    void
    check_memory(const MPI_Comm communicator) const;

    void
    set_boundary_ids();

    /**
     * Compute fingerprint() from the complete coarse triangulation, which
     * every rank holds before distribute().
     */
    void
    compute_fingerprint();

    /**
     * On more than one rank, replace the serial triangulation of a simplex
     * or 1D grid (filled, with boundary ids) by a fully distributed one.
     */
    void
    distribute(const MPI_Comm communicator);

    std::string                         file;
    std::unique_ptr<GmshFile>           gmsh;
    bool                                simplex = false;
    BoundingBox<dim>                    bounding_box;
    std::vector<unsigned int>           blocks;
    std::unique_ptr<Triangulation<dim>> tria;
    std::unique_ptr<Mapping<dim>>       map;
    /**
     * coarse_vertex_index() of every vertex; empty where they agree.
     */
    std::vector<unsigned int> coarse_vertex;
    std::uint32_t             grid_fingerprint = 0;
  };
} // namespace MpmOtm

#endif
