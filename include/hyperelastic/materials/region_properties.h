// What the regions of a scene's mesh give the rest of the program, beyond
// each cell's material: the stiffness contrast the linear solver's AMG
// adapts to, the moduli the automatic contact defaults take (those of the
// materials at the boundary), and the density of each region in dynamics.
#pragma once

#include <deal.II/grid/tria.h>

#include <hyperelastic/assembly/material_regions.h>
#include <hyperelastic/materials/region_parameters.h>
#include <hyperelastic/mesh/cell_regions.h>

#include <vector>

namespace hyperelastic
{
  /// The largest over the smallest small-strain stiffness lambda + 2 mu of
  /// the materials with cells (1 for one material): the linear solver's
  /// 'AMG for contrast = auto'.
  template <int dim>
  double
  stiffness_contrast(const MaterialRegions<dim> &materials,
                     const CellRegions          &cell_regions);

  /// The stiffest moduli of the regions with a cell at the boundary (where
  /// contact acts). Collective.
  template <int dim>
  LameParameters
  boundary_moduli(const MaterialRegions<dim>       &materials,
                  const CellRegions                &cell_regions,
                  const dealii::Triangulation<dim> &triangulation);

  /// The density of each region (region 0, the top-level Material's cells,
  /// first: @p density, 'Time integration/Density'); empty without
  /// regions.
  std::vector<double>
  region_densities(const std::vector<RegionParameters> &regions,
                   double                               density);
} // namespace hyperelastic
