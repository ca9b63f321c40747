// Lagged friction's update rule, shared by the contact terms: the normal
// forces are taken again within Newton's iterations
// (NewtonSolver::update_lagged_early), at a converged state, and in
// dynamics at the step's guess, and Newton goes on with them if they
// changed enough ('Friction lag trigger'):
// - single pair (the default): any pair's normal force changed by more than
//   1e-3 of the largest. In a slide pairs enter and leave every step with
//   normal forces near 0, and it fires on every step;
// - friction force: the friction force they change, assembled over the
//   contact (the l2 norm of mu (lambda_new - lambda) f1(|s|) along each
//   pair's slip s at the iterate), is more than 1e-3 of the contact's
//   normal forces (their l2 norm). The friction force is what the lag gets
//   wrong (issue 67, item 5).
// A step takes at most 'Friction lagging updates' of them, and besides as
// many large ones (a change of more than half the largest normal force, or
// with the friction-force trigger of half the normal forces' norm: the
// first iterates of a first contact or an impact), so that those do not
// use up the updates the answer's accuracy needs; the guess's own update
// is not counted.
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

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace hyperelastic
{
  class FrictionLagging
  {
  public:
    /// At most @p max_updates a step; @p friction_force: the trigger on
    /// the assembled friction force rather than on single pairs.
    FrictionLagging(const unsigned int max_updates, const bool friction_force)
        : max_updates(max_updates)
        , friction_force(friction_force)
    {}

    /// Whether the trigger needs the change of the friction force
    /// (Change::friction_squared).
    bool
    needs_friction_change() const
    {
      return friction_force;
    }

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

    /// What an update would change, summed over this rank's pairs (each
    /// pair counted on one rank).
    struct Change
    {
      /// The squared l2 norm of the change of the assembled friction force.
      double friction_squared = 0.;
      /// The squared l2 norms of the new normal forces and of their change.
      double normal_squared        = 0.;
      double normal_change_squared = 0.;
      /// The largest new normal force and the largest change of one.
      double largest        = 0.;
      double largest_change = 0.;

      /// A pair's normal force goes from @p before to @p after.
      void
      add_normal_force(const double before, const double after)
      {
        normal_squared += after * after;
        normal_change_squared += (after - before) * (after - before);
        largest        = std::max(largest, after);
        largest_change = std::max(largest_change, std::abs(after - before));
      }
    };

    /// The relative change that calls for an update (of the assembled
    /// friction force against the normal forces, or of one normal force
    /// against the largest).
    static constexpr double tolerance = 1e-3;

    /// Whether the change @p c (over all ranks), taken at @p at, calls for
    /// going on with the new values (updated; the update is counted), or is
    /// too small to matter or taken too far from an equilibrium (within the
    /// solve, an unbalanced force above half the largest normal force):
    /// unchanged. Collective.
    LaggedUpdate
    decide(const Change &c, const Iterate &at, const MPI_Comm comm)
    {
      const double largest = dealii::Utilities::MPI::max(c.largest, comm);
      bool         changed = false, large = false;
      if (friction_force)
        {
          const double local[3] = {c.friction_squared,
                                   c.normal_squared,
                                   c.normal_change_squared};
          double       sums[3];
          dealii::Utilities::MPI::sum(local, comm, sums);
          const double normal_forces = std::sqrt(sums[1]);
          changed = std::sqrt(sums[0]) > tolerance * normal_forces;
          large   = std::sqrt(sums[2]) > 0.5 * normal_forces;
        }
      else
        {
          const double change =
            dealii::Utilities::MPI::max(c.largest_change, comm);
          changed = change > tolerance * largest;
          large   = change > 0.5 * largest;
        }
      if (!changed)
        return LaggedUpdate::unchanged;
      if (at.moment == LagMoment::within_solve &&
          !(at.unbalanced_force <= 0.5 * largest))
        return LaggedUpdate::unchanged;
      if (at.moment == LagMoment::predicted)
        return LaggedUpdate::updated;
      if (large && large_updates < max_updates)
        ++large_updates;
      else
        ++updates;
      return LaggedUpdate::updated;
    }

    /// decide(), and if updated, @p next becomes the term's @p lagged.
    template <typename Lagged>
    LaggedUpdate
    take_if_changed(const Change        &change,
                    const Iterate       &at,
                    const MPI_Comm       comm,
                    std::vector<Lagged> &lagged,
                    std::vector<Lagged> &next)
    {
      const LaggedUpdate outcome = decide(change, at, comm);
      if (outcome == LaggedUpdate::updated)
        lagged = std::move(next);
      return outcome;
    }

  private:
    const unsigned int max_updates;
    const bool         friction_force;
    unsigned int       updates       = 0;
    unsigned int       large_updates = 0;
  };
} // namespace hyperelastic
