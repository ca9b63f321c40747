// Loads and supports of a scene as functions of (x, y, z, t): prescribed
// displacements (Dirichlet, with a component mask), body forces per unit
// reference volume and the boundary loads of the registered kinds (dead
// tractions, follower pressures, ...). The forces they exert are EnergyTerms
// (assembly/energy_term.h, loads/load_terms.h).
#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hyperelastic/base/expressions.h>
#include <hyperelastic/loads/loading_parameters.h>

#include <memory>
#include <optional>
#include <set>
#include <vector>

namespace hyperelastic
{
  using dealii::types::boundary_id;

  template <int dim>
  struct DirichletBoundary
  {
    boundary_id                            id;
    dealii::ComponentMask                  mask;
    std::unique_ptr<dealii::Function<dim>> displacement; ///< dim components
    std::string                            subsection;
    /// Only the vertex of the boundary at this reference point, if given.
    std::optional<dealii::Point<dim>> vertex;
  };

  /// A force on the mesh vertex at @p point (Point load 1, ...).
  template <int dim>
  struct PointLoad
  {
    dealii::Point<dim>                     point;
    std::unique_ptr<dealii::Function<dim>> force; ///< dim components
    std::string                            subsection;
  };

  /// A boundary load of a registered kind (traction, pressure, ...) with its
  /// value parsed: dim components for a vector-valued kind, else one.
  template <int dim>
  struct BoundaryLoad
  {
    std::string                            kind; ///< BoundaryLoadKind::name
    boundary_id                            id;
    std::unique_ptr<dealii::Function<dim>> value;
    std::string                            subsection;
  };

  template <int dim>
  struct BoundaryConditions
  {
    std::vector<DirichletBoundary<dim>>    dirichlet;
    std::vector<BoundaryLoad<dim>>         boundary_loads;
    std::vector<PointLoad<dim>>            point_loads;
    std::unique_ptr<dealii::Function<dim>> body_force; ///< null: none

    /// Parses every expression and checks that each named boundary id exists
    /// in @p mesh_ids. Throws InputError naming the entry.
    BoundaryConditions(const LoadingParameters     &loading,
                       const std::set<boundary_id> &mesh_ids);

    /// The boundary ids some Dirichlet condition holds (the bodies touching
    /// none are held by contact only, quasi-statically).
    std::set<boundary_id>
    dirichlet_ids() const
    {
      std::set<boundary_id> ids;
      for (const auto &d : dirichlet)
        ids.insert(d.id);
      return ids;
    }

    /// Constraints u = g(x, t) - @p current on the Dirichlet dofs (the
    /// increment that takes the current displacement to the prescribed one),
    /// or homogeneous ones if @p homogeneous.
    void
    make_constraints(
      const dealii::Mapping<dim>                  &mapping,
      const dealii::DoFHandler<dim>               &dof_handler,
      const dealii::IndexSet                      &relevant_dofs,
      const double                                 t,
      const dealii::TrilinosWrappers::MPI::Vector &current_ghosted,
      const bool                                   homogeneous,
      dealii::AffineConstraints<double>           &constraints) const;
  };

  /// Whether @p x is the vertex @p vertex of a cell of diameter @p h (to
  /// round-off of the coordinates).
  template <int dim>
  inline bool
  is_vertex_at(const dealii::Point<dim> &vertex,
               const dealii::Point<dim> &x,
               const double              h)
  {
    return vertex.distance(x) <= 1e-8 * h;
  }

} // namespace hyperelastic
