// Boundary faces selected by position ('Boundary region' in the Dirichlet and
// boundary-load sections): each distinct condition on the face centre gives
// the faces it selects a boundary id of their own, once, at set-up, on the
// cells each rank sees, so that everything downstream works with boundary ids
// as for a mesh whose faces carry tags.
#pragma once

#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <hyperelastic/loads/loading_parameters.h>

#include <set>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// What assign_boundary_regions() did, for the run header.
  struct BoundaryRegions
  {
    struct Region
    {
      std::string                condition; ///< the entry's text, trimmed
      dealii::types::boundary_id id = 0;    ///< given to its faces
      unsigned long long         n_faces = 0; ///< over all ranks
      std::vector<std::string>   sections;    ///< that name it
    };
    std::vector<Region> regions;
  };

  /// Gives the boundary faces selected by each distinct 'Boundary region'
  /// of @p loading a new boundary id (one more than the largest id of the
  /// mesh or of the scene, in the order of the sections), writes that id
  /// into the sections of @p loading, and updates @p mesh_ids (the boundary
  /// ids of the whole mesh). A condition is evaluated at each face's centre
  /// in the reference configuration, with x, y(, z) and the
  /// Loading/Constants. Collective; InputError naming the entry on every
  /// rank for a condition that does not parse, selects no face, shares a
  /// face with another condition, or takes faces whose boundary id another
  /// section names. Does nothing for a scene without boundary regions.
  template <int dim>
  BoundaryRegions
  assign_boundary_regions(dealii::Triangulation<dim>          &triangulation,
                          LoadingParameters                   &loading,
                          std::set<dealii::types::boundary_id> &mesh_ids);
} // namespace hyperelastic
