#include <mpm_otm/grid_system/nodal_system.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <algorithm>
#include <cmath>

namespace MpmOtm
{
  template <int dim>
  void
  NodalSystem<dim>::setup(
    const ShapeFunctions<dim>               &shape_functions,
    const std::vector<FixedComponents<dim>> &fixed_components,
    const double                             deactivation_threshold,
    const bool                               find_material_boundary)
  {
    this->shape_functions        = &shape_functions;
    this->deactivation_threshold = deactivation_threshold;
    track_material_boundary      = find_material_boundary;
    index_partition = std::make_shared<Utilities::MPI::Partitioner>(
      shape_functions.locally_owned_functions(),
      shape_functions.locally_relevant_functions(),
      shape_functions.dof_handler().get_triangulation().get_communicator());

    lumped_mass.reinit(index_partition);
    if (deactivation_threshold > 0.)
      diagonal_mass.reinit(index_partition);
    if (track_material_boundary)
      {
        filled_cells.reinit(index_partition);
        empty_cells.reinit(index_partition);
      }
    for (unsigned int c = 0; c < dim; ++c)
      {
        momentum[c].reinit(index_partition);
        force[c].reinit(index_partition);
        damping_force[c].reinit(index_partition);
        acceleration[c].reinit(index_partition);
        velocity[c].reinit(index_partition);
      }
    set_fixed_components(fixed_components);
  }



  template <int dim>
  void
  NodalSystem<dim>::set_fixed_components(
    const std::vector<FixedComponents<dim>> &fixed_components)
  {
    for (auto &list : fixed)
      list.clear();
    for (const auto &condition : fixed_components)
      {
        const IndexSet on_boundary =
          shape_functions->boundary_functions(condition.boundary_id);
        for (const auto global : on_boundary)
          if (index_partition->in_local_range(global))
            for (unsigned int c = 0; c < dim; ++c)
              if (condition.fixed[c])
                fixed[c].push_back(index_partition->global_to_local(global));
      }
    for (auto &list : fixed)
      {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
      }
  }



  template <int dim>
  const Utilities::MPI::Partitioner &
  NodalSystem<dim>::partitioner() const
  {
    return *index_partition;
  }



  template <int dim>
  unsigned int
  NodalSystem<dim>::functions_per_node() const
  {
    return shape_functions->functions_per_node();
  }



  template <int dim>
  void
  NodalSystem<dim>::assemble(const MaterialPoints<dim>    &material_points,
                             const ParticleShapeData<dim> &shape_data,
                             const Problem<dim>           &problem,
                             const double                  time,
                             const bool                    tractions_on_points)
  {
    using Layout = PropertyLayout<dim>;
    lumped_mass  = 0.;
    for (unsigned int c = 0; c < dim; ++c)
      {
        momentum[c]      = 0.;
        force[c]         = 0.;
        damping_force[c] = 0.;
      }
    particle_mass.resize(shape_data.n_particles());
    external_power                 = 0.;
    external_force_squared_by_mass = 0.;

    std::vector<Tensor<1, dim>> traction(2 * dim);
    for (const auto id : problem.traction_boundaries())
      traction[id] = problem.traction(id, time);
    const bool               has_body_force    = problem.has_body_force();
    const Tensor<1, dim>     gravity           = problem.gravity(time);
    const SurfaceLoads<dim> &surface_loads     = problem.surface_loads();
    const bool               has_surface_loads = !surface_loads.empty();

    double *const mass = lumped_mass.get_values();
    double       *q[dim];
    double       *f[dim];
    for (unsigned int c = 0; c < dim; ++c)
      {
        q[c] = momentum[c].get_values();
        f[c] = force[c].get_values();
      }

    // The points of a batch share their functions: their contributions are
    // summed per function of the batch, and each sum is added to the nodal
    // vectors once per batch.
    std::vector<double>         batch_mass;
    std::vector<Tensor<1, dim>> batch_momentum;
    std::vector<Tensor<1, dim>> batch_force;
    const unsigned int         *batch_functions = nullptr;
    unsigned int                batch_size      = 0;
    const auto                  add_batch       = [&]() {
      for (unsigned int j = 0; j < batch_size; ++j)
        {
          const unsigned int i = batch_functions[j];
          mass[i] += batch_mass[j];
          for (unsigned int c = 0; c < dim; ++c)
            {
              q[c][i] += batch_momentum[j][c];
              f[c][i] += batch_force[j][c];
            }
        }
    };

    typename ParticleShapeData<dim>::Cursor functions(shape_data);
    unsigned int                            k = 0;
    for (const auto &particle : material_points.particle_handler())
      {
        const auto           properties = particle.get_properties();
        const double         m          = properties[Layout::mass];
        const double         volume     = Layout::volume(properties);
        const Tensor<1, dim> v =
          Layout::get_vector(properties, Layout::velocity);
        const SymmetricTensor<2, dim> sigma = Layout::get_stress(properties);

        Tensor<1, dim> external = m * gravity;
        if (has_body_force)
          external +=
            m *
            problem.body_force(Point<dim>(
                                 Layout::get_vector(properties,
                                                    Layout::initial_position)),
                               time);
        if (tractions_on_points && properties[Layout::traction_measure] > 0.)
          external += properties[Layout::traction_measure] *
                      traction[static_cast<unsigned int>(
                        properties[Layout::traction_boundary])];
        // A surface load acts at the surface point x_p + offset, whose
        // function values are phi_i + grad phi_i . offset.
        typename SurfaceLoads<dim>::PointLoad surface_load;
        const bool                            loaded =
          has_surface_loads && surface_loads.carries_load(properties);
        if (loaded)
          {
            surface_load = surface_loads.load_on(properties, time);
            external += surface_load.force;
          }
        external_power += external * v;
        if (m > 0.)
          external_force_squared_by_mass += external.norm_square() / m;

        const auto point = functions.next();
        if (point.indices != batch_functions)
          {
            add_batch();
            batch_functions = point.indices;
            batch_size      = point.n;
            if (batch_mass.size() < batch_size)
              {
                batch_mass.resize(batch_size);
                batch_momentum.resize(batch_size);
                batch_force.resize(batch_size);
              }
            std::fill_n(batch_mass.begin(), batch_size, 0.);
            std::fill_n(batch_momentum.begin(), batch_size, Tensor<1, dim>());
            std::fill_n(batch_force.begin(), batch_size, Tensor<1, dim>());
          }
        for (unsigned int j = 0; j < point.n; ++j)
          {
            const double phi = point.values[j];
            batch_mass[j] += phi * m;
            batch_momentum[j] += (phi * m) * v;
            batch_force[j] +=
              phi * external - volume * (sigma * point.gradients[j]);
          }
        if (loaded)
          for (unsigned int j = 0; j < point.n; ++j)
            batch_force[j] +=
              (point.gradients[j] * surface_load.offset) * surface_load.force;
        particle_mass[k] = m;
        ++k;
      }
    add_batch();

    if (deactivation_threshold > 0.)
      {
        diagonal_mass          = 0.;
        double *const diagonal = diagonal_mass.get_values();
        typename ParticleShapeData<dim>::Cursor diagonal_functions(shape_data);
        for (k = 0; k < shape_data.n_particles(); ++k)
          {
            const auto point = diagonal_functions.next();
            for (unsigned int j = 0; j < point.n; ++j)
              diagonal[point.indices[j]] +=
                particle_mass[k] * point.values[j] * point.values[j];
          }
      }
    if (track_material_boundary)
      find_material_boundary(material_points);
  }



  template <int dim>
  void
  NodalSystem<dim>::find_material_boundary(
    const MaterialPoints<dim> &material_points)
  {
    filled_cells          = 0.;
    empty_cells           = 0.;
    const auto &particles = material_points.particle_handler();
    for (const auto &cell : shape_functions->dof_handler()
                              .get_triangulation()
                              .active_cell_iterators())
      if (cell->is_locally_owned())
        {
          VectorType &count = particles.n_particles_in_cell(cell) > 0 ?
                                filled_cells :
                                empty_cells;
          shape_functions->functions_on_cell(cell, cell_functions);
          for (const auto global : cell_functions)
            count(global) += 1.;
        }
    filled_cells.compress(VectorOperation::add);
    empty_cells.compress(VectorOperation::add);
    material_boundary.clear();
    for (unsigned int i = 0; i < filled_cells.locally_owned_size(); ++i)
      if (filled_cells.local_element(i) > 0. &&
          empty_cells.local_element(i) > 0.)
        material_boundary.push_back(i);
  }



  template <int dim>
  void
  NodalSystem<dim>::finish_assembly()
  {
    lumped_mass.compress(VectorOperation::add);
    for (unsigned int c = 0; c < dim; ++c)
      {
        momentum[c].compress(VectorOperation::add);
        force[c].compress(VectorOperation::add);
      }

    // A non-finite force would spoil every later step (and make the
    // consistent solve accept anything): stop here on every rank.
    bool finite = true;
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int i = 0; i < force[c].locally_owned_size(); ++i)
        finite = finite && std::isfinite(force[c].local_element(i)) &&
                 std::isfinite(momentum[c].local_element(i));
    AssertThrow(Utilities::MPI::min(finite ? 1 : 0,
                                    lumped_mass.get_mpi_communicator()) == 1,
                ExcMessage("A nodal force or momentum is not finite (NaN or "
                           "infinite): check the body force, traction and "
                           "initial velocity expressions and the time step."));

    deactivated.clear();
    if (deactivation_threshold > 0.)
      {
        diagonal_mass.compress(VectorOperation::add);
        for (unsigned int i = 0; i < diagonal_mass.locally_owned_size(); ++i)
          if (lumped_mass.local_element(i) > 0. &&
              diagonal_mass.local_element(i) < deactivation_threshold)
            deactivated.push_back(i);
      }

    for (unsigned int c = 0; c < dim; ++c)
      {
        AffineConstraints<double> &lines = zero_constraints[c];
        lines.reinit(index_partition->locally_owned_range());
        for (const unsigned int i : fixed[c])
          lines.add_line(index_partition->local_to_global(i));
        for (const unsigned int i : deactivated)
          lines.add_line(index_partition->local_to_global(i));
        for (unsigned int i = 0; i < lumped_mass.locally_owned_size(); ++i)
          if (!(lumped_mass.local_element(i) > 0.))
            lines.add_line(index_partition->local_to_global(i));
      }
  }



  template <int dim>
  void
  NodalSystem<dim>::assemble_momentum(
    const MaterialPoints<dim>    &material_points,
    const ParticleShapeData<dim> &shape_data)
  {
    using Layout = PropertyLayout<dim>;
    double *q[dim];
    for (unsigned int c = 0; c < dim; ++c)
      {
        momentum[c] = 0.;
        q[c]        = momentum[c].get_values();
      }
    typename ParticleShapeData<dim>::Cursor functions(shape_data);
    for (const auto &particle : material_points.particle_handler())
      {
        const auto           properties = particle.get_properties();
        const double         m          = properties[Layout::mass];
        const Tensor<1, dim> v =
          Layout::get_vector(properties, Layout::velocity);
        const auto point = functions.next();
        for (unsigned int j = 0; j < point.n; ++j)
          for (unsigned int c = 0; c < dim; ++c)
            q[c][point.indices[j]] += point.values[j] * m * v[c];
      }
    for (unsigned int c = 0; c < dim; ++c)
      momentum[c].compress(VectorOperation::add);
  }



  template <int dim>
  const typename NodalSystem<dim>::Constraints &
  NodalSystem<dim>::constraints() const
  {
    return zero_constraints;
  }



  template <int dim>
  std::vector<std::pair<unsigned int, double>>
  NodalSystem<dim>::local_lines(
    const AffineConstraints<double> &constraints) const
  {
    std::vector<std::pair<unsigned int, double>> lines;
    for (const auto &line : constraints.get_lines())
      {
        Assert(line.entries.empty(),
               ExcMessage("Only constraints x_i = b_i are supported."));
        lines.emplace_back(index_partition->global_to_local(line.index),
                           line.inhomogeneity);
      }
    std::sort(lines.begin(), lines.end());
    return lines;
  }



  template <int dim>
  const std::vector<unsigned int> &
  NodalSystem<dim>::deactivated_functions() const
  {
    return deactivated;
  }



  template <int dim>
  const std::vector<unsigned int> &
  NodalSystem<dim>::material_boundary_functions() const
  {
    Assert(track_material_boundary,
           ExcMessage("setup() did not ask for the material boundary."));
    return material_boundary;
  }



  template <int dim>
  double
  NodalSystem<dim>::kinetic_energy() const
  {
    double energy = 0;
    for (unsigned int i = 0; i < lumped_mass.locally_owned_size(); ++i)
      for (unsigned int c = 0; c < dim; ++c)
        energy += 0.5 * lumped_mass.local_element(i) *
                  velocity[c].local_element(i) * velocity[c].local_element(i);
    return Utilities::MPI::sum(energy, lumped_mass.get_mpi_communicator());
  }



  template <int dim>
  double
  NodalSystem<dim>::external_work(const double dt) const
  {
    return dt * external_power + 0.5 * dt * dt * external_force_squared_by_mass;
  }



  template <int dim>
  void
  NodalSystem<dim>::add_external_power(const double power)
  {
    external_power += power;
  }



  template <int dim>
  void
  NodalSystem<dim>::save(CheckpointState &state) const
  {
    // Per owned function: its global index, then the accelerations and the
    // velocities of its components.
    std::vector<double> values;
    const auto         &owned = index_partition->locally_owned_range();
    values.reserve(owned.n_elements() * (2 * dim + 1));
    unsigned int local = 0;
    for (const auto index : owned)
      {
        values.push_back(index);
        for (unsigned int c = 0; c < dim; ++c)
          values.push_back(acceleration[c].local_element(local));
        for (unsigned int c = 0; c < dim; ++c)
          values.push_back(velocity[c].local_element(local));
        ++local;
      }
    state.set_own("nodal system/accelerations and velocities", values);
  }



  template <int dim>
  void
  NodalSystem<dim>::load(const CheckpointState &state)
  {
    const auto &owned = index_partition->locally_owned_range();
    for (const auto &part :
         state.parts("nodal system/accelerations and velocities"))
      for (unsigned int k = 0; k + 2 * dim < part.size(); k += 2 * dim + 1)
        {
          const auto index = static_cast<types::global_dof_index>(part[k]);
          if (!owned.is_element(index))
            continue;
          const unsigned int local = owned.index_within_set(index);
          for (unsigned int c = 0; c < dim; ++c)
            {
              acceleration[c].local_element(local) = part[k + 1 + c];
              velocity[c].local_element(local)     = part[k + 1 + dim + c];
            }
        }
  }



  template class NodalSystem<1>;
  template class NodalSystem<2>;
  template class NodalSystem<3>;
} // namespace MpmOtm
