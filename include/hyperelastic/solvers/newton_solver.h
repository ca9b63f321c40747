// Newton's method with a backtracking line search on the total potential
// energy (or, for a system without one, on the residual norm), for a
// nonlinear system it knows only through the NonlinearSystem interface and
// the capabilities the system may have beside it (a trust region, lagged
// quantities, a softened predictor): nothing here is specific to
// elasticity.
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/exceptions.h>

#include <hyperelastic/base/lagged_update.h>
#include <hyperelastic/base/tangent_projection_mode.h>
#include <hyperelastic/solvers/convergence_test.h>
#include <hyperelastic/solvers/lagged_system.h>
#include <hyperelastic/solvers/newton_parameters.h>
#include <hyperelastic/solvers/newton_result.h>
#include <hyperelastic/solvers/nonlinear_system.h>
#include <hyperelastic/solvers/predictor_softening.h>
#include <hyperelastic/solvers/tangent_policy.h>
#include <hyperelastic/solvers/trust_region_system.h>

#include <limits>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// Newton's method with a backtracking line search for a NonlinearSystem:
  /// the tangent from a TangentPolicy, inexact linear solves with
  /// Eisenstat-Walker forcing terms, the ConvergenceTest, and the Newton
  /// table.
  class NewtonSolver
  {
  public:
    /// Newton with @p parameters; with @p verbose the table is printed to
    /// @p pcout as it grows.
    NewtonSolver(const NewtonParameters    &parameters,
                 dealii::ConditionalOStream pcout,
                 bool                       verbose);

    /// A solver with other @p settings that prints as this one does
    /// (SnapSequence's solves).
    NewtonSolver
    with_settings(const NewtonParameters &settings) const;

    /// Iterate until converged; throws ConvergenceFailure with the reason and
    /// the residual history otherwise (iteration limit, line-search failure,
    /// NaN; the system's own failures, such as a Krylov failure, pass
    /// through).
    NewtonResult
    solve(NonlinearSystem &system) const;

    /// The same with @p max_iterations instead of 'Newton/Max iterations'
    /// (a snap step's larger budget).
    NewtonResult
    solve(NonlinearSystem &system, unsigned int max_iterations) const;

    /// The same with a looser end (a pseudo time step of snap sub-steps,
    /// SnapSequence): converged once the residual is at most @p reduction
    /// times the first iteration's, or Newton's tests pass; budget
    /// 'Newton/Max iterations'.
    NewtonResult
    solve_loosely(NonlinearSystem &system, double reduction) const;

    /// The Newton table of @p result as text.
    static std::string
    table(const NewtonResult &result);

    /// The tolerances and limits Newton works with.
    const NewtonParameters &
    settings() const
    {
      return parameters;
    }

  private:
    /// solve() with @p max_iterations, and solve_loosely()'s @p reduction
    /// (0: Newton's tests only).
    NewtonResult
    solve(NonlinearSystem &system,
          unsigned int     max_iterations,
          double           reduction) const;

    /// What a solve carries from one iteration to the next.
    struct SolveState
    {
      /// The system's capabilities beside NonlinearSystem, found once per
      /// solve (null where it does not have one).
      TrustRegionSystem  *trust_region = nullptr;
      LaggedSystem       *lagged       = nullptr;
      PredictorSoftening *softening    = nullptr;
      /// True until a full step has moved the constrained unknowns to their
      /// prescribed values. Until then the energy cannot be compared
      /// between iterates (each satisfies different constraints), so the
      /// line search only keeps the iterates admissible.
      bool moving_constraints = true;
      /// The current iterate (energy unknown yet).
      TrialPoint current;
      /// The residual the convergence test asks for (from the last
      /// iteration).
      double target = 0.;
      /// Each solve of the (lagged) equations has the full iteration
      /// budget; the table counts on through them. The iteration before
      /// the first one of the current solve.
      unsigned int budget_start = 0;
      /// After a shortened step, lagged quantities are updated within the
      /// solve once the residual is below this (a fraction of the first
      /// residual after the step's predictor or after the last update);
      /// negative: to be set from the next residual; zero: after full steps
      /// only.
      double early_lag_residual = -1.;
      /// The trust region's radius (NaN until the first trust-region
      /// iteration of the solve): kept through the load step.
      double trust_radius = std::numeric_limits<double>::quiet_NaN();
      /// A trust-region iteration succeeded where the tangent's own step
      /// had failed: the following iterations of the solve start with the
      /// trust region.
      bool in_trust_region = false;
      /// solve_loosely(): the reduction of the first iteration's residual
      /// that ends the solve (0: Newton's tests only), and the residual it
      /// asks for (set after the first iteration).
      double loose_reduction = 0.;
      double loose_target    = 0.;
      /// The residual, of the equations the next iteration solves, at the
      /// current iterate: the last row's residual, or after a lagged update
      /// the new equations' (NaN: not known).
      double equations_residual = std::numeric_limits<double>::quiet_NaN();
      /// The same at the point the last iteration started from: with the
      /// residual it reached, the Eisenstat-Walker ratio of one set of
      /// equations.
      double step_start_residual = std::numeric_limits<double>::quiet_NaN();
    };

    /// How the current iteration is solved: the tangent's projection, the
    /// trust region, the forcing term's parts.
    struct IterationPlan
    {
      TangentProjection projection = TangentProjection::none;
      /// The smallest J of the current iterate (NaN before the first
      /// iteration).
      double min_J = 0.;
      /// The Eisenstat-Walker term, and whether this iteration imposes the
      /// constraint increment (a predictor, solved fully).
      double eisenstat_walker = 0.;
      bool   predictor        = false;
      /// The iteration is solved in the trust region; it was tried.
      bool in_trust_region    = false;
      bool trust_region_tried = false;
    };

    /// The relative Krylov tolerance of an iteration planned as @p plan.
    double
    iteration_forcing(const NonlinearSystem::Properties &properties,
                      const IterationPlan               &plan) const;

    /// Whether the iteration may go on in the trust region with
    /// @p projection (Newton/Follow negative curvature, a system that has
    /// one, not a predictor).
    bool
    trust_region_allowed(const NonlinearSystem::Properties &properties,
                         const TangentPolicy               &policy,
                         const SolveState                  &state,
                         TangentProjection                  projection) const;

    /// Sets SolveState::trust_radius where it is not set yet; returns
    /// whether there is one.
    bool
    start_trust_region(NonlinearSystem                    &system,
                       SolveState                         &state,
                       const std::vector<NewtonIteration> &history) const;

    /// attempt() (or attempt_trust_region()) and, while that fails, the
    /// trust region once and then the policy's fallbacks from the same
    /// iterate; throws ConvergenceFailure once none is left. The step taken
    /// is the system's last evaluated trial.
    void
    attempt_until_taken(NonlinearSystem                     &system,
                        const NonlinearSystem::Properties   &properties,
                        const TangentPolicy                 &policy,
                        unsigned int                         it,
                        SolveState                          &state,
                        const NewtonResult                  &result,
                        IterationPlan                       &plan,
                        NewtonIteration                     &row,
                        NonlinearSystem::LinearizationSolve &solve) const;

    /// One iteration from the current iterate: the projection @p policy
    /// chooses, then attempt() and, while that fails, attempt() again from
    /// the same iterate with the policy's fallback; throws
    /// ConvergenceFailure once the failure is final. Takes the step and
    /// returns the iteration's row (without its residual).
    NewtonIteration
    iterate(NonlinearSystem                   &system,
            const NonlinearSystem::Properties &properties,
            const TangentPolicy               &policy,
            unsigned int                       iteration,
            SolveState                        &state,
            const NewtonResult                &result) const;

    /// Linearize with @p projection, solve to the relative tolerance
    /// row.forcing and search along the direction. @p soften_predictor: the
    /// tangent policy asks for the softened predictor, which the system is
    /// asked for when this linearization imposes the constraint increment
    /// (PredictorSoftening, where the system has it). Returns false (and the
    /// reason) if the line search or the linear solve failed; the Krylov
    /// iterations add up in @p solve.
    bool
    attempt(NonlinearSystem                     &system,
            const NonlinearSystem::Properties   &properties,
            TangentProjection                    projection,
            bool                                 soften_predictor,
            SolveState                          &state,
            NewtonIteration                     &row,
            NonlinearSystem::LinearizationSolve &solve,
            std::string                         &failure) const;

    /// Whether the residual at the current iterate already meets Newton's
    /// target (assembles the forces there).
    bool
    in_equilibrium(NonlinearSystem &system) const;

    /// The automatic tangent's answer to an indefinite tangent: linearize
    /// with @p projection, solve in the trust region of
    /// SolveState::trust_radius (Steihaug-Toint truncated CG, which follows
    /// negative curvature) and let the energy decide: the step alpha du
    /// (from the feasible step down, halving) is accepted if the energy
    /// falls by at least Newton/Armijo constant times the quadratic
    /// model's predicted decrease. The radius then shrinks to a quarter of
    /// the step where the model predicted poorly or the step was
    /// shortened, and doubles where a step on the boundary was predicted
    /// well. Returns false (and the reason) like attempt().
    bool
    attempt_trust_region(NonlinearSystem                     &system,
                         TangentProjection                    projection,
                         SolveState                          &state,
                         NewtonIteration                     &row,
                         NonlinearSystem::LinearizationSolve &solve,
                         std::string                         &failure) const;

    /// The convergence and lagging decision after @p row, the iteration
    /// @p iteration (residual norms @p norms): true once Newton's tests
    /// pass and the system accepts the state. Where @p policy follows
    /// negative curvature, a converged state at which the exact tangent
    /// has some (a saddle) is not accepted: Newton goes on from it in the
    /// trust region, and an accepted state's row says it was probed. If instead
    /// the system's lagged quantities changed, the solve of the new equations
    /// starts from the current iterate with a fresh budget.
    bool
    finished(NonlinearSystem                   &system,
             const NonlinearSystem::Properties &properties,
             const ConvergenceTest             &convergence,
             const ResidualNorms               &norms,
             NewtonIteration                   &row,
             unsigned int                       iteration,
             SolveState                        &state,
             const TangentPolicy               &policy) const;

    /// The row of an iteration that takes the trial at step length @p alpha
    /// from @p current (energy tested or not): step, energies, min J.
    static void
    take_trial(double            alpha,
               bool              energy_tested,
               const TrialPoint &current,
               const TrialPoint &trial,
               NewtonIteration  &row);

    /// The lagged quantities changed at iteration @p iteration: the
    /// current iterate's energy is unknown, the new equations get a fresh
    /// budget and their own early-update threshold, and their residual at
    /// the iterate is taken from @p system; the table says so.
    void
    lagged_quantities_updated(NonlinearSystem &system,
                              unsigned int     iteration,
                              SolveState      &state) const;

    /// Before convergence: updates the system's lagged quantities after
    /// every full step (@p full_step: the line search accepted step length
    /// 1), and after a shortened one once the residual has fallen to
    /// early_lag_reduction times the first one of the current equations
    /// (SolveState::early_lag_residual); the new equations get a fresh
    /// budget from @p iteration on.
    void
    update_lagged_early(NonlinearSystem     &system,
                        const ResidualNorms &norms,
                        bool                 full_step,
                        unsigned int         iteration,
                        SolveState          &state) const;

    /// The reduction of the residual after which lagged quantities are
    /// updated within a solve.
    static constexpr double early_lag_reduction = 0.1;

    /// The Eisenstat-Walker forcing term for the next linear solve, from the
    /// rows so far of this Newton solve and the residual the last row's
    /// iteration started from, of the equations it solved (0 for an exact
    /// solve).
    double
    forcing_term(const std::vector<NewtonIteration> &history,
                 double                              step_start_residual,
                 double                              residual_target) const;

    /// Backtracks from alpha = 1 until the trial is admissible and, if
    /// @p test_merit, satisfies the sufficient-decrease condition of the
    /// energy (or, without a potential, of the residual norm).
    /// Returns false (and the reason) if no step length down to the minimum
    /// is acceptable.
    bool
    line_search(NonlinearSystem  &system,
                bool              has_potential,
                bool              test_merit,
                const TrialPoint &current,
                NewtonIteration  &row,
                std::string      &failure) const;

    const NewtonParameters     parameters;
    dealii::ConditionalOStream pcout;
    const bool                 verbose;
  };
} // namespace hyperelastic
