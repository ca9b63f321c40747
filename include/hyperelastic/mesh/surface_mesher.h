// A closed surface meshed with tetrahedra on the fly (Mesh/Source =
// surface): the surface checked (closed, consistently oriented, free of
// self-intersections), its triangles split to the target size, the volume
// filled by gmsh's Delaunay mesher keeping the surface's triangles, the
// element quality measured and the result returned as the cell list a gmsh
// file gives (and written as one if asked).
#pragma once

#include <hyperelastic/mesh/gmsh_reader.h>
#include <hyperelastic/mesh/mesh_parameters.h>
#include <hyperelastic/mesh/surface_file.h>

#include <cstddef>
#include <string>

namespace hyperelastic
{
  /// Checks that @p surface bounds a volume: every edge is shared by
  /// exactly two triangles (else the first open or over-shared edge is
  /// named with its coordinates), no two triangles without a common vertex
  /// intersect (else the pair is named), no triangle is degenerate.
  /// Triangles oriented against their neighbours are turned silently so
  /// that all face outward (a closed part inside another, a cavity, faces
  /// into it); returns how many were turned. Errors are
  /// InputErrors starting with @p where (the scene entry and file).
  std::size_t
  check_closed_surface(SurfaceTriangles &surface, const std::string &where);

  /// The volume enclosed by an outward oriented closed surface (cavities
  /// facing inward count negative).
  double
  enclosed_volume(const SurfaceTriangles &surface);

  /// The mean edge length of the surface's triangles.
  double
  mean_edge_length(const SurfaceTriangles &surface);

  /// @p surface with every triangle split into four at its edge midpoints
  /// until the mean edge is at most 1.5 @p size (the shape, the original
  /// vertices and the groups stay).
  SurfaceTriangles
  split_to_size(const SurfaceTriangles &surface, double size);

  /// Tetrahedra filling a checked closed surface, sized @p size inside;
  /// the surface's triangles are the boundary faces (its vertices first, in
  /// order), with boundary id 0 or their group; material id 0.
  GmshMesh<3>
  tetrahedralise(const SurfaceTriangles &surface,
                 double                  size,
                 const std::string      &where);

  /// Element quality: the smallest dihedral angle (degrees) and the radius
  /// ratio 3 r_in / r_out (1 for the regular tetrahedron).
  struct TetQuality
  {
    double min_dihedral_degrees = 0.;
    double max_dihedral_degrees = 0.;
    double min_radius_ratio     = 0.;
    double mean_radius_ratio    = 0.;
    double volume               = 0.;
  };

  TetQuality
  tet_quality(const GmshMesh<3> &mesh);

  /// Writes @p mesh as a gmsh ASCII 4.1 file whose boundary ids are the
  /// physical tags of its triangles (faces of id 0 untagged) and material
  /// ids those of its tetrahedra; read back it gives the same cell list.
  void
  write_gmsh_mesh(const GmshMesh<3> &mesh, const std::string &file_name);

  /// The whole route of Mesh/Source = surface: read, check, split, mesh,
  /// measure (the lines for the run header in @p report) and write the
  /// mesh if Output/Write mesh asks. dim = 2 is an input error.
  template <int dim>
  GmshMesh<dim>
  mesh_closed_surface(const MeshParameters &parameters, std::string &report);
} // namespace hyperelastic
