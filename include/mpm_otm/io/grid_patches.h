#ifndef mpm_otm_io_grid_patches_h
#define mpm_otm_io_grid_patches_h

#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/io/hdf5_patches.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <array>
#include <cstdint>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace MpmOtm
{
  template <int dim>
  class BackgroundGrid;

  /**
   * The grid fields of one output step - the nodal mass, the nodal velocity
   * (one vector, so that ParaView draws it with glyphs and stream lines) and
   * the subdomain - as deal.II patches of this rank's cells: the
   * coefficient fields sum_i c_i phi_i in the element the cells carry (for
   * B-splines their Bernstein form, subdivided by the degree). The VTU
   * writer takes them through DataOut; write_hdf5() writes them directly,
   * each patch's points and sub-cells as they are (points shared by
   * neighbouring patches are not merged), which avoids deal.II's
   * DataOutFilter and its map of all points.
   */
  template <int dim>
  class GridPatches : public DataOut<dim>, public HDF5Patches
  {
  public:
    /**
     * Build the patches of @p grid's locally owned cells from the nodal
     * mass and velocity of @p system (their ghost values are updated).
     */
    GridPatches(const BackgroundGrid<dim> &grid,
                const ShapeFunctions<dim> &shape_functions,
                NodalSystem<dim>          &system);

    /**
     * Each patch's points and sub-cells as they are (a patch subdivided n
     * times has n^dim cells).
     */
    void
    write_hdf5(const std::string &file_name,
               const MPI_Comm     communicator) const override;

    std::uint64_t
    n_nodes() const override;

    std::uint64_t
    n_cells() const override;

    ReferenceCell
    reference_cell() const override;

    std::vector<std::pair<std::string, unsigned int>>
    data_sets() const override;

    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
    get_nonscalar_data_ranges() const override;

  private:
    /// The vectors DataOut refers to: the velocity components and the mass.
    std::array<typename ShapeFunctions<dim>::VectorType, dim + 1> fields;
    Vector<float>                                                 subdomain;
    ReferenceCell                                                 cell_kind;
  };
} // namespace MpmOtm

#endif
