// A preconditioner the linear solver's Krylov method can use instead of ML
// AMG on the whole tangent (the two-level P2 -> P1 one): built for each
// tangent the solver decides to rebuild for, applied as x = B^-1 b.
#pragma once

#include <hyperelastic/base/linear_algebra.h>

#include <string>

namespace hyperelastic
{
  class TangentPreconditioner
  {
  public:
    virtual ~TangentPreconditioner() = default;

    /// Builds the preconditioner for @p A (which must outlive its use).
    virtual void
    initialize(const MatrixType &A) = 0;

    /// x = B^-1 b.
    virtual void
    vmult(VectorType &x, const VectorType &b) const = 0;

    /// What it is, for the run header.
    virtual std::string
    description() const = 0;
  };
} // namespace hyperelastic
