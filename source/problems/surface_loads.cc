#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <mpm_otm/base/collective_error.h>
#include <mpm_otm/base/parsed_expression.h>
#include <mpm_otm/base/read_point.h>
#include <mpm_otm/base/subsection_names.h>
#include <mpm_otm/material_points/material_points.h>
#include <mpm_otm/material_points/property_layout.h>
#include <mpm_otm/materials/material_library.h>
#include <mpm_otm/problems/surface_loads.h>

#include <cmath>
#include <sstream>

namespace MpmOtm
{
  namespace
  {
    /**
     * "(x, y, z)" for messages.
     */
    template <int dim>
    std::string
    to_text(const Point<dim> &point)
    {
      std::ostringstream text;
      text << '(';
      for (unsigned int d = 0; d < dim; ++d)
        text << (d > 0 ? ", " : "") << point[d];
      text << ')';
      return text.str();
    }
  } // namespace



  template <int dim>
  SurfaceLoads<dim>::SurfaceLoads() = default;



  template <int dim>
  SurfaceLoads<dim>::~SurfaceLoads() = default;



  template <int dim>
  void
  SurfaceLoads<dim>::declare_parameters(ParameterHandler               &prm,
                                        const std::vector<std::string> &names)
  {
    const std::string zeros = (dim == 1 ? "0" : dim == 2 ? "0; 0" : "0; 0; 0");
    for (const auto &name : names)
      {
        prm.enter_subsection("Surface load " + name);
        prm.declare_entry(
          "From",
          "",
          Patterns::List(Patterns::Double(), 0, dim),
          "One end of the loaded part of a body's initial surface: in 2D a "
          "segment From-To (any inclination), in 3D the axis-parallel "
          "rectangle with the opposite corners From and To (they agree in "
          "the coordinate normal to it), in 1D the point From = To.");
        prm.declare_entry("To",
                          "",
                          Patterns::List(Patterns::Double(), 0, dim),
                          "The other end (see From).");
        prm.declare_entry(
          "Pressure",
          "0",
          Patterns::Anything(),
          "Pressure (Pa, positive pushes into the body) on the part: an "
          "expression in the initial position (x, y, z) and time t. It "
          "acts normal to the surface as it deforms, on its current area.");
        prm.declare_entry(
          "Traction",
          zeros,
          Patterns::Anything(),
          "Traction (force per unit initial length in 2D, area in 3D) of "
          "fixed direction, a dead load: dim expressions in the initial "
          "position (x, y, z) and time t, separated by ';'. Acts in "
          "addition to the pressure.");
        prm.leave_subsection();
      }
  }



  template <int dim>
  void
  SurfaceLoads<dim>::parse_parameters(ParameterHandler &prm)
  {
    load_names = SubsectionNames::names_in(prm, "Surface loads");
    loads.clear();
    for (const auto &name : load_names)
      {
        const std::string path = "Surface load " + name + "/";
        prm.enter_subsection("Surface load " + name);
        Load load;
        load.name = name;
        load.from = read_point<dim>(prm.get("From"), path + "From");
        load.to   = read_point<dim>(prm.get("To"), path + "To");
        load.pressure =
          std::make_unique<ParsedExpression<dim>>(prm.get("Pressure"),
                                                  1,
                                                  true,
                                                  path + "Pressure");
        load.traction =
          std::make_unique<ParsedExpression<dim>>(prm.get("Traction"),
                                                  dim,
                                                  true,
                                                  path + "Traction");
        prm.leave_subsection();
        AssertThrow(!load.pressure->is_zero() || !load.traction->is_zero(),
                    ExcMessage(path +
                               "Pressure and Traction are both 0: give the "
                               "load, or remove " +
                               name + " from Surface loads."));

        const Tensor<1, dim> span = load.to - load.from;
        if constexpr (dim == 1)
          {
            AssertThrow(span.norm() == 0.,
                        ExcMessage(path + "From and To: in 1D the loaded "
                                          "surface is a point, From = To."));
            load.normal[0] = 1.;
            load.measure   = 1.;
          }
        else if constexpr (dim == 2)
          {
            load.measure = span.norm();
            AssertThrow(load.measure > 0.,
                        ExcMessage(path + "From and To are the same point: "
                                          "the loaded part of the surface is "
                                          "the segment between them."));
            load.normal[0] = -span[1] / load.measure;
            load.normal[1] = span[0] / load.measure;
          }
        else
          {
            unsigned int n_flat = 0;
            load.measure        = 1.;
            for (unsigned int d = 0; d < dim; ++d)
              if (span[d] == 0.)
                {
                  ++n_flat;
                  load.normal[d] = 1.;
                }
              else
                load.measure *= std::abs(span[d]);
            AssertThrow(n_flat == 1,
                        ExcMessage(path +
                                   "From and To: in 3D the loaded part of "
                                   "the surface is an axis-parallel "
                                   "rectangle with the opposite corners From "
                                   "and To, which agree in exactly one "
                                   "coordinate (the one normal to it); "
                                   "they agree in " +
                                   std::to_string(n_flat) + "."));
          }
        loads.push_back(std::move(load));
      }
  }



  template <int dim>
  bool
  SurfaceLoads<dim>::empty() const
  {
    return loads.empty();
  }



  template <int dim>
  const std::vector<std::string> &
  SurfaceLoads<dim>::names() const
  {
    return load_names;
  }



  template <int dim>
  void
  SurfaceLoads<dim>::reserve_point_variables(MaterialLibrary<dim> &materials)
  {
    if (loads.empty())
      return;
    std::vector<std::string> variables = {"surface_load"};
    for (const std::string vector : {"surface_area_", "surface_offset_"})
      for (unsigned int d = 0; d < dim; ++d)
        variables.push_back(vector + "xyz"[d]);
    first_slot = materials.add_point_variables(variables);
  }



  template <int dim>
  bool
  SurfaceLoads<dim>::beside(const Load &load, const Point<dim> &X) const
  {
    const double tolerance = 1e-12 * (1. + load.measure);
    if constexpr (dim == 2)
      {
        const Tensor<1, dim> span  = load.to - load.from;
        const double         along = (X - load.from) * span / load.measure;
        return along >= -tolerance && along <= load.measure + tolerance;
      }
    else if constexpr (dim == 3)
      {
        for (unsigned int d = 0; d < dim; ++d)
          if (load.normal[d] == 0. &&
              (X[d] < std::min(load.from[d], load.to[d]) - tolerance ||
               X[d] > std::max(load.from[d], load.to[d]) + tolerance))
            return false;
        return true;
      }
    else
      return true;
  }



  template <int dim>
  void
  SurfaceLoads<dim>::assign_points(MaterialPoints<dim> &points) const
  {
    using Layout = PropertyLayout<dim>;
    if (loads.empty())
      return;
    const MPI_Comm communicator = points.communicator();

    // The outermost layer beside a region: the points within one point
    // spacing h_p = (V_p^0)^(1/dim) of its plane; the side they are on
    // gives the outward normal, their weights V_p^0 / h_p (the surface
    // share of a point of a regular pattern) are scaled to sum to the
    // region's measure.
    const auto spacing = [](const ArrayView<const double> &properties) {
      return std::pow(properties[Layout::initial_volume], 1. / dim);
    };
    std::vector<double> sums(3 * loads.size());
    for (const auto &particle : points.particle_handler())
      {
        const auto       properties = particle.get_properties();
        const Point<dim> X(
          Layout::get_vector(properties, Layout::initial_position));
        const double h = spacing(properties);
        for (unsigned int k = 0; k < loads.size(); ++k)
          {
            const double distance = (X - loads[k].from) * loads[k].normal;
            if (std::abs(distance) < h && beside(loads[k], X))
              {
                sums[3 * k + (distance >= 0. ? 0 : 1)] += 1.;
                sums[3 * k + 2] += properties[Layout::initial_volume] / h;
              }
          }
      }
    Utilities::MPI::sum(sums, communicator, sums);

    std::vector<double> scale(loads.size());
    std::vector<double> outward(loads.size());
    for (unsigned int k = 0; k < loads.size(); ++k)
      {
        const Load       &load = loads[k];
        const std::string where =
          "Surface load " + load.name + "/From, To: the " +
          (dim == 1 ? "point " + to_text(load.from) :
           dim == 2 ? "segment from " + to_text(load.from) + " to " +
                        to_text(load.to) :
                      "rectangle from " + to_text(load.from) + " to " +
                        to_text(load.to));
        AssertThrow(sums[3 * k] + sums[3 * k + 1] > 0.,
                    ExcMessage(where +
                               " has no material point within one point "
                               "spacing of it: it is not on a body's "
                               "surface. Give a part of the initial "
                               "surface of a body."));
        AssertThrow(sums[3 * k] == 0. || sums[3 * k + 1] == 0.,
                    ExcMessage(where +
                               " has material points on both sides: it runs "
                               "through a body, not along its surface. Give a "
                               "part of the initial surface of a body."));
        AssertThrow(sums[3 * k + 2] >= 0.7 * load.measure,
                    ExcMessage(
                      where + " is covered by the points beside it for " +
                      std::to_string(static_cast<int>(
                        std::round(100. * sums[3 * k + 2] / load.measure))) +
                      " % of its " + (dim == 3 ? "area" : "length") +
                      ": part of it is off the body's surface (or it is "
                      "shorter than two point spacings). Give a part of the "
                      "initial surface of a body."));
        scale[k]   = load.measure / sums[3 * k + 2];
        outward[k] = (sums[3 * k] > 0.) ? -1. : 1.;
      }

    std::string problem;
    for (auto &particle : points.particle_handler())
      {
        const auto       properties = particle.get_properties();
        const Point<dim> X(
          Layout::get_vector(properties, Layout::initial_position));
        const double h         = spacing(properties);
        properties[first_slot] = 0.;
        for (unsigned int k = 0; k < loads.size(); ++k)
          {
            const double distance = (X - loads[k].from) * loads[k].normal;
            if (!(std::abs(distance) < h && beside(loads[k], X)))
              continue;
            if (properties[first_slot] > 0. && problem.empty())
              problem =
                "The material point that starts at " + to_text(X) +
                " lies beside Surface load " +
                loads[static_cast<unsigned int>(properties[first_slot]) - 1]
                  .name +
                " and Surface load " + loads[k].name +
                " (within one point spacing of both): a point carries one "
                "load; let the loads' regions keep apart by two point "
                "spacings.";
            const Tensor<1, dim> normal = outward[k] * loads[k].normal;
            properties[first_slot]      = k + 1;
            Layout::set_vector(
              properties,
              first_slot + 1,
              (scale[k] * properties[Layout::initial_volume] / h) * normal);
            Layout::set_vector(properties,
                               first_slot + 1 + dim,
                               std::abs(distance) * normal);
          }
      }
    stop_if_any_rank_failed(communicator, problem, "", "");
  }



  template <int dim>
  typename SurfaceLoads<dim>::PointLoad
  SurfaceLoads<dim>::load_on(const ArrayView<const double> &properties,
                             const double                   time) const
  {
    using Layout = PropertyLayout<dim>;
    const Load &load =
      loads[static_cast<unsigned int>(properties[first_slot]) - 1];
    const Point<dim> X(
      Layout::get_vector(properties, Layout::initial_position));
    const Tensor<1, dim> area = Layout::get_vector(properties, first_slot + 1);
    const Tensor<2, dim> F    = Layout::get_deformation_gradient(properties);
    PointLoad            result;
    if (load.acting && !load.pressure->is_zero())
      result.force -= load.pressure->value(X, time) * (cofactor(F) * area);
    if (load.acting && !load.traction->is_zero())
      result.force += area.norm() * load.traction->vector_value(X, time);
    result.offset = F * Layout::get_vector(properties, first_slot + 1 + dim);
    return result;
  }



  template <int dim>
  void
  SurfaceLoads<dim>::set_acting(const std::vector<bool> &acting)
  {
    AssertDimension(acting.size(), loads.size());
    for (unsigned int k = 0; k < loads.size(); ++k)
      loads[k].acting = acting[k];
  }



  template <int dim>
  std::vector<std::pair<Tensor<1, dim>, Tensor<1, dim>>>
  SurfaceLoads<dim>::forces_and_displacements(const MaterialPoints<dim> &points,
                                              const double time) const
  {
    using Layout = PropertyLayout<dim>;
    // Per load: the force, the share-weighted displacement and the shares.
    std::vector<double> sums(loads.size() * (2 * dim + 1));
    for (const auto &particle : points.particle_handler())
      {
        const auto properties = particle.get_properties();
        if (!carries_load(properties))
          continue;
        const unsigned int k =
          static_cast<unsigned int>(properties[first_slot]) - 1;
        const Tensor<1, dim> force = load_on(properties, time).force;
        const double         share =
          Layout::get_vector(properties, first_slot + 1).norm();
        const Tensor<1, dim> displacement =
          particle.get_location() -
          Point<dim>(Layout::get_vector(properties, Layout::initial_position));
        double *const sum = sums.data() + k * (2 * dim + 1);
        for (unsigned int d = 0; d < dim; ++d)
          {
            sum[d] += force[d];
            sum[dim + d] += share * displacement[d];
          }
        sum[2 * dim] += share;
      }
    Utilities::MPI::sum(sums, points.communicator(), sums);
    std::vector<std::pair<Tensor<1, dim>, Tensor<1, dim>>> result(loads.size());
    for (unsigned int k = 0; k < loads.size(); ++k)
      {
        const double *const sum = sums.data() + k * (2 * dim + 1);
        for (unsigned int d = 0; d < dim; ++d)
          {
            result[k].first[d]  = sum[d];
            result[k].second[d] = sum[dim + d] / sum[2 * dim];
          }
      }
    return result;
  }



  template <int dim>
  void
  SurfaceLoads<dim>::check_expressions(const MaterialPoints<dim> &points,
                                       const double               time) const
  {
    for (const auto &particle : points.particle_handler())
      if (carries_load(particle.get_properties()))
        load_on(particle.get_properties(), time);
  }



  template class SurfaceLoads<1>;
  template class SurfaceLoads<2>;
  template class SurfaceLoads<3>;
} // namespace MpmOtm
