#ifndef mpm_otm_problems_body_h
#define mpm_otm_problems_body_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <mpm_otm/base/parsed_expression.h>

#include <memory>
#include <string>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  template <int dim>
  class Material;
  template <int dim>
  class MaterialLibrary;
  template <int dim>
  class BackgroundGrid;
  template <int dim>
  class MeshGroups;

  /**
   * One body of a user's problem, read from subsection "Body <name>": its
   * shape (a box, a ball, a polygon in 2D, the region f(x, y, z) <= 0 of
   * a level-set expression, or the cells of a physical group of the Gmsh
   * file the grid is read from), its material, its initial velocity and its
   * initial stress (expressions, or geostatic: computed by the problem from
   * the weight of the material above, with the lateral stress ratio K0).
   * A mesh group may be one of the grid's Mesh file or of a file of the
   * body's own (the grid being a box or another mesh).
   * Material points are seeded where a body contains them.
   */
  template <int dim>
  class Body
  {
  public:
    /**
     * Declare the entries of a body in the current subsection.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the body called @p name from the current subsection; its
     * material is looked up in @p materials.
     */
    void
    parse_parameters(ParameterHandler           &prm,
                     const std::string          &name,
                     const MaterialLibrary<dim> &materials);

    /**
     * Check the body against the background grid @p grid, on which the
     * points are seeded: a box, ball, polygon or group of the body's own
     * Mesh file must lie within the grid's box (a part outside would be
     * cut off without a word); a mesh group must be a group of the Mesh
     * file whose cells @p groups locates (made from the body's own file
     * (group_mesh_file()) or the grid's; nullptr for a box grid and no file
     * of the body's own).
     */
    void
    check_on_grid(const BackgroundGrid<dim> &grid,
                  const MeshGroups<dim>     *groups);

    /**
     * Whether the body is a group of cells of the Mesh file.
     */
    bool
    is_mesh_group() const;

    /**
     * The body's own Mesh file of its group; empty for the grid's.
     */
    const std::string &
    group_mesh_file() const;

    /**
     * The body's name.
     */
    const std::string &
    name() const;

    /**
     * Whether @p point lies in the body (on its boundary counts as inside).
     */
    bool
    contains(const Point<dim> &point) const;

    /**
     * The number of the body's material in the MaterialLibrary.
     */
    unsigned int
    material_id() const;

    /**
     * Initial velocity at @p point.
     */
    Tensor<1, dim>
    initial_velocity(const Point<dim> &point) const;

    /**
     * Whether the initial stress is geostatic.
     */
    bool
    has_geostatic_stress() const;

    /**
     * The lateral stress ratio K0 of a geostatic stress: the entry, or
     * 1 - sin(phi) for a frictional material, nu / (1 - nu) otherwise.
     */
    double
    lateral_stress_ratio() const;

    /**
     * The initial stress at @p point given by expressions (not geostatic):
     * the in-plane components and the out-of-plane one (given, or the
     * plane-strain / uniaxial-strain elastic value).
     */
    std::pair<SymmetricTensor<2, dim>, double>
    initial_stress(const Point<dim> &point) const;

  private:
    enum class Shape
    {
      box,
      ball,
      polygon,
      level_set,
      mesh_group
    };

    std::string                            body_name;
    std::string                            path;
    Shape                                  shape = Shape::box;
    BoundingBox<dim>                       box;
    Point<dim>                             centre;
    double                                 radius = 0;
    std::vector<Point<dim>>                polygon;
    std::unique_ptr<ParsedExpression<dim>> level_set;
    std::string                            group;
    std::string                            group_file;
    types::material_id                     group_tag      = 0;
    const MeshGroups<dim>                 *groups         = nullptr;
    unsigned int                           material       = 0;
    const Material<dim>                   *material_model = nullptr;
    double                                 lateral_ratio  = -1;
    std::unique_ptr<ParsedExpression<dim>> velocity;
    bool                                   geostatic = false;
    std::unique_ptr<ParsedExpression<dim>> stress;
  };
} // namespace MpmOtm

#endif
