// Reading a mesh file of any supported format into a cell list: the format
// is chosen by the file's extension.
#pragma once

#include <hyperelastic/mesh/gmsh_reader.h>

#include <string>

namespace hyperelastic
{
  /// The extensions read_mesh_file() reads, for messages and the manual:
  /// ".msh (gmsh), .mesh (MEDIT), .vtk (legacy VTK)".
  std::string
  supported_mesh_file_extensions();

  /// Reads @p file_name by its extension: .msh with read_gmsh(), .mesh
  /// with read_medit(), .vtk with read_vtk() (case-insensitive). Another
  /// extension is an InputError naming the scene entry @p entry and listing
  /// the supported ones. Without @p cells_required a file of faces alone
  /// (an obstacle's surface) is read too.
  template <int dim>
  GmshMesh<dim>
  read_mesh_file(const std::string &file_name,
                 const std::string &entry          = "Mesh/File",
                 bool               cells_required = true);
} // namespace hyperelastic
