#ifndef mpm_otm_shape_functions_particle_shape_data_h
#define mpm_otm_shape_functions_particle_shape_data_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * The shape functions that do not vanish at each material point, evaluated
   * once per particle per step and reused by every particle-to-grid and
   * grid-to-particle pass of that step.
   *
   * Particles appear in the order of iteration of the particle handler, which
   * groups them by cell. Consecutive particles that share their list of
   * functions (the points of one cell for the cell-based families) form a
   * batch, and the batch stores that list once: the local indices (into the
   * nodal vectors, including ghost entries) of its n functions. Each particle
   * stores only its n values phi_i(x_p) and n gradients grad phi_i(x_p), in
   * the order of the batch's list. All arrays are contiguous and keep their
   * memory from step to step; they only grow when the number of particles
   * or functions does.
   *
   * A shape function family fills the data with reinit(), then per batch
   * start_batch() and per particle add_particle(), and finally finish(). A
   * pass over the particles reads them in order with a Cursor, or per batch
   * with the batch accessors.
   */
  template <int dim>
  class ParticleShapeData
  {
  public:
    /**
     * The functions of one material point: @p n local indices, values and
     * gradients.
     */
    struct PointFunctions
    {
      unsigned int          n;
      const unsigned int   *indices;
      const double         *values;
      const Tensor<1, dim> *gradients;
    };

    /**
     * Walks the particles in the order of the particle handler: each call of
     * next() returns the functions of the next particle.
     */
    class Cursor
    {
    public:
      explicit Cursor(const ParticleShapeData &data)
        : data(data)
      {}

      /**
       * The functions of the next particle.
       */
      PointFunctions
      next()
      {
        AssertIndexRange(particle, data.n_particles());
        if (particle == data.batches[batch + 1].first_particle)
          ++batch;
        const Batch       &current = data.batches[batch];
        const unsigned int n =
          data.batches[batch + 1].first_index - current.first_index;
        const PointFunctions result{n,
                                    &data.indices[current.first_index],
                                    &data.values[entry],
                                    &data.gradients[entry]};
        entry += n;
        ++particle;
        return result;
      }

    private:
      const ParticleShapeData &data;
      unsigned int             particle = 0;
      unsigned int             batch    = 0;
      std::size_t              entry    = 0;
    };

    /// Values phi_i(x_p), particle after particle.
    std::vector<double> values;
    /// Gradients grad phi_i(x_p) in real coordinates, as the values.
    std::vector<Tensor<1, dim>> gradients;

    /**
     * Start over for @p n_particles particles. A family whose points all
     * have @p n_functions_per_particle functions passes that number, and the
     * arrays are sized once; with 0 (a varying number) they grow as the
     * particles are added. The memory is kept from call to call.
     */
    void
    reinit(const unsigned int n_particles,
           const unsigned int n_functions_per_particle)
    {
      expected_particles = n_particles;
      added_particles    = 0;
      n_entries          = 0;
      batches.clear();
      indices.clear();
      const std::size_t size =
        std::size_t(n_particles) * n_functions_per_particle;
      if (values.size() < size)
        {
          values.resize(size);
          gradients.resize(size);
        }
    }

    /**
     * Start a batch: the particles added next have the @p n functions with
     * local indices @p function_indices.
     */
    void
    start_batch(const unsigned int *function_indices, const unsigned int n)
    {
      batches.push_back(
        Batch{added_particles, static_cast<unsigned int>(indices.size())});
      indices.insert(indices.end(), function_indices, function_indices + n);
    }

    /**
     * Add a particle to the current batch; returns the offset of its values
     * and gradients, which the caller fills.
     */
    std::size_t
    add_particle()
    {
      Assert(!batches.empty(), ExcMessage("No batch started."));
      const std::size_t offset = n_entries;
      n_entries += indices.size() - batches.back().first_index;
      if (values.size() < n_entries)
        {
          values.resize(n_entries);
          gradients.resize(n_entries);
        }
      ++added_particles;
      return offset;
    }

    /**
     * Close the last batch once every particle has been added.
     */
    void
    finish()
    {
      Assert(added_particles == expected_particles, ExcInternalError());
      values.resize(n_entries);
      gradients.resize(n_entries);
      batches.push_back(
        Batch{added_particles, static_cast<unsigned int>(indices.size())});
    }

    /**
     * Number of particles described.
     */
    unsigned int
    n_particles() const
    {
      return batches.empty() ? 0 : batches.back().first_particle;
    }

    /**
     * Number of batches.
     */
    unsigned int
    n_batches() const
    {
      return batches.empty() ? 0 : batches.size() - 1;
    }

    /**
     * The first particle of batch @p b; its particles run to
     * first_particle(b + 1).
     */
    unsigned int
    first_particle(const unsigned int b) const
    {
      return batches[b].first_particle;
    }

    /**
     * Number of functions of the particles of batch @p b.
     */
    unsigned int
    n_functions(const unsigned int b) const
    {
      return batches[b + 1].first_index - batches[b].first_index;
    }

    /**
     * The local indices of the functions of batch @p b.
     */
    const unsigned int *
    function_indices(const unsigned int b) const
    {
      return &indices[batches[b].first_index];
    }

  private:
    struct Batch
    {
      unsigned int first_particle;
      unsigned int first_index;
    };

    /// The batches, and one past the last as their end.
    std::vector<Batch> batches;
    /// The list of functions of each batch.
    std::vector<unsigned int> indices;
    std::size_t               n_entries          = 0;
    unsigned int              added_particles    = 0;
    unsigned int              expected_particles = 0;
  };
} // namespace MpmOtm

#endif
