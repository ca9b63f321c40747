// The smoothed Coulomb friction of IPC (Li et al. 2020, section 5) as pure
// functions of the slip magnitude y = |s| and the smoothing eps:
//   f1(y) = 2 y / eps - y^2 / eps^2 for y < eps, 1 beyond (the friction
//           force is mu lambda f1, along -s: it grows from 0 to mu lambda
//           over a slip eps, then the contact slides),
//   f0(y) = -y^3 / (3 eps^2) + y^2 / eps + eps / 3 for y < eps, y beyond
//           (f0' = f1; the dissipation potential is mu lambda f0).
// With s the slip vector in the tangent plane (projection P), the potential
// mu lambda f0(|s|) has the gradient mu lambda (f1 / y) s and the Hessian
// mu lambda ((f1 / y) P + c s s^T), c = (f1' y - f1) / y^3; both
// coefficients are returned, and the Hessian is positive semi-definite.
#pragma once

namespace hyperelastic
{
  struct SmoothedFriction
  {
    double f0 = 0.; ///< f0(y)
    /// f1(y) / y (its limit 2 / eps at y = 0).
    double f1_over_y = 0.;
    /// c = (f1'(y) y - f1(y)) / y^3 (c s s^T -> 0 as y -> 0: 0 there).
    double c = 0.;
  };

  inline SmoothedFriction
  smoothed_friction(const double y, const double eps)
  {
    SmoothedFriction f;
    if (y < eps)
      {
        f.f0        = -y * y * y / (3. * eps * eps) + y * y / eps + eps / 3.;
        f.f1_over_y = 2. / eps - y / (eps * eps);
        f.c         = y > 0. ? -1. / (eps * eps * y) : 0.;
        return f;
      }
    f.f0        = y;
    f.f1_over_y = 1. / y;
    f.c         = -1. / (y * y * y);
    return f;
  }
} // namespace hyperelastic
