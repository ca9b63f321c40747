// The contact layer as the rest of the program sees it: from the scene's
// 'Contact' section, the contact energy terms (obstacles, the boundary with
// itself) added to the operator, and one reporter for all that contact adds
// to a run: the header's lines, the summary's columns
// (contact_force_<k>_<axis>, contact_moment_<k>_<axis>, contact_min_distance,
// contact_active_pairs), the frames' contact_force field and self contact's
// cost. The Model calls
// add_contact_terms() each time it builds its operator; nothing else holds a
// contact type.
#pragma once

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>

#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/contact/contact_parameters.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/output/step_reporter.h>

#include <map>
#include <memory>
#include <string>

namespace hyperelastic
{
  /// What the contact terms are built from; everything outlives them.
  template <int dim>
  struct ContactSetup
  {
    const ContactParameters             &parameters;
    /// The scene's constants (the obstacles' motions are expressions).
    const std::map<std::string, double> &constants;
    const dealii::DoFHandler<dim>       &dof_handler;
    /// The material's small-strain moduli (the automatic kappa).
    const LameParameters &moduli;
    /// Dynamics: friction's smoothing is a slip velocity.
    bool dynamic;
    /// Whether the formulation has pressure unknowns (self contact needs
    /// none).
    bool has_pressure_unknowns;
    /// Contact's work is timed in its section "contact".
    dealii::TimerOutput &timer;
  };

  /// Adds the contact terms the scene asks for to @p elasticity and returns
  /// their reporter; null without contact. Throws InputError for input
  /// contact cannot take (self contact with the mixed formulation, a body
  /// starting through an obstacle or through itself). Collective.
  template <int dim>
  std::unique_ptr<StepReporter<dim>>
  add_contact_terms(const ContactSetup<dim> &setup,
                    ElasticityOperator<dim> &elasticity);
} // namespace hyperelastic
