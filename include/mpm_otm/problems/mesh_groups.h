#ifndef mpm_otm_problems_mesh_groups_h
#define mpm_otm_problems_mesh_groups_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <memory>
#include <set>
#include <string>

namespace dealii
{
  template <int dim, int spacedim>
  class Mapping;
  namespace GridTools
  {
    template <int dim, int spacedim>
    class Cache;
  }
} // namespace dealii

namespace MpmOtm
{
  using namespace dealii;

  class GmshFile;

  /**
   * The physical groups of the cells of a Gmsh file (Body/Shape = mesh
   * group), the grid's or a body's own: which group a point lies in, and
   * the group a name or tag in a parameter file means. deal.II's reader gives
   * every cell its physical tag as material id; this class keeps a serial copy
   * of the file's mesh on every rank (the background grid may be distributed,
   * and a body's geostatic stress asks for points anywhere above its own),
   * and finds a point's cell among those whose bounding box holds it
   * (deal.II's R-tree of the cells), quadrilaterals/hexahedra or
   * triangles/tetrahedra.
   */
  template <int dim>
  class MeshGroups
  {
  public:
    /**
     * Read the mesh of @p file.
     */
    explicit MeshGroups(const GmshFile &file);

    ~MeshGroups();

    /**
     * The tag of the cell group @p group, a name of $PhysicalNames or a
     * tag; stops naming @p entry and the file's groups if there is no such
     * group of cells.
     */
    types::material_id
    tag(const std::string &group, const std::string &entry) const;

    /**
     * The tag of the cell that contains @p point,
     * numbers::invalid_material_id outside the mesh.
     */
    types::material_id
    group_at(const Point<dim> &point) const;

    /**
     * The bounding box of the vertices of the cells of group @p tag.
     */
    BoundingBox<dim>
    bounding_box(const types::material_id tag) const;

  private:
    std::string file_name;
    /// The parameter that names the file.
    std::string                                               file_entry;
    bool                                                      simplex = false;
    Triangulation<dim>                                        triangulation;
    std::unique_ptr<Mapping<dim, dim>>                        mapping;
    std::unique_ptr<GridTools::Cache<dim, dim>>               cache;
    std::map<types::material_id, std::string>                 names;
    std::map<types::material_id, unsigned int>                cells_per_tag;
    mutable typename Triangulation<dim>::active_cell_iterator hint;
  };
} // namespace MpmOtm

#endif
