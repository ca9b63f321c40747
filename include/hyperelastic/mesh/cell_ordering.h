// The order of the cells and vertices of a mesh read from a file: along a
// space-filling curve, so that neighbouring cells (and the unknowns deal.II
// numbers cell by cell) are near each other in memory.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/tria_description.h>

#include <vector>

namespace hyperelastic
{
  /// Sorts @p cells (and @p element_numbers with them) by the Morton
  /// (Z-order) key of their centroids in the bounding box of @p vertices,
  /// then renumbers the vertices in the order the sorted cells first use
  /// them (vertices no cell uses keep their relative order, after the
  /// others), in @p cells and in the faces of @p boundary.
  ///
  /// A mesh generator's cell order follows its meshing front, not space:
  /// deal.II numbers the unknowns cell by cell in the order of the coarse
  /// cells, so on a gmsh mesh of 1.1e6 tetrahedra one product with the
  /// tangent took 2.8 times as long per row as on a generated box.
  /// Geometry, orientation, the element numbers of messages and every
  /// result are unchanged; only the numbering (hence round-off) differs.
  template <int dim>
  void
  order_cells_along_curve(std::vector<dealii::Point<dim>>    &vertices,
                          std::vector<dealii::CellData<dim>> &cells,
                          std::vector<long long>             &element_numbers,
                          dealii::SubCellData                &boundary);

  /// The Morton key of @p x in the box [@p lower, @p upper]: the bits of
  /// the coordinates' positions on a grid of 2^(63/dim) points per
  /// direction, interleaved (NaN and points outside the box are clamped).
  template <int dim>
  unsigned long long
  morton_key(const dealii::Point<dim> &x,
             const dealii::Point<dim> &lower,
             const dealii::Point<dim> &upper);
} // namespace hyperelastic
