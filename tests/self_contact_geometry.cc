// Unit test of the self-contact pair geometry (contact/primitive_distance.h)
// and continuous collision detection (contact/collision_detection.h):
//   a. gradients and Hessians of the point-segment (2D), point-triangle and
//      edge-edge (3D) barrier energies against central finite differences
//      (relative 1e-6), in every closest-feature case and in the degenerate
//      configurations: a point just above an edge of a triangle, nearly
//      parallel edges (mollified) and exactly parallel edges;
//   b. the distance is C1 where the case switches (point above an edge,
//      crossing edges at an endpoint): energy and gradient of the two
//      formulas agree there (1e-12);
//   c. the PSD projection of every pair Hessian has no eigenvalue below
//      -1e-12 of its norm and keeps a PSD Hessian unchanged;
//   d. CCD: a vertex moving through a triangle, edges crossing, a 2D vertex
//      through a segment, each with a known time of impact T at approach
//      speed v: the returned t lies in [T - 10 s d0 / v, T - s d0 / v]
//      (never past the impact, never closer than s d0); a motion that
//      misses returns 1; random motions of random pairs never get a sampled
//      distance below s d0 on [0, t];
//   e. friction of a pair (contact/pair_friction.h): the closest-point
//      coefficients of random pairs in every case give the distance vector
//      (|sum beta_i x_i|^2 = squared distance, 1e-10), sum to 1 on the first
//      feature and -1 on the second and lie inside the features; the
//      friction energy's gradient and Hessian match central differences
//      (relative 1e-6) sticking (|s| < eps) and sliding, the Hessian is
//      positive semi-definite and the force opposes the slip with magnitude
//      mu lambda once sliding.
#include <hyperelastic/contact/collision_detection.h>
#include <hyperelastic/contact/pair_friction.h>
#include <hyperelastic/contact/primitive_distance.h>

#include "support/checker.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

namespace
{
  using namespace hyperelastic;
  using hyperelastic::testing::Checker;

  /// The largest relative error of the gradient and Hessian of the barrier
  /// of case @p c at @p x against central differences of the energy and the
  /// gradient (step 1e-6 of the pair's size).
  template <int dim, std::size_t n>
  std::pair<double, double>
  finite_difference_errors(const std::array<double, n> &x,
                           const DistanceCase          &c,
                           const double                 d_hat,
                           const double                 mollifier)
  {
    const PairBarrier<n> exact =
      pair_barrier<dim>(x, c, d_hat, 1., mollifier, 2);
    double size = 0.;
    for (const double v : x)
      size = std::max(size, std::abs(v));
    const double h       = 1e-6 * std::max(size, 1.) * d_hat;
    double       g_error = 0., g_norm = 0., h_error = 0., h_norm = 0.;
    for (unsigned int i = 0; i < n; ++i)
      {
        std::array<double, n> plus = x, minus = x;
        plus[i] += h;
        minus[i] -= h;
        const double fd =
          (pair_barrier<dim>(plus, c, d_hat, 1., mollifier, 0).energy -
           pair_barrier<dim>(minus, c, d_hat, 1., mollifier, 0).energy) /
          (2. * h);
        g_error       = std::max(g_error, std::abs(fd - exact.gradient[i]));
        g_norm        = std::max(g_norm, std::abs(exact.gradient[i]));
        const auto gp = pair_barrier<dim>(plus, c, d_hat, 1., mollifier, 1);
        const auto gm = pair_barrier<dim>(minus, c, d_hat, 1., mollifier, 1);
        for (unsigned int j = 0; j < n; ++j)
          {
            const double fd2 = (gp.gradient[j] - gm.gradient[j]) / (2. * h);
            h_error = std::max(h_error, std::abs(fd2 - exact.hessian[j][i]));
            h_norm  = std::max(h_norm, std::abs(exact.hessian[j][i]));
          }
      }
    return {g_error / g_norm, h_error / h_norm};
  }

  const char *
  case_name(const DistanceCase &c)
  {
    switch (c.type)
      {
      case DistanceCase::point_point:
        return "point-point";
      case DistanceCase::point_line:
        return "point-line";
      case DistanceCase::point_plane:
        return "point-plane";
      default:
        return "line-line";
      }
  }

  template <int dim, std::size_t n>
  void
  check_pair(Checker                     &check,
             const std::string           &name,
             const std::array<double, n> &x,
             const bool                   edge_edge,
             const double                 d_hat,
             const double                 mollifier,
             const DistanceCase::Type     expected)
  {
    const DistanceCase c = classify_pair<dim>(x, edge_edge);
    check.is_true(name + ": case " + case_name(c), c.type == expected);
    const auto [g, h] = finite_difference_errors<dim>(x, c, d_hat, mollifier);
    check.at_most(name + ": gradient vs FD", g, 1e-6);
    check.at_most(name + ": Hessian vs FD", h, 1e-6);
    const PairBarrier<n> b = pair_barrier<dim>(x, c, d_hat, 1., mollifier, 2);
    check.above(name + ": energy > 0 inside d_hat", b.energy, 0.);
    const SmallMatrix<n>  psd = positive_semidefinite_part<n>(b.hessian);
    std::array<double, n> values;
    SmallMatrix<n>        vectors;
    jacobi_eigen_decomposition<n>(psd, values, vectors);
    double norm = 0.;
    for (const auto &row : b.hessian)
      for (const double v : row)
        norm = std::max(norm, std::abs(v));
    check.at_least(name + ": projected Hessian PSD (min eigenvalue / norm)",
                   *std::min_element(values.begin(), values.end()) / norm,
                   -1e-12);
  }

  /// Energy and gradient of cases @p a and @p b at @p x agree (relative).
  template <int dim, std::size_t n>
  void
  check_continuity(Checker                     &check,
                   const std::string           &name,
                   const std::array<double, n> &x,
                   const DistanceCase          &a,
                   const DistanceCase          &b,
                   const double                 d_hat)
  {
    const auto ea         = pair_barrier<dim>(x, a, d_hat, 1., 0., 1);
    const auto eb         = pair_barrier<dim>(x, b, d_hat, 1., 0., 1);
    double     difference = 0., norm = 0.;
    for (unsigned int i = 0; i < n; ++i)
      {
        difference =
          std::max(difference, std::abs(ea.gradient[i] - eb.gradient[i]));
        norm = std::max(norm, std::abs(ea.gradient[i]));
      }
    check.close(name + ": energy of both cases",
                ea.energy,
                eb.energy,
                std::abs(ea.energy),
                1e-12);
    check.at_most(name + ": gradient of both cases", difference / norm, 1e-12);
  }

  void
  barrier_derivatives(Checker &check)
  {
    check.section("barrier gradients and Hessians against finite differences");
    const double d_hat = 0.1;
    // 2D point-segment: interior and beyond an end.
    check_pair<2>(check,
                  "2D point-segment, interior",
                  std::array<double, 6>{{0.3, 0.04, 0., 0., 1., 0.1}},
                  false,
                  d_hat,
                  0.,
                  DistanceCase::point_line);
    check_pair<2>(check,
                  "2D point-segment, beyond an end",
                  std::array<double, 6>{{1.03, 0.05, 0., 0., 1., 0.}},
                  false,
                  d_hat,
                  0.,
                  DistanceCase::point_point);
    // 3D point-triangle: face, edge and vertex regions; the point just
    // above an edge (1e-9 inside the face's region).
    const std::array<double, 9> t = {{0., 0., 0., 1., 0.1, 0., 0.2, 1., 0.05}};
    const auto pt = [&](const double x, const double y, const double z) {
      std::array<double, 12> a{{x, y, z}};
      std::copy(t.begin(), t.end(), a.begin() + 3);
      return a;
    };
    check_pair<3>(check,
                  "point-triangle, face",
                  pt(0.4, 0.3, 0.06),
                  false,
                  d_hat,
                  0.,
                  DistanceCase::point_plane);
    check_pair<3>(check,
                  "point-triangle, edge",
                  pt(0.5, -0.03, 0.02),
                  false,
                  d_hat,
                  0.,
                  DistanceCase::point_line);
    check_pair<3>(check,
                  "point-triangle, vertex",
                  pt(-0.03, -0.02, 0.04),
                  false,
                  d_hat,
                  0.,
                  DistanceCase::point_point);
    {
      // Above the edge t0 t1: the foot of the normal from the point on the
      // triangle's plane lies on the edge.
      std::array<double, 12> x = pt(0., 0., 0.);
      const double           s = 0.4;
      double                 n[3], e[3], m[3];
      for (unsigned int d = 0; d < 3; ++d)
        e[d] = t[3 + d] - t[d];
      const double u[3] = {t[6] - t[0], t[7] - t[1], t[8] - t[2]};
      n[0]              = e[1] * u[2] - e[2] * u[1];
      n[1]              = e[2] * u[0] - e[0] * u[2];
      n[2]              = e[0] * u[1] - e[1] * u[0];
      // m: in the plane, normal to the edge, towards the triangle.
      m[0]                = n[1] * e[2] - n[2] * e[1];
      m[1]                = n[2] * e[0] - n[0] * e[2];
      m[2]                = n[0] * e[1] - n[1] * e[0];
      const double n_norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      const double m_norm = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
      const double height = 0.05;
      const double inside = 1e-9;
      for (unsigned int d = 0; d < 3; ++d)
        x[d] =
          t[d] + s * e[d] + height * n[d] / n_norm + inside * m[d] / m_norm;
      check_pair<3>(check,
                    "point-triangle, above an edge",
                    x,
                    false,
                    d_hat,
                    0.,
                    DistanceCase::point_plane);
      for (unsigned int d = 0; d < 3; ++d)
        x[d] -= inside * m[d] / m_norm;
      check_continuity<3>(check,
                          "point-triangle, exactly above an edge",
                          x,
                          {DistanceCase::point_plane, {{0, 1, 2, 3}}},
                          {DistanceCase::point_line, {{0, 1, 2, 0}}},
                          d_hat);
    }
    // Edge-edge: crossing (line-line), an end beside the other edge, nearly
    // parallel (mollified) and parallel edges.
    const double eps_x = 1e-3; // edges of length ~1
    check_pair<3>(check,
                  "edge-edge, crossing",
                  std::array<double, 12>{
                    {0., 0., 0., 1., 0.1, 0., 0.4, -0.5, 0.05, 0.5, 0.6, 0.03}},
                  true,
                  d_hat,
                  eps_x,
                  DistanceCase::line_line);
    check_pair<3>(
      check,
      "edge-edge, end beside an edge",
      std::array<double, 12>{
        {0., 0., 0., 1., 0., 0., 1.03, -0.5, 0.02, 1.05, 0.5, 0.03}},
      true,
      d_hat,
      eps_x,
      DistanceCase::point_line);
    {
      // Nearly parallel: c = |ea x eb|^2 = 1e-4 eps_x.
      const std::array<double, 12> x{{0.,
                                      0.,
                                      0.,
                                      1.,
                                      0.,
                                      0.,
                                      0.2,
                                      0.01,
                                      0.04,
                                      1.2,
                                      0.01 + 1e-3 * 1e-2,
                                      0.04}};
      const double                 c = edge_cross_square(x);
      check.below("nearly parallel edges: mollifier active (c / eps_x)",
                  c / eps_x,
                  1.);
      check_pair<3>(check,
                    "edge-edge, nearly parallel (mollified)",
                    x,
                    true,
                    d_hat,
                    eps_x,
                    DistanceCase::point_line);
    }
    {
      // Exactly parallel: an endpoint-edge case (checked without the
      // mollifier, which makes the energy and its gradient vanish here).
      const std::array<double, 12> x{
        {0., 0., 0., 1., 0., 0., 0.2, 0.03, 0.04, 1.2, 0.03, 0.04}};
      check_pair<3>(check,
                    "edge-edge, parallel (no mollifier)",
                    x,
                    true,
                    d_hat,
                    0.,
                    DistanceCase::point_line);
      const auto b =
        pair_barrier<3>(x, classify_pair<3>(x, true), d_hat, 1., eps_x, 1);
      double g = 0.;
      for (const double v : b.gradient)
        g = std::max(g, std::abs(v));
      check.is_true("edge-edge, parallel: mollified energy and gradient 0",
                    b.energy == 0. && g == 0.);
    }
    check_continuity<3>(
      check,
      "edge-edge, the other edge's end exactly beside the edge",
      std::array<double, 12>{
        {0., 0., 0., 1., 0., 0., 0.5, 0., 0.05, 0.5, 1., 0.05}},
      {DistanceCase::line_line, {{0, 1, 2, 3}}},
      {DistanceCase::point_line, {{2, 0, 1, 0}}},
      d_hat);
  }

  /// The distance of the pair at x + t p.
  template <int dim, std::size_t n>
  double
  distance_at(const std::array<double, n> &x,
              const std::array<double, n> &p,
              const double                 t,
              const bool                   edge_edge)
  {
    std::array<double, n> y = x;
    for (unsigned int i = 0; i < n; ++i)
      y[i] += t * p[i];
    return std::sqrt(
      squared_distance<dim>(classify_pair<dim>(y, edge_edge), y));
  }

  template <int dim, std::size_t n>
  void
  check_impact(Checker                     &check,
               const std::string           &name,
               const std::array<double, n> &x,
               const std::array<double, n> &p,
               const bool                   edge_edge,
               const double                 impact,
               const double                 speed)
  {
    const double        s  = 0.01;
    const double        d0 = distance_at<dim>(x, p, 0., edge_edge);
    const CollisionTime r  = additive_ccd<dim>(x, p, edge_edge, s, 1.);
    check.at_least(name + ": t >= T - 10 s d0 / v",
                   r.t,
                   impact - 10. * s * d0 / speed);
    // (The first advancement lands on s d0 exactly in a head-on approach:
    // round-off margins.)
    check.at_most(name + ": t <= T - s d0 / v",
                  r.t,
                  impact - s * d0 / speed + 1e-12);
    check.at_least(name + ": distance at t / (s d0)",
                   distance_at<dim>(x, p, r.t, edge_edge) / (s * d0),
                   1. - 1e-12);
    check.note(name + ": " + std::to_string(r.iterations) +
               " advancement steps");
  }

  void
  collision_detection(Checker &check)
  {
    check.section("continuous collision detection (additive CCD, s = 0.01)");
    // A vertex falling through a triangle in z = 0: impact at t = 0.5.
    check_impact<3>(check,
                    "vertex through a triangle",
                    std::array<double, 12>{
                      {0.2, 0.2, 1., 0., 0., 0., 1., 0., 0., 0., 1., 0.}},
                    std::array<double, 12>{{0., 0., -2.}},
                    false,
                    0.5,
                    2.);
    // The triangle rising to meet the vertex, the vertex sliding sideways.
    check_impact<3>(check,
                    "triangle rising to a sliding vertex",
                    std::array<double, 12>{
                      {0.2, 0.2, 1., 0., 0., 0., 1., 0., 0., 0., 1., 0.}},
                    std::array<double, 12>{
                      {0.3, 0., 0., 0., 0., 4., 0., 0., 4., 0., 0., 4.}},
                    false,
                    0.25,
                    4.);
    // Edges crossing: a along x at z = 1 falling onto b along y at z = 0.
    check_impact<3>(check,
                    "edges crossing",
                    std::array<double, 12>{
                      {-1., 0., 1., 1., 0., 1., 0., -1., 0., 0., 1., 0.}},
                    std::array<double, 12>{{0., 0., -1., 0., 0., -1.}},
                    true,
                    1.,
                    1.);
    check_impact<2>(check,
                    "2D vertex through a segment",
                    std::array<double, 6>{{0.3, 1., -1., 0., 1., 0.}},
                    std::array<double, 6>{{0., -4.}},
                    false,
                    0.25,
                    4.);
    {
      const CollisionTime r = additive_ccd<3>(
        std::array<double, 12>{
          {2., 2., 1., 0., 0., 0., 1., 0., 0., 0., 1., 0.}},
        std::array<double, 12>{{0., 0., -2.}},
        false,
        0.01,
        1.);
      check.is_true("a vertex passing beside the triangle: t = 1", r.t == 1.);
    }
    // Random pairs and motions: the distance sampled on [0, t] stays above
    // s d0 (the sampling also finds crossings that CCD must not pass).
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> unit(-1., 1.);
    double       worst   = std::numeric_limits<double>::infinity();
    unsigned int limited = 0;
    for (unsigned int trial = 0; trial < 400; ++trial)
      {
        const bool             edge_edge = trial % 2 == 1;
        std::array<double, 12> x, p;
        for (unsigned int i = 0; i < 12; ++i)
          {
            x[i] = unit(random) + (i < 6 && edge_edge ? 0. : 0.);
            p[i] = 2. * unit(random);
          }
        // Separate the first primitive upwards; the motion brings it down.
        for (unsigned int i = 0; i < (edge_edge ? 2u : 1u); ++i)
          {
            x[i * 3 + 2] += 2.;
            p[i * 3 + 2] -= 3.;
          }
        const double        d0 = distance_at<3>(x, p, 0., edge_edge);
        const CollisionTime r  = additive_ccd<3>(x, p, edge_edge, 0.01, 1.);
        limited += r.t < 1. ? 1 : 0;
        for (unsigned int k = 0; k <= 2000; ++k)
          worst = std::min(worst,
                           distance_at<3>(x, p, r.t * k / 2000., edge_edge) /
                             (0.01 * d0));
      }
    check.at_least("400 random motions: smallest sampled distance on [0, t] "
                   "/ (s d0)",
                   worst,
                   1.);
    check.above("random motions limited by CCD", limited, 50);
  }

  /// Coefficients of random pairs: the worst relative error of |sum beta
  /// x|^2 against the squared distance, of the sums (1, -1) and how far a
  /// coefficient lies outside [0, 1] (first feature) or [-1, 0] (second).
  template <int dim, std::size_t n>
  void
  check_coefficients(Checker &check, const std::string &name, bool edge_edge)
  {
    std::mt19937                           random(11);
    std::uniform_real_distribution<double> unit(-1., 1.);
    constexpr std::size_t                  n_points = n / dim;
    const unsigned int first_side = edge_edge ? 2 : 1; // points of feature 1
    double             distance_error = 0., sum_error = 0., outside = 0.;
    unsigned int       cases[4] = {0, 0, 0, 0};
    for (unsigned int trial = 0; trial < 2000; ++trial)
      {
        std::array<double, n> x;
        for (double &v : x)
          v = unit(random);
        const DistanceCase c = classify_pair<dim>(x, edge_edge);
        ++cases[c.type];
        const auto beta    = closest_point_coefficients<dim>(c, x);
        double     length2 = 0., sums[2] = {0., 0.};
        for (unsigned int d = 0; d < dim; ++d)
          {
            double v = 0.;
            for (std::size_t i = 0; i < n_points; ++i)
              v += beta[i] * x[i * dim + d];
            length2 += v * v;
          }
        for (std::size_t i = 0; i < n_points; ++i)
          sums[i < first_side ? 0 : 1] += beta[i];
        // The vector may point either way (an edge-edge pair whose closest
        // point on the second edge is an endpoint: point-line from it).
        const double sign = sums[0] > 0. ? 1. : -1.;
        for (std::size_t i = 0; i < n_points; ++i)
          {
            const double b = (i < first_side ? sign : -sign) * beta[i];
            outside        = std::max({outside, -b, b - 1.});
          }
        const double d2 = squared_distance<dim>(c, x);
        distance_error  = std::max(distance_error,
                                  std::abs(length2 - d2) / std::max(d2, 1e-30));
        sum_error       = std::max({sum_error,
                                    std::abs(sign * sums[0] - 1.),
                                    std::abs(sign * sums[1] + 1.)});
      }
    check.at_most(name + ": |sum beta x|^2 vs squared distance (2000 random)",
                  distance_error,
                  1e-10);
    check.at_most(name + ": coefficient sums vs +-1 and -+1", sum_error, 1e-12);
    check.at_most(name + ": coefficients outside their feature",
                  outside,
                  1e-12);
    check.note(name + ": cases point-point " + std::to_string(cases[0]) +
               ", point-line " + std::to_string(cases[1]) + ", point-plane " +
               std::to_string(cases[2]) + ", line-line " +
               std::to_string(cases[3]));
  }

  /// The friction energy of a random pair with slip of size @p slip (eps =
  /// 1): derivatives against central differences, PSD Hessian, and (when
  /// sliding) |force on the first point| = beta_0 mu lambda along -s.
  template <int dim, std::size_t n>
  void
  check_friction(Checker &check, const std::string &name, const double slip)
  {
    constexpr std::size_t                  n_points = n / dim;
    std::mt19937                           random(5);
    std::uniform_real_distribution<double> unit(-1., 1.);
    std::array<double, n>                  x0, x;
    std::array<double, n_points>           beta;
    std::array<double, dim>                normal;
    for (double &v : x0)
      v = unit(random);
    for (double &v : beta)
      v = unit(random);
    double length = 0.;
    for (double &v : normal)
      v = unit(random), length += v * v;
    for (double &v : normal)
      v /= std::sqrt(length);
    // A motion whose lagged slip has length slip.
    std::array<double, n> p;
    for (double &v : p)
      v = unit(random);
    std::array<double, dim> s{};
    for (std::size_t i = 0; i < n_points; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        s[d] += beta[i] * p[i * dim + d];
    double along = 0., size = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      along += s[d] * normal[d];
    for (unsigned int d = 0; d < dim; ++d)
      size += std::pow(s[d] - along * normal[d], 2);
    size = std::sqrt(size);
    for (std::size_t i = 0; i < n; ++i)
      x[i] = x0[i] + slip / size * p[i];
    const double mu_lambda = 0.7, eps = 1.;
    const auto   exact =
      pair_friction<dim>(x, x0, beta, normal, mu_lambda, eps, 2);
    const double h       = 1e-6;
    double       g_error = 0., g_norm = 0., h_error = 0., h_norm = 0.;
    for (std::size_t i = 0; i < n; ++i)
      {
        std::array<double, n> plus = x, minus = x;
        plus[i] += h, minus[i] -= h;
        const auto ep =
          pair_friction<dim>(plus, x0, beta, normal, mu_lambda, eps, 1);
        const auto em =
          pair_friction<dim>(minus, x0, beta, normal, mu_lambda, eps, 1);
        g_error = std::max(g_error,
                           std::abs((ep.energy - em.energy) / (2. * h) -
                                    exact.gradient[i]));
        g_norm  = std::max(g_norm, std::abs(exact.gradient[i]));
        for (std::size_t j = 0; j < n; ++j)
          {
            h_error =
              std::max(h_error,
                       std::abs((ep.gradient[j] - em.gradient[j]) / (2. * h) -
                                exact.hessian[j][i]));
            h_norm = std::max(h_norm, std::abs(exact.hessian[j][i]));
          }
      }
    check.at_most(name + ": gradient vs FD", g_error / g_norm, 1e-6);
    // (2D sliding: the Hessian (f1 / y)(P - s s^T / y^2) vanishes, P being
    // rank one; errors relative to the scale mu lambda / max(y, eps).)
    h_norm = std::max(h_norm, mu_lambda / std::max(slip, eps));
    check.at_most(name + ": Hessian vs FD", h_error / h_norm, 1e-6);
    std::array<double, n> values;
    SmallMatrix<n>        vectors;
    jacobi_eigen_decomposition<n>(exact.hessian, values, vectors);
    check.at_least(name + ": Hessian PSD (min eigenvalue / norm)",
                   *std::min_element(values.begin(), values.end()) / h_norm,
                   -1e-12);
    if (slip > eps)
      {
        double force = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          force += std::pow(exact.gradient[d], 2);
        check.close(name + ": |force on point 0| vs |beta_0| mu lambda",
                    std::sqrt(force),
                    std::abs(beta[0]) * mu_lambda,
                    mu_lambda,
                    1e-12);
      }
  }

  void
  pair_friction_checks(Checker &check)
  {
    check.section("friction of a pair: closest-point coefficients");
    check_coefficients<2, 6>(check, "2D point-segment", false);
    check_coefficients<3, 12>(check, "point-triangle", false);
    check_coefficients<3, 12>(check, "edge-edge", true);
    check.section("friction of a pair: energy derivatives (eps = 1)");
    for (const double slip : {0.3, 2.5})
      {
        const std::string regime = slip < 1. ? " sticking" : " sliding";
        check_friction<2, 6>(check, "2D point-segment" + regime, slip);
        check_friction<3, 12>(check, "3D pair" + regime, slip);
      }
  }
} // namespace

int
main()
{
  Checker check;
  barrier_derivatives(check);
  collision_detection(check);
  pair_friction_checks(check);
  return check.exit_code();
}
