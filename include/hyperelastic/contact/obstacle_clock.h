// Where a step's moving obstacles stand, shared by the obstacle contact
// terms (ObstacleContact, MeshObstaclePairs): within a step the obstacles
// are carried from where they stood at its start to where they stand at its
// end time (the moving-obstacle continuation of MovingAdmissibleSetTerm),
// and under an end-state map (SteppedTerm::set_end_state_map) the step
// solved at load factor t ends at step_start + c (t - step_start).
#pragma once

#include <hyperelastic/contact/end_state_map.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hyperelastic
{
  struct ObstacleClock
  {
    /// The step's start.
    double step_start = 0.;
    /// The obstacle time reached within the step (+inf outside a step: the
    /// obstacles stand at t).
    double reached = std::numeric_limits<double>::infinity();
    /// The step's end-state map.
    EndStateMap end_state;

    /// A step begins at @p t_start: the obstacles stand there, no
    /// end-state map yet.
    void
    begin_step(const double t_start)
    {
      step_start = t_start;
      reached    = t_start;
      end_state  = EndStateMap();
    }

    /// The end time of the step solved at @p t (t, or its image under the
    /// end-state map).
    double
    end_time(const double t) const
    {
      return std::isfinite(reached)
               ? step_start + end_state.c * (t - step_start)
               : t;
    }

    /// The time from the step's start to the end time of @p t (not
    /// negative).
    double
    elapsed(const double t) const
    {
      return std::max(0., end_time(t) - step_start);
    }

    /// Where the obstacles are evaluated for load factor @p t: at the end
    /// time, or where they stand on their way within the step.
    double
    obstacle_time(const double t) const
    {
      return std::min(end_time(t), reached);
    }

    /// Whether the obstacles are still on their way to the end time of
    /// @p t.
    bool
    on_the_way(const double t) const
    {
      return reached < end_time(t);
    }

    /// Whether the obstacles have a way to go to the end time of @p t:
    /// @p moves(from, to) says whether they stand elsewhere at time to
    /// than at time from. Standing still, they are there already.
    template <typename Moves>
    bool
    prepare_motion(const double t, const Moves &moves)
    {
      const double t_end = end_time(t);
      if (!(reached < t_end))
        return false;
      if (moves(reached, t_end))
        return true;
      reached = t_end;
      return false;
    }

    /// The obstacles moved a fraction @p alpha of the rest of their way to
    /// the end time of @p t (all of it for alpha >= 1).
    void
    advance(const double alpha, const double t)
    {
      const double t_end = end_time(t);
      if (reached < t_end)
        reached = alpha >= 1. ? t_end : reached + alpha * (t_end - reached);
    }
  };
} // namespace hyperelastic
