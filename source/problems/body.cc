#include <deal.II/base/utilities.h>

#include <mpm_otm/base/read_point.h>
#include <mpm_otm/grid/background_grid.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/problems/body.h>
#include <mpm_otm/problems/mesh_groups.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

namespace MpmOtm
{
  namespace
  {
    /**
     * Stop, naming @p entry, unless the closed polygon through @p corners
     * is simple: no corner repeated in a row, and no two edges that do not
     * follow each other touching or crossing. The inside of a polygon that
     * crosses itself depends on the rule that decides it, so a body given
     * by one is refused.
     */
    void
    check_simple_polygon(const std::vector<Point<2>> &corners,
                         const std::string           &entry)
    {
      const auto cross =
        [](const Point<2> &p, const Point<2> &q, const Point<2> &r) {
          return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
        };
      // r on the segment p q, given that the three are collinear.
      const auto within =
        [](const Point<2> &p, const Point<2> &q, const Point<2> &r) {
          return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) &&
                 std::min(p[1], q[1]) <= r[1] && r[1] <= std::max(p[1], q[1]);
        };
      const auto touch = [&](const Point<2> &a,
                             const Point<2> &b,
                             const Point<2> &c,
                             const Point<2> &d) {
        const double d1 = cross(c, d, a), d2 = cross(c, d, b),
                     d3 = cross(a, b, c), d4 = cross(a, b, d);
        if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) &&
            ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
          return true;
        return (d1 == 0 && within(c, d, a)) || (d2 == 0 && within(c, d, b)) ||
               (d3 == 0 && within(a, b, c)) || (d4 == 0 && within(a, b, d));
      };
      const unsigned int n    = corners.size();
      const auto         edge = [&](const unsigned int i) {
        std::ostringstream text;
        text << "edge " << i + 1 << " from (" << corners[i] << ") to ("
             << corners[(i + 1) % n] << ")";
        return text.str();
      };
      for (unsigned int i = 0; i < n; ++i)
        AssertThrow(corners[i].distance(corners[(i + 1) % n]) > 0,
                    ExcMessage(entry + ": corner " + std::to_string(i + 1) +
                               " is repeated in the next one; give every "
                               "corner once."));
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = i + 2; j < n; ++j)
          if (!(i == 0 && j == n - 1) && touch(corners[i],
                                               corners[(i + 1) % n],
                                               corners[j],
                                               corners[(j + 1) % n]))
            AssertThrow(false,
                        ExcMessage(entry + ": the polygon crosses itself: " +
                                   edge(i) + " meets " + edge(j) +
                                   ". Give the corners in order around the "
                                   "body."));
    }



    /**
     * Number of independent stress components and their names, in the order
     * of the entry "Initial stress" (that of the particle CSV).
     */
    template <int dim>
    std::vector<std::pair<unsigned int, unsigned int>>
    stress_components()
    {
      std::vector<std::pair<unsigned int, unsigned int>> result;
      for (unsigned int d = 0; d < dim; ++d)
        result.emplace_back(d, d);
      if (dim >= 2)
        result.emplace_back(0, 1);
      if (dim == 3)
        {
          result.emplace_back(1, 2);
          result.emplace_back(0, 2);
        }
      return result;
    }
  } // namespace



  template <int dim>
  void
  Body<dim>::declare_parameters(ParameterHandler &prm)
  {
    const std::string zeros = (dim == 1 ? "0" : dim == 2 ? "0; 0" : "0; 0; 0");
    prm.declare_entry("Shape",
                      "box",
                      Patterns::Selection(
                        "box|ball|polygon|level set|mesh group"),
                      "box: between Lower corner and Upper corner; ball: a "
                      "disk (2D) or sphere (3D) of Radius around Centre; "
                      "polygon (2D): inside the closed polygon of Vertices; "
                      "level set: where the expression Level set is <= 0; "
                      "mesh group: the cells of the physical group Group of "
                      "Mesh file (the grid's Mesh/Mesh file unless the body "
                      "names its own).");
    prm.declare_entry("Lower corner",
                      "",
                      Patterns::List(Patterns::Double(), 0, dim),
                      "Shape = box: lower corner, one value per direction.");
    prm.declare_entry("Upper corner",
                      "",
                      Patterns::List(Patterns::Double(), 0, dim),
                      "Shape = box: upper corner, one value per direction.");
    prm.declare_entry("Centre",
                      "",
                      Patterns::List(Patterns::Double(), 0, dim),
                      "Shape = ball: centre, one value per direction.");
    prm.declare_entry("Radius",
                      "0",
                      Patterns::Double(0.),
                      "Shape = ball: radius (m).");
    prm.declare_entry("Vertices",
                      "",
                      Patterns::Anything(),
                      "Shape = polygon (2D): the corners in order, 'x0, y0; "
                      "x1, y1; ...' (at least 3, the last joined to the "
                      "first; clockwise or counter-clockwise).");
    prm.declare_entry("Level set",
                      "",
                      Patterns::Anything(),
                      "Shape = level set: an expression in the coordinates "
                      "(x, y, z) that is <= 0 inside the body, e.g. "
                      "'(x-1)^2 + (y-1)^2 - 0.25'.");
    prm.declare_entry("Group",
                      "",
                      Patterns::Anything(),
                      "Shape = mesh group: the name (of $PhysicalNames) or "
                      "the tag of a physical group of surfaces (2D) or "
                      "volumes (3D) of the Mesh file.");
    prm.declare_entry("Mesh file",
                      "",
                      Patterns::Anything(),
                      "Shape = mesh group: the Gmsh file (format 2 or 4.1) "
                      "whose group the body is, when the grid is another "
                      "mesh or a box (a relative path starts in the "
                      "directory the program runs in). Empty: the grid's "
                      "Mesh/Mesh file. The body gets the grid's points that "
                      "lie in the group's cells.");
    prm.declare_entry("Material",
                      "default",
                      Patterns::Anything(),
                      "Name of the body's material: 'default' (subsection "
                      "'Material') or a name of the entry 'Materials'.");
    prm.declare_entry("Initial velocity",
                      zeros,
                      Patterns::Anything(),
                      "dim expressions in (x, y, z), separated by ';'.");
    prm.declare_entry(
      "Initial stress",
      "0",
      Patterns::Anything(),
      "'geostatic': vertical stress from the weight of the material above "
      "(gravity from subsection 'Gravity', vertical = the last coordinate), "
      "horizontal stresses K0 times it; or expressions in (x, y, z) "
      "separated by ';' for the components xx (1D); xx, yy, xy (2D); xx, yy, "
      "zz, xy, yz, xz (3D), in Pa, tension positive; in 1D and 2D one more "
      "may follow: the lateral (1D) or out-of-plane (2D) stress, which is "
      "otherwise the elastic value of uniaxial/plane strain. '0': no "
      "stress.");
    prm.declare_entry("Lateral stress ratio",
                      "",
                      Patterns::Anything(),
                      "K0 of a geostatic initial stress (a number > 0). "
                      "Empty: 1 - sin(phi) for a frictional material, "
                      "nu / (1 - nu) otherwise.");
  }



  template <int dim>
  void
  Body<dim>::parse_parameters(ParameterHandler           &prm,
                              const std::string          &name,
                              const MaterialLibrary<dim> &materials)
  {
    body_name        = name;
    path             = "Body " + name;
    const auto entry = [&](const std::string &e) {
      return path + "/" + e;
    };

    const std::string shape_name = prm.get("Shape");
    if (shape_name == "box")
      {
        shape = Shape::box;
        const Point<dim> lower =
          read_point<dim>(prm.get("Lower corner"), entry("Lower corner"));
        const Point<dim> upper =
          read_point<dim>(prm.get("Upper corner"), entry("Upper corner"));
        for (unsigned int d = 0; d < dim; ++d)
          AssertThrow(upper[d] > lower[d],
                      ExcMessage(entry("Upper corner") +
                                 " must be above Lower corner in every "
                                 "direction."));
        box = BoundingBox<dim>(std::make_pair(lower, upper));
      }
    else if (shape_name == "ball")
      {
        shape  = Shape::ball;
        centre = read_point<dim>(prm.get("Centre"), entry("Centre"));
        radius = prm.get_double("Radius");
        AssertThrow(radius > 0,
                    ExcMessage(entry("Radius") + " must be positive."));
      }
    else if (shape_name == "polygon")
      {
        AssertThrow(dim == 2,
                    ExcMessage(entry("Shape") +
                               " = polygon needs Dimension = 2; use box, "
                               "ball or level set."));
        shape = Shape::polygon;
        polygon.clear();
        for (const auto &vertex :
             Utilities::split_string_list(prm.get("Vertices"), ';'))
          polygon.push_back(read_point<dim>(vertex, entry("Vertices")));
        AssertThrow(polygon.size() >= 3,
                    ExcMessage(entry("Vertices") +
                               " needs at least 3 points 'x, y' separated "
                               "by ';'."));
        if constexpr (dim == 2)
          check_simple_polygon(polygon, entry("Vertices"));
      }
    else if (shape_name == "mesh group")
      {
        AssertThrow(dim > 1,
                    ExcMessage(entry("Shape") +
                               " = mesh group needs a Mesh file, which is "
                               "2D or 3D."));
        shape      = Shape::mesh_group;
        group      = Utilities::trim(prm.get("Group"));
        group_file = Utilities::trim(prm.get("Mesh file"));
        AssertThrow(!group.empty(),
                    ExcMessage(entry("Group") +
                               " is empty: Shape = mesh group needs the name "
                               "or tag of a physical group of Mesh/Mesh "
                               "file."));
      }
    else
      {
        shape = Shape::level_set;
        level_set =
          std::make_unique<ParsedExpression<dim>>(prm.get("Level set"),
                                                  1,
                                                  false,
                                                  entry("Level set"));
      }

    material = materials.material_id(prm.get("Material"), entry("Material"));
    material_model = &materials[material];
    velocity =
      std::make_unique<ParsedExpression<dim>>(prm.get("Initial velocity"),
                                              dim,
                                              false,
                                              entry("Initial velocity"));

    const std::string stress_text = prm.get("Initial stress");
    geostatic                     = (stress_text == "geostatic");
    stress.reset();
    if (!geostatic && stress_text != "0")
      {
        const unsigned int n =
          Utilities::split_string_list(stress_text, ';').size();
        const unsigned int n_in_plane = dim * (dim + 1) / 2;
        AssertThrow(n == n_in_plane || (dim < 3 && n == n_in_plane + 1),
                    ExcMessage(entry("Initial stress") + ": <" + stress_text +
                               "> must be 'geostatic', '0', or " +
                               std::to_string(n_in_plane) +
                               (dim < 3 ?
                                  " or " + std::to_string(n_in_plane + 1) :
                                  std::string()) +
                               " expressions separated by ';'."));
        stress =
          std::make_unique<ParsedExpression<dim>>(stress_text,
                                                  n,
                                                  false,
                                                  entry("Initial stress"));
      }

    const std::string material_subsection = prm.get("Material") == "default" ?
                                              "Material" :
                                              "Material " + prm.get("Material");
    AssertThrow(
      (!geostatic && !stress) || material_model->keeps_initial_stress(),
      ExcMessage(entry("Initial stress") + " = " + stress_text +
                 ": the body's material (subsection " + material_subsection +
                 ") computes its stress from the deformation gradient alone "
                 "(Model = linear elastic or neo-Hookean), so it would replace "
                 "the initial stress by zero in the first step and the body "
                 "would move as if it had none. Use Model = hypo-elastic (the "
                 "same elastic constants as a rate, which keeps an initial "
                 "stress) or a plastic model, or Initial stress = 0."));

    lateral_ratio           = -1;
    const std::string ratio = prm.get("Lateral stress ratio");
    if (!ratio.empty())
      {
        double value = -1;
        try
          {
            value = Utilities::string_to_double(ratio);
          }
        catch (const std::exception &)
          {
            value = -1;
          }
        AssertThrow(value > 0,
                    ExcMessage(entry("Lateral stress ratio") + ": <" + ratio +
                               "> must be a positive number, or empty for "
                               "the default."));
        lateral_ratio = value;
      }
  }



  template <int dim>
  void
  Body<dim>::check_on_grid(const BackgroundGrid<dim> &grid,
                           const MeshGroups<dim>     *mesh_groups)
  {
    if (shape == Shape::mesh_group)
      {
        AssertThrow(mesh_groups != nullptr,
                    ExcMessage(path + "/Shape = mesh group needs the grid "
                                      "of a Mesh file (Mesh/Mesh file), "
                                      "whose physical groups name the "
                                      "cells, or the body's own Mesh "
                                      "file; the grid is a box."));
        groups    = mesh_groups;
        group_tag = groups->tag(group, path + "/Group");
        // The grid's own groups lie in it.
        if (group_file.empty())
          return;
      }
    if (shape == Shape::level_set)
      return;
    // The corners of the body's bounding box.
    Point<dim> lower, upper;
    switch (shape)
      {
        case Shape::mesh_group:
          std::tie(lower, upper) =
            groups->bounding_box(group_tag).get_boundary_points();
          break;
        case Shape::box:
          std::tie(lower, upper) = box.get_boundary_points();
          break;
        case Shape::ball:
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = centre[d] - radius;
              upper[d] = centre[d] + radius;
            }
          break;
        default:
          lower = upper = polygon[0];
          for (const auto &vertex : polygon)
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = std::min(lower[d], vertex[d]);
                upper[d] = std::max(upper[d], vertex[d]);
              }
      }
    const auto [grid_lower, grid_upper] = grid.box().get_boundary_points();
    double size                         = 0;
    for (unsigned int d = 0; d < dim; ++d)
      size = std::max(size, grid_upper[d] - grid_lower[d]);
    const double tolerance = 1e-10 * size;
    for (unsigned int d = 0; d < dim; ++d)
      if (lower[d] < grid_lower[d] - tolerance ||
          upper[d] > grid_upper[d] + tolerance)
        {
          const auto text = [](const Point<dim> &point) {
            std::ostringstream coordinates;
            for (unsigned int e = 0; e < dim; ++e)
              coordinates << (e > 0 ? ", " : "") << point[e];
            return coordinates.str();
          };
          std::ostringstream message;
          message << path << ": the body reaches from (" << text(lower)
                  << ") to (" << text(upper) << "), beyond the grid's "
                  << (grid.is_box() ?
                        "box" :
                        "bounding box (of the vertices of Mesh/Mesh file)")
                  << " from (" << text(grid_lower) << ") to ("
                  << text(grid_upper)
                  << "): its part outside would get no material points. "
                  << "Keep the body inside the grid, or enlarge the grid "
                  << (grid.is_box() ? "(Mesh/Lower corner, Upper corner)." :
                                      "(Mesh/Mesh file).");
          AssertThrow(false, ExcMessage(message.str()));
        }
  }



  template <int dim>
  const std::string &
  Body<dim>::group_mesh_file() const
  {
    return group_file;
  }



  template <int dim>
  bool
  Body<dim>::is_mesh_group() const
  {
    return shape == Shape::mesh_group;
  }



  template <int dim>
  const std::string &
  Body<dim>::name() const
  {
    return body_name;
  }



  template <int dim>
  bool
  Body<dim>::contains(const Point<dim> &point) const
  {
    switch (shape)
      {
        case Shape::box:
          return box.point_inside(point);
        case Shape::ball:
          return point.distance(centre) <= radius;
        case Shape::polygon:
          {
            // Crossing number of a ray in +x direction.
            bool inside = false;
            for (unsigned int i = 0, j = polygon.size() - 1; i < polygon.size();
                 j = i++)
              {
                const Point<dim> &a = polygon[i];
                const Point<dim> &b = polygon[j];
                if ((a[1] > point[1]) != (b[1] > point[1]) &&
                    point[0] <
                      a[0] + (b[0] - a[0]) * (point[1] - a[1]) / (b[1] - a[1]))
                  inside = !inside;
              }
            return inside;
          }
        case Shape::mesh_group:
          Assert(groups != nullptr, ExcInternalError());
          if constexpr (dim > 1)
            return groups->group_at(point) == group_tag;
          else
            return false;
        default:
          return level_set->value(point) <= 0.;
      }
  }



  template <int dim>
  unsigned int
  Body<dim>::material_id() const
  {
    return material;
  }



  template <int dim>
  Tensor<1, dim>
  Body<dim>::initial_velocity(const Point<dim> &point) const
  {
    return velocity->vector_value(point);
  }



  template <int dim>
  bool
  Body<dim>::has_geostatic_stress() const
  {
    return geostatic;
  }



  template <int dim>
  double
  Body<dim>::lateral_stress_ratio() const
  {
    if (lateral_ratio > 0)
      return lateral_ratio;
    const double phi = material_model->friction_angle();
    if (phi > 0)
      return 1. - std::sin(phi);
    const double nu = material_model->poissons_ratio();
    return nu / (1. - nu);
  }



  template <int dim>
  std::pair<SymmetricTensor<2, dim>, double>
  Body<dim>::initial_stress(const Point<dim> &point) const
  {
    SymmetricTensor<2, dim> sigma;
    if (!stress)
      return {sigma, 0.};
    const auto components = stress_components<dim>();
    for (unsigned int k = 0; k < components.size(); ++k)
      sigma[components[k].first][components[k].second] =
        stress->value(point, 0., k);
    const double out_of_plane =
      (stress->n_components() > components.size()) ?
        stress->value(point, 0., components.size()) :
        material_model->elastic_out_of_plane_stress(sigma);
    return {sigma, out_of_plane};
  }



  template class Body<1>;
  template class Body<2>;
  template class Body<3>;
} // namespace MpmOtm
