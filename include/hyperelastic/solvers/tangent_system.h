// A capability that only some stepped systems have: the residual and solves
// with the tangent at a state set from outside (ContinuationSystem's), for
// arc length's corrector and the stiffness along the load path.
#pragma once

#include <hyperelastic/base/linear_algebra.h>
#include <hyperelastic/solvers/convergence_test.h>

namespace hyperelastic
{
  // capability interface
  class TangentSystem
  {
  public:
    virtual ~TangentSystem() = default;

    /// The residual f_int - f_ext of the state on the free unknowns (zero
    /// on prescribed rows) into @p r, and Newton's norms of it.
    virtual ResidualNorms
    free_residual(VectorType &r) = 0;

    /// Assembles the tangent at the state (prescribed rows decoupled).
    virtual void
    assemble_tangent() = 0;

    /// Solves K x = b (b zero on prescribed rows, x too) with the last
    /// assembled tangent, to the linear solver's tolerance; returns the
    /// Krylov iterations.
    virtual unsigned int
    solve_tangent(const VectorType &b, VectorType &x) = 0;
  };
} // namespace hyperelastic
