// What changes the equilibrium system's equations for a reason of its own,
// beyond the Dirichlet conditions: a constraint on the unknowns whose
// reactions the residual does not count. The equilibrium system keeps a list
// of them and loops over it at each point its equations pass (the tangent,
// a solve's right-hand side and solution, the residual), with no branch of
// its own for any. The pinned rigid motions of bodies held only by contact
// are one (UnheldRigidMotions); rigid bodies will be another.
#pragma once

#include <hyperelastic/base/linear_algebra.h>

#include <functional>

namespace hyperelastic
{
  class SystemConstraint
  {
  public:
    virtual ~SystemConstraint() = default;

    /// Makes the assembled @p tangent regular along what the constraint
    /// holds. Collective.
    virtual void
    regularize(MatrixType &tangent) = 0;

    /// Before a solve with @p tangent for the right-hand side @p rhs at the
    /// iterate @p u (whose forces have the size @p force_scale): decides
    /// what the constraint holds there. Collective.
    virtual void
    prepare_solve(const VectorType &u,
                  const MatrixType &tangent,
                  const VectorType &rhs,
                  double            force_scale) = 0;

    /// Turns @p update, the tangent's solution of the projected right-hand
    /// side, into the one that meets the constraint at @p u (further solves
    /// x = tangent^{-1} b by @p solve). Collective.
    virtual void
    constrain_update(
      const VectorType                                            &u,
      const std::function<void(const VectorType &, VectorType &)> &solve,
      VectorType &update) const = 0;

    /// Removes from @p v (a residual, a right-hand side or a direction at
    /// @p u) its components along what the constraint holds: their forces
    /// are its reactions. Collective.
    virtual void
    project_out(const VectorType &u, VectorType &v) const = 0;
  };
} // namespace hyperelastic
