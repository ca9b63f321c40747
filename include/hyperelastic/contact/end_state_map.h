// The end-state map of a step (SteppedTerm::set_end_state_map) as the
// contact terms apply it: a vertex at x in the step's solved state is at
// x_start + c (x - x_start) at the step's end, and a pair's potential
// weight V(x_end) / c has the gradient weight V'(x_end) and the Hessian
// weight c V''(x_end) in the solved state.
#pragma once

#include <deal.II/base/point.h>

namespace hyperelastic
{
  struct EndStateMap
  {
    /// c: 2 for implicit midpoint, 1 otherwise.
    double c = 1.;
    /// The scheme's weight of the end-state forces (Newmark: 2).
    double weight = 1.;

    /// Where a vertex solved at @p x, which started the step at @p start,
    /// is at the step's end (callers skip it where c = 1: x itself, and
    /// the start positions may not be set yet).
    template <int dim>
    dealii::Point<dim>
    end_position(const dealii::Point<dim> &start,
                 const dealii::Point<dim> &x) const
    {
      return start + c * (x - start);
    }

    /// The factors of a pair's energy, gradient and Hessian in the solved
    /// state.
    double
    energy_factor() const
    {
      return weight / c;
    }
    double
    gradient_factor() const
    {
      return weight;
    }
    double
    hessian_factor() const
    {
      return weight * c;
    }
  };
} // namespace hyperelastic
