#include <mpm_otm/io/collective_hdf5_file.h>
#include <mpm_otm/io/particle_patches.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material_library.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace MpmOtm
{
  namespace
  {
    /**
     * The logarithmic (Hencky) strain of the current configuration,
     * ln(V) = ln(F F^T) / 2, three-dimensional: F has F_zz = 1 in 2D (plane
     * strain) and F_yy = F_zz = 1 in 1D (uniaxial strain).
     */
    template <int dim>
    SymmetricTensor<2, 3>
    logarithmic_strain(const Tensor<2, dim> &F)
    {
      Tensor<2, 3> F3 = unit_symmetric_tensor<3>();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F3[i][j] = F[i][j];
      const SymmetricTensor<2, 3> left_stretch_squared =
        symmetrize(F3 * transpose(F3));
      SymmetricTensor<2, 3> strain;
      for (const auto &[value, direction] : eigenvectors(left_stretch_squared))
        strain += 0.5 * std::log(value) *
                  symmetrize(outer_product(direction, direction));
      return strain;
    }

    /**
     * The name of component (i, j) of a three-dimensional tensor.
     */
    std::string
    component(const std::string &name,
              const unsigned int i,
              const unsigned int j)
    {
      return name + "_" + "xyz"[i] + "xyz"[j];
    }
  } // namespace



  template <int dim>
  ParticlePatches<dim>::ParticlePatches(
    const MaterialPoints<dim>  &material_points,
    const MaterialLibrary<dim> &materials,
    const bool                  tensors_as_components)
    : tensors_as_components(tensors_as_components)
  {
    // zlib's fastest level: the best level took several times longer per
    // output for files a few percent smaller.
    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    this->set_flags(flags);
    using Layout = PropertyLayout<dim>;
    for (unsigned int d = 0; d < dim; ++d)
      names.push_back("displacement");
    for (unsigned int d = 0; d < dim; ++d)
      names.push_back("velocity");
    // The three-dimensional tensors: all nine components for the VTU
    // writer, the six independent ones (in 2D the four that are not zero by
    // plane strain) as scalars for HDF5.
    const auto add_tensor = [&](const std::string &name) {
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          if (!tensors_as_components)
            names.push_back(name);
          else if (j >= i && (i == j || j < dim))
            names.push_back(component(name, i, j));
    };
    add_tensor("stress");
    names.insert(names.end(),
                 {"mean_stress",
                  "von_mises_stress",
                  "principal_stress_1",
                  "principal_stress_2",
                  "principal_stress_3"});
    add_tensor("log_strain");
    names.insert(names.end(),
                 {"det_F", "volume", "mass", "material", "plastic_strain"});
    const auto internal = materials.internal_variable_names();
    names.insert(names.end(), internal.begin(), internal.end());
    names.push_back("id");

    const unsigned int n_fields = names.size();
    locations.reserve(
      material_points.particle_handler().n_locally_owned_particles());
    values.reserve(locations.capacity() * n_fields);
    const auto push_tensor = [&](const SymmetricTensor<2, 3> &tensor) {
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          if (!tensors_as_components || (j >= i && (i == j || j < dim)))
            values.push_back(tensor[i][j]);
    };
    for (const auto &particle : material_points.particle_handler())
      {
        const auto properties = particle.get_properties();
        locations.push_back(particle.get_location());
        const Point<dim> X(
          Layout::get_vector(properties, Layout::initial_position));
        for (unsigned int d = 0; d < dim; ++d)
          values.push_back(particle.get_location()[d] - X[d]);
        for (unsigned int d = 0; d < dim; ++d)
          values.push_back(properties[Layout::velocity + d]);
        const SymmetricTensor<2, 3> sigma = Layout::get_full_stress(properties);
        push_tensor(sigma);
        values.push_back(trace(sigma) / 3.);
        values.push_back(std::sqrt(1.5) * deviator(sigma).norm());
        const auto principal = eigenvalues(sigma);
        values.insert(values.end(), principal.begin(), principal.end());
        const Tensor<2, dim> F = Layout::get_deformation_gradient(properties);
        push_tensor(logarithmic_strain(F));
        values.push_back(determinant(F));
        values.push_back(Layout::volume(properties));
        values.push_back(properties[Layout::mass]);
        const unsigned int id = Layout::get_material_id(properties);
        values.push_back(id);
        const unsigned int first = materials.first_internal_variable(id);
        values.push_back(materials[id].equivalent_plastic_strain(
          ArrayView<const double>(properties.data() + first,
                                  materials.n_internal_variables(id))));
        for (unsigned int k = Layout::n_fixed_properties; k < properties.size();
             ++k)
          values.push_back(properties[k]);
        values.push_back(particle.get_id());
        AssertDimension(values.size(), locations.size() * n_fields);
      }
  }



  template <int dim>
  const std::vector<DataOutBase::Patch<0, dim>> &
  ParticlePatches<dim>::get_patches() const
  {
    if (patches.size() != locations.size())
      {
        const unsigned int n_fields = names.size();
        patches.resize(locations.size());
        for (unsigned int p = 0; p < locations.size(); ++p)
          {
            patches[p].vertices[0] = locations[p];
            patches[p].data.reinit(n_fields, 1);
            for (unsigned int f = 0; f < n_fields; ++f)
              patches[p].data(f, 0) = values[p * n_fields + f];
          }
      }
    return patches;
  }



  template <int dim>
  std::vector<std::string>
  ParticlePatches<dim>::get_dataset_names() const
  {
    return names;
  }



  template <int dim>
  std::vector<
    std::tuple<unsigned int,
               unsigned int,
               std::string,
               DataComponentInterpretation::DataComponentInterpretation>>
  ParticlePatches<dim>::get_nonscalar_data_ranges() const
  {
    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      ranges;
    if (dim > 1)
      {
        ranges.emplace_back(
          0,
          dim - 1,
          "displacement",
          DataComponentInterpretation::component_is_part_of_vector);
        ranges.emplace_back(
          dim,
          2 * dim - 1,
          "velocity",
          DataComponentInterpretation::component_is_part_of_vector);
      }
    if (!tensors_as_components)
      for (const std::string name : {"stress", "log_strain"})
        {
          const unsigned int first =
            std::find(names.begin(), names.end(), name) - names.begin();
          ranges.emplace_back(
            first,
            first + 8,
            name,
            DataComponentInterpretation::component_is_part_of_tensor);
        }
    return ranges;
  }



  template <int dim>
  std::uint64_t
  ParticlePatches<dim>::n_nodes() const
  {
    return locations.size();
  }



  template <int dim>
  std::uint64_t
  ParticlePatches<dim>::n_cells() const
  {
    return locations.size();
  }



  template <int dim>
  ReferenceCell
  ParticlePatches<dim>::reference_cell() const
  {
    return ReferenceCells::Vertex;
  }



  template <int dim>
  std::vector<std::pair<std::string, unsigned int>>
  ParticlePatches<dim>::data_sets() const
  {
    return xdmf_data_sets(names, get_nonscalar_data_ranges());
  }



  template <int dim>
  void
  ParticlePatches<dim>::write_hdf5(const std::string &file_name,
                                   const MPI_Comm     communicator) const
  {
    CollectiveHDF5File  file(file_name, communicator);
    const std::size_t   n_local = locations.size();
    std::vector<double> nodes;
    nodes.reserve(n_local * dim);
    for (const Point<dim> &location : locations)
      for (unsigned int d = 0; d < dim; ++d)
        nodes.push_back(location[d]);
    const std::uint64_t       first = file.write("nodes", nodes, dim);
    std::vector<unsigned int> cells(n_local);
    for (unsigned int p = 0; p < n_local; ++p)
      cells[p] = first + p;
    file.write("cells", cells, 1);

    const std::size_t n_fields = names.size();
    file.write_fields<double>(data_sets(),
                              n_local,
                              dim,
                              [&](const std::size_t  p,
                                  const unsigned int component) {
                                return values[p * n_fields + component];
                              });
  }



  template class ParticlePatches<1>;
  template class ParticlePatches<2>;
  template class ParticlePatches<3>;
} // namespace MpmOtm
