// The registry of load terms: which LoadTerm each loading section of a scene
// becomes.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/loads/load_term.h>

#include <memory>
#include <vector>

namespace hyperelastic
{
  /// One term per load of @p bc: the body force, each traction, each
  /// pressure. The terms refer to the functions in @p bc, which must outlive
  /// them.
  template <int dim>
  std::vector<std::unique_ptr<LoadTerm<dim>>>
  create_load_terms(const BoundaryConditions<dim> &bc,
                    const dealii::DoFHandler<dim> &dof_handler,
                    const dealii::Mapping<dim>    &mapping);
} // namespace hyperelastic
