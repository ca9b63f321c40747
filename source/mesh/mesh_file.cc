// Reading a mesh file of any supported format: the reader chosen by the
// file's extension.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/medit_reader.h>
#include <hyperelastic/mesh/mesh_file.h>
#include <hyperelastic/mesh/vtk_reader.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace hyperelastic
{
  std::string
  supported_mesh_file_extensions()
  {
    return ".msh (gmsh), .mesh (MEDIT) and .vtk (legacy VTK)";
  }

  template <int dim>
  GmshMesh<dim>
  read_mesh_file(const std::string &file_name,
                 const std::string &entry,
                 const bool         cells_required)
  {
    std::string extension =
      std::filesystem::path(file_name).extension().string();
    std::transform(extension.begin(),
                   extension.end(),
                   extension.begin(),
                   [](const unsigned char c) { return std::tolower(c); });
    if (extension == ".msh")
      return read_gmsh<dim>(file_name, entry, cells_required);
    if (extension == ".mesh")
      return read_medit<dim>(file_name, entry, cells_required);
    if (extension == ".vtk")
      return read_vtk<dim>(file_name, entry, cells_required);
    throw InputError(
      "scene entry '" + entry + "' = '" + file_name + "': " +
      (extension.empty() ? std::string("the file name has no extension")
                         : "the extension '" + extension + "' is not known") +
      "; the mesh formats read are " + supported_mesh_file_extensions() +
      (extension == ".obj" || extension == ".stl" || extension == ".ply" ||
           extension == ".off"
         ? " (a closed surface is filled with tetrahedra with 'Mesh/Source "
           "= surface')"
         : ""));
  }

  template GmshMesh<2>
  read_mesh_file<2>(const std::string &, const std::string &, bool);
  template GmshMesh<3>
  read_mesh_file<3>(const std::string &, const std::string &, bool);
} // namespace hyperelastic
