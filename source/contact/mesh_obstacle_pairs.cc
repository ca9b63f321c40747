// The corner-face and edge-edge pairs between meshed obstacles and the
// body's boundary: the obstacles' sharp features, the body's boundary as
// this rank sees it, broad phase, pair barriers, assembly and CCD.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/rtree.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/contact/barrier_settings.h>
#include <hyperelastic/contact/collision_detection.h>
#include <hyperelastic/contact/mesh_obstacle_pairs.h>
#include <hyperelastic/contact/obstacle_surface.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/mesh/mesh_distribution.h>

#include <algorithm>
#include <iterator>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  bool
  MeshObstaclePairs<dim>::wanted(const ContactParameters &parameters)
  {
    if (!parameters.meshed_obstacle_corners)
      return false;
    return std::any_of(parameters.obstacles.begin(),
                       parameters.obstacles.end(),
                       [](const ObstacleParameters &o) {
                         return o.type == ObstacleType::mesh;
                       });
  }

  template <int dim>
  MeshObstaclePairs<dim>::MeshObstaclePairs(
    const ContactParameters                                        &parameters,
    const std::map<std::string, double>                            &constants,
    const DoFHandler<dim>                                          &dof_handler,
    const std::vector<std::shared_ptr<const ObstacleSurface<dim>>> &surfaces,
    const BarrierSettings                                          &settings)
      : comm(dof_handler.get_communicator())
      , my_subdomain(dof_handler.get_triangulation().locally_owned_subdomain())
      , d_hat(settings.d_hat)
      , kappa(settings.kappa)
      , stiffness(settings.kappa, settings.adaptive_kappa)
  {
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    ghost_buffer.reinit(dof_handler.locally_owned_dofs(), relevant, comm);
    for (const ObstacleParameters &o : parameters.obstacles)
      if (o.type == ObstacleType::mesh)
        motions.push_back(parse_vector_function<dim>(o.motion,
                                                     constants,
                                                     o.subsection + "/Motion"));
    find_features(parameters, surfaces);
    gather_body(dof_handler);
    check_start();
  }

  template <int dim>
  MeshObstaclePairs<dim>::~MeshObstaclePairs() = default;

  template <int dim>
  typename MeshObstaclePairs<dim>::Placement
  MeshObstaclePairs<dim>::placement(const unsigned int m,
                                    const double       time) const
  {
    const auto motion = [&](const double s) {
      motions[m]->set_time(s);
      Tensor<1, dim> w;
      for (unsigned int d = 0; d < dim; ++d)
        w[d] = motions[m]->value(Point<dim>(), d);
      return w;
    };
    Placement p;
    p.shift = motion(time) - motion(0.);
    return p;
  }

  template <int dim>
  std::vector<Point<dim>>
  MeshObstaclePairs<dim>::obstacle_at(const double time) const
  {
    std::vector<Placement> where;
    for (unsigned int m = 0; m < motions.size(); ++m)
      where.push_back(placement(m, time));
    std::vector<Point<dim>> y(obstacle_points.size());
    for (unsigned int i = 0; i < y.size(); ++i)
      y[i] = where[point_obstacle[i]](obstacle_points[i]);
    return y;
  }

  template <int dim>
  const VectorType &
  MeshObstaclePairs<dim>::ghosted(const VectorType &v) const
  {
    if (v.has_ghost_elements())
      return v;
    ghost_buffer = v;
    return ghost_buffer;
  }

  template <int dim>
  std::vector<Point<dim>>
  MeshObstaclePairs<dim>::body_at(const VectorType &u_in) const
  {
    const VectorType       &u = ghosted(u_in);
    std::vector<Point<dim>> x(vertices.size());
    for (unsigned int i = 0; i < vertices.size(); ++i)
      {
        x[i] = vertices[i].X;
        for (unsigned int d = 0; d < dim; ++d)
          x[i][d] += u(vertices[i].dofs[d]);
        if (clock.end_state.c != 1.)
          x[i] = clock.end_state.end_position(start_positions[i], x[i]);
      }
    return x;
  }

  template <int dim>
  std::array<int, MeshObstaclePairs<dim>::n_points>
  MeshObstaclePairs<dim>::body_points(const Pair &pair) const
  {
    std::array<int, n_points> b;
    b.fill(-1);
    if (pair.edge_edge)
      {
        b[0] = edges[pair.body].v[0];
        b[1] = edges[pair.body].v[1];
      }
    else
      for (unsigned int i = 0; i < dim; ++i)
        b[i + 1] = faces[pair.body].v[i];
    return b;
  }

  template <int dim>
  std::array<int, MeshObstaclePairs<dim>::n_points>
  MeshObstaclePairs<dim>::obstacle_points_of(const Pair &pair) const
  {
    std::array<int, n_points> o;
    o.fill(-1);
    if (pair.edge_edge)
      {
        o[2] = ridges[pair.feature].v[0];
        o[3] = ridges[pair.feature].v[1];
      }
    else
      o[0] = corners[pair.feature].v[0];
    return o;
  }

  template <int dim>
  typename MeshObstaclePairs<dim>::Coordinates
  MeshObstaclePairs<dim>::coordinates(const Pair                    &pair,
                                      const std::vector<Point<dim>> &x,
                                      const std::vector<Point<dim>> &y) const
  {
    const auto  b = body_points(pair), o = obstacle_points_of(pair);
    Coordinates c;
    for (unsigned int i = 0; i < n_points; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        c[i * dim + d] = b[i] >= 0 ? x[b[i]][d] : y[o[i]][d];
    return c;
  }

  template <int dim>
  std::vector<typename MeshObstaclePairs<dim>::Pair>
  MeshObstaclePairs<dim>::candidates(const std::vector<Point<dim>>     &x,
                                     const std::vector<Point<dim>>     &y,
                                     const std::vector<Tensor<1, dim>> *p,
                                     const std::vector<Tensor<1, dim>> *q,
                                     const double                       margin,
                                     const bool counted_only) const
  {
    const auto box_of = [](const auto                        &indices,
                           const std::vector<Point<dim>>     &z,
                           const std::vector<Tensor<1, dim>> *motion,
                           const double                       extend) {
      BoundingBox<dim> box(std::make_pair(z[indices[0]], z[indices[0]]));
      for (const unsigned int i : indices)
        {
          box.merge_with(BoundingBox<dim>(std::make_pair(z[i], z[i])));
          if (motion)
            {
              const Point<dim> end = z[i] + (*motion)[i];
              box.merge_with(BoundingBox<dim>(std::make_pair(end, end)));
            }
        }
      box.extend(extend);
      return box;
    };
    const auto takes = [&](const auto &primitive) {
      if (counted_only)
        return primitive.counted;
      return std::any_of(primitive.v.begin(),
                         primitive.v.end(),
                         [&](const unsigned int v) {
                           return vertices[v].owned;
                         }) ||
             primitive.counted;
    };
    using Entry = std::pair<BoundingBox<dim>, unsigned int>;
    std::vector<Pair>  result;
    std::vector<Entry> found;
    const auto         search = [&](const std::vector<Feature> &features,
                            const unsigned int          n,
                            const auto                 &bodies,
                            const bool                  edge_edge) {
      if (features.empty() || bodies.empty())
        return;
      std::vector<Entry> entries;
      for (unsigned int f = 0; f < features.size(); ++f)
        entries.emplace_back(
          box_of(std::vector<unsigned int>(features[f].v.begin(),
                                           features[f].v.begin() + n),
                 y,
                 q,
                 0.),
          f);
      const RTree<Entry> tree = pack_rtree(entries);
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          if (!takes(bodies[b]))
            continue;
          found.clear();
          tree.query(boost::geometry::index::intersects(
                       box_of(bodies[b].v, x, p, margin)),
                     std::back_inserter(found));
          for (const auto &[box, f] : found)
            result.push_back({edge_edge, b, f});
        }
    };
    search(corners, 1, faces, false);
    if constexpr (dim == 3)
      search(ridges, 2, edges, true);
    return result;
  }

  template <int dim>
  template <typename F>
  bool
  MeshObstaclePairs<dim>::for_each_active(const VectorType  &u,
                                          const double       t,
                                          const unsigned int order,
                                          const F           &f,
                                          double            *min_distance) const
  {
    const std::vector<Point<dim>> x = body_at(u);
    const std::vector<Point<dim>> y = obstacle_at(clock.obstacle_time(t));
    PairScan                      scan(d_hat);
    for (const Pair &pair : candidates(x, y, nullptr, nullptr, d_hat, false))
      {
        const Coordinates  c      = coordinates(pair, x, y);
        const DistanceCase k      = classify_pair<dim>(c, pair.edge_edge);
        double             weight = 0., mollifier = 0.;
        if (!pair.edge_edge)
          weight = corners[pair.feature].area;
        else
          {
            weight = 0.5 * (edges[pair.body].area + ridges[pair.feature].area);
            mollifier =
              1e-3 * edges[pair.body].length2 * ridges[pair.feature].length2;
          }
        PairBarrier<n_coordinates> b =
          pair_barrier<dim>(c, k, d_hat, kappa * weight, mollifier, order);
        if (!scan.active(b.distance))
          continue;
        to_solved_state(b, clock.end_state, order);
        f(pair, b);
      }
    if (min_distance)
      *min_distance = scan.closest;
    return scan.touching;
  }

  template <int dim>
  void
  MeshObstaclePairs<dim>::check_start() const
  {
    // No sharp feature of an obstacle on or through the body's boundary at
    // t = 0 (distance 0 to a face or edge).
    const std::vector<Point<dim>> y = obstacle_at(0.);
    std::vector<Point<dim>>       X(vertices.size());
    for (unsigned int i = 0; i < vertices.size(); ++i)
      X[i] = vertices[i].X;
    std::string problem;
    for (const Pair &pair : candidates(X, y, nullptr, nullptr, 0., true))
      {
        const Coordinates c = coordinates(pair, X, y);
        const double      d = std::sqrt(std::max(
          squared_distance<dim>(classify_pair<dim>(c, pair.edge_edge), c), 0.));
        if (d > 0.)
          continue;
        const unsigned int m = pair.edge_edge ? ridges[pair.feature].obstacle
                                              : corners[pair.feature].obstacle;
        std::ostringstream s;
        s << "the obstacle of '" << sections[m] << "' starts on the body's "
          << "boundary: its " << (pair.edge_edge ? "edge" : "vertex") << " at ("
          << y[obstacle_points_of(pair)[pair.edge_edge ? 2 : 0]]
          << ") touches a boundary " << (pair.edge_edge ? "edge" : "face")
          << " of the body at t = 0";
        problem = s.str();
        break;
      }
    throw_input_error_of_first_rank(problem, comm);
  }

  template <int dim>
  typename MeshObstaclePairs<dim>::Stencil
  MeshObstaclePairs<dim>::stencil(const Pair                      &pair,
                                  const AffineConstraints<double> *constraints,
                                  const std::vector<Tensor<1, dim>> *rest) const
  {
    const auto body = body_points(pair), obstacle = obstacle_points_of(pair);
    Stencil    s;
    for (unsigned int i = 0; i < n_points; ++i)
      if (body[i] >= 0)
        s.set_vertex(i,
                     vertices[body[i]].dofs,
                     vertices[body[i]].owned,
                     constraints);
      else
        s.set_obstacle_point(i, rest ? (*rest)[obstacle[i]] : Tensor<1, dim>());
    return s;
  }

  template <int dim>
  std::string
  MeshObstaclePairs<dim>::touching_message(const double t)
  {
    return "a corner or edge of a meshed obstacle touches the body's "
           "boundary at t = " +
           std::to_string(t);
  }

  template <int dim>
  bool
  MeshObstaclePairs<dim>::visit(const VectorType             &u,
                                const double                  t,
                                const typename Sums::Request &request) const
  {
    // The rest of the obstacles' way within the step, per obstacle point:
    // the linearization carries it as a prescribed motion of the pairs'
    // obstacle points (end-state coordinates, hence / c).
    std::vector<Tensor<1, dim>> rest(obstacle_points.size());
    if (request.order == 2 && clock.on_the_way(t))
      {
        const std::vector<Point<dim>> now = obstacle_at(clock.reached),
                                      end = obstacle_at(clock.end_time(t));
        for (unsigned int i = 0; i < rest.size(); ++i)
          rest[i] = (end[i] - now[i]) / clock.end_state.c;
      }
    return for_each_active(
      u, t, request.order, [&](const Pair &pair, const auto &b) {
        request.take(stencil(pair, request.constraints, &rest),
                     b,
                     counted(pair),
                     true);
      });
  }

  template <int dim>
  double
  MeshObstaclePairs<dim>::largest_feasible_step(const VectorType &u,
                                                const VectorType &direction_in,
                                                const double      t) const
  {
    const auto                    scope = timed_section(timer, "contact");
    const std::vector<Point<dim>> x     = body_at(u);
    // The body's motion (end state) and the obstacles' from where they
    // stand to their place at t.
    const VectorType           &direction = ghosted(direction_in);
    std::vector<Tensor<1, dim>> p(vertices.size());
    for (unsigned int i = 0; i < vertices.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        p[i][d] = clock.end_state.c * direction(vertices[i].dofs[d]);
    const std::vector<Point<dim>> y = obstacle_at(clock.obstacle_time(t));
    std::vector<Tensor<1, dim>>   q(y.size());
    if (clock.on_the_way(t))
      {
        const std::vector<Point<dim>> end = obstacle_at(clock.end_time(t));
        for (unsigned int i = 0; i < y.size(); ++i)
          q[i] = end[i] - y[i];
      }
    double alpha = 1.;
    for (const Pair &pair : candidates(x, y, &p, &q, d_hat, true))
      {
        const Coordinates c    = coordinates(pair, x, y);
        const auto        body = body_points(pair),
                   obstacle    = obstacle_points_of(pair);
        Coordinates motion;
        for (unsigned int i = 0; i < n_points; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            motion[i * dim + d] =
              body[i] >= 0 ? p[body[i]][d] : q[obstacle[i]][d];
        alpha = std::min(
          alpha,
          additive_ccd<dim>(
            c, motion, pair.edge_edge, ccd_keep_fraction, alpha)
            .t);
      }
    return Utilities::MPI::min(alpha, comm);
  }

  template <int dim>
  void
  MeshObstaclePairs<dim>::begin_step(const VectorType &u, const double t_start)
  {
    clock.begin_step(t_start);
    start_positions = body_at(u);
    // kappa at a sound operating point for the step to come, from the
    // converged state's smallest distance (BarrierStiffness).
    if (stiffness.adaptive() &&
        stiffness.retarget(measure(u, t_start).min_distance / d_hat))
      kappa = stiffness.value();
  }

  template <int dim>
  ContactMeasures
  MeshObstaclePairs<dim>::measure(const VectorType &u, const double t) const
  {
    std::vector<Tensor<1, dim>> force(numbers.size());
    std::vector<Tensor<1, 3>>   moment(numbers.size());
    unsigned int                active  = 0;
    double                      closest = d_hat;
    // Moments about each obstacle's point where it stands, the forces on
    // the body at its deformed vertices (the pair's energy depends on
    // distances only: minus the moment of its forces on the obstacle's
    // vertices).
    const std::vector<Point<dim>> x = body_at(u);
    std::vector<Point<dim>>       centre;
    for (unsigned int k = 0; k < numbers.size(); ++k)
      centre.push_back(placement(k, clock.obstacle_time(t))(anchors[k]));
    for_each_active(
      u,
      t,
      1,
      [&](const Pair &pair, const auto &b) {
        active += counted(pair) ? 1 : 0;
        const unsigned int m    = pair.edge_edge ? ridges[pair.feature].obstacle
                                                 : corners[pair.feature].obstacle;
        const auto         body = body_points(pair);
        for (unsigned int i = 0; i < n_points; ++i)
          if (body[i] >= 0 && vertices[body[i]].owned)
            {
              Tensor<1, dim> f;
              for (unsigned int d = 0; d < dim; ++d)
                f[d] = -b.gradient[i * dim + d];
              force[m] += f;
              moment[m] += moment_of<dim>(x[body[i]] - centre[m], f);
            }
      },
      &closest);
    ContactMeasures measures;
    measures.add_obstacles<dim>(numbers, force, moment, comm);
    measures.set_pairs(closest, active, comm);
    return measures;
  }

  template class MeshObstaclePairs<2>;
  template class MeshObstaclePairs<3>;
} // namespace hyperelastic
