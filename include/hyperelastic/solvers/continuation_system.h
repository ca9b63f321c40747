// A capability that only some stepped systems have: arc-length continuation,
// where the load factor t is an unknown next to u. States (u, t) set from
// outside, the residual's derivative in t, and the inner product the arc
// length is measured in. The arc-length stepper takes it explicitly, with
// the tangent's solves at such a state (TangentSystem).
#pragma once

#include <hyperelastic/base/linear_algebra.h>

namespace hyperelastic
{
  // capability interface
  class ContinuationSystem
  {
  public:
    virtual ~ContinuationSystem() = default;

    /// Makes (@p u, @p t) the state: u's free entries from @p u (owned
    /// entries), its prescribed entries at their values at t. Collective.
    virtual void
    set_state(const VectorType &u, double t) = 0;

    /// dr/dt at fixed free unknowns (the loads and the prescribed values
    /// move with t), at the state, into @p r_t. Collective.
    virtual void
    load_derivative(VectorType &r_t) = 0;

    /// The inner product the arc length is measured in: over the
    /// displacements (a mixed formulation's pressures left out).
    virtual double
    path_product(const VectorType &a, const VectorType &b) const = 0;
  };
} // namespace hyperelastic
