// Arc-length continuation ('Load stepping/Method = arc length'): the load
// factor t is an unknown next to u, and each step has the length ds in the
// free displacements (Crisfield's cylindrical constraint |Delta u| = ds), so
// the path passes maxima of the load (limit points) where load control
// stops, and t may decrease along it. Knows nothing of elasticity: it works
// on a ContinuationSystem.
//
// A step from the converged (u_n, t_n): the tangent predictor du/dt from
// K du_t = -dr/dt, scaled to ds, its sign that of the last step's increment
// (the sign of det K changes at a limit point, so the tangent alone cannot
// tell the way); then corrector iterations, each with two solves of the same
// tangent and preconditioner,
//   K du_r = -r,   K du_t = -dr/dt,   du = du_r + dt du_t,
// dt from the quadratic |Delta u + du|^2 = ds^2, of whose roots the one that
// keeps the increment closest to the last one in angle is taken. Converged
// by Newton's residual and update tests. A failed step (no real root,
// iteration limit, NaN, a rejected state) is retried from u_n with ds
// halved; after a converged step ds is scaled by sqrt(easy / iterations)
// (within [1/2, 2]), never beyond the first ds, the predictor's length for
// the first nominal load step. The stability of a converged state is the
// tangent's stiffness along the path (stiffness_along_path()) over the
// unloaded one's. A step that would pass 'Maximum load factor' upwards
// is solved at that t instead (plain Newton on u): the run lands on it.
#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <hyperelastic/solvers/load_stepping.h>

#include <functional>

namespace hyperelastic
{
  class ArcLengthStepper
  {
  public:
    ArcLengthStepper(const LoadSteppingParameters &parameters,
                     const NewtonParameters       &newton,
                     double                        nominal_increment,
                     dealii::ConditionalOStream    pcout);

    /// Follows the path from (0, 0) and calls @p on_converged after each
    /// converged step (with the stability estimate at it). Throws
    /// ConvergenceFailure when ds would fall below 'Minimum increment'
    /// times the first one.
    void
    run(SteppedSystem &system,
        const std::function<void(const LoadStep &, const NewtonResult &)>
          &on_converged) const;

  private:
    /// One step of length @p ds from (u_n, t_n) along the predictor
    /// @p du_t (with sign @p sign); @p land_at: solve at this t instead (NaN:
    /// continue). Fills @p delta and @p t and the result's rows; throws
    /// ConvergenceFailure on failure.
    NewtonResult
    step(SteppedSystem    &system,
         const VectorType &u_n,
         double            t_n,
         const VectorType &du_t,
         double            ds,
         double            sign,
         double            land_at,
         VectorType       &delta,
         double           &t) const;

    const LoadSteppingParameters parameters;
    const NewtonParameters       newton;
    const double                 nominal;
    dealii::ConditionalOStream   pcout;
  };
} // namespace hyperelastic
