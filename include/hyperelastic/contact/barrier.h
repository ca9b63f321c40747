// The log barrier of Incremental Potential Contact (Li et al. 2020) as a pure
// function of a distance d and its activation distance d_hat:
//   b(d) = -(d - d_hat)^2 ln(d / d_hat)   for 0 < d < d_hat, 0 beyond,
// C2 at d_hat and infinite at d = 0, so a state of finite energy keeps every
// distance positive. b'(d) < 0 (repulsive) and b''(d) > 0 inside.
#pragma once

#include <cmath>
#include <limits>

namespace hyperelastic
{
  struct Barrier
  {
    double value      = 0.; ///< b(d)
    double derivative = 0.; ///< b'(d)
    double second     = 0.; ///< b''(d)
  };

  /// b, b' and b'' at @p d (+infinity and NaN derivatives for d <= 0).
  inline Barrier
  barrier(const double d, const double d_hat)
  {
    Barrier b;
    if (d >= d_hat)
      return b;
    if (!(d > 0.))
      {
        b.value      = std::numeric_limits<double>::infinity();
        b.derivative = std::numeric_limits<double>::quiet_NaN();
        b.second     = std::numeric_limits<double>::quiet_NaN();
        return b;
      }
    const double g   = d - d_hat; // < 0
    const double log = std::log(d / d_hat);
    b.value          = -g * g * log;
    b.derivative     = -2. * g * log - g * g / d;
    b.second         = -2. * log - 4. * g / d + g * g / (d * d);
    return b;
  }
} // namespace hyperelastic
