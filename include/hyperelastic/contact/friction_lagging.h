// Lagged friction's update rule, shared by the contact terms: at a converged
// state the normal forces are taken again; if one changed by more than 1e-3
// of the largest, the step is solved again with them, at most 'Friction
// lagging updates' times a step.
#pragma once

#include <deal.II/base/mpi.h>

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
      updates = 0;
    }

    /// Whether this step may still update its lagged quantities.
    bool
    may_update() const
    {
      return updates < max_updates;
    }

    /// The largest change of a normal force on this rank and the largest
    /// normal force: whether the change (over all ranks) calls for solving
    /// the step again with the new ones; counts the update if so.
    /// Collective.
    bool
    accept(double change, double largest, const MPI_Comm comm)
    {
      change  = dealii::Utilities::MPI::max(change, comm);
      largest = dealii::Utilities::MPI::max(largest, comm);
      if (!(change > 1e-3 * largest))
        return false;
      ++updates;
      return true;
    }

  private:
    const unsigned int max_updates;
    unsigned int       updates = 0;
  };
} // namespace hyperelastic
