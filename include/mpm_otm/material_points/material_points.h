#ifndef mpm_otm_material_points_material_points_h
#define mpm_otm_material_points_material_points_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm_otm/material_points/property_layout.h>

#include <memory>
#include <vector>

namespace dealii
{
  namespace GridTools
  {
    template <int dim, int spacedim>
    class Cache;
  }
} // namespace dealii

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class BackgroundGrid;
  template <int dim>
  class Material;
  template <int dim>
  class Problem;

  /**
   * The material points: a thin layer over Particles::ParticleHandler with
   * the property layout of PropertyLayout. It seeds a regular pattern of
   * points per block of the background grid (n per direction, thesis
   * Sect. 2.4 and Fig. 4.2), gives them mass from density and volume, marks
   * the points next to a traction boundary as boundary particles (thesis
   * Sect. 2.4.1 / 2.5), and re-associates moved points with their cells.
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
     * Create the particle handler on @p grid and seed the points inside the
     * problem's material region: X_p, V_p = block volume / points per
     * block, m_p = rho V_p, v_p = v0(X_p), F_p = I, sigma_p = 0.
     */
    void
    seed(const BackgroundGrid<dim> &grid,
         const Material<dim>       &material,
         const Problem<dim>        &problem);

    /**
     * Find the cell of every point after the points have moved. A point
     * that has left the grid stops the run with its id and position.
     */
    void
    locate();

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


  private:
    void
    insert_points_of_block(
      const std::vector<unsigned int>                         &block,
      const typename Triangulation<dim>::active_cell_iterator &block_cell,
      const Material<dim>                                     &material,
      const Problem<dim>                                      &problem);

    void
    locate_on_simplices();

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
    std::unique_ptr<GridTools::Cache<dim, dim>>               cache;
    std::vector<unsigned int>                                 n_per_direction;
    std::unique_ptr<Particles::ParticleHandler<dim>>          particles;
    std::vector<std::pair<types::particle_index, Point<dim>>> lost_points;
  };
} // namespace MpmOtm

#endif
