#ifndef mpm_otm_grid_system_background_grid_h
#define mpm_otm_grid_system_background_grid_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <memory>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * The background grid: a coordinate-parallel box split into blocks, each
   * block a quadrilateral/hexahedral cell ("hypercube") or, for "simplex",
   * four triangles around the block's centre vertex in 2D (as in the thesis,
   * Fig. 4.2) and tetrahedra in 3D; intervals in 1D. Boundary ids per side:
   * 2 d for the lower and 2 d + 1 for the upper side in direction d (0: x =
   * x_min, 1: x = x_max, 2: y = y_min, ...). Hypercube grids in 2D and 3D are
   * p4est-distributed; 1D and simplex grids are serial.
   */
  template <int dim>
  class BackgroundGrid
  {
  public:
    /**
     * Declare subsection "Mesh".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read and check subsection "Mesh".
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Build the triangulation and the mapping. With @p vertices_move (OTM and
     * the unified approach advect the vertices) quadrilaterals and hexahedra
     * get the bilinear/trilinear MappingQ(1) instead of MappingCartesian,
     * because moved cells are no longer axis-parallel boxes.
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
     * The box covered by the grid.
     */
    const BoundingBox<dim> &
    box() const;

    /**
     * Number of blocks per direction.
     */
    const std::vector<unsigned int> &
    subdivisions() const;

    /**
     * Smallest distance between two vertices of one cell over the whole
     * (global) grid: the h of the CFL bound, thesis Eq. 2.48.
     */
    double
    minimal_cell_size() const;

  private:
    void
    create_simplex_blocks_2d();

    void
    set_boundary_ids();

    bool                                simplex = false;
    BoundingBox<dim>                    bounding_box;
    std::vector<unsigned int>           blocks;
    std::unique_ptr<Triangulation<dim>> tria;
    std::unique_ptr<Mapping<dim>>       map;
  };
} // namespace MpmOtm

#endif
