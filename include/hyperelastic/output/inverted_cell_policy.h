// The solver's policy on inverted cells at a converged state ('Newton/
// Inverted elements at equilibrium'): accept it with a warning, or reject it
// as no solution.
#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <hyperelastic/output/inverted_cells.h>
#include <hyperelastic/solvers/newton_parameters.h>

#include <string>

namespace hyperelastic
{
  /// The verdict on a converged state with @p inverted cells, by
  /// 'Newton/Inverted elements at equilibrium': nothing if there are none; a
  /// warning on @p pcout if accepted (a model defined at J <= 0, @p defined,
  /// can have them as its correct discrete answer, e.g. near the clamped
  /// edges of a crushed body); a ConvergenceFailure otherwise (for a model
  /// undefined there such a state is never a solution). @p model: the
  /// model's name for the messages.
  template <int dim>
  void
  judge_inverted_cells(const InvertedCells<dim>         &inverted,
                       const NewtonParameters           &newton,
                       const std::string                &model,
                       bool                              defined,
                       const dealii::ConditionalOStream &pcout);
} // namespace hyperelastic
