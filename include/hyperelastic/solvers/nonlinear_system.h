// What Newton's method needs from a problem: the core interface, ten pure
// virtual methods. What only some systems can do (a trust region, lagged
// quantities, a softened predictor, damping, continuation) is an interface of
// its own beside it (solvers/*_system.h, predictor_softening.h), which the
// solvers find by dynamic_cast; a system implements only what it has.
#pragma once

#include <hyperelastic/base/tangent_projection_mode.h>
#include <hyperelastic/solvers/convergence_test.h>

#include <limits>
#include <string>

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
      /// A system that is a TrustRegionSystem can solve in a trust region
      /// now (a potential, a Krylov solver that follows negative
      /// curvature).
      bool trust_region = false;
      /// A system that is a DampedSystem can take the damping now.
      bool damping = false;
    };

    /// The system's Properties; they do not change during a solve.
    virtual Properties
    properties() const = 0;

    /// Linearize at the current iterate. With @p impose_constraint_increment
    /// the next update must also move the constrained unknowns from their
    /// current to their prescribed values. Returns whether that increment,
    /// or a load term's admissible set on its way, moves anything (the
    /// linearization is a predictor; false without either).
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
      /// constraint increment (PredictorSoftening).
      bool softened_predictor = false;
      /// Asked by Newton (where Properties::trust_region): the Krylov
      /// method stops where it meets negative curvature, and says so in
      /// negative_curvature; du is then not a Newton direction.
      bool watch_curvature    = false;
      bool negative_curvature = false;
    };

    /// Solve the linearized system for the direction du, with a Krylov
    /// method to the relative tolerance @p forcing (0: as accurately as the
    /// linear solver is set up to; the system never solves more loosely
    /// than asked). Adds the Krylov iterations to @p solve.
    virtual void
    solve_linearization(double forcing, LinearizationSolve &solve) = 0;

    /// Derivative of the energy at the current iterate along du (negative for
    /// a descent direction). Valid when du leaves the constraints unchanged.
    virtual double
    directional_derivative() const = 0;

    /// The largest step length in (0, 1] along the last solved direction
    /// that keeps the state feasible (1 where every step is); the line
    /// search starts there.
    virtual double
    largest_feasible_step() = 0;

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

    /// Called once Newton's tests pass (and the lagged quantities of a
    /// LaggedSystem stand): throws ConvergenceFailure if the converged
    /// state is not acceptable (for example inverted elements).
    virtual void
    judge_converged_state() = 0;
  };
} // namespace hyperelastic
