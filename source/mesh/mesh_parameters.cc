// The scene's Mesh subsection: declaration, documentation and validation of its
// entries.
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/mesh/mesh_parameters.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  using namespace entry_patterns;

  namespace
  {
    // The box's 3D defaults (a 2D scene takes their first two values).
    constexpr const char *lower_corner_default = "0, 0, 0";
    constexpr const char *upper_corner_default = "1, 1, 1";
    constexpr const char *subdivisions_default = "1, 1, 1";
  } // namespace

  void
  MeshParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry(
      "Source",
      "box",
      Selection("box|file|surface"),
      "'box': a generated box of simplices (rectangle in 2D) with boundary ids "
      "0/1 on the faces x = min/max, 2/3 on y = min/max, 4/5 on z = min/max. "
      "'file': a mesh file (see File) whose tags on cells become material "
      "ids and on boundary faces boundary ids. "
      "'surface': a closed triangulated surface (OBJ, STL ASCII or binary, "
      "PLY ASCII or binary little-endian, OFF; 3D only) filled with "
      "tetrahedra on the fly by gmsh's Delaunay mesher, keeping the "
      "surface's triangles as the boundary faces (split to 'Mesh size'). "
      "Boundary faces get boundary id 0, or, if the surface has groups "
      "(OBJ 'g'/'o' lines, a PLY face property), the ids 1, 2, ... in the "
      "order the groups first appear; cells get material id 0. A surface "
      "that is not closed or that intersects itself is an input error; "
      "triangles oriented against their neighbours are turned.");
    prm.declare_entry("File",
                      "",
                      Anything(),
                      "Mesh file for Source = file, its format chosen by the "
                      "extension: .msh (gmsh; ASCII formats 1, 2.2, 4.0, 4.1, "
                      "binary 2.2 and 4.1), .mesh (MEDIT, ASCII), .vtk "
                      "(legacy VTK unstructured grid, ASCII or binary; ids "
                      "from the cell data array MaterialID, gmsh:physical or "
                      "CellEntityIds). For Source = surface a closed surface "
                      "file (.obj, .stl, .ply, .off). A relative path is read "
                      "relative to the folder of the scene file.");
    prm.declare_entry(
      "Mesh size",
      "0",
      Double(0.),
      "Source = surface: the target edge length of the tetrahedra. The "
      "surface's triangles are split into four (at their edge midpoints, "
      "so the shape and its vertices stay) until their mean edge is at most "
      "1.5 times this size, and the inside is filled at the sizes of the "
      "surface. 0: the surface's triangles as they are (the inside at "
      "their mean edge length).");
    prm.declare_entry("Lower corner",
                      lower_corner_default,
                      List(Double(), 2, 3),
                      "Box: coordinates of the lower corner (dim values; "
                      "the default's first two in 2D).");
    prm.declare_entry("Upper corner",
                      upper_corner_default,
                      List(Double(), 2, 3),
                      "Box: coordinates of the upper corner (dim values; "
                      "the default's first two in 2D).");
    prm.declare_entry("Subdivisions",
                      subdivisions_default,
                      List(Integer(1), 2, 3),
                      "Box: number of cells per direction (dim values; the "
                      "default's first two in 2D); each "
                      "square is split into 2 triangles, each cube into 5 "
                      "tetrahedra.");
    prm.declare_entry("Global refinements",
                      "0",
                      Integer(0, 10),
                      "Uniform refinements of the mesh before it is "
                      "partitioned (each one multiplies the cell count by "
                      "2^dim).");
    prm.leave_subsection();
  }

  void
  MeshParameters::parse(ParameterHandler  &prm,
                        const std::string &scene_folder,
                        const unsigned int dim)
  {
    prm.enter_subsection("Mesh");
    const std::string source_name = prm.get("Source");
    source = source_name == "box"    ? MeshSource::box
             : source_name == "file" ? MeshSource::file
                                     : MeshSource::surface;
    file   = dealii::Utilities::trim(prm.get("File"));
    mesh_size = prm.get_double("Mesh size");
    if (!std::isfinite(mesh_size))
      reject("Mesh/Mesh size", prm.get("Mesh size"), "must be a finite length");
    if (source != MeshSource::box)
      {
        if (file.empty())
          reject("Mesh/File",
                 file,
                 "a mesh file is needed when Source = " + source_name);
        if (file[0] != '/')
          file = scene_folder + "/" + file;
      }
    // The box's defaults are 3D: a 2D scene that leaves them takes their
    // first two values.
    const auto list = [&](const std::string &entry, const char *default_3d) {
      return dealii::Utilities::split_string_list(
        list_for_dimension(prm.get(entry), default_3d, dim, ','));
    };
    for (const auto &v : list("Lower corner", lower_corner_default))
      lower_corner.push_back(dealii::Utilities::string_to_double(v));
    for (const auto &v : list("Upper corner", upper_corner_default))
      upper_corner.push_back(dealii::Utilities::string_to_double(v));
    for (const auto &v : list("Subdivisions", subdivisions_default))
      subdivisions.push_back(dealii::Utilities::string_to_int(v));
    global_refinements = prm.get_integer("Global refinements");
    prm.leave_subsection();
  }

  void
  MeshParameters::check_dimension(const unsigned int dim) const
  {
    if (source == MeshSource::surface && dim != 3)
      reject("Mesh/Source",
             "surface",
             "a closed surface is filled with tetrahedra: it needs "
             "'Problem/Dimension = 3'");
    if (source != MeshSource::box)
      return;
    const auto size = [](const auto &v) { return std::to_string(v.size()); };
    if (lower_corner.size() != dim)
      reject("Mesh/Lower corner",
             size(lower_corner) + " values",
             "needs " + std::to_string(dim) + " values");
    if (upper_corner.size() != dim)
      reject("Mesh/Upper corner",
             size(upper_corner) + " values",
             "needs " + std::to_string(dim) + " values");
    if (subdivisions.size() != dim)
      reject("Mesh/Subdivisions",
             size(subdivisions) + " values",
             "needs " + std::to_string(dim) + " values");
    for (unsigned int d = 0; d < dim; ++d)
      if (!(upper_corner[d] > lower_corner[d]))
        reject("Mesh/Upper corner",
               std::to_string(upper_corner[d]),
               "every coordinate must exceed the lower corner's");
  }
} // namespace hyperelastic
