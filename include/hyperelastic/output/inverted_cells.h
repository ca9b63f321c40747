// Inverted cells of a displacement field: how many cells have J = det(I +
// grad u) <= 0 at a quadrature point, the smallest J and where it is. For
// the CSV summary, and for the solver's verdict on a converged state
// (output/inverted_cell_policy.h).
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

namespace hyperelastic
{
  /// The inverted cells of a displacement field (find_inverted_cells()).
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
} // namespace hyperelastic
