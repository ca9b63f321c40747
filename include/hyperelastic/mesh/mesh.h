// Mesh creation: a generated box of simplices or a gmsh file, refined, then
// partitioned with METIS and handed to a fully distributed triangulation, so
// that after creation every rank stores only its own cells (plus a ghost
// layer).
#pragma once

#include <deal.II/base/types.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <hyperelastic/mesh/mesh_parameters.h>

#include <set>

namespace hyperelastic
{
  /// Builds @p tria from the scene's mesh section and returns the boundary ids
  /// the whole mesh has. Collective; throws InputError for unreadable or
  /// unsuitable meshes, among them meshes with cells of zero area or volume,
  /// with inverted cells (orientation opposite to the rest of the mesh; a
  /// mesh whose cells are all negatively oriented is accepted) and 2D meshes
  /// whose nodes do not lie in a plane z = const. The messages list the
  /// offending cells by their gmsh element numbers.
  template <int dim>
  std::set<dealii::types::boundary_id>
  create_mesh(const MeshParameters &parameters,
              dealii::parallel::fullydistributed::Triangulation<dim> &tria);

  /// Boundary ids of a box: 2 d on the face x_d = min, 2 d + 1 on x_d = max.
  /// Set from face centres since deal.II 9.4 cannot colorize simplex boxes.
  template <int dim>
  void
  set_box_boundary_ids(dealii::Triangulation<dim> &tria);
} // namespace hyperelastic
