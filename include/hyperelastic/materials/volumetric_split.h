// The volumetric-isochoric split psi(F) = psi_iso(F) + U(J) of the decoupled
// models, as the displacement-pressure (mixed) formulation uses it.
//
// The pressure is coupled through the Legendre transform of U: with
//   U*(p) = sup_J [p (J - 1) - U(J)],
// the two-field functional
//   Pi(u, p) = int psi_iso(F) + p (J - 1) - U*(p) dV - W_ext(u)
// is stationary in p where J - 1 = U*'(p), i.e. p = U'(J): eliminating p
// point by point gives back int psi(F) dV exactly, for any convex U. p is
// then the Cauchy mean stress (positive in tension): P = P_iso + p J F^-T.
// For U = kappa/2 (J - 1)^2 this is the perturbed Lagrangian of Simo and
// Taylor (U* = p^2 / (2 kappa)); kappa = infinity gives U* = 0 and p is the
// Lagrange multiplier of J = 1.
//
// The models here share U(J) = kappa/4 (J^2 - 1 - 2 ln J):
//   U'(J) = kappa/2 (J - 1/J),  U''(J) = kappa/2 (1 + 1/J^2),
// and U'(J) = p is solved by J*(p) = p/kappa + sqrt((p/kappa)^2 + 1), so
//   U*'(p) = J*(p) - 1,  U*''(p) = dJ*/dp = 1 / U''(J*(p)),
//   U*(p) = p (J*(p) - 1) - U(J*(p)).
#pragma once

#include <cmath>
#include <limits>
#include <memory>

namespace hyperelastic
{
  /// U(J) = kappa/4 (J^2 - 1 - 2 ln J) and its conjugate U*(p); kappa may be
  /// +infinity (exact incompressibility: U* = 0).
  class LogVolumetricEnergy
  {
  public:
    explicit LogVolumetricEnergy(const double kappa)
        : kappa(kappa)
    {
    }

    double
    bulk_modulus() const
    {
      return kappa;
    }

    bool
    incompressible() const
    {
      return std::isinf(kappa);
    }

    /// J*(p): the J at which U'(J) = p (1 when incompressible).
    double
    conjugate_J(const double p) const
    {
      if (incompressible())
        return 1.;
      const double s = p / kappa;
      // s + sqrt(s^2 + 1) written to avoid cancellation for s < 0.
      return s >= 0. ? s + std::sqrt(s * s + 1.) : 1. / (std::sqrt(s * s + 1.) - s);
    }

    /// dJ*/dkappa at fixed p: with s = p / kappa, J* = s + sqrt(s^2 + 1),
    /// dJ*/ds = J* / sqrt(s^2 + 1) and ds/dkappa = -s / kappa (0 when
    /// incompressible).
    double
    conjugate_J_bulk_derivative(const double p) const
    {
      if (incompressible())
        return 0.;
      const double s = p / kappa;
      return -conjugate_J(p) * s / (kappa * std::sqrt(s * s + 1.));
    }

    /// U*'(p) = J*(p) - 1.
    double
    conjugate_derivative(const double p) const
    {
      return conjugate_J(p) - 1.;
    }

    /// U*''(p) = 1 / U''(J*(p)) (0 when incompressible).
    double
    conjugate_second_derivative(const double p) const
    {
      if (incompressible())
        return 0.;
      const double J = conjugate_J(p);
      return 2. * J * J / (kappa * (J * J + 1.));
    }

    /// U*(p) = p (J* - 1) - U(J*).
    double
    conjugate(const double p) const
    {
      if (incompressible())
        return 0.;
      const double J = conjugate_J(p);
      return p * (J - 1.) - 0.25 * kappa * ((J - 1.) * (J + 1.) - 2. * std::log(J));
    }

  private:
    double kappa;
  };

  template <int dim>
  class Material;

  /// A model split into its isochoric part (the same model with a zero bulk
  /// modulus: a Material of its own) and its volumetric energy.
  template <int dim>
  struct VolumetricSplit
  {
    std::unique_ptr<Material<dim>> isochoric;
    LogVolumetricEnergy            volumetric;
  };
} // namespace hyperelastic
