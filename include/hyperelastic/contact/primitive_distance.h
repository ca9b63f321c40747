// Distances between boundary primitives for self-contact (IPC, Li et al.
// 2020): point-segment pairs in 2D, point-triangle and edge-edge pairs in 3D.
//
// A pair's coordinates are one flat array x of its points (dim entries each):
//   point-segment  [p, a, b]            (2D, n = 6)
//   point-triangle [p, t0, t1, t2]      (3D, n = 12)
//   edge-edge      [a0, a1, b0, b1]     (3D, n = 12)
// The closest features decide which smooth formula gives the squared
// distance (IPC's "distance types"): point-point |p - a|^2, point-line
// |(a - p) x (b - p)|^2 / |b - a|^2, point-plane ((p - a) . n)^2 / |n|^2 and
// line-line ((b0 - a0) . (ea x eb))^2 / |ea x eb|^2. classify_*() picks the
// case at the current x (in doubles); squared_distance() evaluates it for
// any number type, so that the barrier energy of a pair,
//   kappa w m(x) b(sqrt(d^2(x)), d_hat)
// (m the edge-edge mollifier, 1 otherwise), is differentiated exactly by
// forward automatic differentiation (Sacado, nested twice for the Hessian).
// Within a case the formulas are smooth; across cases the distance is C1.
//
// Parallel and nearly parallel edges: the lines' normal ea x eb is computed
// without cancellation (accurate_cross), and the line-line case is taken
// only where it is consistent with the endpoint cases (classify_edge_edge),
// so that every pair's case gives the segments' true distance (to about
// eps |x| / d relative) at any angle, parallel, anti-parallel and collinear
// edges included; the feasible step (CCD) and the reference-configuration
// check measure with the same cases.
//
// Edge-edge pairs of nearly parallel edges are mollified (IPC): with
// c = |ea x eb|^2 and eps_x = 1e-3 |ea_rest|^2 |eb_rest|^2,
//   m(c) = (2 - c / eps_x) c / eps_x  for c < eps_x, 1 beyond,
// so the energy goes to zero smoothly as the edges turn parallel, where the
// line-line distance loses its meaning.
//
// Pure functions of the coordinates: nothing here knows about meshes or MPI.
#pragma once

#include <hyperelastic/materials/tangent_projection.h>

#include <Sacado.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

namespace hyperelastic
{
  /// The smooth formula that gives a pair's squared distance, and the
  /// points (indices into the pair's point list) it involves.
  struct DistanceCase
  {
    enum Type
    {
      point_point, ///< |x_i - x_j|^2
      point_line,  ///< x_i to the line through x_j, x_k
      point_plane, ///< x_i to the plane through x_j, x_k, x_l
      line_line    ///< the line x_i x_j to the line x_k x_l
    };
    Type                        type = point_point;
    std::array<unsigned int, 4> p    = {{0, 0, 0, 0}};
  };

  namespace primitive_geometry
  {
    template <typename T, int dim>
    using Vec = std::array<T, dim>;

    template <int dim, typename T, std::size_t n>
    Vec<T, dim>
    point(const std::array<T, n> &x, const unsigned int i)
    {
      Vec<T, dim> v;
      for (int d = 0; d < dim; ++d)
        v[d] = x[i * dim + d];
      return v;
    }

    template <typename T, int dim>
    Vec<T, dim>
    minus(const Vec<T, dim> &a, const Vec<T, dim> &b)
    {
      Vec<T, dim> v;
      for (int d = 0; d < dim; ++d)
        v[d] = a[d] - b[d];
      return v;
    }

    template <typename T, int dim>
    T
    dot(const Vec<T, dim> &a, const Vec<T, dim> &b)
    {
      T s = a[0] * b[0];
      for (int d = 1; d < dim; ++d)
        s += a[d] * b[d];
      return s;
    }

    template <typename T>
    Vec<T, 3>
    cross(const Vec<T, 3> &a, const Vec<T, 3> &b)
    {
      return {{a[1] * b[2] - a[2] * b[1],
               a[2] * b[0] - a[0] * b[2],
               a[0] * b[1] - a[1] * b[0]}};
    }

    /// |(a - p) x (b - p)|^2 (2D: the squared scalar cross product).
    template <typename T, int dim>
    T
    cross_square(const Vec<T, dim> &u, const Vec<T, dim> &v)
    {
      if constexpr (dim == 2)
        {
          const T c = u[0] * v[1] - u[1] * v[0];
          return c * c;
        }
      else
        {
          const Vec<T, 3> c = cross(u, v);
          return dot<T, 3>(c, c);
        }
    }

    /// a x b without the cancellation of the plain formula for nearly
    /// parallel (or anti-parallel) a, b: with u, v the unit vectors,
    /// u x v = (u + v) x (v - u) / 2, where the small one of u + v and
    /// v - u is a difference of nearly equal numbers, exact to its own
    /// rounding, and the two factors are orthogonal. So the result is
    /// accurate to a few ulps relative to |a x b| at any angle, where the
    /// plain formula's error is about eps |a| |b| (relative eps / sin of
    /// the angle), which ruins the line-line distance of nearly parallel
    /// edges. NaN if a or b is zero.
    template <typename T>
    Vec<T, 3>
    accurate_cross(const Vec<T, 3> &a, const Vec<T, 3> &b)
    {
      using std::sqrt;
      const T   la = sqrt(dot<T, 3>(a, a)), lb = sqrt(dot<T, 3>(b, b));
      Vec<T, 3> sum, difference;
      for (int d = 0; d < 3; ++d)
        {
          const T u = a[d] / la, v = b[d] / lb;
          sum[d]        = u + v;
          difference[d] = v - u;
        }
      Vec<T, 3> c     = cross(sum, difference);
      const T   scale = 0.5 * la * lb;
      for (int d = 0; d < 3; ++d)
        c[d] *= scale;
      return c;
    }

    /// The parameters (s, t) of the closest points a0 + s ea, b0 + t eb of
    /// two lines, from the normal n = ea x eb (accurate_cross):
    /// s = (b0 - a0) . (eb x n) / |n|^2, t = (b0 - a0) . (ea x n) / |n|^2.
    /// Their error is about eps |b0 - a0| / (|ea| sin angle), the lines'
    /// own sensitivity; the 2 x 2 normal equations would square it.
    inline std::array<double, 2>
    line_line_parameters(const Vec<double, 3> &a0,
                         const Vec<double, 3> &ea,
                         const Vec<double, 3> &b0,
                         const Vec<double, 3> &eb,
                         const Vec<double, 3> &n)
    {
      const Vec<double, 3> w  = minus<double, 3>(b0, a0);
      const double         nn = dot<double, 3>(n, n);
      return {{dot<double, 3>(w, cross(eb, n)) / nn,
               dot<double, 3>(w, cross(ea, n)) / nn}};
    }
  } // namespace primitive_geometry

  /// The squared distance of case @p c at @p x (any number type).
  template <int dim, typename T, std::size_t n>
  T
  squared_distance(const DistanceCase &c, const std::array<T, n> &x)
  {
    using namespace primitive_geometry;
    const Vec<T, dim> a = point<dim>(x, c.p[0]), b = point<dim>(x, c.p[1]);
    switch (c.type)
      {
      case DistanceCase::point_point:
        {
          const Vec<T, dim> r = minus<T, dim>(a, b);
          return dot<T, dim>(r, r);
        }
      case DistanceCase::point_line:
        {
          // a: the point; b, e: the line.
          const Vec<T, dim> e = point<dim>(x, c.p[2]);
          const Vec<T, dim> t = minus<T, dim>(e, b);
          return cross_square<T, dim>(minus<T, dim>(b, a),
                                      minus<T, dim>(e, a)) /
                 dot<T, dim>(t, t);
        }
      case DistanceCase::point_plane:
      case DistanceCase::line_line:
        {
          if constexpr (dim == 3)
            {
              // (r . n)^2 / |n|^2 with n = u x v: point-plane r = a - b,
              // u, v the triangle's edges from b; line-line r = e - a, u, v
              // the lines' directions.
              // The lines' normal by accurate_cross: the plain cross
              // product's error, relative eps / sin of the angle, would
              // enter the distance as eps |e - a| / (d sin angle).
              const Vec<T, 3> e = point<3>(x, c.p[2]), f = point<3>(x, c.p[3]);
              const bool      plane = c.type == DistanceCase::point_plane;
              const Vec<T, 3> normal =
                plane ? cross(minus<T, 3>(e, b), minus<T, 3>(f, b))
                      : accurate_cross(minus<T, 3>(b, a), minus<T, 3>(f, e));
              const T h =
                dot<T, 3>(plane ? minus<T, 3>(a, b) : minus<T, 3>(e, a),
                          normal);
              return h * h / dot<T, 3>(normal, normal);
            }
          break;
        }
      }
    return T(-1.);
  }

  /// Point [p, a, b] to segment a b (2D or 3D).
  template <int dim, std::size_t n>
  DistanceCase
  classify_point_segment(const std::array<double, n> &x,
                         const unsigned int           p = 0,
                         const unsigned int           a = 1,
                         const unsigned int           b = 2)
  {
    using namespace primitive_geometry;
    const Vec<double, dim> e =
      minus<double, dim>(point<dim>(x, b), point<dim>(x, a));
    const double s =
      dot<double, dim>(minus<double, dim>(point<dim>(x, p), point<dim>(x, a)),
                       e) /
      dot<double, dim>(e, e);
    if (s <= 0.)
      return {DistanceCase::point_point, {{p, a, 0, 0}}};
    if (s >= 1.)
      return {DistanceCase::point_point, {{p, b, 0, 0}}};
    return {DistanceCase::point_line, {{p, a, b, 0}}};
  }

  /// Point [p, t0, t1, t2] to triangle (3D): the closest feature by the
  /// Voronoi regions of the triangle's vertices, edges and face.
  inline DistanceCase
  classify_point_triangle(const std::array<double, 12> &x)
  {
    using namespace primitive_geometry;
    const Vec<double, 3> p = point<3>(x, 0), a = point<3>(x, 1),
                         b = point<3>(x, 2), c = point<3>(x, 3);
    const Vec<double, 3> ab = minus<double, 3>(b, a),
                         ac = minus<double, 3>(c, a);
    const Vec<double, 3> ap = minus<double, 3>(p, a),
                         bp = minus<double, 3>(p, b),
                         cp = minus<double, 3>(p, c);
    const double d1 = dot<double, 3>(ab, ap), d2 = dot<double, 3>(ac, ap);
    if (d1 <= 0. && d2 <= 0.)
      return {DistanceCase::point_point, {{0, 1, 0, 0}}};
    const double d3 = dot<double, 3>(ab, bp), d4 = dot<double, 3>(ac, bp);
    if (d3 >= 0. && d4 <= d3)
      return {DistanceCase::point_point, {{0, 2, 0, 0}}};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0. && d1 >= 0. && d3 <= 0.)
      return {DistanceCase::point_line, {{0, 1, 2, 0}}};
    const double d5 = dot<double, 3>(ab, cp), d6 = dot<double, 3>(ac, cp);
    if (d6 >= 0. && d5 <= d6)
      return {DistanceCase::point_point, {{0, 3, 0, 0}}};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0. && d2 >= 0. && d6 <= 0.)
      return {DistanceCase::point_line, {{0, 1, 3, 0}}};
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0. && d4 - d3 >= 0. && d5 - d6 >= 0.)
      return {DistanceCase::point_line, {{0, 2, 3, 0}}};
    return {DistanceCase::point_plane, {{0, 1, 2, 3}}};
  }

  /// Edge [a0, a1] to edge [b0, b1] (3D). The segments' distance is the
  /// smallest of the four endpoint-to-edge distances unless the lines'
  /// closest points lie inside both edges, where it is the lines' distance.
  /// The line-line case is taken only if it is consistent:
  ///  - the closest points' parameters (line_line_parameters, from the
  ///    accurate normal) lie in (0, 1);
  ///  - it is shorter than the best endpoint case by more than round-off
  ///    (otherwise the endpoint case gives the same distance and stays
  ///    well conditioned as the edges turn parallel);
  ///  - d_end^2 - d_line^2 <= |ea x eb|^2 / min(|ea|^2, |eb|^2)
  ///    (= L^2 sin^2 of the angle, L the longer edge). With the closest
  ///    points inside both edges an endpoint lies within half the shorter
  ///    edge of them, so its distance exceeds the lines' by at most a
  ///    quarter of that. Parallel and nearly parallel edges whose
  ///    parameters are round-off (exactly parallel edges have no closest
  ///    points; the plain formulas gave any s, t) fail this test and keep
  ///    the endpoint case, so the line-line case of two parallel coplanar
  ///    edges can no longer give distance 0.
  inline DistanceCase
  classify_edge_edge(const std::array<double, 12> &x)
  {
    using namespace primitive_geometry;
    // The best of the endpoint-to-edge cases (point-line or point-point).
    const DistanceCase candidates[4] = {classify_point_segment<3>(x, 0, 2, 3),
                                        classify_point_segment<3>(x, 1, 2, 3),
                                        classify_point_segment<3>(x, 2, 0, 1),
                                        classify_point_segment<3>(x, 3, 0, 1)};
    DistanceCase       best          = candidates[0];
    double             end2          = squared_distance<3>(best, x);
    for (unsigned int k = 1; k < 4; ++k)
      {
        const double d2 = squared_distance<3>(candidates[k], x);
        if (d2 < end2)
          end2 = d2, best = candidates[k];
      }
    const Vec<double, 3> a0 = point<3>(x, 0), b0 = point<3>(x, 2);
    const Vec<double, 3> ea = minus<double, 3>(point<3>(x, 1), a0),
                         eb = minus<double, 3>(point<3>(x, 3), b0);
    const Vec<double, 3> n  = accurate_cross(ea, eb);
    const double         nn = dot<double, 3>(n, n);
    if (!(nn > 0.))
      return best; // parallel (or a degenerate edge)
    const auto [s, t] = line_line_parameters(a0, ea, b0, eb, n);
    if (!(s > 0. && s < 1. && t > 0. && t < 1.))
      return best;
    const DistanceCase line{DistanceCase::line_line, {{0, 1, 2, 3}}};
    const double       line2 = squared_distance<3>(line, x);
    // Round-off: a few ulps of the squared distances.
    constexpr double same = 64. * std::numeric_limits<double>::epsilon();
    const double     shorter =
      std::min(dot<double, 3>(ea, ea), dot<double, 3>(eb, eb));
    if (line2 < (1. - same) * end2 && end2 - line2 <= nn / shorter)
      return line;
    return best;
  }

  /// The closest-feature case of a pair of @p n_points points in @p dim
  /// dimensions (3 points in 2D: point-segment; in 3D @p edge_edge tells
  /// the edge-edge pairs from the point-triangle ones).
  template <int dim, std::size_t n>
  DistanceCase
  classify_pair(const std::array<double, n> &x, const bool edge_edge)
  {
    if constexpr (dim == 2)
      {
        (void)edge_edge;
        return classify_point_segment<2>(x);
      }
    else
      return edge_edge ? classify_edge_edge(x) : classify_point_triangle(x);
  }

  /// The edge-edge mollifier's c = |ea x eb|^2 at @p x (any number type;
  /// accurate_cross, so exactly 0 for exactly parallel edges).
  template <typename T>
  T
  edge_cross_square(const std::array<T, 12> &x)
  {
    using namespace primitive_geometry;
    const Vec<T, 3> n =
      accurate_cross(minus<T, 3>(point<3>(x, 1), point<3>(x, 0)),
                     minus<T, 3>(point<3>(x, 3), point<3>(x, 2)));
    return dot<T, 3>(n, n);
  }

  /// A pair's barrier energy and its derivatives in the pair's coordinates.
  template <std::size_t n>
  struct PairBarrier
  {
    double                distance = 0.;
    double                energy   = 0.;
    std::array<double, n> gradient{};
    SmallMatrix<n>        hessian{};
  };

  /// The distance cases whose barriers make up a pair's energy, with their
  /// coefficients: the pair's own case first (coefficient 1), then the
  /// sub-cases that remove the double counting of the features the pair
  /// shares with its neighbours (contact/duplicate_counting.h), at most 6.
  struct PairTerms
  {
    std::array<DistanceCase, 7> cases{};
    std::array<double, 7>       coefficient{};
    unsigned int                size = 0;

    void
    add(const DistanceCase &c, const double k)
    {
      cases[size] = c, coefficient[size] = k, ++size;
    }
  };

  /// The energy scale * m(x) * sum_k c_k b(d_k(x), d_hat) of a pair at @p x
  /// with the @p terms (cases k, coefficients c_k; d_k = sqrt of the
  /// case's squared distance, the pair's distance that of the first); the
  /// mollifier m only if @p mollifier_eps > 0 (edge-edge: eps_x). The
  /// terms beyond d_hat are left out (b is C2 there). With @p order 1 the
  /// gradient, with 2 the Hessian too (not projected). Zero if the first
  /// case is beyond d_hat; +infinity energy if its d <= 0.
  template <int dim, std::size_t n>
  PairBarrier<n>
  pair_barrier(const std::array<double, n> &x,
               const PairTerms             &all_terms,
               const double                 d_hat,
               const double                 scale,
               const double                 mollifier_eps,
               const unsigned int           order)
  {
    PairBarrier<n> result;
    result.distance =
      std::sqrt(std::max(squared_distance<dim>(all_terms.cases[0], x), 0.));
    if (!(result.distance > 0.))
      {
        result.energy = std::numeric_limits<double>::infinity();
        return result;
      }
    if (result.distance >= d_hat)
      return result;
    PairTerms terms;
    for (unsigned int k = 0; k < all_terms.size; ++k)
      if (all_terms.coefficient[k] != 0. &&
          squared_distance<dim>(all_terms.cases[k], x) < d_hat * d_hat)
        terms.add(all_terms.cases[k], all_terms.coefficient[k]);
    const auto energy = [&](const auto &y) {
      using T = typename std::decay_t<decltype(y)>::value_type;
      using std::log;
      using std::sqrt;
      T e = T(0.);
      for (unsigned int k = 0; k < terms.size; ++k)
        {
          const T d = sqrt(squared_distance<dim>(terms.cases[k], y));
          const T g = d - d_hat;
          e -= (scale * terms.coefficient[k]) * g * g * log(d / d_hat);
        }
      if constexpr (dim == 3)
        if (mollifier_eps > 0.)
          {
            const T cs = edge_cross_square(y);
            if (cs < mollifier_eps)
              e = e * (2. - cs / mollifier_eps) * cs / mollifier_eps;
          }
      return e;
    };
    if (order == 0)
      {
        result.energy = energy(x);
        return result;
      }
    if (order == 1)
      {
        using Fad = Sacado::Fad::SFad<double, n>;
        std::array<Fad, n> y;
        for (unsigned int i = 0; i < n; ++i)
          y[i] = Fad(n, i, x[i]);
        const Fad e   = energy(y);
        result.energy = e.val();
        for (unsigned int i = 0; i < n; ++i)
          result.gradient[i] = e.dx(i);
        return result;
      }
    using Inner = Sacado::Fad::SFad<double, n>;
    using Outer = Sacado::Fad::SFad<Inner, n>;
    std::array<Outer, n> y;
    for (unsigned int i = 0; i < n; ++i)
      y[i] = Outer(n, i, Inner(n, i, x[i]));
    const Outer e = energy(y);
    result.energy = e.val().val();
    for (unsigned int i = 0; i < n; ++i)
      {
        result.gradient[i] = e.val().dx(i);
        for (unsigned int j = 0; j < n; ++j)
          result.hessian[i][j] = e.dx(i).dx(j);
      }
    return result;
  }

  /// The same for the single case @p c (coefficient 1).
  template <int dim, std::size_t n>
  PairBarrier<n>
  pair_barrier(const std::array<double, n> &x,
               const DistanceCase          &c,
               const double                 d_hat,
               const double                 scale,
               const double                 mollifier_eps,
               const unsigned int           order)
  {
    PairTerms terms;
    terms.add(c, 1.);
    return pair_barrier<dim>(x, terms, d_hat, scale, mollifier_eps, order);
  }

  /// The closest-point coefficients of case @p c at @p x: one per point of
  /// the pair (n / dim of them), such that sum_i beta_i x_i is the vector
  /// from the closest point of the second feature to that of the first
  /// (point-point [1, -1], point-line [1, -(1 - t), -t], point-plane [1,
  /// -barycentric], line-line [1 - s, s, -(1 - t), -t] on the involved
  /// points, 0 on the others); its length is the distance. Friction lags
  /// them, with the normal, to measure the tangential slip of the pair.
  template <int dim, std::size_t n>
  std::array<double, n / dim>
  closest_point_coefficients(const DistanceCase          &c,
                             const std::array<double, n> &x)
  {
    using namespace primitive_geometry;
    std::array<double, n / dim> beta{};
    const Vec<double, dim> a = point<dim>(x, c.p[0]), b = point<dim>(x, c.p[1]);
    switch (c.type)
      {
      case DistanceCase::point_point:
        beta[c.p[0]] = 1., beta[c.p[1]] = -1.;
        break;
      case DistanceCase::point_line:
        {
          const Vec<double, dim> e =
            minus<double, dim>(point<dim>(x, c.p[2]), b);
          const double t = dot<double, dim>(minus<double, dim>(a, b), e) /
                           dot<double, dim>(e, e);
          beta[c.p[0]] = 1., beta[c.p[1]] = -(1. - t), beta[c.p[2]] = -t;
          break;
        }
      case DistanceCase::point_plane:
      case DistanceCase::line_line:
        if constexpr (dim == 3)
          {
            // Solve [u v] (y, z) = r in the least-squares sense (u, v: the
            // triangle's edges from b, or the lines' directions).
            const bool           plane = c.type == DistanceCase::point_plane;
            const Vec<double, 3> e     = point<3>(x, c.p[2]),
                                 f     = point<3>(x, c.p[3]);
            const Vec<double, 3> u     = plane ? minus<double, 3>(e, b)
                                               : minus<double, 3>(b, a),
                                 v     = plane ? minus<double, 3>(f, b)
                                               : minus<double, 3>(f, e);
            const double uu = dot<double, 3>(u, u), uv = dot<double, 3>(u, v),
                         vv  = dot<double, 3>(v, v);
            const double det = uu * vv - uv * uv;
            if (plane)
              {
                // The projection of a is b + y u + z v.
                const Vec<double, 3> r  = minus<double, 3>(a, b);
                const double         ru = dot<double, 3>(r, u),
                             rv         = dot<double, 3>(r, v);
                const double y          = (vv * ru - uv * rv) / det,
                             z          = (uu * rv - uv * ru) / det;
                beta[c.p[0]] = 1., beta[c.p[1]] = -(1. - y - z),
                beta[c.p[2]] = -y, beta[c.p[3]] = -z;
              }
            else
              {
                // Closest points a + s u and e + t v of the two lines.
                const auto [s, t] =
                  line_line_parameters(a, u, e, v, accurate_cross(u, v));
                beta[c.p[0]] = 1. - s, beta[c.p[1]] = s,
                beta[c.p[2]] = -(1. - t), beta[c.p[3]] = -t;
              }
          }
        break;
      }
    return beta;
  }

  /// @p matrix projected onto the positive semi-definite cone (its negative
  /// eigenvalues set to zero).
  template <std::size_t n>
  SmallMatrix<n>
  positive_semidefinite_part(const SmallMatrix<n> &matrix)
  {
    std::array<double, n> values;
    SmallMatrix<n>        vectors;
    jacobi_eigen_decomposition<n>(matrix, values, vectors);
    SmallMatrix<n> result{};
    for (unsigned int k = 0; k < n; ++k)
      if (values[k] > 0.)
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            result[i][j] += values[k] * vectors[i][k] * vectors[j][k];
    return result;
  }
} // namespace hyperelastic
