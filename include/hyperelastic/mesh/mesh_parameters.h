// The scene's Mesh subsection: a generated box or a gmsh file.
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
    file
  };

  struct MeshParameters
  {
    MeshSource                source = MeshSource::box;
    std::string               file; ///< resolved against the scene's folder
    std::vector<double>       lower_corner;
    std::vector<double>       upper_corner;
    std::vector<unsigned int> subdivisions;
    unsigned int              global_refinements = 0;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &scene_folder);
    /// The box's entries against Problem/Dimension @p dim (one value per
    /// coordinate, the upper corner above the lower one).
    void
    check_dimension(unsigned int dim) const;
  };
} // namespace hyperelastic
