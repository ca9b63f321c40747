// Reading a run's step summaries by CSV column name: one value, the step
// that ends at a given time, and the mean rate of change of a column (e.g.
// an acceleration from the momentum) between two times, the smallest
// value over the steps and the sum over them.
#pragma once

#include <hyperelastic/output/step_summary.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace hyperelastic::testing
{
  /// The value of column @p name in @p summary (NaN if it has none).
  template <int dim>
  double
  column(const StepSummary<dim> &summary, const std::string &name)
  {
    for (const auto &c : summary.columns())
      if (c.name == name)
        return c.value;
    return std::nan("");
  }

  /// The summary of the step that ends at time (load factor) @p t.
  template <int dim>
  const StepSummary<dim> &
  at_time(const std::vector<StepSummary<dim>> &summaries, const double t)
  {
    for (const auto &s : summaries)
      if (std::abs(s.load_factor - t) < 1e-9)
        return s;
    throw std::runtime_error("no step ends at t = " + std::to_string(t));
  }

  /// (column(t1) - column(t0)) / (t1 - t0) of column @p name.
  template <int dim>
  double
  mean_rate(const std::vector<StepSummary<dim>> &summaries,
            const std::string                   &name,
            const double                         t0,
            const double                         t1)
  {
    return (column(at_time(summaries, t1), name) -
            column(at_time(summaries, t0), name)) /
           (t1 - t0);
  }

  /// The smallest value of column @p name over @p summaries.
  template <int dim>
  double
  smallest(const std::vector<StepSummary<dim>> &summaries,
           const std::string                   &name)
  {
    double result = std::numeric_limits<double>::infinity();
    for (const auto &s : summaries)
      result = std::min(result, column(s, name));
    return result;
  }

  /// The sum of column @p name over @p summaries (e.g. a run's Newton
  /// iterations in all).
  template <int dim>
  double
  total(const std::vector<StepSummary<dim>> &summaries, const std::string &name)
  {
    double result = 0.;
    for (const auto &s : summaries)
      result += column(s, name);
    return result;
  }
} // namespace hyperelastic::testing
