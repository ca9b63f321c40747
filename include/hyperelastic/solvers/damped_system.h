// A capability that only some stepped systems have: a damping energy
// c/2 (u - w)^T D (u - w) added to the potential (D a diagonal metric on the
// free unknowns, w the centre), the pseudo-transient continuation of snap
// sub-steps (SnapSequence), where NonlinearSystem::Properties::damping.
#pragma once

namespace hyperelastic
{
  // capability interface
  class DampedSystem
  {
  public:
    virtual ~DampedSystem() = default;

    /// Sets the damping @p c (0: none) centred at the current iterate: the
    /// forces, tangent and energy include it until it is set again.
    /// Collective.
    virtual void
    set_damping(double c) = 0;

    /// The norm of the damping force c D (u - w) at the current iterate on
    /// the free unknowns (0 without damping). Collective.
    virtual double
    damping_force() = 0;

    /// The damping at which c D matches the diagonal of the tangent at the
    /// last converged state on average (the stiffness per unit of the
    /// metric). Leaves the system at its last converged state, without
    /// damping. Collective.
    virtual double
    damping_scale() = 0;
  };
} // namespace hyperelastic
