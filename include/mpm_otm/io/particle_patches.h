#ifndef mpm_otm_io_particle_patches_h
#define mpm_otm_io_particle_patches_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/reference_cell.h>

#include <mpm_otm/io/hdf5_patches.h>

#include <cstdint>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class MaterialPoints;

  /**
   * The material points of this rank as zero-dimensional patches for
   * ParaView, with displacement and velocity (vectors); the
   * three-dimensional Cauchy stress (a 3 x 3 tensor, with sigma_zz of plane
   * strain in 2D and the lateral stress of uniaxial strain in 1D in their
   * places), its mean tr(sigma)/3, its von Mises stress sqrt(3 J2) and its
   * principal stresses sigma_1 >= sigma_2 >= sigma_3 (tension positive);
   * the logarithmic strain ln(V) = ln(F F^T)/2 (a 3 x 3 tensor); det F,
   * volume, mass, material, equivalent plastic strain, the materials'
   * internal variables and the id. With @p tensors_as_components the two
   * tensors are written as their independent components stress_xx,
   * stress_yy, stress_zz, stress_xy, ... (in 2D and 1D without those that
   * plane or uniaxial strain keeps at zero) instead, which HDF5 output
   * needs (deal.II 9.4's XDMF index knows scalars and vectors).
   * The values are kept in one array, point by point, in double precision;
   * the patches (single precision, one allocation per point) are built
   * only for the VTU writer.
   */
  template <int dim>
  class ParticlePatches : public DataOutInterface<0, dim>, public HDF5Patches
  {
  public:
    ParticlePatches(const MaterialPoints<dim>  &material_points,
                    const MaterialLibrary<dim> &materials,
                    const bool                  tensors_as_components);

    /**
     * The points as deal.II's write_hdf5_parallel lays them out, but
     * directly, in double precision; each point is a cell.
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

  private:
    const std::vector<DataOutBase::Patch<0, dim>> &
    get_patches() const override;

    std::vector<std::string>
    get_dataset_names() const override;

    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
    get_nonscalar_data_ranges() const override;

    const bool               tensors_as_components;
    std::vector<std::string> names;
    /// The points' locations and, point by point, the values of all names.
    std::vector<Point<dim>> locations;
    std::vector<double>     values;
    /// The patches, built from those when a DataOutInterface writer asks.
    mutable std::vector<DataOutBase::Patch<0, dim>> patches;
  };
} // namespace MpmOtm

#endif
