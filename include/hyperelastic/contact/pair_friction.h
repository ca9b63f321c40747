// Lagged friction of a self-contact pair (IPC, Li et al. 2020, section 5) as
// a pure function of the pair's coordinates. With the closest-point
// coefficients beta (closest_point_coefficients()) and the unit normal n
// lagged from a known state, and the normal force lambda lagged with them,
// the pair's tangential slip over the step is
//   s = P sum_i beta_i (x_i - x_i^start),   P = I - n n^T,
// and its dissipation potential mu lambda f0(|s|) (contact/friction.h) has
// the gradient beta_i mu lambda (f1 / y) s on point i and the Hessian blocks
//   beta_i beta_j mu lambda ((f1 / y) P + c s s^T)   (y = |s|),
// positive semi-definite by construction.
#pragma once

#include <hyperelastic/contact/friction.h>
#include <hyperelastic/contact/primitive_distance.h>

#include <array>
#include <cmath>
#include <cstddef>

namespace hyperelastic
{
  /// The friction energy mu lambda f0(|s|) of a pair (n coordinates, n /
  /// dim points) at @p x with start positions @p x_start, lagged
  /// coefficients @p beta and unit normal @p normal, @p scale = mu lambda,
  /// smoothing @p eps; the gradient with @p order >= 1, the Hessian with 2.
  /// (The result's distance is left at 0.)
  template <int dim, std::size_t n>
  PairBarrier<n>
  pair_friction(const std::array<double, n>       &x,
                const std::array<double, n>       &x_start,
                const std::array<double, n / dim> &beta,
                const std::array<double, dim>     &normal,
                const double                       scale,
                const double                       eps,
                const unsigned int                 order)
  {
    constexpr std::size_t   n_points = n / dim;
    std::array<double, dim> s{};
    for (std::size_t i = 0; i < n_points; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        s[d] += beta[i] * (x[i * dim + d] - x_start[i * dim + d]);
    double along = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      along += s[d] * normal[d];
    double y2 = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        s[d] -= along * normal[d];
        y2 += s[d] * s[d];
      }
    const SmoothedFriction f = smoothed_friction(std::sqrt(y2), eps);
    PairBarrier<n>         result;
    result.energy = scale * f.f0;
    if (order == 0)
      return result;
    for (std::size_t i = 0; i < n_points; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        result.gradient[i * dim + d] = beta[i] * scale * f.f1_over_y * s[d];
    if (order == 1)
      return result;
    // The dim x dim block (f1 / y) P + c s s^T, scaled by beta_i beta_j.
    std::array<std::array<double, dim>, dim> block;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        block[a][b] =
          scale * (f.f1_over_y * ((a == b ? 1. : 0.) - normal[a] * normal[b]) +
                   f.c * s[a] * s[b]);
    for (std::size_t i = 0; i < n_points; ++i)
      for (std::size_t j = 0; j < n_points; ++j)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            result.hessian[i * dim + a][j * dim + b] =
              beta[i] * beta[j] * block[a][b];
    return result;
  }
} // namespace hyperelastic
