#ifndef mpm_otm_shape_functions_particle_shape_data_h
#define mpm_otm_shape_functions_particle_shape_data_h

#include <deal.II/base/tensor.h>

#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * The shape functions that do not vanish at each material point, evaluated
   * once per particle per step and reused by every particle-to-grid and
   * grid-to-particle pass of that step. Particles appear in the order of
   * iteration of the particle handler; for particle k the entries
   * offsets[k] .. offsets[k+1]-1 hold the local indices (into the nodal
   * vectors, including ghost entries) of the functions, their values and
   * their gradients. The arrays are contiguous and are only reallocated when
   * the number of particles grows.
   */
  template <int dim>
  struct ParticleShapeData
  {
    /// Start of each particle's entries; size n_particles + 1.
    std::vector<unsigned int> offsets;
    /// Local index of each function in the nodal vectors.
    std::vector<unsigned int> indices;
    /// Values phi_i(x_p).
    std::vector<double> values;
    /// Gradients grad phi_i(x_p) in real coordinates.
    std::vector<Tensor<1, dim>> gradients;

    /**
     * Number of particles described.
     */
    unsigned int
    n_particles() const
    {
      return offsets.empty() ? 0 : offsets.size() - 1;
    }
  };
} // namespace MpmOtm

#endif
