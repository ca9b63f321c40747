// Reading a MEDIT (INRIA) .mesh file, ASCII, TetWild's other output, into the
// cell list the gmsh reader produces: tetrahedra (3D) or triangles (2D) with
// their references as material ids, triangles (3D) or edges (2D) with their
// references as boundary ids.
#pragma once

#include <hyperelastic/mesh/gmsh_reader.h>

#include <string>

namespace hyperelastic
{
  /// Reads the ASCII MEDIT file @p file_name: the sections Dimension,
  /// Vertices, Tetrahedra (3D cells), Triangles (2D cells, 3D faces) and
  /// Edges (2D faces); other sections (Corners, Ridges, Normals, ...) are
  /// skipped. A cell's reference is its material id, a face's its boundary
  /// id; element numbers are the positions in their section, from 1.
  /// Errors name the file and the line, and the scene entry @p entry when
  /// the file cannot be opened. Without @p cells_required a file of faces
  /// alone (an obstacle's surface) is read too.
  template <int dim>
  GmshMesh<dim>
  read_medit(const std::string &file_name,
             const std::string &entry          = "Mesh/File",
             bool               cells_required = true);
} // namespace hyperelastic
