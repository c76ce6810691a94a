#ifndef mpm_otm_algorithms_method_h
#define mpm_otm_algorithms_method_h

#include <deal.II/base/parameter_handler.h>

#include <mpm_otm/algorithms/grid_motion.h>
#include <mpm_otm/algorithms/nodal_update.h>

#include <memory>
#include <string>

namespace MpmOtm
{
  /**
   * A method of the journal - MPM (Alg. 1), OTM (Alg. 2) or the unified
   * approach (Alg. 3) - as the combination of the two strategies in which
   * they differ (ARCHITECTURE.md): a nodal update and a grid motion, with
   * what the method needs of the shape-function family. Methods are named
   * plugins, chosen by the entry "Method"; the simulator asks the method
   * for its strategies and never tests which method or family runs.
   */
  template <int dim>
  class Method
  {
  public:
    virtual ~Method() = default;

    /**
     * Read and check the entries the method depends on ("Update scheme",
     * and the names of the family and the mass matrix for its messages).
     */
    virtual void
    parse_parameters(ParameterHandler &prm) = 0;

    /**
     * The nodal update of the method (its parameters not yet read).
     */
    virtual std::unique_ptr<NodalUpdate<dim>>
    create_nodal_update() const = 0;

    /**
     * The grid motion of the method for @p shape_functions; stops with a
     * message that names the entries if the family cannot follow it.
     */
    virtual std::unique_ptr<GridMotion<dim>>
    create_grid_motion(ShapeFunctions<dim> &shape_functions) const = 0;

    /**
     * True if the grid stays where it is, so that conditions on its nodes
     * (the entry "Boundaries") apply.
     */
    virtual bool
    fixed_grid() const = 0;

    /**
     * A note on the chosen combination for the run's log, or nothing.
     */
    virtual std::string
    note() const
    {
      return {};
    }
  };
} // namespace MpmOtm

#endif
