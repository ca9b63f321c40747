// Reading a legacy VTK .vtk file (DATASET UNSTRUCTURED_GRID, ASCII or
// BINARY) into the cell list the gmsh reader produces.
#pragma once

#include <hyperelastic/mesh/gmsh_reader.h>

#include <string>

namespace hyperelastic
{
  /// Reads the legacy VTK unstructured grid @p file_name (ASCII, or BINARY:
  /// big-endian): tetrahedra (3D, VTK cell type 10) or triangles (2D, type
  /// 5) are the cells; triangles (3D) or lines (2D, type 3) are boundary
  /// faces; vertices (type 1) and, in 3D, lines are skipped. The cell data
  /// array MaterialID, gmsh:physical or CellEntityIds (preferred in this
  /// order, as SCALARS or in a FIELD) gives the material id of each cell
  /// and the boundary id of each face (0 without such an array). Element
  /// numbers are the VTK cell ids (positions in the cell list, from 0).
  /// Versions 2 to 4 (CELLS as counts and points) and 5 (OFFSETS and
  /// CONNECTIVITY) are read; POINT_DATA and other arrays are skipped. Errors
  /// name the file and the line or section, and the scene entry @p entry when
  /// the file cannot be opened. Without @p cells_required a file of faces alone
  /// (an obstacle's surface) is read too.
  template <int dim>
  GmshMesh<dim>
  read_vtk(const std::string &file_name,
           const std::string &entry          = "Mesh/File",
           bool               cells_required = true);
} // namespace hyperelastic
