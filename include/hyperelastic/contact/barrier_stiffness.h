// The barrier stiffness kappa of a contact term and its operating point
// (issue 67, item 3). A pair carrying the normal force lambda sits where
// kappa w (-b'(d)) = lambda, b(d) = -(d - d_hat)^2 ln(d / d_hat): with
// x = d / d_hat, -b'(d) = d_hat g(x), g(x) = 2 (1 - x) (-ln x) + (1 - x)^2 / x
// (force_factor()). Near d_hat (x above 0.7) the force grows as (1 - x)^2:
// Newton gains about a bit an iteration there, and the working layer
// d_hat - d is thinner than the sag of a P1 chord of a curved boundary, so
// pairs switch on and off as the kinks of a sliding boundary pass. Deep
// inside (x below 0.3) the barrier is stiff and the gaps small.
//
// Automatic kappa (quasi-static scenes, 'Contact/Barrier stiffness = 0'):
// it starts where the pressure (lambda + 2 mu) d_hat / h that compresses a
// boundary element of the mean size h by d_hat holds a pair at d_hat / 2
// (barrier_settings(): the element's stiffness across d_hat), and is
// re-targeted between steps only: where the smallest distance of the
// converged state lies outside [lowest, highest] d_hat, kappa is scaled by
// g(x) / g(target), the factor that puts a pair of that normal force at
// target d_hat (at most a factor of 8 a step; within [1e-3, 1e3] of the
// start), so that the most pressed pairs work in the middle of the
// barrier's range. A given kappa, and dynamics (whose energy a change of
// kappa would not conserve), keep kappa fixed. The intersection-free
// guarantee does not depend on kappa.
#pragma once

namespace hyperelastic
{
  class BarrierStiffness
  {
  public:
    /// The band of the smallest converged distance over d_hat that is left
    /// alone, and the distance ratio a re-target aims at.
    static constexpr double lowest = 0.25, target = 0.5, highest = 0.75;
    /// The largest change of kappa in one re-target, and how far kappa may
    /// go from its start.
    static constexpr double largest_factor = 8., range = 1e3;

    /// -b'(x d_hat) / d_hat, for 0 < x < 1 (0 at and beyond 1).
    static double
    force_factor(double x);

    BarrierStiffness() = default;
    /// @p kappa the start; re-targeted only if @p adaptive.
    BarrierStiffness(double kappa, bool adaptive);

    double
    value() const
    {
      return kappa;
    }
    bool
    adaptive() const
    {
      return is_adaptive;
    }

    /// Between steps, with @p ratio the smallest distance of the active
    /// pairs at the converged state over d_hat (1 or more: no active
    /// pair): re-targets kappa where the ratio lies outside [lowest,
    /// highest]. Returns whether kappa changed.
    bool
    retarget(double ratio);

    /// How often kappa changed, and the smallest and largest ratio of the
    /// converged states with active pairs (1 if none).
    unsigned int
    n_retargets() const
    {
      return retargets;
    }
    double
    smallest_ratio() const
    {
      return least;
    }
    double
    largest_ratio() const
    {
      return most;
    }

  private:
    double       kappa = 0., start = 0.;
    bool         is_adaptive = false;
    unsigned int retargets   = 0;
    double       least = 1., most = 0.;
  };
} // namespace hyperelastic
