#include <deal.II/base/data_out_base.h>

#include <mpm_otm/shape_functions/powell_sabin.h>

#include <algorithm>
#include <fstream>

// The picture of the Powell-Sabin functions (Output/Powell-Sabin basis at),
// apart from the family's evaluation in powell_sabin.cc.

namespace MpmOtm
{
  namespace
  {
    /**
     * The Powell-Sabin refinement of the cells around the vertex of
     * @p splines nearest to @p near (and of their neighbours), each
     * sub-triangle divided into @p n x @p n triangles, with the values of
     * that vertex's three functions.
     */
    std::vector<DataOutBase::Patch<2, 2>>
    powell_sabin_basis_patches(const PowellSabin<2> &splines,
                               const Point<2>       &near,
                               const unsigned int    n)
    {
      const Triangulation<2> &triangulation =
        splines.dof_handler().get_triangulation();
      const auto        &vertices = triangulation.get_vertices();
      const unsigned int chosen =
        std::distance(vertices.begin(),
                      std::min_element(vertices.begin(),
                                       vertices.end(),
                                       [&](const Point<2> &a,
                                           const Point<2> &b) {
                                         return a.distance_square(near) <
                                                b.distance_square(near);
                                       }));

      // The chosen vertex's cells (its functions' support) and their
      // neighbours through a vertex.
      std::vector<bool> near_support(vertices.size(), false);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex_index(v) == chosen)
            for (const unsigned int w : cell->vertex_indices())
              near_support[cell->vertex_index(w)] = true;

      std::vector<DataOutBase::Patch<2, 2>>                      patches;
      std::array<double, PowellSabin<2>::n_cell_functions>       values;
      std::array<Tensor<1, 2>, PowellSabin<2>::n_cell_functions> gradients;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          bool shown = false;
          for (const unsigned int v : cell->vertex_indices())
            shown = shown || near_support[cell->vertex_index(v)];
          if (!shown)
            continue;
          // Local number of the chosen vertex in the cell, if any.
          unsigned int local = numbers::invalid_unsigned_int;
          for (const unsigned int v : cell->vertex_indices())
            if (cell->vertex_index(v) == chosen)
              local = v;

          // Reference coordinates of a real point of the cell.
          Tensor<2, 2> jacobian;
          for (unsigned int d = 0; d < 2; ++d)
            for (unsigned int e = 0; e < 2; ++e)
              jacobian[d][e] = cell->vertex(e + 1)[d] - cell->vertex(0)[d];
          const Tensor<2, 2> inverse = invert(jacobian);

          const Point<2> incentre = splines.geometry().split_point(cell, 3);
          for (unsigned int k = 0; k < 3; ++k)
            {
              // The sub-triangles (V_k, R_k, Z) and (V_k, Z, R_{k-1}).
              const Point<2> corner = cell->vertex(k);
              const Point<2> next   = splines.geometry().split_point(cell, k);
              const Point<2> before =
                splines.geometry().split_point(cell, (k + 2) % 3);
              for (const auto &[b, c] : {std::make_pair(next, incentre),
                                         std::make_pair(incentre, before)})
                for (unsigned int i = 0; i < n; ++i)
                  for (unsigned int j = 0; i + j < n; ++j)
                    for (unsigned int upper = 0;
                         upper < (i + j + 1 < n ? 2 : 1);
                         ++upper)
                      {
                        // Lattice triangle (i, j) of the sub-triangle,
                        // pointing up, or the one pointing down next to it.
                        const std::array<std::array<unsigned int, 2>, 3> ij =
                          upper == 0 ?
                            std::array<std::array<unsigned int, 2>, 3>{
                              {{{i, j}}, {{i + 1, j}}, {{i, j + 1}}}} :
                            std::array<std::array<unsigned int, 2>, 3>{
                              {{{i + 1, j}}, {{i + 1, j + 1}}, {{i, j + 1}}}};
                        DataOutBase::Patch<2, 2> patch;
                        patch.reference_cell = ReferenceCells::Triangle;
                        patch.n_subdivisions = 1;
                        patch.data.reinit(3, 3);
                        for (unsigned int p = 0; p < 3; ++p)
                          {
                            const Point<2> x =
                              corner + (double(ij[p][0]) / n) * (b - corner) +
                              (double(ij[p][1]) / n) * (c - corner);
                            patch.vertices[p] = x;
                            if (local == numbers::invalid_unsigned_int)
                              continue;
                            const Point<2> xi(inverse * (x - cell->vertex(0)));
                            splines.geometry().cell_values(cell,
                                                           xi,
                                                           values.data(),
                                                           gradients.data());
                            for (unsigned int q = 0; q < 3; ++q)
                              patch.data(q, p) = values[3 * local + q];
                          }
                        patch.patch_index = patches.size();
                        patches.push_back(std::move(patch));
                      }
            }
        }
      return patches;
    }
  } // namespace



  template <int dim>
  bool
  PowellSabin<dim>::has_basis_picture() const
  {
    return true;
  }



  template <int dim>
  void
  PowellSabin<dim>::write_basis_picture(const Point<dim>  &point,
                                        const std::string &file_name) const
  {
    if constexpr (dim == 2)
      {
        const auto    patches = powell_sabin_basis_patches(*this, point, 6);
        std::ofstream file(file_name);
        DataOutBase::write_vtu(patches,
                               {"phi_0", "phi_1", "phi_2"},
                               {},
                               DataOutBase::VtkFlags(),
                               file);
        AssertThrow(file.good(),
                    ExcMessage("Cannot write <" + file_name + ">."));
      }
    else
      {
        (void)point;
        (void)file_name;
        Assert(false, ExcNotImplemented());
      }
  }



  template bool
  PowellSabin<1>::has_basis_picture() const;
  template bool
  PowellSabin<2>::has_basis_picture() const;
  template bool
  PowellSabin<3>::has_basis_picture() const;
  template void
  PowellSabin<1>::write_basis_picture(const Point<1> &,
                                      const std::string &) const;
  template void
  PowellSabin<2>::write_basis_picture(const Point<2> &,
                                      const std::string &) const;
  template void
  PowellSabin<3>::write_basis_picture(const Point<3> &,
                                      const std::string &) const;
} // namespace MpmOtm
