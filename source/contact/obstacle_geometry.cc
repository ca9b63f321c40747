// Where ObstacleContact's rigid obstacles stand at a time (their Motion and
// Rotation angle applied), the signed distance of a point to each (plane,
// sphere, surface mesh) with its derivatives, the motion an obstacle
// carries a point along, and how far a Newton step may go before a
// boundary vertex reaches an obstacle.
#include <deal.II/base/mpi.h>

#include <hyperelastic/contact/obstacle_contact.h>

#include <algorithm>
#include <cmath>
#include <limits>

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

  template class ObstacleContact<2>;
  template class ObstacleContact<3>;
} // namespace hyperelastic
