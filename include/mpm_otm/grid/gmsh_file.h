#ifndef mpm_otm_grid_gmsh_file_h
#define mpm_otm_grid_gmsh_file_h

#include <deal.II/grid/tria.h>

#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace MpmOtm
{
  using namespace dealii;

  /**
   * A Gmsh mesh file (the entry Mesh/Mesh file, or a body's own Mesh
   * file for its mesh group), checked before deal.II
   * reads it: the constructor scans the whole file and stops, with a
   * message naming the entry and the file, if it cannot be opened, is
   * not an ASCII file of format 2 (2.0 to 2.2) or 4.1, is truncated or
   * malformed (a section out of order, a count that does not match, an
   * element with a node that does not exist), holds elements other than
   * first-order points, lines, triangles, quadrilaterals, tetrahedra and
   * hexahedra, mixes cell types, has cells of another dimension than the
   * run's, or (2D) has nodes off the plane z = 0. read() then builds the
   * triangulation with deal.II's own reader GridIn::read_msh(std::istream &)
   * (not the Gmsh API), which takes the first (format 2) or the entity's
   * (format 4.1) physical tag of every boundary line (2D) or surface
   * element (3D) as the boundary id of that face; faces without such an
   * element get boundary id 0.
   */
  class GmshFile
  {
  public:
    /**
     * Scan and check @p filename for a mesh of dimension @p dim (2 or 3);
     * @p entry is the parameter that names the file, for messages.
     */
    GmshFile(const std::string &filename,
             const unsigned int dim,
             const std::string &entry = "Mesh/Mesh file");

    /**
     * Read the mesh into the empty @p triangulation (serial, or
     * parallel::distributed for quadrilaterals/hexahedra, whose coarse
     * cells become p4est's trees) and check that every cell has a positive
     * measure. Every rank reads the file.
     */
    template <int dim>
    void
    read(Triangulation<dim> &triangulation) const;

    /**
     * True if the cells are triangles/tetrahedra, false for
     * quadrilaterals/hexahedra.
     */
    bool
    is_simplex() const;

    /**
     * Number of cells (elements of the mesh's dimension) in the file.
     */
    unsigned int
    n_cells() const;

    /**
     * The file's format version as written in it, e.g. "2.2" or "4.1".
     */
    const std::string &
    format() const;

    /**
     * The names of the physical groups of dimension @p group_dimension
     * ($PhysicalNames), by their tags; empty if the file names none.
     */
    std::map<types::material_id, std::string>
    physical_names(const unsigned int group_dimension) const;

    /**
     * The name of the file.
     */
    const std::string &
    name() const;

    /**
     * The parameter that names the file.
     */
    const std::string &
    entry() const;

  private:
    void
    scan(std::istream &in);

    void
    scan_nodes(std::istream &in);

    void
    scan_physical_names(std::istream &in);

    void
    scan_elements(std::istream &in);

    /**
     * Stop with @p what, prefixed by the entry and the file name.
     */
    [[noreturn]] void
    fail(const std::string &what) const;

    std::string  filename;
    std::string  entry_name;
    unsigned int dimension;
    std::string  version;
    bool         format_4 = false;
    /// Number of elements per Gmsh element type.
    std::map<int, unsigned int> elements_of_type;
    /// The $PhysicalNames: dimension, tag and name of each.
    std::vector<std::tuple<unsigned int, types::material_id, std::string>>
      group_names;
    /// Node tags of the file.
    std::set<long> node_tags;
    /// Largest |z| of a node and the extent of the nodes in x and y.
    double largest_z = 0, extent = 0;
  };
} // namespace MpmOtm

#endif
