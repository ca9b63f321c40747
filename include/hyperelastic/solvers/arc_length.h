// Arc-length continuation ('Load stepping/Method = arc length'): the load
// factor t is an unknown next to u, and each step has the length ds in the
// free displacements (Crisfield's cylindrical constraint |Delta u| = ds), so
// the path passes maxima of the load (limit points) where load control
// stops, and t may decrease along it. Knows nothing of elasticity: it works
// on a SteppedSystem with the ContinuationSystem and TangentSystem
// capabilities.
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

#include <hyperelastic/base/error_handling.h>
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
    /// converged step (with the stability estimate at it); @p continuation
    /// and @p tangent are @p system's capabilities. Throws
    /// ConvergenceFailure when ds would fall below 'Minimum increment'
    /// times the first one. Returns false, having taken no step, where the
    /// loads move nothing (dr/dt = 0 at the start): nothing to follow.
    bool
    run(SteppedSystem      &system,
        ContinuationSystem &continuation,
        TangentSystem      &tangent,
        const std::function<void(const LoadStep &, const NewtonResult &)>
          &on_converged) const;

  private:
    /// Where the path stands: the last converged state (u_n, t_n), the
    /// predictor du/dt there with -dr/dt, the last step's increment and
    /// the one being solved, the unloaded stiffness along the path.
    struct Path
    {
      explicit Path(const VectorType &u)
          : u_n(u)
          , r_t(u)
          , du_t(u)
          , delta(u)
          , last_delta(u)
      {
      }
      VectorType u_n, r_t, du_t, delta, last_delta;
      double     t_n       = 0.;
      bool       have_last = false;
      double     unloaded  = 0.;
    };

    /// One step of length @p ds from the path's (u_n, t_n) along its
    /// predictor du_t (with sign @p sign); @p land_at: solve at this t
    /// instead (NaN: continue). Fills the path's delta, @p t and the
    /// result's rows; throws ConvergenceFailure on failure.
    NewtonResult
    step(SteppedSystem      &system,
         ContinuationSystem &continuation,
         TangentSystem      &tangent,
         Path               &path,
         double              ds,
         double              sign,
         double              land_at,
         double             &t) const;

    /// The path's start at (0, 0): the predictor and the unloaded
    /// stiffness in @p path; returns the first step's length (0 where the
    /// loads move nothing: the system is then back at its converged state).
    double
    start(SteppedSystem      &system,
          ContinuationSystem &continuation,
          TangentSystem      &tangent,
          Path               &path) const;

    /// Prints the header of step @p number from the path's t_n (length
    /// @p ds) and
    /// returns the load factor it lands on (the maximum load factor where
    /// the predicted @p dt_predicted, or @p land, would take it past; NaN:
    /// none).
    /// |du/dt| of the path's predictor (path_product()).
    static double
    path_length(const ContinuationSystem &continuation, const Path &path);

    double
    announce_step(unsigned int number,
                  const Path  &path,
                  double       ds,
                  double       dt_predicted,
                  bool         land) const;

    /// The step to @p t converged: it becomes the path's last converged
    /// state (counted in @p step), with the next predictor and the
    /// stability in @p result.
    void
    advance(SteppedSystem      &system,
            ContinuationSystem &continuation,
            TangentSystem      &tangent,
            double              t,
            Path               &path,
            LoadStep           &step,
            NewtonResult       &result) const;

    /// The corrector's dt: the root of |delta + du_r + dt du_t| = ds (in
    /// path_product()) whose increment turns least from @p delta; throws
    /// ConvergenceFailure where there is no real one.
    static double
    constraint_root(const ContinuationSystem &continuation,
                    const VectorType         &delta,
                    const VectorType         &du_r,
                    const VectorType         &du_t,
                    double                    ds);

    /// After the step of length @p ds from @p t_n failed with @p failure:
    /// the halved length (a cut-back counted in @p step), or a
    /// ConvergenceFailure below 'Minimum increment' times @p first_ds.
    double
    halved_length(const ConvergenceFailure &failure,
                  double                    ds,
                  double                    first_ds,
                  double                    t_n,
                  LoadStep                 &step) const;

    const LoadSteppingParameters parameters;
    const NewtonParameters       newton;
    const double                 nominal;
    dealii::ConditionalOStream   pcout;
  };
} // namespace hyperelastic
