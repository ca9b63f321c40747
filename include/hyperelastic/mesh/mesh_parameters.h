// The scene's Mesh subsection: a generated box, a gmsh file or a closed
// surface meshed on the fly.
// Declared with pattern, default and documentation; parsed with the values
// checked (an invalid value is an InputError naming the entry).
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  enum class MeshSource
  {
    box,
    file,
    surface ///< a closed surface (OBJ, STL, PLY, OFF) tetrahedralised
  };

  struct MeshParameters
  {
    MeshSource                source = MeshSource::box;
    std::string               file; ///< resolved against the scene's folder
    std::vector<double>       lower_corner;
    std::vector<double>       upper_corner;
    std::vector<unsigned int> subdivisions;
    unsigned int              global_refinements = 0;
    /// 'Mesh size' (Source = surface): the target edge length; 0: the
    /// surface's mean edge length.
    double mesh_size = 0.;
    /// Where the volume mesh generated from a surface is written
    /// ('Output/Write mesh'; set by Parameters from the Output section),
    /// empty: not written.
    std::string generated_mesh_file;

    static void
    declare(ParameterHandler &prm);
    /// The entries of 'Mesh' for a scene of dimension @p dim (the box's 3D
    /// defaults become 2D ones in 2D).
    void
    parse(ParameterHandler  &prm,
          const std::string &scene_folder,
          unsigned int       dim);
    /// The box's entries against Problem/Dimension @p dim (one value per
    /// coordinate, the upper corner above the lower one); a surface is
    /// meshed in 3D only.
    void
    check_dimension(unsigned int dim) const;
  };
} // namespace hyperelastic
