// The scene's Output subsection: declaration, documentation and validation of
// its entries.
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/output/output_parameters.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  using namespace entry_patterns;

  void
  OutputParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Anything(),
                      "Folder for all output (created if missing; relative to "
                      "the working directory).");
    prm.declare_entry("Base name",
                      "solution",
                      Anything(),
                      "Prefix of the output files: <base>.pvd, "
                      "<base>_<step>.pvtu, <base>_<step>.<rank>.vtu and "
                      "<base>.csv.");
    prm.declare_entry("Write VTU",
                      "true",
                      Bool(),
                      "Write the ParaView files at every load step (the CSV "
                      "summary is always written).");
    prm.declare_entry(
      "Surface format",
      "none",
      Selection("none|obj|ply"),
      "The deformed surface for animation tools (Blender and most "
      "pipelines import OBJ or PLY sequences), one file per output frame: "
      "<base>_surface_NNNN.obj or .ply (NNNN = 0000 for the initial state, "
      "then one per output step, like the PVD's entries), written whether "
      "or not 'Write VTU' is set. 3D: the boundary triangles, oriented "
      "outward; 2D: the body's triangles in the plane z = 0. The same "
      "vertex order in every frame and for any number of ranks (the "
      "reference coordinates' lexicographic order). PLY adds the von Mises "
      "stress per vertex (the average over the cells of its faces).");
    prm.declare_entry(
      "Checkpoint every",
      "0",
      Integer(0),
      "Every this many converged load or time steps, write the state a "
      "restart needs to <base>.checkpoint (displacement, velocity and "
      "acceleration, pressure, history variables, load factor or time, step "
      "size and stepping state), replacing the previous one atomically (it "
      "is kept as <base>.checkpoint.previous until the new one is "
      "complete). `hyperelastic --restart <base>.checkpoint scene.prm` "
      "continues the run, the CSV and the PVD where the checkpoint was "
      "written, on the same number of MPI ranks; the scene may run further "
      "(a later End time). 0: no checkpoints.");
    prm.declare_entry(
      "Write HDF5",
      "false",
      Bool(),
      "Also write the fields as HDF5 with an XDMF index for big runs: "
      "<base>.xdmf (open it in ParaView or VisIt; rewritten every output "
      "step), the reference mesh once in <base>_mesh.h5 and one "
      "<base>_NNNN.h5 per output step, written by all ranks together (one "
      "file per step instead of one per rank). Every cell has its own "
      "vertices, so cell fields stay exact; P2 is written at its vertices "
      "(linear cells). Independent of 'Write VTU'.");
    prm.declare_entry(
      "Write mesh",
      "false",
      Bool(),
      "With 'Mesh/Source = surface': write the generated volume mesh as "
      "<base>_mesh.msh (gmsh ASCII 4.1; the boundary ids as the physical "
      "tags of the boundary triangles), which 'Mesh/Source = file' reads "
      "back to the same run.");
    prm.declare_entry("Verbose",
                      "true",
                      Bool(),
                      "Print the Newton table of every load step.");
    prm.declare_entry(
      "Points",
      "",
      Anything(),
      "Reference points at which the displacement is reported after every "
      "converged load step, as 'x, y; x, y' in 2D or 'x, y, z; x, y, z' in "
      "3D (for example '48, 60; 48, 52'). Each point adds the CSV columns "
      "point<k>_ux, point<k>_uy (, point<k>_uz), k = 1, 2, ... in the order "
      "given. A point on a vertex, edge or face shared by several cells gets "
      "their average. A point outside the mesh is an input error. Empty: no "
      "points.");
    prm.declare_entry(
      "Moment point",
      "0, 0, 0",
      Anything(),
      "The point p about which the CSV columns reaction_moment_<id>_x, _y, "
      "_z (2D: reaction_moment_<id>_z only) give the moment of each "
      "Dirichlet boundary id's support forces: the sum over that "
      "boundary's nodes (with P2 every node, edge midpoints too) of "
      "(X + u - p) x f, the nodal forces f of the reaction_<id> columns "
      "taken at the nodes' deformed positions X + u. 'x, y, z' in 3D, "
      "'x, y' in 2D (the default is the origin in both). Obstacles' "
      "contact_moment_<k> columns are taken about each obstacle's own "
      "point instead (Contact/Obstacle k/Point moved by its Motion).");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse(ParameterHandler &prm, const unsigned int dim)
  {
    prm.enter_subsection("Output");
    directory = dealii::Utilities::trim(prm.get("Directory"));
    base_name = dealii::Utilities::trim(prm.get("Base name"));
    write_vtu = prm.get_bool("Write VTU");
    write_hdf5 = prm.get_bool("Write HDF5");
    write_mesh = prm.get_bool("Write mesh");
    verbose   = prm.get_bool("Verbose");
    checkpoint_every = prm.get_integer("Checkpoint every");
    const std::string surface = prm.get("Surface format");
    surface_format = surface == "obj"   ? SurfaceFormat::obj
                     : surface == "ply" ? SurfaceFormat::ply
                                        : SurfaceFormat::none;
    if (directory.empty())
      reject("Output/Directory", "", "must not be empty");
    if (base_name.empty() || base_name.find('/') != std::string::npos)
      reject("Output/Base name", base_name, "must be a non-empty file name");
    const std::string points_text = prm.get("Points");
    points.clear();
    for (const auto &point : split_expressions(points_text))
      {
        const std::vector<double> coordinates = parse_coordinates(point);
        if (coordinates.empty())
          reject("Output/Points",
                 points_text,
                 "expected points 'x, y[, z]' separated by ';', got '" + point +
                   "'");
        points.push_back(coordinates);
      }
    const std::string moment_text =
      list_for_dimension(prm.get("Moment point"), "0, 0, 0", dim, ',');
    moment_point = parse_coordinates(moment_text);
    if (moment_point.size() != dim)
      reject("Output/Moment point",
             prm.get("Moment point"),
             "needs " + std::to_string(dim) + " numbers (" +
               (dim == 2 ? "'x, y'" : "'x, y, z'") + ") in a " +
               std::to_string(dim) + "D scene");
    prm.leave_subsection();
  }
} // namespace hyperelastic
