// The tests' sums over the nodes of a displacement field (forces, moments,
// mean displacements, rotations): every vertex whose unknowns this rank owns,
// visited once; the caller sums over the ranks.
#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <set>

namespace hyperelastic::testing
{
  /// Calls @p visit(cell, v) once for every vertex of the locally owned
  /// cells whose unknowns this rank owns (a vertex's components are owned
  /// together).
  template <int dim, typename Visit>
  void
  for_each_owned_vertex(const dealii::DoFHandler<dim> &dof_handler,
                        Visit                        &&visit)
  {
    std::set<dealii::types::global_dof_index> seen;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto first = cell->vertex_dof_index(v, 0);
            if (dof_handler.locally_owned_dofs().is_element(first) &&
                seen.insert(first).second)
              visit(cell, v);
          }
  }
} // namespace hyperelastic::testing
