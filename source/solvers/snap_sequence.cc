// Snap sub-steps: pseudo-transient continuation at a fixed load factor
// (see the header).
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/solvers/snap_sequence.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace hyperelastic
{
  namespace
  {
    /// @p settings with negative curvature followed (not with the
    /// projected tangent, which has no exact-tangent iterations); with
    /// @p exact the automatic tangent becomes exact, projected on failure.
    NewtonParameters
    following(const NewtonParameters &settings, const bool exact)
    {
      NewtonParameters result = settings;
      result.follow_negative_curvature =
        settings.tangent != NewtonTangent::projected;
      if (exact && settings.tangent == NewtonTangent::automatic)
        result.tangent = NewtonTangent::exact_then_projected;
      return result;
    }
  } // namespace

  SnapSequence::SnapSequence(const NewtonSolver        &newton,
                             const unsigned int         budget,
                             dealii::ConditionalOStream pcout)
      : damped_newton(newton.with_settings(following(newton.settings(), false)))
      , undamped_newton(
          newton.with_settings(following(newton.settings(), true)))
      , budget(budget)
      , pcout(pcout)
  {
  }

  /// One run of the sequence: its state and its parts.
  class SnapSequence::Run
  {
  public:
    Run(const SnapSequence &sequence,
        SteppedSystem      &system,
        DampedSystem       &damped,
        ContinuationSystem &states,
        const double        t,
        const Accept       &accept)
        : sequence(sequence)
        , system(system)
        , damped(damped)
        , states(states)
        , t(t)
        , accept(accept)
        , max_iterations(sequence.damped_newton.settings().max_iterations)
        , convergence(sequence.damped_newton.settings())
    {
    }

    void
    run()
    {
      // The first damping: c D a sixteenth of the tangent's diagonal on
      // average at the last converged state. As large as the diagonal,
      // the damping held the body back so firmly that an obstacle moving
      // over the step could not push it (the shell of tests/stability.cc
      // case shell_plate: every sub-step failed, and more damping made it
      // worse).
      c = damped.damping_scale() / 16.;
      if (!(c > 0.))
        throw ConvergenceFailure("snap sub-steps: the system has no damping "
                                 "scale (no stiffness on the free unknowns)");
      system.set_load_factor(t);
      while (true)
        {
          double residual = 0.;
          if (!damped_sub_step(residual))
            continue;
          if (residual <= 0.)
            return;
          // An undamped solve from the sub-step once the undamped residual
          // has fallen to a quarter of where the last one was tried (the
          // first sub-step's, before any): where it converges, the snap is
          // over.
          if (!std::isfinite(attempted_at))
            attempted_at = residual;
          if (!(residual <= 0.25 * attempted_at))
            continue;
          attempted_at = residual;
          if (undamped_solve())
            return;
        }
    }

  private:
    /// One damped sub-step from the last accepted state: false if it
    /// failed (retried with more damping); otherwise accepted, and
    /// @p residual the undamped residual there (0: an equilibrium, the
    /// snap is over).
    bool
    damped_sub_step(double &residual)
    {
      sequence.pcout << "   snap sub-step " << sub_steps + 1
                     << " (damping c = " << c << ")" << std::endl;
      damped.set_damping(c);
      NewtonResult sub;
      try
        {
          sub =
            sequence.damped_newton.solve_loosely(system, sub_step_reduction);
        }
      catch (const ConvergenceFailure &failure)
        {
          spent += std::max(1u, failure.newton_iterations());
          ++failed;
          ++failed_in_a_row;
          back();
          if (failed_in_a_row > failures_in_a_row)
            give_up(
              "a sub-step failed with " + std::to_string(failures_in_a_row) +
              " increases of the damping (" + first_line(failure.what()) + ")");
          if (spent >= sequence.budget)
            give_up("the iteration budget is spent");
          c *= growth;
          sequence.pcout
            << "   snap sub-step failed: " << first_line(failure.what())
            << "\n   retried from its start with four times the damping"
            << std::endl;
          return false;
        }
      failed_in_a_row = 0;
      spent += sub.iterations();
      ++sub_steps;
      residual = undamped_residual(sub);
      if (residual <= 0.)
        return true;
      adapt_damping(sub, residual);
      return true;
    }

    /// The sub-step's state without the damping: the residual of the
    /// undamped equations there (the damping force it balanced). Accepts
    /// the sub-step; returns 0 where it is an equilibrium.
    double
    undamped_residual(const NewtonResult &sub)
    {
      const double force = damped.damping_force();
      damped.set_damping(0.);
      const VectorType at(system.state());
      states.set_state(at, t);
      const ResidualNorms norms  = system.residual_norms();
      const double        target = convergence.residual_target(norms);
      sequence.pcout << "   snap sub-step " << sub_steps << ": "
                     << sub.iterations() << " Newton iterations; damping force "
                     << force << ", residual without damping " << norms.residual
                     << " (target " << target << ")" << std::endl;
      if (norms.residual <= target)
        {
          accept(sub, failed, true);
          return 0.;
        }
      accept(sub, failed, false);
      failed = 0;
      return norms.residual;
    }

    /// The pseudo time step grows (c falls fourfold) after an easy
    /// sub-step, and with the fall of the undamped residual (switched
    /// evolution relaxation, at most fourfold); it shrinks after a hard
    /// one.
    void
    adapt_damping(const NewtonResult &sub, const double residual)
    {
      if (sub.iterations() <= easy_sub_step)
        c /= growth;
      else if (sub.iterations() > max_iterations / 2)
        c *= 2.;
      if (std::isfinite(previous_residual))
        c *= std::clamp(residual / previous_residual, 1. / growth, 1.);
      previous_residual = residual;
      if (spent >= sequence.budget)
        give_up("the iteration budget is spent");
    }

    /// An undamped Newton solve from the last sub-step: true where it
    /// converged (the snap is over).
    bool
    undamped_solve()
    {
      sequence.pcout << "   undamped Newton from snap sub-step " << sub_steps
                     << std::endl;
      system.set_load_factor(t);
      try
        {
          const NewtonResult result = sequence.undamped_newton.solve(system);
          spent += result.iterations();
          accept(result, failed, true);
          return true;
        }
      catch (const ConvergenceFailure &failure)
        {
          spent += std::max(1u, failure.newton_iterations());
          ++failed;
          back();
          sequence.pcout << "   undamped Newton failed: "
                         << first_line(failure.what()) << std::endl;
          if (spent >= sequence.budget)
            give_up("the iteration budget is spent");
          return false;
        }
    }

    /// Back to the start of the sub-step (the last accepted state) at t.
    void
    back()
    {
      damped.set_damping(0.);
      system.restore_converged_state();
      system.set_load_factor(t);
    }

    [[noreturn]] void
    give_up(const std::string &why)
    {
      damped.set_damping(0.);
      system.restore_converged_state();
      std::ostringstream message;
      message << "snap sub-steps to t = " << t << ": " << why << " after "
              << sub_steps << " sub-steps (" << spent
              << " Newton iterations counted against 'Load stepping/Snap "
                 "sub-step iterations' = "
              << sequence.budget << ")";
      throw ConvergenceFailure(message.str());
    }

    const SnapSequence   &sequence;
    SteppedSystem        &system;
    DampedSystem         &damped;
    ContinuationSystem   &states;
    const double          t;
    const Accept         &accept;
    const unsigned int    max_iterations;
    const ConvergenceTest convergence;
    double                c     = 0.;
    unsigned int          spent = 0, sub_steps = 0, failed = 0;
    unsigned int          failed_in_a_row = 0;
    double previous_residual = std::numeric_limits<double>::quiet_NaN();
    double attempted_at      = std::numeric_limits<double>::quiet_NaN();
  };

  void
  SnapSequence::run(SteppedSystem      &system,
                    DampedSystem       &damped,
                    ContinuationSystem &states,
                    const double        t,
                    const Accept       &accept) const
  {
    Run(*this, system, damped, states, t, accept).run();
  }
} // namespace hyperelastic
