#include <mpm_otm/algorithms/energy_monitor.h>
#include <mpm_otm/algorithms/time_stepper.h>
#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/shape_functions/shape_functions.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace MpmOtm
{
  template <int dim>
  TimeStepper<dim>::TimeStepper(
    MaterialPoints<dim>          &material_points,
    const ShapeFunctions<dim>    &shape_functions,
    NodalSystem<dim>             &system,
    MassMatrix<dim>              &mass_matrix,
    const NodalUpdate<dim>       &nodal_update,
    GridMotion<dim>              &grid_motion,
    const MaterialLibrary<dim>   &materials,
    const Problem<dim>           &problem,
    BoundaryConditions<dim>      &boundary_conditions,
    const LocalDamping<dim>      &damping,
    VolumetricLockingRemedy<dim> *locking_remedy,
    SofteningRegularisation<dim> *softening_regularisation,
    const ParticleTransfer<dim>  &particle_transfer,
    TimerOutput                  &timer)
    : material_points(material_points)
    , shape_functions(shape_functions)
    , system(system)
    , mass_matrix(mass_matrix)
    , nodal_update(nodal_update)
    , grid_motion(grid_motion)
    , materials(materials)
    , problem(problem)
    , boundary_conditions(boundary_conditions)
    , damping(damping)
    , locking_remedy(locking_remedy)
    , softening_regularisation(softening_regularisation)
    , particle_transfer(particle_transfer)
    , timer(timer)
  {}



  template <int dim>
  void
  TimeStepper<dim>::advance(const double time, const double dt)
  {
    {
      TimerOutput::Scope scope(timer, "shape functions");
      shape_functions.evaluate(material_points, system.partitioner(), data);
    }
    {
      TimerOutput::Scope scope(timer, "particle to grid");
      system.assemble(material_points,
                      data,
                      problem,
                      time,
                      !grid_motion.tractions_on_grid_faces());
      particle_transfer.add_affine_momentum(material_points, data, system);
      grid_motion.add_face_tractions(problem, time, system);
      system.finish_assembly();
      boundary_conditions.add_loads(system, time, dt);
      if (damping.is_active(time))
        damping.apply(system);
      mass_matrix.assemble(system, data);
    }
    if (nodal_update.needs_nodal_accelerations())
      {
        TimerOutput::Scope scope(timer, "solve");
        boundary_conditions.make_acceleration_constraints(
          system,
          time,
          dt,
          acceleration_constraints);
        for (unsigned int c = 0; c < dim; ++c)
          mass_matrix.solve(system,
                            data,
                            system.force[c],
                            system.acceleration[c],
                            acceleration_constraints[c]);
        boundary_conditions.correct_accelerations(system,
                                                  mass_matrix,
                                                  material_points,
                                                  data,
                                                  time,
                                                  dt);
        for (unsigned int c = 0; c < dim; ++c)
          system.acceleration[c].update_ghost_values();
      }
    using ParticleVelocity = typename NodalUpdate<dim>::ParticleVelocity;
    const ParticleVelocity particle_velocity = nodal_update.particle_velocity();
    {
      TimerOutput::Scope scope(timer, "solve");
      boundary_conditions.make_velocity_constraints(system,
                                                    time + dt,
                                                    velocity_constraints);
    }
    if (particle_velocity ==
        ParticleVelocity::from_acceleration_before_projection)
      {
        if (particle_transfer.flip_fraction() < 1.)
          {
            // PIC's part of the points' new velocities interpolates the
            // nodal velocities of the grid's own update, M^-1 q + dt a
            // (USL's), before MUSL projects the points' momenta.
            TimerOutput::Scope scope(timer, "solve");
            grid_velocities.compute_nodal_velocities(system,
                                                     mass_matrix,
                                                     material_points,
                                                     particle_transfer,
                                                     data,
                                                     velocity_constraints,
                                                     dt,
                                                     dt);
            boundary_conditions.correct_velocities(system, time + dt);
            for (unsigned int c = 0; c < dim; ++c)
              system.velocity[c].update_ghost_values();
          }
        TimerOutput::Scope scope(timer, "grid to particle");
        advance_particle_velocities(dt);
      }
    {
      TimerOutput::Scope scope(timer, "solve");
      nodal_update.compute_nodal_velocities(system,
                                            mass_matrix,
                                            material_points,
                                            particle_transfer,
                                            data,
                                            velocity_constraints,
                                            dt,
                                            previous_dt > 0. ? previous_dt :
                                                               dt);
      boundary_conditions.correct_velocities(system, time + dt);
      for (unsigned int c = 0; c < dim; ++c)
        system.velocity[c].update_ghost_values();
    }
    {
      TimerOutput::Scope scope(timer, "grid to particle");
      if (particle_transfer.flip_fraction() == 1.)
        update_particles<false>(dt, particle_velocity);
      else
        update_particles<true>(dt, particle_velocity);
    }
    {
      TimerOutput::Scope scope(timer, "move grid, locate particles");
      grid_motion.advance(system, material_points, dt);
    }
    // The positive part of the step's work on all ranks together, held by
    // the first rank, so that the sum over the ranks does not depend on
    // their number.
    const MPI_Comm communicator = system.lumped_mass.get_mpi_communicator();
    const double   external_work =
      Utilities::MPI::sum(system.external_work(dt), communicator);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      work_supplied += std::max(external_work, 0.);
    work_supplied += boundary_conditions.take_work_of_prescribed_velocities();
    previous_dt = dt;
  }



  template <int dim>
  void
  TimeStepper<dim>::advance_particle_velocities(const double dt)
  {
    using Layout = PropertyLayout<dim>;
    const double *a[dim];
    const double *v[dim];
    for (unsigned int c = 0; c < dim; ++c)
      {
        a[c] = system.acceleration[c].get_values();
        v[c] = system.velocity[c].get_values();
      }
    const double flip_fraction = particle_transfer.flip_fraction();
    const bool   affine        = particle_transfer.is_affine();
    std::vector<Tensor<1, dim>>             point_nodal_velocities;
    typename ParticleShapeData<dim>::Cursor functions(data);
    for (auto &particle : material_points.particle_handler())
      {
        const auto properties = particle.get_properties();
        const auto point      = functions.next();
        if (flip_fraction == 1.)
          {
            for (unsigned int j = 0; j < point.n; ++j)
              for (unsigned int c = 0; c < dim; ++c)
                properties[Layout::velocity + c] +=
                  dt * point.values[j] * a[c][point.indices[j]];
            continue;
          }
        // FLIP's and PIC's velocities, blended; the nodal velocities are
        // the grid's own (advance()).
        Tensor<1, dim> flip = Layout::get_vector(properties, Layout::velocity);
        Tensor<1, dim> pic;
        if (point_nodal_velocities.size() < point.n)
          point_nodal_velocities.resize(point.n);
        for (unsigned int j = 0; j < point.n; ++j)
          for (unsigned int c = 0; c < dim; ++c)
            {
              const unsigned int i = point.indices[j];
              flip[c] += dt * point.values[j] * a[c][i];
              pic[c] += point.values[j] * v[c][i];
              point_nodal_velocities[j][c] = v[c][i];
            }
        Layout::set_vector(properties,
                           Layout::velocity,
                           flip_fraction * flip + (1. - flip_fraction) * pic);
        if (affine)
          particle_transfer.store_affine_velocity(
            properties,
            particle.get_location(),
            point,
            point_nodal_velocities.data());
      }
  }



  template <int dim>
  inline bool
  TimeStepper<dim>::update_deformation_and_stress(
    const ArrayView<double> &properties,
    const Tensor<2, dim>    &velocity_gradient,
    const double             dt) const
  {
    using Layout     = PropertyLayout<dim>;
    Tensor<2, dim> F = Layout::get_deformation_gradient(properties);
    F = (unit_symmetric_tensor<dim>() + dt * velocity_gradient) * F;
    Layout::set_deformation_gradient(properties, F);

    const unsigned int id    = Layout::get_material_id(properties);
    StressState<dim>   state = materials.stress_state(id, properties);
    materials[id].update_stress(F, velocity_gradient, dt, state);
    materials.store(state, properties);

    const double check =
      state.stress.norm() +
      Layout::get_vector(properties, Layout::velocity).norm() +
      Layout::volume(properties);
    return std::isfinite(check) && determinant(F) > 0.;
  }



  template <int dim>
  template <bool other_rule>
  void
  TimeStepper<dim>::update_particles(
    const double                                      dt,
    const typename NodalUpdate<dim>::ParticleVelocity particle_velocity)
  {
    using Layout = PropertyLayout<dim>;
    const double *v[dim];
    const double *a[dim];
    for (unsigned int c = 0; c < dim; ++c)
      {
        v[c] = system.velocity[c].get_values();
        a[c] = system.acceleration[c].get_values();
      }
    const bool velocity_from_acceleration =
      particle_velocity ==
      NodalUpdate<dim>::ParticleVelocity::from_acceleration;
    const bool velocity_from_displacement =
      particle_velocity ==
      NodalUpdate<dim>::ParticleVelocity::from_displacement;
    // FLIP's share alpha of the new velocity (the rest is PIC's) and APIC.
    const double flip_fraction = particle_transfer.flip_fraction();
    const bool   affine        = particle_transfer.is_affine();

    // The velocity of each point and its velocity gradient; the point moves
    // with the velocity. Without a remedy the point's F and stress follow
    // at once; with one, after it has changed all points' gradients.
    types::particle_index bad_point = numbers::invalid_unsigned_int;
    Point<dim>            bad_location;
    const auto            update_state = [&](const auto              &particle,
                                  const ArrayView<double> &properties,
                                  const Tensor<2, dim>    &velocity_gradient) {
      if (!update_deformation_and_stress(properties, velocity_gradient, dt) &&
          bad_point == numbers::invalid_unsigned_int)
        {
          bad_point    = particle.get_id();
          bad_location = particle.get_location();
        }
    };
    velocity_gradients.resize(locking_remedy ? data.n_particles() : 0);
    point_properties.resize(velocity_gradients.size());
    {
      // The nodal velocities and accelerations of a batch's functions,
      // gathered once for the points of the batch.
      std::vector<Tensor<1, dim>>             batch_velocity;
      std::vector<Tensor<1, dim>>             batch_acceleration;
      const unsigned int                     *batch_functions = nullptr;
      typename ParticleShapeData<dim>::Cursor functions(data);
      unsigned int                            p = 0;
      for (auto &particle : material_points.particle_handler())
        {
          const auto     properties = particle.get_properties();
          Tensor<1, dim> point_velocity;
          Tensor<2, dim> velocity_gradient;
          // The particle's velocity, advanced in the order of
          // advance_particle_velocities() (the same round-off).
          Tensor<1, dim> advanced_velocity;
          if (velocity_from_acceleration)
            advanced_velocity =
              Layout::get_vector(properties, Layout::velocity);
          const auto point = functions.next();
          if (point.indices != batch_functions)
            {
              batch_functions = point.indices;
              if (batch_velocity.size() < point.n)
                {
                  batch_velocity.resize(point.n);
                  batch_acceleration.resize(point.n);
                }
              for (unsigned int j = 0; j < point.n; ++j)
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    batch_velocity[j][c]     = v[c][point.indices[j]];
                    batch_acceleration[j][c] = a[c][point.indices[j]];
                  }
            }
          for (unsigned int j = 0; j < point.n; ++j)
            {
              const Tensor<1, dim> &grad = point.gradients[j];
              for (unsigned int c = 0; c < dim; ++c)
                {
                  point_velocity[c] += point.values[j] * batch_velocity[j][c];
                  velocity_gradient[c] += batch_velocity[j][c] * grad;
                }
              if (velocity_from_acceleration)
                for (unsigned int c = 0; c < dim; ++c)
                  advanced_velocity[c] +=
                    dt * point.values[j] * batch_acceleration[j][c];
            }
          if (velocity_from_acceleration)
            {
              if constexpr (!other_rule)
                Layout::set_vector(properties,
                                   Layout::velocity,
                                   advanced_velocity);
              else
                {
                  Layout::set_vector(properties,
                                     Layout::velocity,
                                     flip_fraction * advanced_velocity +
                                       (1. - flip_fraction) * point_velocity);
                  if (affine)
                    particle_transfer.store_affine_velocity(
                      properties,
                      particle.get_location(),
                      point,
                      batch_velocity.data());
                }
            }
          else if (velocity_from_displacement)
            Layout::set_vector(properties, Layout::velocity, point_velocity);
          particle.set_location(particle.get_location() + dt * point_velocity);
          if (locking_remedy)
            {
              velocity_gradients[p] = velocity_gradient;
              point_properties[p++] = properties;
            }
          else
            update_state(particle, properties, velocity_gradient);
        }
    }

    if (locking_remedy)
      {
        locking_remedy->correct(material_points, data, dt, velocity_gradients);
        // The points' property arrays of the first pass, so that the
        // particle handler is not walked again; a failing point is found
        // by its number.
        unsigned int bad_number = numbers::invalid_unsigned_int;
        for (unsigned int p = 0; p < point_properties.size(); ++p)
          if (!update_deformation_and_stress(point_properties[p],
                                             velocity_gradients[p],
                                             dt) &&
              bad_number == numbers::invalid_unsigned_int)
            bad_number = p;
        if (bad_number != numbers::invalid_unsigned_int)
          {
            auto particle = material_points.particle_handler().begin();
            std::advance(particle, bad_number);
            bad_point    = particle->get_id();
            bad_location = particle->get_location();
          }
        locking_remedy->after_stress_update(material_points);
      }
    if (softening_regularisation)
      softening_regularisation->update(material_points, data);

    std::string problem;
    if (bad_point != numbers::invalid_unsigned_int)
      {
        std::ostringstream message;
        message << "material point " << bad_point << " at (" << bad_location
                << ") has a non-finite velocity, stress "
                << "or volume, or an inverted deformation (det F <= 0). ";
        problem = message.str();
      }
    stop_if_any_rank_failed(system.lumped_mass.get_mpi_communicator(),
                            problem,
                            "The computation became unstable: ",
                            EnergyMonitor<dim>::advice());
  }



  template <int dim>
  double
  TimeStepper<dim>::supplied_work() const
  {
    return work_supplied;
  }



  template <int dim>
  void
  TimeStepper<dim>::save(CheckpointState &state) const
  {
    state.set_shared("time stepper/previous time step", {previous_dt});
    state.set_own("time stepper/supplied work", {work_supplied});
  }



  template <int dim>
  void
  TimeStepper<dim>::load(const CheckpointState &state)
  {
    previous_dt   = state.shared("time stepper/previous time step").at(0);
    work_supplied = state.share_of_sums("time stepper/supplied work").at(0);
  }



  template class TimeStepper<1>;
  template class TimeStepper<2>;
  template class TimeStepper<3>;
} // namespace MpmOtm
