// The registry of load terms: which EnergyTerm each loading section of a
// scene becomes. A new kind of boundary load is an EnergyTerm class with a static
// scene_kind() (its scene section, loads/loading_parameters.h) and a
// constructor (value function, boundary id, subsection, dof handler,
// mapping), registered with one line in source/loads/load_terms.cc: the scene
// entries, their documentation, validation and the term itself follow.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/assembly/energy_term.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/loads/loading_parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// The kinds of boundary load a scene can have, in registration order
  /// (the order of their sections in the scene documentation).
  const std::vector<BoundaryLoadKind> &
  boundary_load_kinds();

  /// The registered kind called @p name (an internal error if none is).
  const BoundaryLoadKind &
  boundary_load_kind(const std::string &name);

  /// One term per load of @p bc: the body force, then each boundary load.
  /// The terms refer to the functions in @p bc, which must outlive them.
  template <int dim>
  std::vector<std::unique_ptr<EnergyTerm<dim>>>
  create_load_terms(const BoundaryConditions<dim> &bc,
                    const dealii::DoFHandler<dim> &dof_handler,
                    const dealii::Mapping<dim>    &mapping);

  /// Throws InputError on every rank if the load of scene entry @p entry was
  /// not finite on some rank (@p bad_here on this one).
  inline void
  throw_if_load_not_finite(const bool         bad_here,
                           const std::string &entry,
                           const MPI_Comm     comm)
  {
    throw_input_error_if_any(
      bad_here,
      "scene entry '" + entry +
        "' is not a finite number somewhere on the mesh (a division by zero, "
        "the logarithm of a negative number or similar)",
      comm);
  }
} // namespace hyperelastic
