#ifndef mpm_otm_algorithms_softening_regularisation_h
#define mpm_otm_algorithms_softening_regularisation_h

#include <deal.II/lac/la_parallel_vector.h>

#include <mpm_otm/shape_functions/particle_shape_data.h>

#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class MaterialPoints;
  template <int dim>
  class NodalSystem;

  /**
   * A regularisation of strain softening by a nodal average of the
   * equivalent plastic strain (Softening regularisation = nodal average).
   *
   * With a local softening law a shear band is as narrow as the
   * discretisation lets it be, and on a grid of linear functions it is not
   * even that: a band at an angle to the cells crosses them as a staircase,
   * the velocity jump of a cell is carried by the points near its nodes,
   * and the points of the same cells away from them soften little and carry
   * load across the band (the biaxial test of doc/benchmarks.md: 16 %
   * above the residual strength). Here the strength of a point softens with
   * a nonlocal strain instead, in the spirit of the nonlocal plasticity of
   * Burghardt, Brannon & Guilkey (2012, "A nonlocal plasticity formulation
   * for the material point method", CMAME 225-228) with the grid's
   * functions as the averaging kernel: after the stress update of a step,
   * the equivalent plastic strains eps_p of the points of the softening
   * materials are projected to the nodes,
   *   eps_i = sum_p V_p^0 phi_i(x_p) eps_p / sum_p V_p^0 phi_i(x_p),
   * and interpolated back,
   *   eps~_p = sum_i phi_i(x_p) eps_i / sum_i phi_i(x_p),
   * which becomes the point's softening strain (the internal variable
   * "softening_strain", Material::softening_variable()), the strain that
   * sets its strength in the next step; its own plastic strain stays
   * local. The kernel reaches the points of the cells around a point's
   * cell (two cells across for linear functions, three for quadratic
   * B-splines), so every point of a band's cells softens with the band,
   * and the band's width is set by the grid, as with local softening, but
   * the whole of it softens. Only points of materials that soften take
   * part; their weight is their initial volume. The nodal sums are
   * distributed vectors of the nodal system's layout: a collective call
   * each step on every rank.
   */
  template <int dim>
  class SofteningRegularisation
  {
  public:
    /**
     * Get ready for the materials of @p materials and the nodal vectors of
     * @p system (call again when the grid changes).
     */
    void
    initialize(const MaterialLibrary<dim> &materials,
               const NodalSystem<dim>     &system);

    /**
     * One line for the start of a run: what the regularisation does.
     */
    std::string
    description() const;

    /**
     * Replace the softening strains of the points of @p material_points,
     * whose shape functions in this step are @p shape_data (same points,
     * same order), by the nodal average of their equivalent plastic
     * strains. A collective call: every rank makes it in every step.
     */
    void
    update(MaterialPoints<dim>          &material_points,
           const ParticleShapeData<dim> &shape_data);

  private:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /// Per material: the offsets in a point's property array of its
    /// equivalent plastic strain and of its softening strain, or
    /// numbers::invalid_unsigned_int for a material that does not soften.
    std::vector<std::pair<unsigned int, unsigned int>> offsets;

    /// The nodal sums of V_p^0 phi_i eps_p and of V_p^0 phi_i.
    VectorType weighted_strain, weight;
  };
} // namespace MpmOtm

#endif
