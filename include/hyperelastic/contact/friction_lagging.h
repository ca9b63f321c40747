// Lagged friction's update rule, shared by the contact terms: the normal
// forces are taken again within Newton's iterations
// (NewtonSolver::update_lagged_early), at a converged state, and in
// dynamics at the step's guess; if one changed by more than 1e-3 of the
// largest, Newton goes on with them. A step takes at most 'Friction lagging
// updates' of them, and besides as many large ones (a change of more than
// half the largest normal force: the first iterates of a first contact or
// an impact), so that those do not use up the updates the answer's
// accuracy needs; the guess's own update is not counted.
//
// Within the solve they are taken only at an iterate whose unbalanced force
// (the residual's l2 norm on the free unknowns) is below half the largest
// normal force there. A barrier's normal force changes by orders of
// magnitude with a small change of its gap, so an iterate far from
// equilibrium has normal forces of no equilibrium: taken there, they spent
// the step's updates on values Newton then moved away from, and the
// converged state kept friction forces of an earlier iterate (two blocks
// sliding with mu = 0.3 showed |Fx|/|Fy| up to 0.92, and 19.4 Newton
// iterations a step; with the rule 0.298-0.305 and 11.7,
// benchmarks/sliding_friction).
#pragma once

#include <deal.II/base/mpi.h>

#include <hyperelastic/base/lagged_update.h>

#include <utility>
#include <vector>

namespace hyperelastic
{
  class FrictionLagging
  {
  public:
    explicit FrictionLagging(const unsigned int max_updates)
        : max_updates(max_updates)
    {}

    /// A step begins: no update made yet.
    void
    begin_step()
    {
      updates       = 0;
      large_updates = 0;
    }

    /// Whether this step may still update its lagged quantities.
    bool
    may_update() const
    {
      return updates < max_updates;
    }

    /// Where the new values were taken: the moment, and the l2 norm of the
    /// residual on the free unknowns there (0 at a prediction).
    struct Iterate
    {
      LagMoment moment;
      double    unbalanced_force;
    };

    /// The largest change of a normal force on this rank and the largest
    /// normal force, taken at @p at: whether the change (over all ranks)
    /// calls for going on with the new ones (updated; the update is
    /// counted), or is too small to matter or taken too far from an
    /// equilibrium (within the solve, an unbalanced force above half the
    /// largest normal force): unchanged. Collective.
    LaggedUpdate
    decide(double change, double largest, const Iterate &at, const MPI_Comm comm)
    {
      change  = dealii::Utilities::MPI::max(change, comm);
      largest = dealii::Utilities::MPI::max(largest, comm);
      if (!(change > 1e-3 * largest))
        return LaggedUpdate::unchanged;
      if (at.moment == LagMoment::within_solve &&
          !(at.unbalanced_force <= 0.5 * largest))
        return LaggedUpdate::unchanged;
      if (at.moment == LagMoment::predicted)
        return LaggedUpdate::updated;
      if (change > 0.5 * largest && large_updates < max_updates)
        ++large_updates;
      else
        ++updates;
      return LaggedUpdate::updated;
    }

    /// decide(), and if updated, @p next becomes the term's @p lagged.
    template <typename Lagged>
    LaggedUpdate
    take_if_changed(const double         change,
                    const double         largest,
                    const Iterate       &at,
                    const MPI_Comm       comm,
                    std::vector<Lagged> &lagged,
                    std::vector<Lagged> &next)
    {
      const LaggedUpdate outcome = decide(change, largest, at, comm);
      if (outcome == LaggedUpdate::updated)
        lagged = std::move(next);
      return outcome;
    }

  private:
    const unsigned int max_updates;
    unsigned int       updates       = 0;
    unsigned int       large_updates = 0;
  };
} // namespace hyperelastic
