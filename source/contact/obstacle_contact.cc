// The barrier contact and lagged friction of boundary vertices with rigid
// planes, spheres and surface meshes.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/contact/barrier.h>
#include <hyperelastic/contact/barrier_settings.h>
#include <hyperelastic/contact/friction.h>
#include <hyperelastic/contact/obstacle_contact.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/mesh/mesh_distribution.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  ObstacleContact<dim>::ObstacleContact(
    const ContactParameters             &parameters,
    const std::map<std::string, double> &constants,
    const DoFHandler<dim>               &dof_handler,
    const LameParameters                &moduli,
    const bool                           dynamic,
    const BarrierSettings               *shared)
      : obstacles(parameters.obstacles)
      , comm(dof_handler.get_communicator())
      , dynamic(dynamic)
      , lagging(parameters.friction_lagging_updates,
                parameters.friction_force_trigger)
  {
    for (const auto &o : obstacles)
      {
        motions.push_back(parse_vector_function<dim>(o.motion,
                                                     constants,
                                                     o.subsection + "/Motion"));
        angles.push_back(
          o.rotation_axis.empty()
            ? nullptr
            : parse_vector_function<dim>({o.rotation_angle},
                                         constants,
                                         o.subsection + "/Rotation angle"));
        surfaces.push_back(o.type == ObstacleType::mesh
                             ? std::make_shared<const ObstacleSurface<dim>>(
                                 o.file, o.subsection + "/File")
                             : nullptr);
      }

    const double        diagonal = std::sqrt(gather_vertices(dof_handler));
    std::vector<double> areas;
    for (const Vertex &v : vertices)
      areas.push_back(v.area);
    const double element_size = mean_element_size(areas, dim, true, comm);
    shared_settings =
      shared
        ? *shared
        : barrier_settings(parameters, diagonal, moduli, dynamic, element_size);
    d_hat_value = shared_settings.d_hat;
    kappa       = shared_settings.kappa;
    eps_setting = shared_settings.eps;
    stiffness   = BarrierStiffness(kappa, shared_settings.adaptive_kappa);

    check_start();
  }

  template <int dim>
  ObstacleContact<dim>::~ObstacleContact() = default;

  template <int dim>
  double
  ObstacleContact<dim>::gather_vertices(const DoFHandler<dim> &dof_handler)
  {
    // The boundary vertices whose dofs this rank owns (ghost cells too: an
    // owned vertex may lie only on a neighbour's boundary face); the faces
    // where the ghost layer ends are not the body's boundary.
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    std::map<types::global_dof_index, unsigned int>
               index; // first dof -> vertex
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::numeric_limits<double>::max();
        upper[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = std::min(lower[d], cell->vertex(v)[d]);
              upper[d] = std::max(upper[d], cell->vertex(v)[d]);
            }
    for_each_boundary_face(dof_handler, [&](const auto &, const auto &face) {
      // The face's measure, shared equally by its vertices (the
      // lumped weights of a uniform pressure on P1 faces).
      double measure = face->vertex(0).distance(face->vertex(1));
      if constexpr (dim == 3)
        measure = 0.5 * cross_product_3d(face->vertex(1) - face->vertex(0),
                                         face->vertex(2) - face->vertex(0))
                          .norm();
      for (unsigned int v = 0; v < face->n_vertices(); ++v)
        {
          const types::global_dof_index first = face->vertex_dof_index(v, 0);
          if (!owned.is_element(first))
            continue;
          auto it = index.find(first);
          if (it == index.end())
            {
              Vertex vertex;
              vertex.X = face->vertex(v);
              for (unsigned int d = 0; d < dim; ++d)
                vertex.dofs[d] = face->vertex_dof_index(v, d);
              it = index.emplace(first, vertices.size()).first;
              vertices.push_back(vertex);
            }
          vertices[it->second].area += measure / face->n_vertices();
        }
    });
    double diagonal = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double extent = Utilities::MPI::max(upper[d], comm) -
                              Utilities::MPI::min(lower[d], comm);
        diagonal += extent * extent;
      }
    return diagonal;
  }

  template <int dim>
  void
  ObstacleContact<dim>::check_start() const
  {
    // The start must be feasible.
    std::string               problem;
    const std::vector<Placed> start = placed(0.);
    for (const Vertex &v : vertices)
      {
        for (unsigned int k = 0; k < obstacles.size() && problem.empty(); ++k)
          if (!(distance(start[k], v.X, d_hat_value) > 0.))
            {
              std::ostringstream s;
              s << "the body starts on the wrong side of the obstacle of '"
                << obstacles[k].subsection << "': the boundary vertex at ("
                << v.X << ") has distance "
                << distance(start[k], v.X, d_hat_value)
                << " (must be positive at t = 0)";
              problem = s.str();
            }
        if (!problem.empty())
          break;
      }
    throw_input_error_of_first_rank(problem, comm);
  }

  template <int dim>
  bool
  ObstacleContact<dim>::has_friction() const
  {
    return std::any_of(obstacles.begin(), obstacles.end(), [](const auto &o) {
      return o.friction > 0.;
    });
  }

  template <int dim>
  Point<dim>
  ObstacleContact<dim>::position(const unsigned int a,
                                 const VectorType  &u) const
  {
    const Vertex &v = vertices[a];
    Point<dim>    x = v.X;
    for (unsigned int d = 0; d < dim; ++d)
      x[d] += u(v.dofs[d]);
    if (clock.end_state.c != 1.)
      x = clock.end_state.end_position(start_positions[a], x);
    return x;
  }

  template <int dim>
  typename ObstacleContact<dim>::PairState
  ObstacleContact<dim>::pair(const unsigned int a,
                             const unsigned int k,
                             const Point<dim>  &x,
                             const Placed      &o,
                             const double       eps,
                             const double       since_start,
                             const bool         with_stiffness) const
  {
    PairState      state;
    Tensor<1, dim> n;
    Tensor<2, dim> H;
    state.distance =
      distance(o, x, d_hat_value, &n, with_stiffness ? &H : nullptr);
    const double d = state.distance;
    if (!(d > 0.))
      return state;
    if (d < d_hat_value)
      {
        state.active    = true;
        const Barrier b = barrier(d, d_hat_value);
        const double  w = kappa * vertices[a].area;
        state.energy    = w * b.value;
        // g = -dV/dx = -w b'(d) grad d (b' < 0: away from the obstacle).
        state.force = -w * b.derivative * n;
        if (with_stiffness)
          {
            // d2V/dx2 = w (b'' n n^T + b' d2d), projected: b'' > 0 along
            // n; the sphere's tangential curvature term b'/r < 0 is dropped
            // (its eigenvalue is negative).
            SymmetricTensor<2, dim> K;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                K[i][j] = w * (b.second * n[i] * n[j] + b.derivative * H[i][j]);
            for (const auto &[value, vector] : eigenvectors(K))
              if (value > 0.)
                state.stiffness +=
                  value * symmetrize(outer_product(vector, vector));
          }
      }
    if (lagged.empty() || !(o.friction > 0.))
      return state;
    const Lagged &l      = lagged[a * obstacles.size() + k];
    const double  lambda = l.normal_force_after(since_start);
    if (!(lambda > 0.))
      return state;
    const Tensor<1, dim>   s  = slip(a, x, o, l);
    const SmoothedFriction f  = smoothed_friction(s.norm(), eps);
    const double           ml = o.friction * lambda;
    state.energy += ml * f.f0;
    state.force -= ml * f.f1_over_y * s;
    if (with_stiffness)
      state.stiffness += ml * (f.f1_over_y * l.tangent_projection +
                               f.c * symmetrize(outer_product(s, s)));
    return state;
  }

  template <int dim>
  Tensor<1, dim>
  ObstacleContact<dim>::slip(const unsigned int a,
                             const Point<dim>  &x,
                             const Placed      &o,
                             const Lagged      &l) const
  {
    // The slip of the step relative to the obstacle, in the lagged tangent
    // plane: the obstacle's point under the vertex's start has moved by
    // the shift and, turning, by (turn - I) (x_start - its start point).
    Tensor<1, dim> w = o.shift;
    if (o.turns)
      w += (o.turn - unit_symmetric_tensor<dim>()) *
           (start_positions[a] - o.start_point);
    return l.tangent_projection * (x - start_positions[a] - w);
  }

  template <int dim>
  void
  ObstacleContact<dim>::project_trial(
    const VectorType                &u,
    VectorType                      &trial,
    const double                     t,
    const AffineConstraints<double> &constraints) const
  {
    if (lagged.empty() || !has_friction())
      return;
    const auto                scope = timed_section(timer, "contact");
    const std::vector<Placed> where = placed(clock.obstacle_time(t));
    const double              eps =
      friction_smoothing(clock.end_time(t) - std::min(clock.step_start, t));
    const double                         since_start = clock.elapsed(t);
    std::vector<types::global_dof_index> rows;
    std::vector<double>                  values;
    for (unsigned int a = 0; a < vertices.size(); ++a)
      {
        if (std::any_of(vertices[a].dofs.begin(),
                        vertices[a].dofs.end(),
                        [&](const types::global_dof_index i) {
                          return constraints.is_constrained(i);
                        }))
          continue;
        const Point<dim> x      = position(a, u);
        const Point<dim> x_next = position(a, trial);
        for (unsigned int k = 0; k < obstacles.size(); ++k)
          {
            const Lagged &l = lagged[a * obstacles.size() + k];
            if (!(obstacles[k].friction > 0.) ||
                !(l.normal_force_after(since_start) > 0.))
              continue;
            const Tensor<1, dim> s = slip(a, x, where[k], l);
            if (!(s.norm() > eps))
              continue;
            const Tensor<1, dim> along = s / s.norm();
            const double         back  = slip(a, x_next, where[k], l) * along;
            // Only a jump across the whole stick zone: a trial that ends
            // within it is left alone (a sharp test at zero would let the
            // Krylov solves' round-off decide, and the number of ranks).
            if (!(back < -eps))
              continue;
            // Onto the kink: the slip's component along its old direction
            // back to zero (in the solved state: divided by the end-state
            // map's factor).
            for (unsigned int d = 0; d < dim; ++d)
              {
                rows.push_back(vertices[a].dofs[d]);
                values.push_back(trial(vertices[a].dofs[d]) -
                                 back * along[d] / clock.end_state.c);
              }
            break;
          }
      }
    // Collective, with or without moved vertices here.
    trial.set(rows, values);
    trial.compress(VectorOperation::insert);
  }

  template <int dim>
  template <typename F>
  bool
  ObstacleContact<dim>::for_each_pair(const VectorType &u,
                                      const double      t,
                                      const bool        with_stiffness,
                                      const F          &f) const
  {
    const std::vector<Placed> where = placed(clock.obstacle_time(t));
    const double              eps =
      friction_smoothing(clock.end_time(t) - std::min(clock.step_start, t));
    const double since_start = clock.elapsed(t);
    bool         crossed     = false;
    for (unsigned int a = 0; a < vertices.size(); ++a)
      {
        const Point<dim> x = position(a, u);
        for (unsigned int k = 0; k < obstacles.size(); ++k)
          {
            PairState p =
              pair(a, k, x, where[k], eps, since_start, with_stiffness);
            // The potential w V(x_end) / c in the solved state: gradient
            // w V'(x_end), Hessian w c V''(x_end).
            p.energy *= clock.end_state.energy_factor();
            p.force *= clock.end_state.gradient_factor();
            p.stiffness *= clock.end_state.hessian_factor();
            crossed = crossed || !(p.distance > 0.);
            f(a, k, p);
          }
      }
    return crossed;
  }

  template <int dim>
  typename ObstacleContact<dim>::Stencil
  ObstacleContact<dim>::stencil(const unsigned int               a,
                                const AffineConstraints<double> *constraints,
                                const Tensor<1, dim>            &motion) const
  {
    Stencil s;
    s.set_vertex(0, vertices[a].dofs, true, constraints);
    s.set_obstacle_point(1, motion);
    return s;
  }

  template <int dim>
  PairBarrier<2 * dim>
  ObstacleContact<dim>::as_barrier(const PairState &p, const unsigned int order)
  {
    // The pair's energy depends on x - w (w the obstacle's point): the
    // obstacle's gradient and Hessian blocks are the vertex's, negated.
    PairBarrier<2 * dim> b;
    b.distance = p.distance;
    b.energy   = p.energy;
    for (unsigned int i = 0; i < dim && order > 0; ++i)
      {
        b.gradient[i]       = -p.force[i];
        b.gradient[dim + i] = p.force[i];
        for (unsigned int j = 0; j < dim && order > 1; ++j)
          {
            b.hessian[i][j] = b.hessian[dim + i][dim + j] = p.stiffness[i][j];
            b.hessian[i][dim + j] = b.hessian[dim + i][j] = -p.stiffness[i][j];
          }
      }
    return b;
  }

  template <int dim>
  std::string
  ObstacleContact<dim>::touching_message(const double t)
  {
    return "a boundary vertex is on the wrong side of an obstacle at t = " +
           std::to_string(t) +
           " (an obstacle moved into the body over the step; a shorter step "
           "lets the body follow it)";
  }

  template <int dim>
  bool
  ObstacleContact<dim>::visit(const VectorType             &u,
                              const double                  t,
                              const typename Sums::Request &request) const
  {
    // While the obstacles are on their way (Placed at the clock's
    // obstacle_time(t)), the linearization carries the rest of their
    // motion w (of the obstacle's point at the vertex), in the solved
    // state (/ c): the pair's forces depend on x - w, so the obstacle drags
    // the vertices it touches.
    const bool          moving = request.order == 2 && clock.on_the_way(t);
    std::vector<Placed> now, end;
    if (moving)
      {
        now = placed(clock.reached);
        end = placed(clock.end_time(t));
      }
    return for_each_pair(
      u,
      t,
      request.order == 2,
      [&](const unsigned int a, const unsigned int k, const PairState &p) {
        // Pairs without force or stiffness add nothing.
        if ((request.order == 1 && p.force.norm_square() == 0.) ||
            (request.order == 2 && p.stiffness.norm() == 0.))
          return;
        const Tensor<1, dim> w =
          moving ? carried(now[k], end[k], position(a, u)) / clock.end_state.c
                 : Tensor<1, dim>();
        request.take(stencil(a, request.constraints, w),
                     as_barrier(p, request.order),
                     true,
                     false);
      });
  }

  template <int dim>
  std::vector<typename ObstacleContact<dim>::Lagged>
  ObstacleContact<dim>::lagged_at(const VectorType &u, const double time) const
  {
    std::vector<Lagged> result(vertices.size() * obstacles.size());
    if (!has_friction())
      return result;
    const std::vector<Placed> where = placed(time);
    for (unsigned int a = 0; a < vertices.size(); ++a)
      {
        const Point<dim> x = position(a, u);
        for (unsigned int k = 0; k < obstacles.size(); ++k)
          {
            Tensor<1, dim> n;
            const double   d = distance(where[k], x, d_hat_value, &n);
            if (!(d > 0.) || !(d < d_hat_value) ||
                !(obstacles[k].friction > 0.))
              continue;
            Lagged &l = result[a * obstacles.size() + k];
            l.normal_force =
              -kappa * vertices[a].area * barrier(d, d_hat_value).derivative;
            l.tangent_projection =
              unit_symmetric_tensor<dim>() - symmetrize(outer_product(n, n));
          }
      }
    return result;
  }

  template <int dim>
  void
  ObstacleContact<dim>::begin_step(const VectorType &u, const double t_start)
  {
    clock.begin_step(t_start);
    lagging.begin_step();
    // kappa at a sound operating point for the step to come, from the
    // converged state's smallest distance (BarrierStiffness).
    if (stiffness.adaptive() &&
        stiffness.retarget(measure(u, t_start).min_distance / d_hat_value))
      kappa = stiffness.value();
    start_positions.resize(vertices.size());
    for (unsigned int a = 0; a < vertices.size(); ++a)
      start_positions[a] = position(a, u);
    lagged = lagged_at(u, t_start);
  }

  template <int dim>
  LaggedUpdate
  ObstacleContact<dim>::update_lagged(const VectorType &u,
                                      const double      t,
                                      const LagMoment   moment,
                                      const double      unbalanced_force)
  {
    if (!has_friction() || !lagging.may_update())
      return LaggedUpdate::unchanged;
    const double              time  = clock.obstacle_time(t);
    std::vector<Lagged>       next  = lagged_at(u, time);
    const std::vector<Placed> where = placed(time);
    const double              since_start = clock.elapsed(t);
    const double              eps =
      friction_smoothing(clock.end_time(t) - std::min(clock.step_start, t));
    // The change of each vertex's friction force, mu (lambda_new - lambda)
    // f1(|s|) along its slip s (in the new tangent plane where it is in
    // contact now, else in the old).
    FrictionLagging::Change change;
    for (unsigned int a = 0; a < vertices.size(); ++a)
      {
        const Point<dim> x = position(a, u);
        Tensor<1, dim>   force;
        for (unsigned int k = 0; k < obstacles.size(); ++k)
          {
            const unsigned int i      = a * obstacles.size() + k;
            const double       before = lagged[i].normal_force_after(since_start);
            change.add_normal_force(before, next[i].normal_force);
            if (!lagging.needs_friction_change() || !(eps > 0.) ||
                next[i].normal_force == before)
              continue;
            const Lagged &l = next[i].normal_force > 0. ? next[i] : lagged[i];
            const Tensor<1, dim>   s = slip(a, x, where[k], l);
            const SmoothedFriction f = smoothed_friction(s.norm(), eps);
            force += obstacles[k].friction * (next[i].normal_force - before) *
                     f.f1_over_y * s;
          }
        change.friction_squared += force.norm_square();
      }
    return lagging.take_if_changed(
      change, {moment, unbalanced_force}, comm, lagged, next);
  }

  template <int dim>
  void
  ObstacleContact<dim>::extrapolate_lagged(const VectorType &u_before,
                                           const double      t_before)
  {
    // Quasi-static only: in dynamics the step is short, lambda_n is close,
    // and the difference of two states carries their vibrations.
    if (dynamic || !has_friction() || !(t_before < clock.step_start))
      return;
    // The positions of the state before, with the obstacles where they
    // stood then (the end-state map is the identity between steps).
    const std::vector<Lagged> before = lagged_at(u_before, t_before);
    for (unsigned int i = 0; i < lagged.size(); ++i)
      if (lagged[i].normal_force > 0. && before[i].normal_force > 0.)
        lagged[i].rate = (lagged[i].normal_force - before[i].normal_force) /
                         (clock.step_start - t_before);
  }

  template <int dim>
  ContactMeasures
  ObstacleContact<dim>::measure(const VectorType &u, const double t) const
  {
    ContactMeasures             m;
    std::vector<Tensor<1, dim>> force(obstacles.size());
    std::vector<Tensor<1, 3>>   moment(obstacles.size());
    // Moments about each obstacle's point where it stands (Point moved by
    // its Motion: the centre of its rotation), the forces at the vertices.
    const std::vector<Placed> where = placed(clock.obstacle_time(t));
    double       min_distance       = std::numeric_limits<double>::infinity();
    unsigned int active             = 0;
    for_each_pair(
      u,
      t,
      false,
      [&](const unsigned int a, const unsigned int k, const PairState &p) {
        min_distance = std::min(min_distance, p.distance);
        active += p.active ? 1 : 0;
        force[k] += p.force;
        moment[k] += moment_of<dim>(position(a, u) - where[k].point, p.force);
      });
    std::vector<unsigned int> numbers;
    for (const ObstacleParameters &o : obstacles)
      numbers.push_back(o.number);
    m.add_obstacles<dim>(numbers, force, moment, comm);
    m.set_pairs(min_distance, active, comm);
    return m;
  }

  template class ObstacleContact<2>;
  template class ObstacleContact<3>;
} // namespace hyperelastic
