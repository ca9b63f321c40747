// Snap sub-steps (pseudo-transient continuation at a fixed load factor):
// where the equilibrium path folds under displacement control, the step to
// the new load factor is carried out as a sequence of sub-steps, each an
// ordinary Newton solve (budget 'Newton/Max iterations') of the potential
// plus a damping energy c/2 (u - u_k)^T D (u - u_k) about the sub-step's
// start u_k (D: the system's diagonal metric, DampedSystem). Each converged
// sub-step is an accepted step of its own (a row of the Newton table and
// the CSV, with its own iterations), the state of a pseudo time step.
// After each sub-step an undamped Newton solve (the same budget) is tried
// from it; the sequence ends where one converges: that state is an
// equilibrium of the undamped problem. c follows the undamped residual of
// the sub-steps (switched evolution relaxation, Kelley-Keyes: c times the
// ratio of the last two), rises fourfold after a failed sub-step (retried
// from its start). Knows nothing of elasticity.
#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <hyperelastic/solvers/damped_system.h>
#include <hyperelastic/solvers/load_stepping.h>
#include <hyperelastic/solvers/newton_solver.h>

#include <functional>

namespace hyperelastic
{
  class SnapSequence
  {
  public:
    /// @p budget: the Newton iterations of all sub-steps and undamped
    /// attempts together, failed ones counted ('Load stepping/Snap sub-step
    /// iterations').
    SnapSequence(const NewtonSolver        &newton,
                 unsigned int               budget,
                 dealii::ConditionalOStream pcout);

    /// What the sequence hands to the stepper for each accepted state:
    /// the Newton rows of its solve, the failed attempts before it (to be
    /// counted as cut-backs), and whether it ends the snap (an undamped
    /// equilibrium) or is a damped sub-step. The stepper stores the state
    /// as converged and reports it.
    using Accept = std::function<
      void(const NewtonResult &result, unsigned int failed, bool final)>;

    /// From the system's last converged state to the load factor @p t:
    /// sub-steps until an undamped solve converges. Leaves the system at
    /// that state, without damping. Throws ConvergenceFailure when the
    /// budget is spent or a sub-step fails with the largest damping tried;
    /// the system is then at its last converged state (the last accepted
    /// sub-step's, if any), without damping. @p damped and @p states are
    /// @p system's capabilities (the damping, and states set from outside
    /// for the undamped residual at a sub-step).
    void
    run(SteppedSystem      &system,
        DampedSystem       &damped,
        ContinuationSystem &states,
        double              t,
        const Accept       &accept) const;

    /// The factor by which c rises after a failed sub-step, and the most
    /// the residual ratio may change it by after a converged one.
    static constexpr double growth = 4.;
    /// Failed sub-steps in a row (c raised each time) before the sequence
    /// gives up.
    static constexpr unsigned int failures_in_a_row = 3;
    /// A sub-step's Newton solve ends once its residual has fallen to this
    /// fraction of its first iteration's (NewtonSolver::solve_loosely()).
    static constexpr double sub_step_reduction = 0.1;
    /// A sub-step solved in at most this many Newton iterations is easy:
    /// the damping falls.
    static constexpr unsigned int easy_sub_step = 4;

  private:
    /// One run: its state, the damped sub-steps and the undamped solves.
    class Run;

    /// The stepper's Newton with negative curvature followed (the
    /// sub-steps and the undamped solves pass saddles): for the damped
    /// sub-steps, and for the undamped solves, which start near an
    /// equilibrium, with the exact tangent (projected on failure) for a
    /// quadratic end (the automatic tangent would project where J <= 0
    /// until the residual fell a thousandfold from its first, small one).
    const NewtonSolver         damped_newton;
    const NewtonSolver         undamped_newton;
    const unsigned int         budget;
    dealii::ConditionalOStream pcout;
  };
} // namespace hyperelastic
