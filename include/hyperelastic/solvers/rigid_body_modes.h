// The rigid-body modes of a displacement field (dim translations and
// dim (dim - 1) / 2 rotations), the near-null space ML's smoothed-aggregation
// AMG needs for elasticity. deal.II 9.4 has no helper for this.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <vector>

namespace hyperelastic
{
  /// The modes on the locally owned dofs, stored column by column (mode m of
  /// owned dof k at [m * n_owned + k], the layout ML expects), rotations taken
  /// about the centre of the mesh's bounding box for better conditioning.
  template <int dim>
  std::vector<double>
  rigid_body_modes(const dealii::Mapping<dim>    &mapping,
                   const dealii::DoFHandler<dim> &dof_handler);

  template <int dim>
  constexpr unsigned int n_rigid_body_modes = dim *(dim + 1) / 2;
} // namespace hyperelastic
