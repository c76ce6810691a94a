#ifndef mpm_otm_material_points_material_points_h
#define mpm_otm_material_points_material_points_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm_otm/material_points/property_layout.h>

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class BackgroundGrid;
  template <int dim>
  class CellLocator;
  template <int dim>
  class SeedingBodies;

  /**
   * The material points: a thin layer over Particles::ParticleHandler with
   * the property layout of PropertyLayout. It seeds a regular pattern of
   * points per block of a box grid (n per direction, thesis Sect. 2.4 and
   * Fig. 4.2) or per cell of a Mesh file (n per direction of the reference
   * cell) where the bodies are, with the properties the bodies give them
   * (SeedingBodies: it knows no material and no problem), marks the points
   * next to a traction boundary as boundary particles (thesis Sect. 2.4.1 /
   * 2.5, box grids), and re-associates moved points with their cells.
   */
  template <int dim>
  class MaterialPoints
  {
  public:
    MaterialPoints();

    ~MaterialPoints();

    /**
     * Declare subsection "Particles".
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read subsection "Particles".
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Create the particle handler on @p grid and seed the points of the
     * regular pattern of each block that lie in one of @p bodies, with the
     * volume V_p = block volume / points per block and the properties the
     * bodies give a point there (SeedingBodies::set_properties()). On a
     * Mesh file the pattern is that of each cell (insert_points_of_cells()).
     * Stops if a body receives no point.
     */
    void
    seed(const BackgroundGrid<dim> &grid, const SeedingBodies<dim> &bodies);

    /**
     * Seed @p bodies into the points there are already, by the same
     * pattern as seed() (a body a stage adds to the run). The new points'
     * ids are those of their places in the pattern, which no point that
     * was seeded elsewhere has. Stops if a body receives no point.
     */
    void
    add(const SeedingBodies<dim> &bodies);

    /**
     * Find the cell of every point after the points have moved. A point
     * that has left the grid stops the run with its id and position.
     */
    void
    locate();

    /**
     * Write this rank's points to @p out for a checkpoint: per point its
     * cell, id, location, reference location and properties, in the order
     * of the particle handler (the order of the sums over points, which a
     * run resumed from the checkpoint must repeat to continue bit by bit).
     * Returns false if a write failed.
     */
    bool
    write_points(std::ostream &out) const;

    /**
     * Replace the points by those in @p files, written by write_points()
     * on each rank of a saved run (on any number of ranks): this rank keeps
     * the points whose cell it owns, each cell's points in their saved
     * order. Stops with a message naming the file if one does not fit this
     * run (another dimension or number of properties, a cell that the grid
     * does not have) or not every point found a rank. Collective.
     */
    void
    read_points(const std::vector<std::string> &files);

    /**
     * The particle handler.
     */
    Particles::ParticleHandler<dim> &
    particle_handler();

    /**
     * The particle handler.
     */
    const Particles::ParticleHandler<dim> &
    particle_handler() const;

    /**
     * The MPI communicator of the background grid.
     */
    MPI_Comm
    communicator() const;

    /**
     * Number of points on all ranks.
     */
    types::particle_index
    n_global_points() const;

    /**
     * Number of points of the seeding pattern (on all ranks) that lay in no
     * body and were left out; 0 if the bodies fill the grid.
     */
    types::particle_index
    n_pattern_points_outside_bodies() const;


  private:
    /**
     * Insert the points of the seeding pattern that lie in @p bodies, count
     * them per body and stop if a body has none. Collective.
     */
    void
    insert_pattern(const SeedingBodies<dim> &bodies);

    /**
     * Seed the cells of a Mesh file: per locally owned cell, n^dim points
     * at reference positions mapped to the cell (quadrilaterals/hexahedra:
     * the centres of the n^dim subcells of side 1/n of the reference cell;
     * triangles/tetrahedra: the centroids of the n^dim equal simplices of
     * the regular subdivision of the reference simplex), each with the
     * volume |J(xi_p)| |cell| / sum_q |J(xi_q)| (|cell| / n^dim on affine
     * cells), and the points outside every body left out. Stops for
     * tractions (which need the box material region) and for
     * per-direction Particles per cell.
     */
    void
    insert_points_of_cells(const SeedingBodies<dim> &bodies);

    /**
     * Stop if a body has received no point (points_per_body summed over
     * the ranks).
     */
    void
    check_every_body_has_points(const SeedingBodies<dim> &bodies) const;

    void
    insert_points_of_block(
      const std::vector<unsigned int>                         &block,
      const typename Triangulation<dim>::active_cell_iterator &block_cell,
      const SeedingBodies<dim>                                &bodies);

    /**
     * Locate on a grid of simplices, or of cells that are not axis-parallel
     * boxes (a Mesh file): a point still inside its cell only gets its
     * reference coordinates; the others are searched for from their cell
     * (CellLocator::find(), CellLocator::owning()) and sent to the rank that
     * owns the cell they entered. Collective.
     */
    void
    locate_in_cells();

    /**
     * Stop, on every rank and before any point is created, if the points
     * of the seeding pattern that lie in the bodies need more memory than
     * the node has available for its ranks. The points are counted only if
     * the whole pattern would not fit, and only until one rank's points
     * alone exceed the node's memory. Collective.
     */
    void
    check_memory(const SeedingBodies<dim> &bodies) const;

    /**
     * Locate on a fixed grid of axis-parallel boxes by arithmetic: a point
     * still inside its cell only gets its reference coordinates; a point
     * that entered another locally owned cell is moved there. Returns false
     * (on every rank) if some point has to change rank or has left the
     * grid, which deal.II's sort then handles.
     */
    bool
    locate_in_boxes();

    /**
     * The locally owned cell of each block of a hypercube grid, in
     * lexicographic block order (invalid where not locally owned).
     */
    std::vector<typename Triangulation<dim>::active_cell_iterator>
      owned_cell_of_block;

    const BackgroundGrid<dim>                                *grid = nullptr;
    std::unique_ptr<CellLocator<dim>>                         locator;
    std::vector<unsigned int>                                 n_per_direction;
    std::unique_ptr<Particles::ParticleHandler<dim>>          particles;
    std::vector<std::pair<types::particle_index, Point<dim>>> lost_points;
    /// Points seeded in each of the bodies (on all ranks).
    std::vector<unsigned int> points_per_body;
    /// Pattern points in no body (on all ranks after seeding).
    types::particle_index points_outside_bodies = 0;
  };
} // namespace MpmOtm

#endif
