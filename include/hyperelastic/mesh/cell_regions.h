// Which region (materials/region_parameters.h) each cell of the mesh belongs
// to: the cells of a region's gmsh physical tag ('Material id') or those
// whose centre satisfies its condition ('Cells'); 0 for the cells in no
// region (the top-level Material). Decided once, on the cells each rank
// sees (own and ghost cells: both need their material), with the scene's
// input errors checked over all ranks.
#pragma once

#include <deal.II/grid/tria.h>

#include <hyperelastic/materials/region_parameters.h>

#include <vector>

namespace hyperelastic
{
  struct CellRegions
  {
    /// The region of each active cell by active cell index, 0 for the
    /// top-level Material and k for the k-th entry of the scene's regions
    /// (in the order of RegionParameters::parse_all()). Meaningful on the
    /// cells this rank sees; empty if the scene has no region.
    std::vector<unsigned char> of_cell;
    /// The number of cells of each region over all ranks, [0] the cells in
    /// none.
    std::vector<unsigned long long> n_cells;

    /// The region of the cell with active index @p cell.
    unsigned int
    operator()(const unsigned int cell) const
    {
      return of_cell.empty() ? 0 : of_cell[cell];
    }
  };

  /// The regions of @p regions on @p triangulation. Collective; throws
  /// InputError on every rank for a region that selects no cell (a
  /// 'Material id' the mesh does not have, a 'Cells' condition no cell
  /// centre satisfies, a condition that cannot be parsed) and for a cell
  /// selected by two regions.
  template <int dim>
  CellRegions
  assign_cell_regions(const dealii::Triangulation<dim>    &triangulation,
                      const std::vector<RegionParameters> &regions);
} // namespace hyperelastic
