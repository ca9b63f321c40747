// The barrier contact and lagged friction of boundary vertices with rigid
// planes, spheres and surface meshes.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>

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

  namespace
  {
    /// A tenth of each distance is kept along a Newton direction.
    constexpr double feasible_fraction = 0.9;

    template <int dim>
    Point<dim>
    to_point(const std::vector<double> &values)
    {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = values[d];
      return p;
    }

    /// The rotation by @p angle about @p axis (a unit vector; 2D: its z
    /// component, +1 or -1, the out-of-plane axis), right-handed.
    template <int dim>
    Tensor<2, dim>
    rotation_about(const Tensor<1, 3> &axis, const double angle)
    {
      const double   c = std::cos(angle), s = std::sin(angle);
      Tensor<2, dim> Q;
      if constexpr (dim == 2)
        {
          Q[0][0] = c;
          Q[0][1] = -axis[2] * s;
          Q[1][0] = axis[2] * s;
          Q[1][1] = c;
        }
      else
        {
          // Rodrigues: c I + s [a]x + (1 - c) a a^T.
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              Q[i][j] = (i == j ? c : 0.) + (1. - c) * axis[i] * axis[j];
          Q[0][1] -= s * axis[2];
          Q[0][2] += s * axis[1];
          Q[1][0] += s * axis[2];
          Q[1][2] -= s * axis[0];
          Q[2][0] -= s * axis[1];
          Q[2][1] += s * axis[0];
        }
      return Q;
    }

    /// The part of @p v across @p axis (2D: all of it).
    template <int dim>
    Tensor<1, dim>
    across(const Tensor<1, 3> &axis, const Tensor<1, dim> &v)
    {
      Tensor<1, dim> result = v;
      if constexpr (dim == 3)
        result -= (axis * v) * axis;
      return result;
    }
  } // namespace

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
      , lagging(parameters.friction_lagging_updates)
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

    const double diagonal = std::sqrt(gather_vertices(dof_handler));
    std::vector<double> areas;
    for (const Vertex &v : vertices)
      areas.push_back(v.area);
    const double element_size = mean_element_size(areas, dim, true, comm);
    shared_settings =
      shared ? *shared
             : barrier_settings(
                 parameters, diagonal, moduli, dynamic, element_size);
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
      {
        if (cell->is_artificial())
          continue;
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = std::min(lower[d], cell->vertex(v)[d]);
                upper[d] = std::max(upper[d], cell->vertex(v)[d]);
              }
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() ||
                face->boundary_id() == partition_edge_boundary_id)
              continue;
            // The face's measure, shared equally by its vertices (the
            // lumped weights of a uniform pressure on P1 faces).
            double measure = face->vertex(0).distance(face->vertex(1));
            if constexpr (dim == 3)
              measure =
                0.5 * cross_product_3d(face->vertex(1) - face->vertex(0),
                                       face->vertex(2) - face->vertex(0))
                        .norm();
            for (unsigned int v = 0; v < face->n_vertices(); ++v)
              {
                const types::global_dof_index first =
                  face->vertex_dof_index(v, 0);
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
          }
      }
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
  std::vector<typename ObstacleContact<dim>::Placed>
  ObstacleContact<dim>::placed(const double time) const
  {
    std::vector<Placed> result(obstacles.size());
    const auto          offset = [&](const unsigned int k, const double t) {
      motions[k]->set_time(t);
      Tensor<1, dim> w;
      for (unsigned int d = 0; d < dim; ++d)
        w[d] = motions[k]->value(Point<dim>(), d);
      return w;
    };
    const auto angle = [&](const unsigned int k, const double t) {
      angles[k]->set_time(t);
      return angles[k]->value(Point<dim>(), 0);
    };
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      {
        const ObstacleParameters &o = obstacles[k];
        Placed                   &p = result[k];
        const Tensor<1, dim>      w = offset(k, time);
        p.type                      = o.type;
        p.point                     = to_point<dim>(o.point) + w;
        p.rotation                  = unit_symmetric_tensor<dim>();
        p.turn                      = p.rotation;
        p.turns                     = angles[k] != nullptr;
        if (p.turns)
          {
            for (unsigned int d = 0; d < o.rotation_axis.size(); ++d)
              p.axis[3 - o.rotation_axis.size() + d] = o.rotation_axis[d];
            p.angle    = angle(k, time);
            p.rotation = rotation_about<dim>(p.axis, p.angle);
          }
        if (o.type == ObstacleType::plane)
          p.normal = p.turns ? p.rotation * to_point<dim>(o.normal)
                             : Tensor<1, dim>(to_point<dim>(o.normal));
        p.radius   = o.radius;
        p.friction = o.friction;
        p.surface  = surfaces[k].get();
        if (std::isfinite(clock.reached) && o.friction > 0.)
          {
            const Tensor<1, dim> w_start = offset(k, clock.step_start);
            p.shift                      = w - w_start;
            if (p.turns)
              {
                p.start_point = to_point<dim>(o.point) + w_start;
                p.turn =
                  rotation_about<dim>(p.axis,
                                      p.angle - angle(k, clock.step_start));
              }
          }
      }
    return result;
  }

  template <int dim>
  double
  ObstacleContact<dim>::distance(const Placed     &o,
                                 const Point<dim> &x,
                                 const double      reach,
                                 Tensor<1, dim>   *gradient,
                                 Tensor<2, dim>   *hessian)
  {
    if (o.type == ObstacleType::mesh && o.turns)
      {
        // In the surface's coordinates Q^T (x - p); grad = Q grad_s,
        // Hessian Q H_s Q^T.
        const double d =
          o.surface->distance(Point<dim>(transpose(o.rotation) * (x - o.point)),
                              reach,
                              gradient,
                              hessian);
        if (gradient)
          *gradient = o.rotation * *gradient;
        if (hessian)
          *hessian = o.rotation * *hessian * transpose(o.rotation);
        return d;
      }
    if (o.type == ObstacleType::mesh)
      return o.surface->distance(Point<dim>(x - o.point),
                                 reach,
                                 gradient,
                                 hessian);
    if (o.type == ObstacleType::plane)
      {
        if (gradient)
          *gradient = o.normal;
        if (hessian)
          *hessian = Tensor<2, dim>();
        return o.normal * (x - o.point);
      }
    // Sphere: d = |x - c| - R, grad d = e = (x - c)/r,
    // d2 d = (I - e e^T) / r.
    const Tensor<1, dim> r_vector = x - o.point;
    const double         r        = r_vector.norm();
    const Tensor<1, dim> e        = r_vector / r;
    if (gradient)
      *gradient = e;
    if (hessian)
      *hessian = (unit_symmetric_tensor<dim>() - outer_product(e, e)) / r;
    return r - o.radius;
  }

  template <int dim>
  Tensor<1, dim>
  ObstacleContact<dim>::carried(const Placed     &from,
                                const Placed     &to,
                                const Point<dim> &x)
  {
    Tensor<1, dim> w = to.point - from.point;
    if (to.angle != from.angle)
      w += (rotation_about<dim>(to.axis, to.angle - from.angle) -
            unit_symmetric_tensor<dim>()) *
           (x - from.point);
    return w;
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
  void
  ObstacleContact<dim>::contact_forces(const VectorType &u,
                                       const double      t,
                                       VectorType       &forces) const
  {
    std::vector<types::global_dof_index> rows;
    std::vector<double>                  values;
    const bool                           crossed = for_each_pair(
      u, t, false, [&](const unsigned int a, unsigned int, const PairState &p) {
        if (p.force.norm_square() == 0.)
          return;
        for (unsigned int c = 0; c < dim; ++c)
          {
            rows.push_back(vertices[a].dofs[c]);
            values.push_back(p.force[c]);
          }
      });
    // On every rank, even without contact: the first add after an insert
    // makes Trilinos assemble the vector, a collective operation.
    forces.add(rows, values);
    if (Utilities::MPI::max(crossed ? 1 : 0, comm) != 0)
      throw ConvergenceFailure(
        "a boundary vertex is on the wrong side of an obstacle at t = " +
        std::to_string(t) +
        " (an obstacle moved into the body over the step; a shorter step "
        "lets the body follow it)");
  }

  template <int dim>
  ForceSize
  ObstacleContact<dim>::add_forces(const VectorType &u,
                                   const double      t,
                                   VectorType       &forces) const
  {
    const auto scope = timed_section(timer, "contact");
    contact_forces(u, t, forces);
    return {};
  }

  template <int dim>
  void
  ObstacleContact<dim>::add_stiffness(
    const VectorType &u,
    const double      t,
    TangentProjection,
    const AffineConstraints<double> &constraints,
    MatrixType                      &matrix,
    VectorType                      &rhs) const
  {
    const auto scope = timed_section(timer, "contact");
    // While the obstacles are on their way (Placed at the clock's
    // obstacle_time(t)), the linearization carries the rest of their motion
    // w_ak (of the obstacle's point at vertex a): the pair's forces depend on x
    // - w, so the right-hand side gains K w on the pair's rows (the obstacle
    // drags the vertices it touches).
    const bool          moving = clock.on_the_way(t);
    std::vector<Placed> now, end;
    if (moving)
      {
        now = placed(clock.reached);
        end = placed(clock.end_time(t));
      }
    FullMatrix<double>                   block(dim, dim);
    std::vector<types::global_dof_index> dofs(dim);
    std::vector<types::global_dof_index> drag_rows;
    std::vector<double>                  drag;
    // The right-hand side's switch to adding, on every rank (collective in
    // Trilinos); add_condensed then adds on the ranks with contact only.
    rhs.add(std::vector<types::global_dof_index>(), std::vector<double>());
    stiff_rows.clear();
    for_each_pair(
      u,
      t,
      true,
      [&](const unsigned int a, const unsigned int k, const PairState &p) {
        if (p.stiffness.norm() == 0.)
          return;
        for (unsigned int i = 0; i < dim; ++i)
          {
            dofs[i] = vertices[a].dofs[i];
            for (unsigned int j = 0; j < dim; ++j)
              block(i, j) = p.stiffness[i][j];
          }
        add_condensed(block, dofs, constraints, matrix, rhs);
        for (const types::global_dof_index dof : dofs)
          if (rhs.in_local_range(dof) && !constraints.is_constrained(dof))
            stiff_rows.push_back(dof);
        // K w, K the pair's stiffness in the end state.
        if (!moving)
          return;
        const Tensor<1, dim> pull = p.stiffness *
                                    carried(now[k], end[k], position(a, u)) /
                                    clock.end_state.c;
        for (unsigned int i = 0; i < dim; ++i)
          if (pull[i] != 0. && !constraints.is_constrained(dofs[i]))
            {
              drag_rows.push_back(dofs[i]);
              drag.push_back(pull[i]);
            }
      });
    rhs.add(drag_rows, drag);
  }

  template <int dim>
  void
  ObstacleContact<dim>::add_stiff_dofs(IndexSet &dofs) const
  {
    for (const types::global_dof_index dof : stiff_rows)
      dofs.add_index(dof);
  }

  template <int dim>
  double
  ObstacleContact<dim>::energy(const VectorType &u, const double t) const
  {
    const auto scope   = timed_section(timer, "contact");
    double     sum     = 0.;
    const bool crossed = for_each_pair(
      u, t, false, [&](unsigned int, unsigned int, const PairState &p) {
        sum += p.energy;
      });
    if (crossed)
      sum = std::numeric_limits<double>::infinity();
    return Utilities::MPI::sum(sum, comm);
  }

  template <int dim>
  double
  ObstacleContact<dim>::largest_feasible_step(const VectorType &u,
                                              const VectorType &direction,
                                              const double      t) const
  {
    const auto scope = timed_section(timer, "contact");
    // The obstacles move jointly with the body: from where they stand to
    // their place at t (a straight way in between).
    const std::vector<Placed> now = placed(clock.obstacle_time(t));
    std::vector<Placed>       end = now;
    if (clock.on_the_way(t))
      end = placed(clock.end_time(t));
    double alpha = 1.;
    for (unsigned int a = 0; a < vertices.size(); ++a)
      {
        const Vertex    &v = vertices[a];
        const Point<dim> x = position(a, u);
        for (unsigned int k = 0; k < obstacles.size(); ++k)
          {
            // The vertex's motion relative to the obstacle's point p: in
            // the obstacle's frame as it stands now, x - p moves to
            // R(-s turn) (x - p + s w) over s in [0, 1].
            Tensor<1, dim> p = now[k].point - end[k].point;
            for (unsigned int c = 0; c < dim; ++c)
              p[c] += clock.end_state.c * direction(v.dofs[c]);
            const double         turn   = end[k].angle - now[k].angle;
            const Tensor<1, dim> offset = x - now[k].point;
            const Tensor<1, 3>  &axis   = now[k].axis;
            if (now[k].type == ObstacleType::mesh)
              {
                const double keep = 1. - feasible_fraction;
                if (!now[k].turns)
                  alpha = std::min(
                    alpha,
                    now[k].surface->largest_step(Point<dim>(offset), p, keep));
                else if (turn == 0.)
                  alpha =
                    std::min(alpha,
                             now[k].surface->largest_step(
                               Point<dim>(transpose(now[k].rotation) * offset),
                               transpose(now[k].rotation) * p,
                               keep));
                else
                  {
                    // In the surface's coordinates Q(s)^T (x(s) - p(s)),
                    // moving at most |w| + |turn| |(x(s) - p(s)) across
                    // the axis|.
                    const Tensor<2, dim> back = transpose(now[k].rotation);
                    const double         speed =
                      p.norm() + std::abs(turn) * (across(axis, offset).norm() +
                                                   across(axis, p).norm());
                    alpha =
                      std::min(alpha,
                               now[k].surface->largest_step_along(
                                 [&](const double s) {
                                   return Point<dim>(
                                     back *
                                     (rotation_about<dim>(axis, -s * turn) *
                                      (offset + s * p)));
                                 },
                                 speed,
                                 keep));
                  }
                continue;
              }
            const double d0 = distance(now[k], x, d_hat_value);
            if (!(d0 > 0.))
              continue; // the forces say so
            double hit = std::numeric_limits<double>::infinity();
            if (now[k].type == ObstacleType::plane)
              {
                // d(s) = n(s) . (x - p + s w), n(s) the normal turned by
                // s turn: d' >= n . w - |turn| |n across| (|x - p across| +
                // 2 |w across|) (the normal turns at |turn| |n across|,
                // and has turned by at most that much), so d(s) stays above
                // d0 - s approach. Without rotation: -n . w.
                const double approach =
                  -(now[k].normal * p) +
                  std::abs(turn) * across(axis, now[k].normal).norm() *
                    (across(axis, offset).norm() + 2. * across(axis, p).norm());
                if (approach > 0.)
                  hit = d0 / approach;
              }
            else
              {
                // |x - c + s p| = R: a s^2 + 2 b s + c0 = 0, first root > 0
                // (a sphere turns about its centre: the rotation leaves
                // the distances alone).
                const Tensor<1, dim> r  = x - now[k].point;
                const double         a  = p * p;
                const double         b  = r * p;
                const double         c0 = r * r - now[k].radius * now[k].radius;
                const double         disc = b * b - a * c0;
                if (a > 0. && b < 0. && disc >= 0.)
                  hit = c0 / (-b + std::sqrt(disc));
              }
            alpha = std::min(alpha, feasible_fraction * hit);
          }
      }
    return Utilities::MPI::min(alpha, comm);
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
  bool
  ObstacleContact<dim>::prepare_motion(const double t)
  {
    const double t_end = clock.end_time(t);
    if (!(clock.reached < t_end))
      return false;
    const std::vector<Placed> now = placed(clock.reached), end = placed(t_end);
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      if (now[k].point != end[k].point || now[k].angle != end[k].angle)
        return true;
    // Standing still: nothing to carry.
    clock.reached = t_end;
    return false;
  }

  template <int dim>
  void
  ObstacleContact<dim>::advance(const double alpha, const double t)
  {
    clock.advance(alpha, t);
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
    std::vector<Lagged> next        = lagged_at(u, clock.obstacle_time(t));
    const double        since_start = clock.elapsed(t);
    double              change = 0., largest = 0.;
    for (unsigned int i = 0; i < next.size(); ++i)
      {
        change = std::max(change,
                          std::abs(next[i].normal_force -
                                   lagged[i].normal_force_after(since_start)));
        largest = std::max(largest, next[i].normal_force);
      }
    return lagging.take_if_changed(
      change, largest, {moment, unbalanced_force}, comm, lagged, next);
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
    double       min_distance = std::numeric_limits<double>::infinity();
    unsigned int active       = 0;
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
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      m.add_obstacle<dim>(obstacles[k].number,
                          Utilities::MPI::sum(force[k], comm),
                          Utilities::MPI::sum(moment[k], comm));
    m.min_distance = Utilities::MPI::min(min_distance, comm);
    m.active_pairs = static_cast<double>(Utilities::MPI::sum(active, comm));
    return m;
  }

  template class ObstacleContact<2>;
  template class ObstacleContact<3>;
} // namespace hyperelastic
