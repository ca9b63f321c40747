// A capability that only some nonlinear systems have: solves of the tangent's
// quadratic model in a trust region (Steihaug-Toint truncated CG, which
// follows negative curvature) and a probe for negative curvature. Newton's
// automatic tangent uses it where NonlinearSystem::Properties::trust_region.
#pragma once

#include <hyperelastic/solvers/nonlinear_system.h>

namespace hyperelastic
{
  // capability interface
  class TrustRegionSystem
  {
  public:
    virtual ~TrustRegionSystem() = default;

    /// What solve_linearization_in_trust_region() found.
    struct Step
    {
      /// The Krylov method met negative curvature: the tangent is
      /// indefinite, and du follows such a direction to the boundary.
      bool negative_curvature = false;
      /// |du| = radius.
      bool on_boundary = false;
      /// du^T K du: the quadratic model predicts the energy change
      /// alpha g^T du + alpha^2 curvature / 2 for the step alpha du.
      double curvature = 0.;
      /// |du|.
      double norm = 0.;
    };

    /// Like NonlinearSystem::solve_linearization() (never for the
    /// linearization that imposes the constraint increment), but du
    /// approximately minimizes the tangent's quadratic model of the energy
    /// within |du| <= @p radius: along a direction of negative curvature it
    /// goes to the boundary instead of failing.
    virtual void
    solve_linearization_in_trust_region(
      double                               forcing,
      double                               radius,
      NonlinearSystem::LinearizationSolve &solve,
      Step                                &step) = 0;

    /// Whether the exact tangent at the current iterate has a direction of
    /// negative curvature (a saddle, not a minimum), as far as a Krylov
    /// probe finds one (truncated CG from a fixed pseudo-random right-hand
    /// side). Overwrites the last linearization.
    virtual bool
    has_negative_curvature() = 0;
  };
} // namespace hyperelastic
