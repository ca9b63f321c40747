// Unit test of the barrier without double counting
// (contact/duplicate_counting.h):
//   a. a point at gap h in (0, d_hat) above a straight 2D boundary of uneven
//      segments, or a flat 3D one of uneven triangles (d_hat larger than the
//      mesh spacing, so many pairs are active): the pairs' energies with
//      their corrections sum to b(h) (relative 1e-12) wherever the point is,
//      above vertices and edges included, and the tangential force vanishes
//      (1e-10 of the normal one); without the corrections the sum is off by
//      more than 10 % (the double counting the corrections remove);
//   b. gradients and Hessians of corrected pairs (random corrections,
//      points near the triangle's and segment's features, edge-edge pairs)
//      against central differences of the energy and gradient (1e-6);
//   c. the sharp edges of a meshed box: its 12 edges, not its faces'
//      diagonals.
#include <hyperelastic/contact/duplicate_counting.h>

#include "support/checker.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace
{
  using namespace hyperelastic;
  using hyperelastic::testing::Checker;

  constexpr double d_hat = 0.3;

  /// A flat boundary: the vertices (the last one is the point p), faces,
  /// and the incidence.
  template <int dim>
  struct Flat
  {
    std::vector<std::array<double, dim>>       points;
    std::vector<std::array<unsigned int, dim>> faces;
  };

  /// 2D: 21 vertices along y = 0, spacing 0.1 give or take 0.03.
  Flat<2>
  line()
  {
    Flat<2> f;
    for (unsigned int i = 0; i <= 20; ++i)
      f.points.push_back({{0.1 * i + 0.013 * (i % 3), 0.}});
    for (unsigned int i = 0; i < 20; ++i)
      f.faces.push_back({{i, i + 1}});
    f.points.push_back({{0., 0.}}); // p
    return f;
  }

  /// 3D: a 12 x 12 grid in z = 0, spacing 0.1 moved randomly by up to
  /// 0.02, cut into triangles along alternating diagonals.
  Flat<3>
  plane()
  {
    Flat<3>                                f;
    std::mt19937                           random(1);
    std::uniform_real_distribution<double> jitter(-0.02, 0.02);
    const unsigned int                     n = 12;
    for (unsigned int j = 0; j <= n; ++j)
      for (unsigned int i = 0; i <= n; ++i)
        f.points.push_back(
          {{0.1 * i + jitter(random), 0.1 * j + jitter(random), 0.}});
    const auto id = [&](unsigned int i, unsigned int j) {
      return j * (n + 1) + i;
    };
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        if ((i + j) % 2)
          {
            f.faces.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
            f.faces.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
          }
        else
          {
            f.faces.push_back({{id(i, j), id(i + 1, j), id(i, j + 1)}});
            f.faces.push_back({{id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}});
          }
    f.points.push_back({{0., 0., 0.}}); // p
    return f;
  }

  /// The energy of point p = @p x against every face of @p flat (with or
  /// without the corrections) and its gradient in p.
  template <int dim>
  std::pair<double, std::array<double, dim>>
  point_energy(const Flat<dim>               &flat,
               const BoundaryIncidence<dim>  &incidence,
               const std::array<double, dim> &x,
               const bool                     corrected)
  {
    constexpr std::size_t   n      = (dim + 1) * dim;
    const unsigned int      p      = flat.points.size() - 1;
    double                  energy = 0.;
    std::array<double, dim> gradient{};
    for (unsigned int f = 0; f < flat.faces.size(); ++f)
      {
        std::array<double, n> c;
        for (unsigned int d = 0; d < dim; ++d)
          c[d] = x[d];
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int d = 0; d < dim; ++d)
            c[(k + 1) * dim + d] = flat.points[flat.faces[f][k]][d];
        const PairTerms terms =
          corrected ? pair_terms<dim>(c, false, incidence.point_face(p, f))
                    : pair_terms<dim>(c, false, PairCorrection{});
        const PairBarrier<n> b = pair_barrier<dim>(c, terms, d_hat, 1., 0., 1);
        energy += b.energy;
        for (unsigned int d = 0; d < dim; ++d)
          gradient[d] += b.gradient[d];
      }
    return {energy, gradient};
  }

  template <int dim>
  void
  flat_boundary(Checker &checker, const Flat<dim> &flat)
  {
    const BoundaryIncidence<dim> incidence(flat.faces, flat.points);
    const std::string tag   = std::to_string(dim) + "D flat boundary: ";
    double            worst = 0., tangential = 0., uncorrected = 0.;
    for (const double h : {0.2 * d_hat, 0.5 * d_hat, 0.9 * d_hat})
      {
        const double b = barrier(h, d_hat).value;
        // Along the boundary, through vertices and edges: dim == 2 sweeps
        // x in [0.7, 1.3]; dim == 3 a grid over [0.5, 0.7]^2 and the
        // vertices themselves.
        std::vector<std::array<double, dim>> places;
        if constexpr (dim == 2)
          {
            for (double x = 0.7; x < 1.3; x += 0.00731)
              places.push_back({{x, h}});
            for (unsigned int i = 7; i <= 13; ++i)
              places.push_back({{flat.points[i][0], h}});
          }
        else
          {
            for (double x = 0.5; x < 0.7; x += 0.0173)
              for (double y = 0.5; y < 0.7; y += 0.0191)
                places.push_back({{x, y, h}});
            for (const unsigned int v : {71u, 72u, 84u, 85u})
              places.push_back({{flat.points[v][0], flat.points[v][1], h}});
          }
        for (const auto &x : places)
          {
            const auto [e, g] = point_energy<dim>(flat, incidence, x, true);
            worst             = std::max(worst, std::abs(e / b - 1.));
            for (int d = 0; d + 1 < dim; ++d)
              tangential = std::max(tangential, std::abs(g[d] / g[dim - 1]));
            uncorrected = std::max(
              uncorrected,
              std::abs(point_energy<dim>(flat, incidence, x, false).first / b -
                       1.));
          }
      }
    checker.at_most(tag + "|sum of the corrected pairs / b(h) - 1|",
                    worst,
                    1e-12);
    checker.at_most(tag + "|tangential force| / |normal force|",
                    tangential,
                    1e-10);
    checker.above(tag + "without the corrections: |sum / b(h) - 1|",
                  uncorrected,
                  0.1);
  }

  /// Central differences of the energy and gradient of a corrected pair
  /// against its gradient and Hessian: the largest relative errors.
  template <int dim, std::size_t n>
  std::pair<double, double>
  derivative_errors(const std::array<double, n> &x,
                    const bool                   edge_edge,
                    const PairCorrection        &correction,
                    const double                 mollifier)
  {
    const auto at = [&](const std::array<double, n> &y, unsigned int order) {
      return pair_barrier<dim>(y,
                               pair_terms<dim>(y, edge_edge, correction),
                               d_hat,
                               1.,
                               mollifier,
                               order);
    };
    const PairBarrier<n> exact   = at(x, 2);
    const double         step    = 1e-6 * d_hat;
    double               g_error = 0., g_norm = 0., h_error = 0., h_norm = 0.;
    for (unsigned int i = 0; i < n; ++i)
      {
        std::array<double, n> plus = x, minus = x;
        plus[i] += step;
        minus[i] -= step;
        const double fd =
          (at(plus, 0).energy - at(minus, 0).energy) / (2. * step);
        g_error       = std::max(g_error, std::abs(fd - exact.gradient[i]));
        g_norm        = std::max(g_norm, std::abs(exact.gradient[i]));
        const auto gp = at(plus, 1), gm = at(minus, 1);
        for (unsigned int j = 0; j < n; ++j)
          {
            h_error = std::max(h_error,
                               std::abs((gp.gradient[j] - gm.gradient[j]) /
                                          (2. * step) -
                                        exact.hessian[j][i]));
            h_norm  = std::max(h_norm, std::abs(exact.hessian[j][i]));
          }
      }
    return {g_error / g_norm, h_error / h_norm};
  }

  void
  derivatives(Checker &checker)
  {
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> unit(-1., 1.);
    std::uniform_real_distribution<double> share(-1., 0.5);
    double                                 g2 = 0., h2 = 0., g3 = 0., h3 = 0.;
    unsigned int                           tried = 0;
    for (unsigned int k = 0; k < 200; ++k)
      {
        PairCorrection c;
        for (double &v : c)
          v = share(random);
        // 2D: p above the segment [0, 0]-[0.2, 0], within d_hat of its
        // ends; 3D: p above the triangle (0,0,0), (0.2,0,0), (0,0.2,0),
        // and two crossing edges 0.1 apart.
        std::array<double, 6>  x2 = {{0.1 + 0.2 * unit(random),
                                      0.05 + 0.04 * unit(random),
                                      0.,
                                      0.,
                                      0.2,
                                      0.}};
        std::array<double, 12> x3 = {{0.07 + 0.15 * unit(random),
                                      0.07 + 0.15 * unit(random),
                                      0.06 + 0.04 * unit(random),
                                      0.,
                                      0.,
                                      0.,
                                      0.2,
                                      0.,
                                      0.,
                                      0.,
                                      0.2,
                                      0.}};
        std::array<double, 12> e3 = {{-0.1,
                                      0.05 * unit(random),
                                      0.,
                                      0.1,
                                      0.05 * unit(random),
                                      0.,
                                      0.05 * unit(random),
                                      -0.1,
                                      0.1,
                                      0.05 * unit(random),
                                      0.1,
                                      0.08 + 0.02 * unit(random)}};
        const auto [a2, b2]       = derivative_errors<2>(x2, false, c, 0.);
        const auto [a3, b3]       = derivative_errors<3>(x3, false, c, 0.);
        const auto [a4, b4] =
          derivative_errors<3>(e3, true, c, 1e-3 * 0.04 * 0.04);
        g2 = std::max(g2, a2), h2 = std::max(h2, b2);
        g3 = std::max({g3, a3, a4}), h3 = std::max({h3, b3, b4});
        ++tried;
      }
    checker.at_most("2D corrected pairs: gradient error", g2, 1e-6);
    checker.at_most("2D corrected pairs: Hessian error", h2, 1e-6);
    checker.at_most("3D corrected pairs: gradient error", g3, 1e-6);
    checker.at_most("3D corrected pairs: Hessian error", h3, 1e-6);
    checker.note("pairs checked: " + std::to_string(tried) + " of each kind");
  }

  void
  box_edges(Checker &checker)
  {
    // The unit cube's 8 corners, each face cut along one diagonal.
    std::vector<std::array<double, 3>> points;
    for (unsigned int v = 0; v < 8; ++v)
      points.push_back({{double(v & 1), double((v >> 1) & 1), double(v >> 2)}});
    const std::vector<std::array<unsigned int, 4>> quads = {{{0, 1, 3, 2}},
                                                            {{4, 5, 7, 6}},
                                                            {{0, 1, 5, 4}},
                                                            {{2, 3, 7, 6}},
                                                            {{0, 2, 6, 4}},
                                                            {{1, 3, 7, 5}}};
    std::vector<std::array<unsigned int, 3>>       faces;
    for (const auto &q : quads)
      {
        faces.push_back({{q[0], q[1], q[2]}});
        faces.push_back({{q[0], q[2], q[3]}});
      }
    const BoundaryIncidence<3> incidence(faces, points);
    unsigned int               sharp = 0, flat = 0;
    for (unsigned int v = 0; v < 8; ++v)
      for (unsigned int w = v + 1; w < 8; ++w)
        if (incidence.sharp(v, w))
          sharp += __builtin_popcount(v ^ w) == 1 ? 1 : 100; // diagonal: 100
    for (const auto &q : quads)
      flat += !incidence.sharp(q[0], q[2]);
    checker.is_true("box: the 12 cube edges sharp, no face diagonal (" +
                      std::to_string(sharp) + ")",
                    sharp == 12);
    checker.is_true("box: the 6 face diagonals flat (" + std::to_string(flat) +
                      ")",
                    flat == 6);
  }
} // namespace

int
main()
{
  Checker checker;
  flat_boundary<2>(checker, line());
  flat_boundary<3>(checker, plane());
  derivatives(checker);
  box_edges(checker);
  return checker.exit_code();
}
