// The bodies of a mesh: its connected parts (cells joined through shared
// vertices), found across MPI ranks, each with its volume tag (the gmsh
// physical tag, deal.II's material id), bounding box and whether a
// Dirichlet boundary face holds it. A quasi-static scene needs every body
// held: by a Dirichlet condition or by a possible contact.
#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>

#include <set>
#include <string>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  struct Body
  {
    /// The smallest volume tag among its cells.
    dealii::types::material_id volume_tag = 0;
    dealii::BoundingBox<dim>   box;
    /// Whether one of its boundary faces has a Dirichlet boundary id.
    bool held = false;

    /// "body k (volume tag t, bounding box (lower) to (upper))".
    std::string
    describe(unsigned int k) const;
  };

  /// The bodies of the mesh of @p dof_handler (identical on every rank, in
  /// the order of their volume tags, then of their boxes); @p dirichlet_ids:
  /// the boundary ids of the Dirichlet conditions. With @p body_of_cell,
  /// also the index of each locally owned cell's body (by active cell
  /// index; invalid_unsigned_int for the other cells). Collective.
  template <int dim>
  std::vector<Body<dim>>
  find_bodies(const dealii::DoFHandler<dim>              &dof_handler,
              const std::set<dealii::types::boundary_id> &dirichlet_ids,
              std::vector<unsigned int> *body_of_cell = nullptr);

  /// The supports of a problem that needs them (quasi-static): unless
  /// contact may hold bodies (@p contact_may_hold), throws InputError if
  /// there is no Dirichlet condition at all (@p max_sections: the scene's
  /// last 'Dirichlet k' section, for the message) or if a body of the mesh
  /// has no boundary face with one of the @p dirichlet_ids, naming it.
  /// Collective.
  template <int dim>
  void
  check_supports(const dealii::DoFHandler<dim>              &dof_handler,
                 const std::set<dealii::types::boundary_id> &dirichlet_ids,
                 bool                                        contact_may_hold,
                 unsigned int                                max_sections);
} // namespace hyperelastic
