// A capability that only some nonlinear systems have: quantities the
// equations lag behind the iterate (friction's normal forces and tangents),
// taken again when Newton asks. Newton decides when (solvers/newton_solver.h);
// the system decides whether they changed enough to make the equations new.
#pragma once

#include <hyperelastic/base/lagged_update.h>

namespace hyperelastic
{
  // capability interface
  class LaggedSystem
  {
  public:
    virtual ~LaggedSystem() = default;

    /// Takes the lagged quantities again at the current iterate, at the
    /// @p moment Newton is at (a converged state of the current equations,
    /// or an iterate within the solve), whose residual on the free unknowns
    /// has the l2 norm @p unbalanced_force; returns whether they changed
    /// (updated: the energy of the current iterate is new) or changed too
    /// little, or are not to be taken at this iterate (unchanged).
    virtual LaggedUpdate
    update_lagged(LagMoment moment, double unbalanced_force) = 0;
  };
} // namespace hyperelastic
