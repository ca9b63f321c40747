// Newton's method for a nonlinear system it knows only through the
// NonlinearSystem interface: nothing here is specific to elasticity.
#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <hyperelastic/parameters.h>

#include <vector>

namespace hyperelastic
{
  /// Norms of the residual at the current iterate.
  struct ResidualNorms
  {
    double residual; ///< on the free (unconstrained) unknowns
    /// Size of the forces of the run so far, for the relative test (a
    /// running maximum, so that it does not vanish when loads are removed).
    double scale;
  };

  /// What Newton needs from a problem.
  class NonlinearSystem
  {
  public:
    virtual ~NonlinearSystem() = default;

    /// Linearize at the current iterate. With @p impose_constraint_increment
    /// the next update must also move the constrained unknowns to their new
    /// prescribed values (the first iteration of a load step).
    virtual void
    assemble_linearization(bool impose_constraint_increment) = 0;

    /// Solve the linearized system for the update; returns Krylov iterations.
    virtual unsigned int
    solve_linearization() = 0;

    /// Add the update to the iterate; returns the update's norm.
    virtual double
    apply_update() = 0;

    virtual ResidualNorms
    residual_norms() = 0;

    /// Size of the solution in the run so far (the largest norm reached),
    /// for the relative update test.
    virtual double
    solution_scale() const = 0;
  };

  /// One row of the Newton table.
  struct NewtonIteration
  {
    unsigned int iteration;
    double       residual;
    double       update;
    unsigned int linear_iterations;
  };

  struct NewtonResult
  {
    std::vector<NewtonIteration> history;
    unsigned int
    iterations() const
    {
      return history.size();
    }
    unsigned int
    linear_iterations() const;
  };

  class NewtonSolver
  {
  public:
    NewtonSolver(const NewtonParameters    &parameters,
                 dealii::ConditionalOStream pcout,
                 bool                       verbose);

    /// Iterate until converged; throws ConvergenceFailure with the residual
    /// history otherwise (NaN, or the iteration limit).
    NewtonResult
    solve(NonlinearSystem &system) const;

  private:
    const NewtonParameters     parameters;
    dealii::ConditionalOStream pcout;
    const bool                 verbose;
  };
} // namespace hyperelastic
