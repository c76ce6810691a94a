#include <deal.II/base/hdf5.h>

#include <mpm_otm/io/particle_patches.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material_library.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace MpmOtm
{
  template <int dim>
  ParticlePatches<dim>::ParticlePatches(
    const MaterialPoints<dim>  &material_points,
    const MaterialLibrary<dim> &materials,
    const bool                  stress_as_components)
    : stress_as_components(stress_as_components)
  {
    using Layout = PropertyLayout<dim>;
    for (unsigned int d = 0; d < dim; ++d)
      names.push_back("displacement");
    for (unsigned int d = 0; d < dim; ++d)
      names.push_back("velocity");
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        if (dim == 1 || (stress_as_components && j >= i))
          names.push_back(std::string("stress_") + "xyz"[i] + "xyz"[j]);
        else if (!stress_as_components)
          names.push_back("stress");
    if (dim == 2)
      names.push_back("stress_zz");
    if (dim == 1)
      names.push_back("stress_lateral");
    names.insert(names.end(),
                 {"mean_stress",
                  "von_mises_stress",
                  "det_F",
                  "volume",
                  "mass",
                  "material",
                  "plastic_strain"});
    const auto internal = materials.internal_variable_names();
    names.insert(names.end(), internal.begin(), internal.end());
    names.push_back("id");

    const unsigned int n_fields = names.size();
    locations.reserve(
      material_points.particle_handler().n_locally_owned_particles());
    values.reserve(locations.capacity() * n_fields);
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
        const SymmetricTensor<2, dim> sigma = Layout::get_stress(properties);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = stress_as_components ? i : 0; j < dim; ++j)
            values.push_back(sigma[i][j]);
        const double out_of_plane = Layout::get_out_of_plane_stress(properties);
        if (dim < 3)
          values.push_back(out_of_plane);
        // The three-dimensional stress: plane strain or uniaxial strain.
        SymmetricTensor<2, 3> full;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            full[i][j] = sigma[i][j];
        for (unsigned int d = dim; d < 3; ++d)
          full[d][d] = out_of_plane;
        values.push_back(trace(full) / 3.);
        values.push_back(std::sqrt(1.5) * deviator(full).norm());
        values.push_back(
          determinant(Layout::get_deformation_gradient(properties)));
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
    if (dim == 1)
      return {};
    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      ranges = {{0,
                 dim - 1,
                 "displacement",
                 DataComponentInterpretation::component_is_part_of_vector},
                {dim,
                 2 * dim - 1,
                 "velocity",
                 DataComponentInterpretation::component_is_part_of_vector}};
    if (!stress_as_components)
      ranges.emplace_back(
        2 * dim,
        2 * dim + dim * dim - 1,
        "stress",
        DataComponentInterpretation::component_is_part_of_tensor);
    return ranges;
  }



  template <int dim>
  unsigned int
  ParticlePatches<dim>::n_points() const
  {
    return locations.size();
  }



  template <int dim>
  std::vector<std::pair<std::string, unsigned int>>
  ParticlePatches<dim>::data_sets() const
  {
    // The vectors (padded to three components), then the scalars, in the
    // order of the data.
    std::vector<std::pair<std::string, unsigned int>> result;
    const auto ranges = get_nonscalar_data_ranges();
    for (unsigned int k = 0; k < names.size();)
      {
        const auto range =
          std::find_if(ranges.begin(), ranges.end(), [&](const auto &r) {
            return std::get<0>(r) == k;
          });
        if (range != ranges.end())
          {
            result.emplace_back(std::get<2>(*range), 3);
            k = std::get<1>(*range) + 1;
          }
        else
          result.emplace_back(names[k++], 1);
      }
    return result;
  }



  template <int dim>
  void
  ParticlePatches<dim>::write_hdf5(const std::string &file_name,
                                   const MPI_Comm     communicator) const
  {
    // This rank's rows start after those of the ranks before it.
    const hsize_t              n_local = locations.size();
    const std::vector<hsize_t> counts =
      Utilities::MPI::all_gather(communicator, n_local);
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
    const hsize_t      first =
      std::accumulate(counts.begin(), counts.begin() + rank, hsize_t(0));
    const hsize_t n_total =
      std::accumulate(counts.begin(), counts.end(), hsize_t(0));

    HDF5::File file(file_name,
                    HDF5::File::FileAccessMode::create,
                    communicator);
    const auto write = [&](const std::string &name,
                           const auto        &values,
                           const unsigned int n_columns) {
      using Number = typename std::decay_t<decltype(values)>::value_type;
      auto dataset =
        file.create_dataset<Number>(name, {n_total, hsize_t(n_columns)});
      if (n_local > 0)
        dataset.write_hyperslab(values, {first, 0}, {n_local, n_columns});
      else
        dataset.template write_none<Number>();
    };

    std::vector<double> nodes;
    nodes.reserve(n_local * dim);
    for (const Point<dim> &location : locations)
      for (unsigned int d = 0; d < dim; ++d)
        nodes.push_back(location[d]);
    write("nodes", nodes, dim);
    std::vector<unsigned int> cells(n_local);
    for (unsigned int p = 0; p < n_local; ++p)
      cells[p] = first + p;
    write("cells", cells, 1);

    unsigned int        component = 0;
    std::vector<double> column;
    for (const auto &[name, n_columns] : data_sets())
      {
        const unsigned int n_components =
          n_columns == 1 ? 1 : static_cast<unsigned int>(dim);
        column.assign(n_local * n_columns, 0.);
        for (unsigned int p = 0; p < n_local; ++p)
          for (unsigned int c = 0; c < n_components; ++c)
            column[p * n_columns + c] =
              values[p * names.size() + component + c];
        write(name, column, n_columns);
        component += n_components;
      }
  }



  template class ParticlePatches<1>;
  template class ParticlePatches<2>;
  template class ParticlePatches<3>;
} // namespace MpmOtm
