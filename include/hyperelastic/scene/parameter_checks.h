// The checks of a scene that involve more than one subsection, in one place
// above the concerns (each subsection checks its own entries where it parses
// them). Each throws an InputError naming the entry.
#pragma once

#include <hyperelastic/contact/contact_parameters.h>
#include <hyperelastic/dynamics/time_integration_parameters.h>
#include <hyperelastic/formulation/formulation_parameters.h>
#include <hyperelastic/materials/material_parameters.h>
#include <hyperelastic/mesh/mesh_parameters.h>
#include <hyperelastic/output/output_parameters.h>
#include <hyperelastic/solvers/load_stepping_parameters.h>
#include <hyperelastic/solvers/newton_parameters.h>

namespace hyperelastic
{
  /// What 'Load stepping/Method = arc length' continues: a quasi-static path
  /// of the displacement formulation without contact.
  void
  check_arc_length(const LoadSteppingParameters    &load_stepping,
                   const TimeIntegrationParameters &time_integration,
                   const ContactParameters         &contact,
                   const ProblemParameters         &problem);

  /// 'Inverted elements at equilibrium = warn' accepts states with J <= 0:
  /// only for a model defined there.
  void
  check_inverted_elements(const NewtonParameters   &newton,
                          const MaterialParameters &material);

  /// What 'Material/Viscoelasticity' needs of the stepping: steps of known
  /// length that solve at their end.
  void
  check_viscoelasticity(const MaterialParameters        &material,
                        const LoadSteppingParameters    &load_stepping,
                        const TimeIntegrationParameters &time_integration);

  /// 'Output/Checkpoint every' against the stepping: checkpoints continue
  /// load control or time stepping, not quasi-static arc length.
  void
  check_checkpoints(const OutputParameters          &output,
                    const LoadSteppingParameters    &load_stepping,
                    const TimeIntegrationParameters &time_integration);

  /// 'Problem/Reference = loaded' (the unloaded shape searched from a
  /// loaded mesh): a gmsh .msh mesh file read as it is (no refinement), no
  /// contact, no checkpoints. A restart is refused where it is read
  /// (Problem::read_checkpoint).
  void
  check_loaded_reference(const ProblemParameters &problem,
                         const MeshParameters    &mesh,
                         const ContactParameters &contact,
                         const OutputParameters  &output);
} // namespace hyperelastic
