// Post-processing: per-cell quantities of a displacement field for the VTU
// output (J, energy density, Cauchy stress, von Mises stress).
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/assembly/material_regions.h>
#include <hyperelastic/materials/material.h>

#include <array>

namespace hyperelastic
{
  /// Cell-wise derived quantities of a displacement field, for output. For
  /// P1 they are exact; for higher degrees they are cell averages.
  struct CellFields
  {
    dealii::Vector<double> J;
    dealii::Vector<double> energy_density;
    dealii::Vector<double> von_mises;
    /// Cauchy stress components xx, yy, zz, xy, xz, yz (zz from plane strain
    /// in 2D; xz and yz are zero there).
    std::array<dealii::Vector<double>, 6> cauchy;
    /// The number k of each cell's 'Region k' (0: the top-level Material);
    /// empty (not written) for a scene without regions.
    dealii::Vector<double> region;
    /// det Fg of the growth tensor (materials/grown.h), 1 where a region
    /// does not grow; empty (not written) for a scene without growth.
    dealii::Vector<double> growth_J;
  };

  /// The fields of the locally owned cells for displacement @p u (with
  /// ghost entries), each cell with its region's model. @p material3d holds
  /// the 3D twins of @p material's models (the same regions), for the
  /// plane-strain out-of-plane stress.
  template <int dim>
  CellFields
  compute_cell_fields(const dealii::DoFHandler<dim>               &dof_handler,
                      const dealii::Mapping<dim>                  &mapping,
                      const MaterialRegions<dim>                  &material,
                      const MaterialRegions<3>                    &material3d,
                      const dealii::TrilinosWrappers::MPI::Vector &u);
} // namespace hyperelastic
