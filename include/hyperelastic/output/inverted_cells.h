// Inverted cells of a displacement field: how many cells have J = det(I +
// grad u) <= 0 at a quadrature point, the smallest J and where it is. Used
// to accept or reject a converged state (judge_inverted_cells) and for the
// CSV summary.
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hyperelastic/solvers/newton_parameters.h>

#include <string>

namespace hyperelastic
{
  template <int dim>
  struct InvertedCells
  {
    /// Cells with J <= 0 at one of their quadrature points, over all ranks.
    dealii::types::global_cell_index n_cells = 0;
    /// The smallest J at the quadrature points of the whole mesh.
    double min_J = 1.;
    /// Reference centre of the cell where that smallest J is.
    dealii::Point<dim> worst_cell_center;
  };

  /// Evaluates F = I + grad u at the stress quadrature points
  /// (QGaussSimplex(degree): one point for P1) of every locally owned cell.
  /// Collective; @p u must have ghost entries.
  template <int dim>
  InvertedCells<dim>
  find_inverted_cells(const dealii::Mapping<dim>                  &mapping,
                      const dealii::DoFHandler<dim>               &dof_handler,
                      const dealii::TrilinosWrappers::MPI::Vector &u);

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
