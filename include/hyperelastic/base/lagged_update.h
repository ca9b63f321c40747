// What an update of lagged quantities (friction's normal forces and
// tangents) did: shared by the terms that lag, the operator that asks them
// and Newton's solver that decides when to ask.
#pragma once

namespace hyperelastic
{
  /// When lagged quantities are taken again.
  enum class LagMoment
  {
    converged,    ///< at a converged state of the current equations
    within_solve, ///< before convergence, at a Newton iterate
    predicted     ///< at the step's first iterate, a prediction of its
                  ///< answer (the dynamics guess; obstacle friction only)
  };

  /// The outcome of an update of lagged quantities.
  enum class LaggedUpdate
  {
    unchanged, ///< they changed too little to matter (or may not change)
    updated    ///< they changed: the equations are new
  };

  /// The combined outcome of several terms' updates: updated if any
  /// updated, else unchanged.
  inline LaggedUpdate
  combine(const LaggedUpdate a, const LaggedUpdate b)
  {
    if (a == LaggedUpdate::updated || b == LaggedUpdate::updated)
      return LaggedUpdate::updated;
    return LaggedUpdate::unchanged;
  }
} // namespace hyperelastic
