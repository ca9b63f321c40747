// Continuous collision detection for self-contact pairs: additive CCD (Li,
// Kaufman, Jiang 2021), a conservative advancement on a lower bound of the
// distance along a linear motion.
//
// A pair (point-segment, point-triangle or edge-edge, coordinates as in
// primitive_distance.h) moves from x to x + t p. With the common motion
// removed (the mean of the points' p), the distance can shrink at most at
// the rate l_p = |p of the one side| + max |p of the other side| (point vs
// segment/triangle: |p_0| + max_j |p_j|; edge vs edge: max over each edge),
// so advancing by (1 - s) d / l_p never reaches the surface; repeating with
// 0.9 d / l_p from the new distance approaches the first time of impact
// from below. The returned t keeps the pair at a distance of at least
// s d(0) (the stated minimum separation: s = 0.1 in the solver), or is
// t_max if the motion never comes that close. Pure function.
#pragma once

#include <hyperelastic/contact/primitive_distance.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace hyperelastic
{
  /// The fraction of its distance that each pair keeps along a Newton
  /// direction (the s of additive_ccd), for the obstacle and self contact.
  constexpr double ccd_keep_fraction = 0.1;

  /// The result of one pair's CCD.
  struct CollisionTime
  {
    double       t          = 0.; ///< the largest safe fraction of the motion
    unsigned int iterations = 0;  ///< advancement steps taken
  };

  /// Additive CCD of the pair at @p x moving by @p p (see above); 3 points
  /// in 2D (point-segment), 4 in 3D (@p edge_edge: two edges, otherwise a
  /// point and a triangle). @p keep: s; @p t_max: the step's bound.
  template <int dim, std::size_t n>
  CollisionTime
  additive_ccd(std::array<double, n>        x,
               const std::array<double, n> &p_in,
               const bool                   edge_edge,
               const double                 keep,
               const double                 t_max)
  {
    constexpr unsigned int n_points = n / dim;
    std::array<double, n>  p        = p_in;
    for (int d = 0; d < dim; ++d)
      {
        double mean = 0.;
        for (unsigned int i = 0; i < n_points; ++i)
          mean += p[i * dim + d];
        mean /= n_points;
        for (unsigned int i = 0; i < n_points; ++i)
          p[i * dim + d] -= mean;
      }
    std::array<double, n_points> speed;
    for (unsigned int i = 0; i < n_points; ++i)
      {
        double s = 0.;
        for (int d = 0; d < dim; ++d)
          s += p[i * dim + d] * p[i * dim + d];
        speed[i] = std::sqrt(s);
      }
    double rate;
    if (dim == 3 && edge_edge)
      rate = std::max(speed[0], speed[1]) + std::max(speed[2], speed[3]);
    else
      rate = speed[0] + *std::max_element(speed.begin() + 1, speed.end());
    CollisionTime result;
    result.t = t_max;
    if (!(rate > 0.))
      return result;
    const auto distance = [&](const std::array<double, n> &y) {
      return std::sqrt(
        std::max(squared_distance<dim>(classify_pair<dim>(y, edge_edge), y),
                 0.));
    };
    double       d    = distance(x);
    const double gap  = keep * d;
    double       t    = 0.;
    double       step = (1. - keep) * d / rate;
    // A bound on the iterations: each advances by at least 0.9 gap / rate
    // until the gap is crossed.
    for (unsigned int k = 0; k < 100000; ++k)
      {
        ++result.iterations;
        for (unsigned int i = 0; i < n; ++i)
          x[i] += step * p_in[i];
        d = distance(x);
        if (t > 0. && d < gap)
          break;
        t += step;
        if (t >= t_max)
          return result;
        step = 0.9 * d / rate;
      }
    result.t = t;
    return result;
  }
} // namespace hyperelastic
