// Newton's method with a backtracking line search on the total potential
// energy (or, for a system without one, on the residual norm), for a
// nonlinear system it knows only through the NonlinearSystem interface:
// nothing here is specific to elasticity.
#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <hyperelastic/base/tangent_projection_mode.h>
#include <hyperelastic/solvers/convergence_test.h>
#include <hyperelastic/solvers/newton_parameters.h>
#include <hyperelastic/solvers/newton_result.h>

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

    /// Linearize at the current iterate. With @p impose_constraint_increment
    /// the next update must also move the constrained unknowns from their
    /// current to their prescribed values. Returns whether that increment is
    /// non-zero anywhere (false without @p impose_constraint_increment).
    /// @p projection says where dP/dF is made positive semi-definite
    /// (projected Newton: everywhere, and the direction descends).
    virtual bool
    assemble_linearization(bool              impose_constraint_increment,
                           TangentProjection projection) = 0;

    /// Solve the linearized system for the direction du, with a Krylov
    /// method to the relative tolerance @p forcing (0: as accurately as the
    /// linear solver is set up to; the system never solves more loosely
    /// than asked). Returns Krylov iterations.
    virtual unsigned int
    solve_linearization(double forcing) = 0;

    /// True if the residual is linear in the unknowns: the first Newton
    /// step, solved to the linear solver's tolerance, is the solution.
    virtual bool
    is_linear() const
    {
      return false;
    }

    /// Whether the system has a total potential energy (its residual is the
    /// energy's gradient). Without one the line search tests the residual
    /// norm instead.
    virtual bool
    has_potential() const
    {
      return true;
    }

    /// Why there is no potential (for the Newton table).
    virtual std::string
    why_no_potential() const
    {
      return "a load has no potential";
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

    /// Called by the automatic tangent policy after the solve of the
    /// linearization that imposes the constraint increment (a load step's
    /// predictor): if that update would invert cells of a state that has
    /// none, the system may replace it by a gentler extension of the
    /// increment into the body. Returns whether it did; @p
    /// linear_iterations gets the Krylov iterations spent on trying.
    virtual bool
    soften_inverting_predictor(unsigned int &linear_iterations)
    {
      (void)linear_iterations;
      return false;
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

    virtual ResidualNorms
    residual_norms() = 0;

    /// Size of the solution in the run so far (the largest norm reached),
    /// for the relative update test.
    virtual double
    solution_scale() const = 0;

    /// Called once Newton's tests pass; throws ConvergenceFailure if the
    /// converged state is not acceptable (for example inverted elements).
    virtual void
    verify_converged_state() = 0;

    /// Called once Newton's tests pass, before verify_converged_state():
    /// updates quantities the equations lag behind the iterate (friction's
    /// normal forces and tangents). Returns true if they changed enough that
    /// Newton must go on from the current iterate (the energy changed).
    virtual bool
    update_lagged_quantities()
    {
      return false;
    }
  };

  class NewtonSolver
  {
  public:
    NewtonSolver(const NewtonParameters    &parameters,
                 dealii::ConditionalOStream pcout,
                 bool                       verbose);

    /// Iterate until converged; throws ConvergenceFailure with the reason and
    /// the residual history otherwise (iteration limit, line-search failure,
    /// NaN; the system's own failures, such as a Krylov failure, pass
    /// through).
    NewtonResult
    solve(NonlinearSystem &system) const;

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
    /// The Eisenstat-Walker forcing term for the next linear solve, from the
    /// rows so far of this Newton solve (0 for an exact solve).
    double
    forcing_term(const std::vector<NewtonIteration> &history,
                 double                              residual_target) const;

    /// Backtracks from alpha = 1 until the trial is admissible and, if
    /// @p test_merit, satisfies the sufficient-decrease condition of the
    /// energy (or, without a potential, of the residual norm).
    /// Returns false (and the reason) if no step length down to the minimum
    /// is acceptable.
    bool
    line_search(NonlinearSystem  &system,
                bool              test_merit,
                const TrialPoint &current,
                NewtonIteration  &row,
                std::string      &failure) const;

    const NewtonParameters     parameters;
    dealii::ConditionalOStream pcout;
    const bool                 verbose;
  };
} // namespace hyperelastic
