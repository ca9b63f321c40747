// Newton's method with a backtracking line search on the total potential
// energy (or, for a system without one, on the residual norm), for a
// nonlinear system it knows only through the NonlinearSystem interface:
// nothing here is specific to elasticity.
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/exceptions.h>

#include <hyperelastic/base/lagged_update.h>
#include <hyperelastic/base/tangent_projection_mode.h>
#include <hyperelastic/solvers/convergence_test.h>
#include <hyperelastic/solvers/newton_parameters.h>
#include <hyperelastic/solvers/newton_result.h>
#include <hyperelastic/solvers/tangent_policy.h>

#include <limits>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// What is known of a trial iterate u + alpha du.
  struct TrialPoint
  {
    /// False if the iterate is outside the model's domain (an element with
    /// J <= 0 for a model undefined there) or its energy is not finite.
    bool admissible = true;
    /// Total potential energy (NaN if it was not asked for).
    double energy = std::numeric_limits<double>::quiet_NaN();
    /// Round-off level of the energy: differences below it are noise.
    double energy_noise = 0.;
    /// Smallest J of the iterate (NaN if it was not computed).
    double min_J = std::numeric_limits<double>::quiet_NaN();
    /// Residual norm on the free unknowns (NaN if it was not asked for),
    /// and its round-off level.
    double residual       = std::numeric_limits<double>::quiet_NaN();
    double residual_noise = 0.;
  };

  /// What Newton needs from a problem. Every call is collective: all ranks
  /// make the same calls and get the same answers.
  class NonlinearSystem
  {
  public:
    virtual ~NonlinearSystem() = default;

    /// What Newton needs to know of the system once per solve.
    struct Properties
    {
      /// The residual is linear in the unknowns: the first Newton step,
      /// solved to the linear solver's tolerance, is the solution.
      bool linear = false;
      /// The system has a total potential energy (its residual is the
      /// energy's gradient). Without one the line search tests the residual
      /// norm instead.
      bool has_potential = true;
      /// Why there is no potential (for the Newton table).
      std::string why_no_potential = "a load has no potential";
      /// The load factor moves only prescribed values (and obstacles): no
      /// force scales with it, so every load factor has an energy minimum,
      /// and a step past a fold may snap to it (LoadStepper).
      bool displacement_controlled = false;
    };

    /// The system's Properties; they do not change during a solve.
    virtual Properties
    properties() const
    {
      return Properties();
    }

    /// Linearize at the current iterate. With @p impose_constraint_increment
    /// the next update must also move the constrained unknowns from their
    /// current to their prescribed values. Returns whether that increment is
    /// non-zero anywhere (false without @p impose_constraint_increment).
    /// @p projection says where dP/dF is made positive semi-definite
    /// (projected Newton: everywhere, and the direction descends).
    virtual bool
    assemble_linearization(bool              impose_constraint_increment,
                           TangentProjection projection) = 0;

    /// What solve_linearization() did.
    struct LinearizationSolve
    {
      /// Krylov iterations, added as each solve returns (those of the
      /// solves before a failure stay counted).
      unsigned int linear_iterations = 0;
      /// The predictor's update was replaced by a gentler extension of the
      /// constraint increment (set only when asked for).
      bool softened_predictor = false;
      /// Asked by Newton (where supports_trust_region()): the Krylov
      /// method stops where it meets negative curvature, and says so in
      /// negative_curvature; du is then not a Newton direction.
      bool watch_curvature    = false;
      bool negative_curvature = false;
    };

    /// Solve the linearized system for the direction du, with a Krylov
    /// method to the relative tolerance @p forcing (0: as accurately as the
    /// linear solver is set up to; the system never solves more loosely
    /// than asked). Adds the Krylov iterations to @p solve.
    ///
    /// With @p soften_predictor (the automatic tangent policy's
    /// request, for the linearization that imposes the constraint
    /// increment: a load step's predictor): if the update would invert
    /// cells of a state that has none, the system may replace it by a
    /// gentler extension of the increment into the body, and sets
    /// @p solve.softened_predictor to whether it did (the Krylov iterations
    /// spent on trying count too).
    virtual void
    solve_linearization(double              forcing,
                        bool                soften_predictor,
                        LinearizationSolve &solve) = 0;

    /// Whether solve_linearization_in_trust_region() is available (a
    /// potential and a Krylov solver that can follow negative curvature).
    virtual bool
    supports_trust_region() const
    {
      return false;
    }

    /// What solve_linearization_in_trust_region() found.
    struct TrustRegionStep
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

    /// Like solve_linearization() (never for the linearization that
    /// imposes the constraint increment), but du approximately minimizes
    /// the tangent's quadratic model of the energy within |du| <= @p radius
    /// (Steihaug-Toint truncated CG): along a direction of negative
    /// curvature it goes to the boundary instead of failing. Only where
    /// supports_trust_region().
    virtual void
    solve_linearization_in_trust_region(double              forcing,
                                        double              radius,
                                        LinearizationSolve &solve,
                                        TrustRegionStep    &step)
    {
      (void)forcing;
      (void)radius;
      (void)solve;
      (void)step;
      Assert(false, dealii::ExcNotImplemented());
    }

    /// Whether the exact tangent at the current iterate has a direction of
    /// negative curvature (a saddle, not a minimum), as far as a Krylov
    /// probe finds one (truncated CG from a fixed pseudo-random right-hand
    /// side). Only where supports_trust_region(); overwrites the last
    /// linearization.
    virtual bool
    has_negative_curvature()
    {
      Assert(false, dealii::ExcNotImplemented());
      return false;
    }

    /// Derivative of the energy at the current iterate along du (negative for
    /// a descent direction). Valid when du leaves the constraints unchanged.
    virtual double
    directional_derivative() const = 0;

    /// The largest step length in (0, 1] along the last solved direction
    /// that keeps the state feasible (no vertex through an obstacle); the
    /// line search starts there. 1 by default.
    virtual double
    largest_feasible_step()
    {
      return 1.;
    }

    /// What evaluate_trial() must find out about a trial iterate.
    enum class TrialCheck
    {
      none,          ///< nothing: plain Newton
      admissibility, ///< whether it lies in the model's domain
      energy,        ///< that, and its energy
      residual       ///< that, and its residual norm
    };

    /// Evaluate u + alpha du.
    virtual TrialPoint
    evaluate_trial(double alpha, TrialCheck check) = 0;

    /// Make the last evaluated trial the current iterate; returns the norm of
    /// the step taken (alpha |du|).
    virtual double
    accept_trial() = 0;

    /// The residual norms at the current iterate (after accept_trial()).
    virtual ResidualNorms
    residual_norms() = 0;

    /// Size of the solution in the run so far (the largest norm reached),
    /// for the relative update test.
    virtual double
    solution_scale() const = 0;

    /// What judge_converged_state() decided.
    enum class Verdict
    {
      accepted,          ///< the converged state stands
      continue_iterating ///< the equations changed: Newton goes on
    };

    /// Called once Newton's tests pass. With @p update_lagged, first updates
    /// quantities the equations lag behind the iterate (friction's normal
    /// forces and tangents): if they changed enough that Newton must go on
    /// from the current iterate (the energy changed), returns
    /// continue_iterating. Otherwise checks the converged state: throws
    /// ConvergenceFailure if it is not acceptable (for example inverted
    /// elements), and returns accepted.
    virtual Verdict
    judge_converged_state(bool update_lagged) = 0;

    /// Before convergence, once the residual is small: updates the lagged
    /// quantities at the current iterate as judge_converged_state() would;
    /// returns whether they changed (updated: the energy of the current
    /// iterate is new) or changed too little. Nothing changes by default.
    virtual LaggedUpdate
    update_lagged()
    {
      return LaggedUpdate::unchanged;
    }
  };

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
    /// (NonlinearSystem::solve_linearization). Returns false (and the
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
