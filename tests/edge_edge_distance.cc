// Edge-edge distances of every kind of pair (issue 43, item 0):
//   a. random pairs of edges (general, parallel, anti-parallel, collinear
//      overlapping and disjoint, nearly parallel at angles down to 1e-12
//      with the closest points inside or outside the edges, and the same on
//      a binary grid, where parallel edges stay exactly parallel in floating
//      point), at random scales (1e-3 to 1e3) and offsets (up to 3 edge
//      lengths): the distance of the chosen case equals a brute-force
//      minimisation (golden section in long double over one edge's
//      parameter of the exact point-to-segment distance, which is convex)
//      to 1e-12 relative (collinear overlapping edges: 0 to 1e-12 of the
//      edge length);
//   b. the gradient and Hessian of the squared distance (Sacado, as the
//      barrier differentiates it) and of the mollified pair barrier match
//      central differences (Richardson, relative 1e-6) wherever the case is
//      the same at every perturbed point (away from case boundaries; at
//      least 5000 pairs); the mollified gradient where c >= 1e-6 eps_x
//      (below, it vanishes with the angle faster than the differences'
//      truncation error);
//   c. CCD: parallel, anti-parallel and collinear edges moving through
//      each other stop before they touch (the returned step lies within
//      [T - 2 s d0 / v, T - s d0 / v] of the known impact T), and random
//      motions of random parallel and nearly parallel pairs end at a
//      brute-force distance of at least s d0 and never come closer than
//      s d0 / 10 on [0, t] (each advancement keeps a tenth of its start);
//   d. the reported case: two concentric circles' chords (the shells of
//      the bug report), coplanar and parallel, are 0.02 apart, not 0.
#include <hyperelastic/contact/collision_detection.h>
#include <hyperelastic/contact/primitive_distance.h>

#include "support/checker.h"

#include <Sacado.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

namespace
{
  using namespace hyperelastic;
  using hyperelastic::testing::Checker;
  using X    = std::array<double, 12>;
  using Real = long double;

  /// The distance of point p to segment [a, b] in long double.
  Real
  point_segment(const std::array<Real, 3> &p,
                const std::array<Real, 3> &a,
                const std::array<Real, 3> &b)
  {
    Real ee = 0., pe = 0.;
    for (int d = 0; d < 3; ++d)
      {
        ee += (b[d] - a[d]) * (b[d] - a[d]);
        pe += (p[d] - a[d]) * (b[d] - a[d]);
      }
    const Real t = std::clamp(pe / ee, Real(0.), Real(1.));
    Real       r = 0.;
    for (int d = 0; d < 3; ++d)
      {
        const Real v = p[d] - (a[d] + t * (b[d] - a[d]));
        r += v * v;
      }
    return std::sqrt(r);
  }

  /// The segments' distance by golden section over the first edge's
  /// parameter (the distance of a0 + s ea to the second edge is convex in
  /// s), to an interval of 1e-16, the ends checked too.
  double
  brute_force_distance(const X &x)
  {
    std::array<Real, 3> a0, ea, b0, b1;
    for (int d = 0; d < 3; ++d)
      {
        a0[d] = x[d];
        ea[d] = Real(x[3 + d]) - Real(x[d]);
        b0[d] = x[6 + d];
        b1[d] = x[9 + d];
      }
    const auto f = [&](const Real s) {
      std::array<Real, 3> p;
      for (int d = 0; d < 3; ++d)
        p[d] = a0[d] + s * ea[d];
      return point_segment(p, b0, b1);
    };
    const Real ratio = (std::sqrt(Real(5.)) - 1.) / 2.;
    Real       lo = 0., hi = 1.;
    Real       s1 = hi - ratio * (hi - lo), s2 = lo + ratio * (hi - lo);
    Real       f1 = f(s1), f2 = f(s2);
    while (hi - lo > 1e-16)
      {
        if (f1 <= f2)
          {
            hi = s2, s2 = s1, f2 = f1;
            s1 = hi - ratio * (hi - lo), f1 = f(s1);
          }
        else
          {
            lo = s1, s1 = s2, f1 = f2;
            s2 = lo + ratio * (hi - lo), f2 = f(s2);
          }
      }
    return static_cast<double>(
      std::min({f1, f2, f(0.5L * (lo + hi)), f(0.), f(1.)}));
  }

  double
  distance(const X &x)
  {
    return std::sqrt(
      std::max(squared_distance<3>(classify_edge_edge(x), x), 0.));
  }

  /// The kinds of random pairs.
  enum class Kind
  {
    general,
    parallel,
    anti_parallel,
    collinear_overlapping,
    collinear_disjoint,
    nearly_parallel,
    nearly_parallel_inside,
    n_kinds
  };

  const char *
  kind_name(const Kind k)
  {
    static const char *names[] = {"general",
                                  "parallel",
                                  "anti-parallel",
                                  "collinear overlapping",
                                  "collinear disjoint",
                                  "nearly parallel",
                                  "nearly parallel, closest points inside"};
    return names[static_cast<int>(k)];
  }

  using V3 = std::array<double, 3>;

  V3
  unit(std::mt19937 &rng)
  {
    std::normal_distribution<double> n;
    V3                               v;
    double                           l = 0.;
    for (double &c : v)
      c = n(rng), l += c * c;
    for (double &c : v)
      c /= std::sqrt(l);
    return v;
  }

  /// A unit vector orthogonal to @p u.
  V3
  orthogonal(const V3 &u, std::mt19937 &rng)
  {
    V3     v = unit(rng);
    double p = 0.;
    for (int d = 0; d < 3; ++d)
      p += u[d] * v[d];
    double l = 0.;
    for (int d = 0; d < 3; ++d)
      v[d] -= p * u[d], l += v[d] * v[d];
    for (double &c : v)
      c /= std::sqrt(l);
    return v;
  }

  /// A random pair of kind @p k: scale 10^[-3, 3], offset up to 3 edge
  /// lengths, gaps 10^[-3, 0] of the scale. On the grid (@p grid), every
  /// coordinate is an integer times a power of 2, and the second edge's
  /// direction is the first's times +-1, +-2 or +-1/2 (exactly parallel
  /// in floating point), for the parallel kinds; the gap is in the grid.
  /// Returns the pair and the exact distance where it is known (else -1).
  std::pair<X, double>
  random_pair(const Kind k, const bool grid, std::mt19937 &rng)
  {
    std::uniform_real_distribution<double> u01(0., 1.);
    const auto                             uniform = [&](double a, double b) {
      return a + (b - a) * u01(rng);
    };
    const double scale = std::pow(10., uniform(-3., 3.));
    const double gap   = scale * std::pow(10., uniform(-3., 0.));
    const double la = scale * uniform(0.3, 1.), lb = scale * uniform(0.3, 1.);
    V3           offset;
    for (double &c : offset)
      c = 3. * scale * uniform(-1., 1.);
    const V3   u = unit(rng), m = orthogonal(u, rng);
    X          x;
    double     exact = -1.;
    const auto set =
      [&](const V3 &a0, const V3 &ea, const V3 &b0, const V3 &eb) {
        for (int d = 0; d < 3; ++d)
          {
            x[d]     = offset[d] + a0[d];
            x[3 + d] = offset[d] + a0[d] + ea[d];
            x[6 + d] = offset[d] + b0[d];
            x[9 + d] = offset[d] + b0[d] + eb[d];
          }
      };
    const auto combine = [](const V3 &p, double a, const V3 &q, double b) {
      return V3{
        {a * p[0] + b * q[0], a * p[1] + b * q[1], a * p[2] + b * q[2]}};
    };
    const V3 zero{{0., 0., 0.}};
    if (grid &&
        (k == Kind::parallel || k == Kind::anti_parallel ||
         k == Kind::collinear_overlapping || k == Kind::collinear_disjoint))
      {
        // Integers up to 2^10 times 2^e: sums and the factors 1, 2, 1/2
        // are exact.
        const double q = std::ldexp(1., std::ilogb(scale) - 10);
        std::uniform_int_distribution<int> integer(-1024, 1024);
        V3                                 ea, a0, shift;
        // Parallel edges in a coordinate plane in half the cases (as the
        // shells' edges on their symmetry plane: the plain cross product's
        // round-off is then normal to that plane).
        const int plane = rng() % 6;
        for (;;)
          {
            for (int d = 0; d < 3; ++d)
              {
                ea[d]    = d == plane ? 0. : integer(rng) * q;
                a0[d]    = d == plane ? 0. : integer(rng) * q;
                shift[d] = d == plane ? 0. : integer(rng) * q / 4.;
              }
            // ea x shift != 0: the parallel edges are apart.
            const double c0 = ea[1] * shift[2] - ea[2] * shift[1],
                         c1 = ea[2] * shift[0] - ea[0] * shift[2],
                         c2 = ea[0] * shift[1] - ea[1] * shift[0];
            if (c0 != 0. || c1 != 0. || c2 != 0.)
              break;
          }
        const double factors[] = {1., 2., 0.5};
        double       f         = factors[rng() % 3];
        if (k == Kind::anti_parallel || rng() % 2 == 0)
          f = k == Kind::parallel ? f : -f;
        const V3 eb = combine(ea, f, zero, 0.);
        V3       b0;
        if (k == Kind::parallel || k == Kind::anti_parallel)
          b0 = combine(a0, 1., shift, 1.);
        else if (k == Kind::collinear_overlapping)
          b0 = combine(a0, 1., ea, 0.25 * double(rng() % 4)); // inside a
        else
          {
            // Beyond a1 by (1 + j/4) |ea|, pointing either way.
            const double beyond = 1. + (1 + rng() % 4) * 0.25;
            b0       = combine(a0, 1., ea, f > 0 ? beyond : beyond - f);
            double l = 0.;
            for (const double c : ea)
              l += c * c;
            exact = (beyond - 1.) * std::sqrt(l);
          }
        set(a0, ea, b0, eb);
        if (k == Kind::collinear_overlapping)
          exact = 0.;
        return {x, exact};
      }
    switch (k)
      {
      case Kind::general:
        {
          V3 b0 =
            combine(u, uniform(-1., 1.) * scale, m, uniform(-1., 1.) * scale);
          b0[2] += uniform(-1., 1.) * scale;
          set(zero,
              combine(u, la, zero, 0.),
              b0,
              combine(unit(rng), lb, zero, 0.));
          break;
        }
      case Kind::parallel:
      case Kind::anti_parallel:
        {
          const double sign = k == Kind::parallel ? 1. : -1.;
          const V3     b0   = combine(u, uniform(-1.5, 1.5) * la, m, gap);
          set(zero,
              combine(u, la, zero, 0.),
              b0,
              combine(u, sign * lb, zero, 0.));
          break;
        }
      case Kind::collinear_overlapping:
        set(zero,
            combine(u, la, zero, 0.),
            combine(u, uniform(0., 1.) * la, zero, 0.),
            combine(u, (rng() % 2 ? 1. : -1.) * lb, zero, 0.));
        exact = 0.;
        break;
      case Kind::collinear_disjoint:
        {
          const double sign = rng() % 2 ? 1. : -1.;
          set(zero,
              combine(u, la, zero, 0.),
              combine(u, la + gap + (sign < 0 ? lb : 0.), zero, 0.),
              combine(u, sign * lb, zero, 0.));
          exact = gap;
          break;
        }
      case Kind::nearly_parallel:
      case Kind::nearly_parallel_inside:
        {
          // eb along cos(phi) u + sin(phi) w, phi = 10^[-12, -1]; inside:
          // the lines' closest points at s, t in (0.1, 0.9), gap apart along
          // the common normal.
          const double phi  = std::pow(10., uniform(-12., -1.));
          const V3     w    = orthogonal(u, rng);
          const double sign = rng() % 2 ? 1. : -1.;
          const V3     v  = combine(u, sign * std::cos(phi), w, std::sin(phi));
          const V3     eb = combine(v, lb, zero, 0.);
          if (k == Kind::nearly_parallel)
            set(zero,
                combine(u, la, zero, 0.),
                combine(u, uniform(-1.5, 1.5) * la, orthogonal(u, rng), gap),
                eb);
          else
            {
              // n = u x w is normal to both lines.
              const V3 n{{u[1] * w[2] - u[2] * w[1],
                          u[2] * w[0] - u[0] * w[2],
                          u[0] * w[1] - u[1] * w[0]}};
              const V3 p = combine(u, uniform(0.1, 0.9) * la, n, gap);
              set(zero,
                  combine(u, la, zero, 0.),
                  combine(p, 1., eb, -uniform(0.1, 0.9)),
                  eb);
            }
          break;
        }
      default:
        break;
      }
    return {x, exact};
  }

  /// The relative errors of the Sacado gradient and Hessian of @p f (a
  /// function of the pair's coordinates for any number type) against
  /// Richardson-extrapolated central differences with step @p h; false in
  /// .second if the case of the pair differs at a perturbed point.
  template <typename F>
  std::pair<std::array<double, 2>, bool>
  derivative_errors(const X &x, const F &f, const double h)
  {
    using Inner             = Sacado::Fad::SFad<double, 12>;
    using Outer             = Sacado::Fad::SFad<Inner, 12>;
    const DistanceCase    c = classify_edge_edge(x);
    std::array<Outer, 12> y;
    for (unsigned int i = 0; i < 12; ++i)
      y[i] = Outer(12, i, Inner(12, i, x[i]));
    const Outer e    = f(c, y);
    const auto  same = [&](const DistanceCase &k) {
      return k.type == c.type && k.p == c.p;
    };
    const auto gradient = [&](const X &z) {
      std::array<Inner, 12> w;
      for (unsigned int i = 0; i < 12; ++i)
        w[i] = Inner(12, i, z[i]);
      const Inner            v = f(c, w);
      std::array<double, 12> g;
      for (unsigned int i = 0; i < 12; ++i)
        g[i] = v.dx(i);
      return g;
    };
    double g_error = 0., g_norm = 0., h_error = 0., h_norm = 0.;
    bool   smooth = true;
    for (unsigned int i = 0; i < 12; ++i)
      {
        std::array<double, 2>                 fd;
        std::array<std::array<double, 12>, 2> fd2;
        for (unsigned int r = 0; r < 2; ++r)
          {
            const double step = r == 0 ? h : h / 2.;
            X            plus = x, minus = x;
            plus[i] += step;
            minus[i] -= step;
            smooth = smooth && same(classify_edge_edge(plus)) &&
                     same(classify_edge_edge(minus));
            fd[r]         = (f(c, plus) - f(c, minus)) / (2. * step);
            const auto gp = gradient(plus), gm = gradient(minus);
            for (unsigned int j = 0; j < 12; ++j)
              fd2[r][j] = (gp[j] - gm[j]) / (2. * step);
          }
        const double g = (4. * fd[1] - fd[0]) / 3.;
        g_error        = std::max(g_error, std::abs(g - e.val().dx(i)));
        g_norm         = std::max(g_norm, std::abs(e.val().dx(i)));
        for (unsigned int j = 0; j < 12; ++j)
          {
            const double hij = (4. * fd2[1][j] - fd2[0][j]) / 3.;
            h_error          = std::max(h_error, std::abs(hij - e.dx(i).dx(j)));
            h_norm           = std::max(h_norm, std::abs(e.dx(i).dx(j)));
          }
      }
    return {{{g_norm > 0. ? g_error / g_norm : g_error,
              h_norm > 0. ? h_error / h_norm : h_error}},
            smooth};
  }

  void
  random_pairs(Checker &check)
  {
    check.section("random edge pairs against brute force");
    std::mt19937       rng(43);
    const unsigned int per_kind  = 1000;
    double             worst_all = 0., worst_fd_g = 0., worst_fd_h = 0.;
    double             worst_barrier_g = 0., worst_barrier_h = 0.;
    unsigned int       n_pairs = 0, n_smooth = 0, n_rough = 0;
    unsigned int       n_line_line_small_angle = 0;
    double             smallest_line_line_sine = 1.;
    for (int k = 0; k < static_cast<int>(Kind::n_kinds); ++k)
      for (const bool grid : {false, true})
        {
          const Kind kind = static_cast<Kind>(k);
          if (grid && !(kind == Kind::parallel || kind == Kind::anti_parallel ||
                        kind == Kind::collinear_overlapping ||
                        kind == Kind::collinear_disjoint))
            continue;
          double       worst = 0.;
          std::string  worst_text;
          unsigned int smooth_here = 0;
          for (unsigned int trial = 0; trial < per_kind; ++trial, ++n_pairs)
            {
              const auto [x, exact] = random_pair(kind, grid, rng);
              const double d = distance(x), bf = brute_force_distance(x);
              double       la2 = 0., lb2 = 0.;
              for (int dd = 0; dd < 3; ++dd)
                la2 += (x[3 + dd] - x[dd]) * (x[3 + dd] - x[dd]),
                  lb2 += (x[9 + dd] - x[6 + dd]) * (x[9 + dd] - x[6 + dd]);
              const double length = std::sqrt(std::max(la2, lb2));
              // Relative error; collinear overlapping (distance 0): of the
              // edge length.
              const double error = kind == Kind::collinear_overlapping
                                     ? std::abs(d - bf) / length
                                     : std::abs(d - bf) / bf;
              if (!(error <= worst))
                {
                  worst = error;
                  std::ostringstream s;
                  s.precision(17);
                  s << "worst: distance " << d << ", brute force " << bf
                    << ", constructed " << exact << ", case "
                    << classify_edge_edge(x).type << ", x =";
                  for (const double v : x)
                    s << ' ' << v;
                  worst_text = s.str();
                }
              // The constructed distance agrees too (to the rounding of the
              // construction, as the brute force's own check).
              if (exact > 0. && std::abs(bf - exact) > 1e-9 * exact)
                worst = std::max(worst, 1.); // a broken brute force fails
              if (kind == Kind::collinear_overlapping)
                continue;
              const DistanceCase c = classify_edge_edge(x);
              if (c.type == DistanceCase::line_line &&
                  edge_cross_square(x) < 1e-12 * la2 * lb2)
                ++n_line_line_small_angle;
              // Derivatives of d^2 and of the mollified barrier (d_hat
              // 2 d, eps_x = 1e-3 |ea|^2 |eb|^2), step 1e-4 d.
              const double h              = 1e-4 * std::min(d, length);
              const auto [errors, smooth] = derivative_errors(
                x,
                [](const DistanceCase &c, const auto &y) {
                  return squared_distance<3>(c, y);
                },
                h);
              if (!smooth)
                {
                  ++n_rough;
                  continue;
                }
              ++n_smooth;
              if (c.type == DistanceCase::line_line)
                smallest_line_line_sine =
                  std::min(smallest_line_line_sine,
                           std::sqrt(edge_cross_square(x) / (la2 * lb2)));
              ++smooth_here;
              worst_fd_g         = std::max(worst_fd_g, errors[0]);
              worst_fd_h         = std::max(worst_fd_h, errors[1]);
              const double d_hat = 2. * d, eps_x = 1e-3 * la2 * lb2;
              const auto [barrier_errors, barrier_smooth] = derivative_errors(
                x,
                [&](const DistanceCase &c, const auto &y) {
                  using T = typename std::decay_t<decltype(y)>::value_type;
                  using std::log;
                  using std::sqrt;
                  const T dist = sqrt(squared_distance<3>(c, y));
                  T e = -(dist - d_hat) * (dist - d_hat) * log(dist / d_hat);
                  const T cs = edge_cross_square(y);
                  if (cs < eps_x)
                    e = e * (2. - cs / eps_x) * cs / eps_x;
                  return e;
                },
                h);
              // The mollified gradient vanishes with c = |ea x eb|^2 (it is
              // proportional to sin of the angle) while the energy's higher
              // derivatives do not: below c = 1e-6 eps_x the differences'
              // truncation error exceeds it (the Hessian is checked).
              if (edge_cross_square(x) >= 1e-6 * eps_x)
                worst_barrier_g = std::max(worst_barrier_g, barrier_errors[0]);
              worst_barrier_h = std::max(worst_barrier_h, barrier_errors[1]);
              // The pair barrier computes the same energy.
              const PairBarrier<12> b =
                pair_barrier<3>(x, c, d_hat, 1., eps_x, 0);
              const double dist = std::sqrt(squared_distance<3>(c, x));
              double       e =
                -(dist - d_hat) * (dist - d_hat) * std::log(dist / d_hat);
              const double cs = edge_cross_square(x);
              if (cs < eps_x)
                e = e * (2. - cs / eps_x) * cs / eps_x;
              if (!(std::abs(b.energy - e) <= 1e-12 * std::abs(e)))
                worst_barrier_g = std::max(worst_barrier_g, 1.);
              (void)barrier_smooth;
            }
          worst_all = std::max(worst_all, worst);
          if (!check.at_most(std::string(kind_name(kind)) +
                               (grid ? " (exact grid)" : "") +
                               ": largest relative distance error vs brute "
                               "force over " +
                               std::to_string(per_kind) + " pairs",
                             worst,
                             1e-12))
            check.note(worst_text);
          check.note(
            std::to_string(smooth_here) +
            " of them away from case boundaries (derivatives checked)");
        }
    check.at_least("random pairs checked", n_pairs, 10000);
    check.at_most("all kinds: largest relative distance error",
                  worst_all,
                  1e-12);
    check.note("line-line cases at |ea x eb|^2 < 1e-12 |ea|^2 |eb|^2: " +
               std::to_string(n_line_line_small_angle));
    check.section("derivatives against central differences (same case at "
                  "every perturbed point)");
    check.note(std::to_string(n_rough) +
               " pairs lie at or near a case boundary (tied endpoint cases of "
               "overlapping parallel edges, the line-line case's limits); the "
               "smallest angle's sine of a checked line-line pair: " +
               std::to_string(smallest_line_line_sine));
    check.at_least("pairs whose derivatives are checked", n_smooth, 5000);
    check.at_most("d^2: gradient vs FD (largest relative)", worst_fd_g, 1e-6);
    check.at_most("d^2: Hessian vs FD (largest relative)", worst_fd_h, 1e-6);
    check.at_most("mollified barrier: gradient vs FD (largest relative)",
                  worst_barrier_g,
                  1e-6);
    check.at_most("mollified barrier: Hessian vs FD (largest relative)",
                  worst_barrier_h,
                  1e-6);
  }

  /// The brute-force distance of the pair at x + t p.
  double
  distance_at(const X &x, const X &p, const double t)
  {
    X y = x;
    for (unsigned int i = 0; i < 12; ++i)
      y[i] += t * p[i];
    return brute_force_distance(y);
  }

  void
  collision_detection(Checker &check)
  {
    check.section("CCD of parallel edges");
    const double s = 0.1;
    // Edge a on the x axis; edge b (length 1) gap d0 away, moving at speed
    // v towards a (through it if nothing stopped it): impact at d0 / v.
    struct Motion
    {
      std::string name;
      X           x, p;
      double      d0, v;
    };
    const Motion motions[] = {
      {"parallel, coplanar, sideways",
       {{0., 0., 0., 1., 0., 0., 0.2, 0.05, 0., 1.2, 0.05, 0.}},
       {{0., 0., 0., 0., 0., 0., 0., -0.1, 0., 0., -0.1, 0.}},
       0.05,
       0.1},
      {"anti-parallel, skew offset",
       {{0., 0., 0., 1., 0., 0., 1.1, 0.03, 0.04, 0.3, 0.03, 0.04}},
       {{0., 0., 0., 0., 0., 0., 0., -0.06, -0.08, 0., -0.06, -0.08}},
       0.05,
       0.1},
      {"collinear, along the line",
       {{0., 0., 0., 1., 0., 0., 1.05, 0., 0., 2.05, 0., 0.}},
       {{0., 0., 0., 0., 0., 0., -0.1, 0., 0., -0.1, 0., 0.}},
       0.05,
       0.1},
      {"nearly parallel (1e-10), coplanar, sideways",
       {{0., 0., 0., 1., 0., 0., 0.2, 0.05, 0., 1.2, 0.05 + 1e-10, 0.}},
       {{0., 0., 0., 0., 0., 0., 0., -0.1, 0., 0., -0.1, 0.}},
       0.05,
       0.1}};
    for (const Motion &m : motions)
      {
        const CollisionTime r = additive_ccd<3>(m.x, m.p, true, s, 1.);
        const double        T = m.d0 / m.v;
        check.close(
          m.name + ": distance at the start", distance(m.x), m.d0, m.d0, 1e-12);
        check.at_most(m.name + ": step / (T - s d0 / v)",
                      r.t / (T - s * m.d0 / m.v),
                      1. + 1e-12);
        check.at_least(m.name + ": step / (T - 2 s d0 / v)",
                       r.t / (T - 2. * s * m.d0 / m.v),
                       1.);
        check.at_least(m.name + ": brute-force distance at the step / (s d0)",
                       distance_at(m.x, m.p, r.t) / (s * m.d0),
                       1. - 1e-9);
      }
    // Random motions of random parallel, anti-parallel, collinear and
    // nearly parallel pairs: the sampled distance on [0, t] stays >= s d0.
    std::mt19937                           rng(4343);
    std::uniform_real_distribution<double> u11(-1., 1.);
    double                                 worst = 1e300, worst_end = 1e300;
    unsigned int                           n = 0, limited = 0;
    for (const Kind kind : {Kind::parallel,
                            Kind::anti_parallel,
                            Kind::collinear_disjoint,
                            Kind::nearly_parallel,
                            Kind::nearly_parallel_inside})
      for (const bool grid : {false, true})
        for (unsigned int trial = 0; trial < 40; ++trial, ++n)
          {
            const auto [x, exact] = random_pair(kind, grid, rng);
            const double d0       = brute_force_distance(x);
            double       size     = 0.;
            for (int d = 0; d < 3; ++d)
              size = std::max(size, std::abs(x[3 + d] - x[d]));
            // Both edges translate (the second towards and past the first),
            // each end a little differently.
            X p;
            for (unsigned int i = 0; i < 12; ++i)
              p[i] = 0.1 * size * u11(rng);
            for (int d = 0; d < 3; ++d)
              {
                const double towards = 3. * (x[d] - x[6 + d]);
                p[6 + d] += towards;
                p[9 + d] += towards;
              }
            const CollisionTime r = additive_ccd<3>(x, p, true, s, 1.);
            limited += r.t < 1. ? 1 : 0;
            worst_end = std::min(worst_end, distance_at(x, p, r.t) / (s * d0));
            for (unsigned int k = 0; k <= 200; ++k)
              worst =
                std::min(worst, distance_at(x, p, r.t * k / 200.) / (s * d0));
          }
    check.at_least("random parallel motions checked", n, 400);
    check.at_least("random parallel motions limited by CCD", limited, 200);
    check.at_least("random parallel motions: brute-force distance at t / "
                   "(s d0)",
                   worst_end,
                   1. - 1e-9);
    // Within [0, t] each advancement keeps a tenth of the distance it
    // started from (>= s d0), so the pair never comes closer than s d0 / 10
    // (nor passes through).
    check.at_least("random parallel motions: smallest sampled distance / "
                   "(s d0) on [0, t]",
                   worst,
                   0.1);
  }

  void
  concentric_chords(Checker &check)
  {
    check.section("the bug report: chords of concentric circles 0.02 apart");
    // Radius 12 and 12.02 in the plane y = 0, 40 equal angles of a
    // quarter: the chords of equal angles are parallel and coplanar.
    double       smallest = 1e300, worst = 0.;
    const double r1 = 12., r2 = 12.02;
    const int    n = 40;
    for (int k = 0; k < n; ++k)
      for (int j = std::max(k - 1, 0); j <= std::min(k + 1, n - 1); ++j)
        {
          const double t0 = M_PI / 2 * k / n, t1 = M_PI / 2 * (k + 1) / n;
          const double s0 = M_PI / 2 * j / n, s1 = M_PI / 2 * (j + 1) / n;
          const X      x{{r1 * std::sin(t0),
                          0.,
                          r1 * std::cos(t0),
                          r1 * std::sin(t1),
                          0.,
                          r1 * std::cos(t1),
                          r2 * std::sin(s0),
                          0.,
                          r2 * std::cos(s0),
                          r2 * std::sin(s1),
                          0.,
                          r2 * std::cos(s1)}};
          const double d = distance(x), bf = brute_force_distance(x);
          smallest = std::min(smallest, d);
          worst    = std::max(worst, std::abs(d - bf) / bf);
        }
    // The chords of equal angles: 0.02 cos(pi / 160).
    check.close("smallest chord distance against 0.02 cos(pi / 160)",
                smallest,
                0.02 * std::cos(M_PI / 160.),
                0.02,
                1e-12);
    check.at_most("chords: largest relative error vs brute force",
                  worst,
                  1e-12);
  }
} // namespace

int
main()
{
  Checker    check;
  const auto start = std::chrono::steady_clock::now();
  random_pairs(check);
  collision_detection(check);
  concentric_chords(check);
  check.note("run time " +
             std::to_string(std::chrono::duration<double>(
                              std::chrono::steady_clock::now() - start)
                              .count()) +
             " s");
  return check.exit_code();
}
