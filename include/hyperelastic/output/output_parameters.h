// The scene's Output subsection: files, verbosity and reported points.
// Declared with pattern, default and documentation; parsed with the values
// checked (an invalid value is an InputError naming the entry).
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  /// 'Output/Surface format': the deformed surface per output frame for
  /// animation tools (output/surface_writer.h), or none.
  enum class SurfaceFormat
  {
    none,
    obj,
    ply
  };

  struct OutputParameters
  {
    std::string directory = "output";
    std::string base_name = "solution";
    bool        write_vtu = true;
    /// 'Write HDF5': <base>.xdmf with <base>_mesh.h5 and <base>_NNNN.h5.
    bool write_hdf5 = false;
    /// 'Write mesh': the volume mesh generated from a closed surface as
    /// <base>_mesh.msh (gmsh ASCII 4.1).
    bool write_mesh = false;
    bool        verbose   = true;
    SurfaceFormat surface_format = SurfaceFormat::none;
    /// 'Checkpoint every': steps between checkpoints (0: none).
    unsigned int checkpoint_every = 0;

    /// <Directory>/<Base name>.checkpoint.
    std::string
    checkpoint_file() const
    {
      return directory + "/" + base_name + ".checkpoint";
    }
    /// Reference points at which the displacement is reported every load
    /// step ("Points"): each 2 or 3 coordinates as written (the number is
    /// checked against the dimension at setup).
    std::vector<std::vector<double>> points;
    /// 'Moment point': the point about which the reaction_moment_<id>
    /// columns take the supports' moments; Problem/Dimension values.
    std::vector<double> moment_point = {0., 0., 0.};

    static void
    declare(ParameterHandler &prm);
    /// Reads the entries; 'Moment point' must have @p dim values (its 3D
    /// default is cut to 2 values in 2D).
    void
    parse(ParameterHandler &prm, unsigned int dim);
  };
} // namespace hyperelastic
