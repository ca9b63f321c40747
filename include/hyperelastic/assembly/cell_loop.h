// The loop over a rank's own cells that every FEValues assembly pass shares:
// a failure on one cell (a non-finite stress, a bubble that does not
// converge) stops the pass and becomes a ConvergenceFailure on every rank,
// naming the cell.
#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <hyperelastic/assembly/assembly_tools.h>
#include <hyperelastic/base/error_handling.h>

#include <exception>
#include <string>

namespace hyperelastic
{
  /// Calls @p worker(cell) for every locally owned cell of @p dof_handler
  /// (collective).
  template <int dim, typename CellWorker>
  void
  for_each_owned_cell(const dealii::DoFHandler<dim> &dof_handler,
                      CellWorker                   &&worker)
  {
    std::string error;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          try
            {
              worker(cell);
            }
          catch (const std::exception &e)
            {
              error = cell_failure_text(cell->active_cell_index(),
                                        cell->center(),
                                        exception_message(e));
              break;
            }
        }
    throw_convergence_failure_if_any(error, dof_handler.get_communicator());
  }
} // namespace hyperelastic
