// Closed surfaces as users have them: OBJ, STL (ASCII and binary), PLY
// (ASCII and binary little-endian) and OFF files read into one list of
// triangles on shared vertices, with the file's groups (OBJ 'g'/'o', a PLY
// face property) as numbers 1, 2, ... in order of appearance.
#pragma once

#include <deal.II/base/point.h>

#include <array>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// A triangulated surface: vertices, triangles (0-based vertex indices)
  /// and each triangle's group (0: none; else 1, 2, ... in the order the
  /// groups first appear in the file).
  struct SurfaceTriangles
  {
    std::vector<dealii::Point<3>>            vertices;
    std::vector<std::array<unsigned int, 3>> triangles;
    std::vector<unsigned int>                groups;
    /// group_names[k - 1]: the file's name (or PLY value) of group k.
    std::vector<std::string> group_names;
  };

  /// Reads @p file_name by its extension (.obj, .stl, .ply, .off, any
  /// case). Polygons are split into triangles around their first vertex;
  /// vertices at equal coordinates are joined (STL's separate triangles,
  /// exporters writing each face's corners) and vertices no triangle uses
  /// dropped, the others kept in the file's order. Errors are
  /// InputErrors naming the scene entry @p entry.
  SurfaceTriangles
  read_surface_file(const std::string &file_name,
                    const std::string &entry = "Mesh/File");
} // namespace hyperelastic
