#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>

#include <mpm_otm/base/exception_message.h>
#include <mpm_otm/grid/gmsh_file.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace MpmOtm
{
  namespace
  {
    /**
     * Dimension, number of nodes and name of the Gmsh element types that
     * deal.II's reader takes (first-order points, lines, triangles,
     * quadrilaterals, tetrahedra, hexahedra).
     */
    struct ElementType
    {
      unsigned int dimension;
      unsigned int n_nodes;
      const char  *name;
      const char  *plural;
    };

    const std::map<int, ElementType> supported_types = {
      {15, {0, 1, "point", "points"}},
      {1, {1, 2, "line", "lines"}},
      {2, {2, 3, "triangle", "triangles"}},
      {3, {2, 4, "quadrilateral", "quadrilaterals"}},
      {4, {3, 4, "tetrahedron", "tetrahedra"}},
      {5, {3, 8, "hexahedron", "hexahedra"}}};

    /**
     * Names of the Gmsh element types that users meet most often among
     * those deal.II cannot read.
     */
    std::string
    unsupported_type_name(const int type)
    {
      static const std::map<int, std::string> names = {
        {6, "prism"},
        {7, "pyramid"},
        {8, "second-order line"},
        {9, "second-order triangle"},
        {10, "second-order quadrilateral (9 nodes)"},
        {11, "second-order tetrahedron"},
        {12, "second-order hexahedron (27 nodes)"},
        {16, "second-order quadrilateral (8 nodes)"},
        {17, "second-order hexahedron (20 nodes)"}};
      const auto name = names.find(type);
      return (name == names.end() ? std::string("element") : name->second) +
             " (Gmsh element type " + std::to_string(type) + ")";
    }

    /**
     * The text of an exception on one line: the Gmsh reader's messages are
     * indented over several.
     */
    std::string
    one_line_message_of(const std::exception &error)
    {
      std::string line;
      bool        space = false;
      for (const char c : message_of(error))
        if (c == '\n' || c == ' ')
          space = true;
        else
          {
            if (space && !line.empty())
              line += ' ';
            line += c;
            space = false;
          }
      return line;
    }
  } // namespace



  GmshFile::GmshFile(const std::string &filename,
                     const unsigned int dim,
                     const std::string &entry)
    : filename(filename)
    , entry_name(entry)
    , dimension(dim)
  {
    AssertThrow(dim == 2 || dim == 3,
                ExcMessage("Mesh/Mesh file needs Dimension = 2 or 3; in 1D "
                           "use the box grid (Mesh/Mesh file empty)."));
    // Opening a named pipe would wait for a writer, and a device such as
    // /dev/zero would be read to the memory limit: only a regular file is
    // opened.
    std::error_code error;
    if (std::filesystem::is_directory(filename, error))
      fail("is a directory, not a Gmsh .msh file");
    if (std::filesystem::exists(filename, error) &&
        !std::filesystem::is_regular_file(filename, error))
      fail("is not a regular file (it is a named pipe, a device or a "
           "socket); give a Gmsh .msh file");
    std::ifstream in(filename);
    if (!in)
      fail("cannot be opened: it does not exist or is not readable (a "
           "relative path starts in the directory the program runs in)");
    scan(in);

    // The cells: the elements of the highest dimension.
    unsigned int cell_dimension = 0;
    for (const auto &[type, n] : elements_of_type)
      cell_dimension =
        std::max(cell_dimension, supported_types.at(type).dimension);
    const auto list_of_dimension = [&](const unsigned int d) {
      std::string list;
      for (const auto &[type, n] : elements_of_type)
        if (supported_types.at(type).dimension == d)
          list += (list.empty() ? "" : " and ") + std::to_string(n) + " " +
                  (n == 1 ? supported_types.at(type).name :
                            supported_types.at(type).plural);
      return list;
    };
    const std::string d = std::to_string(dim);
    if (cell_dimension > dim)
      fail("holds a " + std::to_string(cell_dimension) + "D mesh (" +
           list_of_dimension(cell_dimension) + "), but Dimension = " + d +
           ": set Dimension = " + std::to_string(cell_dimension) +
           " or give a " + d + "D mesh");
    if (cell_dimension < dim)
      fail(
        "holds no " + d + "D cells (" +
        (elements_of_type.empty() ? std::string("no elements at all") :
                                    "its elements of highest dimension are " +
                                      list_of_dimension(cell_dimension)) +
        "), but Dimension = " + d + ": " +
        (cell_dimension >= 2 ?
           "for a " + std::to_string(cell_dimension) +
             "D mesh set Dimension = " + std::to_string(cell_dimension) + "; " :
           std::string()) +
        "if the mesh is " + d +
        "D, put its cells into a physical group (Gmsh writes only the "
        "elements of physical groups if there are any) or save all "
        "elements (Mesh.SaveAll = 1)");

    const int  simplex_type = (dim == 2 ? 2 : 4);
    const int  cube_type    = (dim == 2 ? 3 : 5);
    const auto count        = [&](const int type) {
      const auto entry = elements_of_type.find(type);
      return entry == elements_of_type.end() ? 0u : entry->second;
    };
    if (count(simplex_type) > 0 && count(cube_type) > 0)
      fail("mixes " + list_of_dimension(dim) + ": the cells must be all " +
           (dim == 2 ? "quadrilaterals or all triangles" :
                       "hexahedra or all tetrahedra") +
           " (a mixed mesh is not supported)");
    if (dim == 3)
      {
        // Boundary faces of the other shape would not be faces of a cell.
        const bool simplex = count(simplex_type) > 0;
        if (count(simplex ? 3 : 2) > 0)
          fail("holds " +
               std::string(simplex ? "quadrilaterals" : "triangles") +
               " (boundary faces) on a mesh of " +
               (simplex ? "tetrahedra" : "hexahedra") +
               ": the boundary faces must be " +
               (simplex ? "triangles" : "quadrilaterals") + " like the cells'");
      }
    if (dim == 2 && largest_z > 1e-10 * extent)
      fail("has nodes off the plane z = 0 (|z| up to " +
           Utilities::to_string(largest_z) +
           "): a 2D mesh must lie in the x-y plane");
  }



  void
  GmshFile::fail(const std::string &what) const
  {
    AssertThrow(false,
                ExcMessage(entry_name + ": <" + filename + "> " + what + "."));
    std::abort();
  }



  void
  GmshFile::scan(std::istream &in)
  {
    std::string token;
    if (!(in >> token))
      fail("is empty");
    if (token == "$NOD")
      fail("is in Gmsh's format 1; save it in format 2.2 or 4.1 (Gmsh: "
           "File > Export, or gmsh -format msh22)");
    if (token != "$MeshFormat")
      fail("does not start with $MeshFormat, so it is not a Gmsh .msh "
           "file");
    int file_type = -1, data_size = -1;
    if (!(in >> version >> file_type >> data_size))
      fail("has a malformed $MeshFormat section (expected: version, file "
           "type, data size)");
    if (version == "4.1")
      format_4 = true;
    else if (!(version == "2" || version == "2.0" || version == "2.1" ||
               version == "2.2"))
      fail("is in Gmsh's format " + version +
           "; the formats read are 2.2 (and 2.0, 2.1) and 4.1 (Gmsh: "
           "Mesh.MshFileVersion = 2.2 or 4.1)");
    if (file_type != 0)
      fail("is a binary Gmsh file; save it as ASCII (Gmsh: Mesh.Binary = 0)");
    if (data_size != static_cast<int>(sizeof(double)))
      fail("has data size " + std::to_string(data_size) +
           " in $MeshFormat; "
           "only " +
           std::to_string(sizeof(double)) + " is read");
    if (!(in >> token) || token != "$EndMeshFormat")
      fail("has no $EndMeshFormat after the format line");

    const auto skip_section = [&](const std::string &name) {
      const std::string end = "$End" + name.substr(1);
      while (in >> token)
        if (token == end)
          return;
      fail("ends inside its section " + name + " (no " + end + ")");
    };
    if (!(in >> token))
      fail("ends after $MeshFormat (no $Nodes)");
    for (const std::string optional :
         {"$PhysicalNames", "$Entities", "$PartitionedEntities"})
      if (token == optional)
        {
          if (optional == "$PhysicalNames")
            scan_physical_names(in);
          else
            skip_section(optional);
          if (!(in >> token))
            fail("ends after " + optional + " (no $Nodes)");
        }
    if (token != "$Nodes")
      fail("has the section " + token +
           " where $Nodes is expected; before $Nodes only $PhysicalNames, "
           "$Entities and $PartitionedEntities (in this order) are read");
    scan_nodes(in);
    if (!(in >> token) || token != "$Elements")
      fail("has no $Elements section after $Nodes");
    scan_elements(in);
  }



  void
  GmshFile::scan_nodes(std::istream &in)
  {
    double     lower[2] = {std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::max()};
    double     upper[2] = {-std::numeric_limits<double>::max(),
                           -std::numeric_limits<double>::max()};
    const auto node     = [&](const long tag, const double x[3]) {
      if (!node_tags.insert(tag).second)
        fail("defines node " + std::to_string(tag) + " twice in $Nodes");
      for (unsigned int d = 0; d < 3; ++d)
        if (!std::isfinite(x[d]))
          fail("has a coordinate of node " + std::to_string(tag) +
               " that is not a finite number");
      for (unsigned int d = 0; d < 2; ++d)
        {
          lower[d] = std::min(lower[d], x[d]);
          upper[d] = std::max(upper[d], x[d]);
        }
      largest_z = std::max(largest_z, std::abs(x[2]));
    };
    const auto malformed = [&]() {
      fail("has a malformed or truncated $Nodes section");
    };

    unsigned long n_nodes = 0;
    if (!format_4)
      {
        if (!(in >> n_nodes))
          malformed();
        for (unsigned long i = 0; i < n_nodes; ++i)
          {
            long   tag;
            double x[3];
            if (!(in >> tag >> x[0] >> x[1] >> x[2]))
              malformed();
            node(tag, x);
          }
      }
    else
      {
        unsigned long n_blocks, min_tag, max_tag, n_read = 0;
        if (!(in >> n_blocks >> n_nodes >> min_tag >> max_tag))
          malformed();
        for (unsigned long b = 0; b < n_blocks; ++b)
          {
            int           entity_dimension, entity_tag, parametric;
            unsigned long n_in_block;
            if (!(in >> entity_dimension >> entity_tag >> parametric >>
                  n_in_block))
              malformed();
            if (parametric != 0)
              fail("has parametric node coordinates, which are not read "
                   "(Gmsh: Mesh.SaveParametric = 0)");
            std::vector<long> tags(n_in_block);
            for (auto &tag : tags)
              if (!(in >> tag))
                malformed();
            for (const long tag : tags)
              {
                double x[3];
                if (!(in >> x[0] >> x[1] >> x[2]))
                  malformed();
                node(tag, x);
              }
            n_read += n_in_block;
          }
        if (n_read != n_nodes)
          fail("announces " + std::to_string(n_nodes) +
               " nodes in $Nodes but its blocks hold " +
               std::to_string(n_read));
      }
    std::string token;
    if (!(in >> token) || token != "$EndNodes")
      fail("has more or fewer nodes in $Nodes than it announces (no "
           "$EndNodes after " +
           std::to_string(n_nodes) + " nodes)");
    if (n_nodes > 0)
      extent = std::max(upper[0] - lower[0], upper[1] - lower[1]);
  }



  void
  GmshFile::scan_physical_names(std::istream &in)
  {
    const auto malformed = [&]() {
      fail("has a malformed or truncated $PhysicalNames section (expected "
           "the number of names, then per name its dimension, tag and "
           "\"name\")");
    };
    unsigned long n_names = 0;
    if (!(in >> n_names))
      malformed();
    for (unsigned long i = 0; i < n_names; ++i)
      {
        unsigned int group_dimension;
        long         tag;
        std::string  rest;
        if (!(in >> group_dimension >> tag) || !std::getline(in, rest))
          malformed();
        const auto first = rest.find('"');
        const auto last  = rest.rfind('"');
        if (first == std::string::npos || last == first || tag < 0)
          malformed();
        group_names.emplace_back(group_dimension,
                                 static_cast<types::material_id>(tag),
                                 rest.substr(first + 1, last - first - 1));
      }
    std::string token;
    if (!(in >> token) || token != "$EndPhysicalNames")
      fail("has more or fewer names in $PhysicalNames than it announces (no "
           "$EndPhysicalNames after " +
           std::to_string(n_names) + " names)");
  }



  void
  GmshFile::scan_elements(std::istream &in)
  {
    const auto malformed = [&]() {
      fail("has a malformed or truncated $Elements section");
    };
    const auto element = [&](const long tag, const int type) {
      const auto entry = supported_types.find(type);
      if (entry == supported_types.end())
        fail("holds a " + unsupported_type_name(type) +
             "; only first-order points, lines, triangles, "
             "quadrilaterals, tetrahedra and hexahedra are read (Gmsh: "
             "Mesh.ElementOrder = 1)");
      for (unsigned int v = 0; v < entry->second.n_nodes; ++v)
        {
          long node;
          if (!(in >> node))
            malformed();
          if (node_tags.find(node) == node_tags.end())
            fail("has element " + std::to_string(tag) + " with node " +
                 std::to_string(node) + ", which $Nodes does not define");
        }
      ++elements_of_type[type];
    };

    unsigned long n_elements = 0;
    if (!format_4)
      {
        if (!(in >> n_elements))
          malformed();
        for (unsigned long i = 0; i < n_elements; ++i)
          {
            long tag;
            int  type, n_tags;
            if (!(in >> tag >> type >> n_tags) || n_tags < 0)
              malformed();
            for (int t = 0; t < n_tags; ++t)
              {
                long value;
                if (!(in >> value))
                  malformed();
              }
            element(tag, type);
          }
      }
    else
      {
        unsigned long n_blocks, min_tag, max_tag, n_read = 0;
        if (!(in >> n_blocks >> n_elements >> min_tag >> max_tag))
          malformed();
        for (unsigned long b = 0; b < n_blocks; ++b)
          {
            int           entity_dimension, entity_tag, type;
            unsigned long n_in_block;
            if (!(in >> entity_dimension >> entity_tag >> type >> n_in_block))
              malformed();
            for (unsigned long i = 0; i < n_in_block; ++i)
              {
                long tag;
                if (!(in >> tag))
                  malformed();
                element(tag, type);
              }
            n_read += n_in_block;
          }
        if (n_read != n_elements)
          fail("announces " + std::to_string(n_elements) +
               " elements in $Elements but its blocks hold " +
               std::to_string(n_read));
      }
    std::string token;
    if (!(in >> token) || token != "$EndElements")
      fail("has more or fewer elements in $Elements than it announces (no "
           "$EndElements after " +
           std::to_string(n_elements) + " elements)");
  }



  template <int dim>
  void
  GmshFile::read(Triangulation<dim> &triangulation) const
  {
    std::ifstream in(filename);
    if (!in)
      fail("cannot be opened");
    GridIn<dim> reader;
    reader.attach_triangulation(triangulation);
    try
      {
        reader.read_msh(in);
      }
    catch (const std::exception &error)
      {
        fail("could not be read by deal.II's Gmsh reader: " +
             one_line_message_of(error) +
             " (a tagged line or surface element must be a boundary face "
             "of a cell)");
      }
    if (triangulation.n_global_active_cells() != n_cells())
      fail("gave " + std::to_string(triangulation.n_global_active_cells()) +
           " cells instead of the " + std::to_string(n_cells()) +
           " of the file");
    // The coarse mesh is the same on every rank, also for a distributed
    // triangulation: every cell is checked everywhere.
    for (const auto &cell : triangulation.active_cell_iterators())
      if (!(cell->measure() > 0.))
        fail("has a cell of zero or negative " +
             std::string(dim == 2 ? "area" : "volume") + " at (" +
             Utilities::to_string(cell->center()[0]) + ", " +
             Utilities::to_string(cell->center()[1]) +
             (dim == 3 ? ", " + Utilities::to_string(cell->center()[dim - 1]) :
                         std::string()) +
             ")");
  }



  bool
  GmshFile::is_simplex() const
  {
    return elements_of_type.count(dimension == 2 ? 2 : 4) > 0;
  }



  unsigned int
  GmshFile::n_cells() const
  {
    const auto entry = elements_of_type.find(
      dimension == 2 ? (is_simplex() ? 2 : 3) : (is_simplex() ? 4 : 5));
    return entry == elements_of_type.end() ? 0 : entry->second;
  }



  std::map<types::material_id, std::string>
  GmshFile::physical_names(const unsigned int group_dimension) const
  {
    std::map<types::material_id, std::string> names;
    for (const auto &[d, tag, name] : group_names)
      if (d == group_dimension)
        names[tag] = name;
    return names;
  }



  const std::string &
  GmshFile::name() const
  {
    return filename;
  }



  const std::string &
  GmshFile::entry() const
  {
    return entry_name;
  }



  const std::string &
  GmshFile::format() const
  {
    return version;
  }



  template void
  GmshFile::read(Triangulation<2> &) const;
  template void
  GmshFile::read(Triangulation<3> &) const;
} // namespace MpmOtm
