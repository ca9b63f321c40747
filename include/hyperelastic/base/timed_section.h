// An optional scope of a timer section: parts that may run with or without
// a TimerOutput (an energy term in a scene times its work, the same term in
// a unit test does not) open it the same way; and a stopwatch that adds its
// life to a sum.
#pragma once

#include <deal.II/base/timer.h>

#include <optional>
#include <string>

namespace hyperelastic
{
  /// A scope of section @p name of @p timer while it lives; empty if
  /// @p timer is null.
  inline std::optional<dealii::TimerOutput::Scope>
  timed_section(dealii::TimerOutput *timer, const std::string &name)
  {
    if (timer)
      return std::optional<dealii::TimerOutput::Scope>(std::in_place,
                                                       *timer,
                                                       name);
    return std::nullopt;
  }
  /// Adds the wall time of its life to @p sum (a part's accumulated cost,
  /// as self contact reports it).
  class Stopwatch
  {
  public:
    explicit Stopwatch(double &sum)
        : sum(sum)
    {}
    ~Stopwatch()
    {
      sum += timer.wall_time();
    }

  private:
    double        &sum;
    dealii::Timer  timer;
  };
} // namespace hyperelastic
