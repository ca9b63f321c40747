// What a Newton solve reports: one row per iteration (the printed table) and
// the totals of a solve. Plain data, read by the step summary and the tests.
#pragma once

#include <limits>
#include <vector>

namespace hyperelastic
{
  /// One row of the Newton table.
  struct NewtonIteration
  {
    unsigned int iteration   = 0;
    double       residual    = 0.;
    double       update      = 0.; ///< norm of the step taken
    double       step_length = 1.; ///< alpha of the line search
    unsigned int backtracks  = 0;  ///< trials rejected before it
    /// The longest step that keeps the state feasible (contact), where the
    /// line search started; 1 without such a limit.
    double       feasible_step     = 1.;
    unsigned int linear_iterations = 0;
    /// Relative Krylov tolerance asked for (0: the linear solver's own).
    double forcing   = 0.;
    bool   projected = false; ///< tangent made semi-definite everywhere
    /// dP/dF projected at the quadrature points with J <= 0 only.
    bool projected_where_inverted = false;
    /// The predictor's update inverted cells and was replaced by the
    /// increment extended at zero Poisson's ratio
    /// (PredictorSoftening).
    bool softened_predictor = false;
    /// The trust region's radius this iteration was solved in (NaN: a
    /// Newton step with line search, no trust region).
    double trust_radius = std::numeric_limits<double>::quiet_NaN();
    /// The truncated CG met negative curvature (the tangent is indefinite)
    /// and the step follows it.
    bool negative_curvature = false;
    /// The converged state of this (last) iteration was probed for
    /// negative curvature of the exact tangent and none was found
    /// (Newton/Follow negative curvature): a minimum, not a saddle.
    bool probed_stable = false;
    /// Whether the energy had to decrease (sufficient decrease) in this
    /// iteration's line search; false while prescribed displacements are
    /// still being imposed or without a line search.
    bool   energy_tested = false;
    double energy_before = std::numeric_limits<double>::quiet_NaN();
    double energy        = std::numeric_limits<double>::quiet_NaN();
    double energy_noise  = 0.;
    double min_J         = std::numeric_limits<double>::quiet_NaN();
    /// The residual norm of the accepted trial, when the line search
    /// tested it (systems without a potential).
    double trial_residual = std::numeric_limits<double>::quiet_NaN();
  };

  struct NewtonResult
  {
    std::vector<NewtonIteration> history;
    /// The line search tested the residual norm (no total potential)
    /// instead of the energy.
    bool residual_merit = false;
    /// Arc length: the tangent's stiffness along the path at the converged
    /// state over the unloaded one's (CSV column 'stability': 1 unloaded,
    /// 0 at a maximum of the load, negative beyond).
    double stability = std::numeric_limits<double>::quiet_NaN();
    unsigned int
    iterations() const
    {
      return history.size();
    }
    unsigned int
    linear_iterations() const;
    unsigned int
    backtracks() const;
  };
} // namespace hyperelastic
