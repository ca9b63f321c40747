// The checks of a scene that involve more than one subsection (see the
// header).
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/materials/material_registry.h>
#include <hyperelastic/scene/parameter_checks.h>

#include <string>

namespace hyperelastic
{
  void
  check_arc_length(const LoadSteppingParameters    &load_stepping,
                   const TimeIntegrationParameters &time_integration,
                   const ContactParameters         &contact,
                   const ProblemParameters         &problem)
  {
    // Arc length continues a quasi-static path of the displacement
    // formulation (the constraint measures displacements; contact and
    // inertia have states of their own along t).
    if (load_stepping.method != LoadControl::arc_length)
      return;
    const auto arc = [&](const std::string &entry,
                         const std::string &value,
                         const std::string &why) {
      reject(entry, value, "'Load stepping/Method = arc length' " + why);
    };
    if (time_integration.dynamic())
      arc("Time integration/Scheme",
          time_integration.scheme_name(),
          "continues quasi-static scenes only");
    if (contact.active())
      arc(contact.self_contact ? "Contact/Self contact"
                               : "Contact/Obstacle 1/Type",
          contact.self_contact ? "true" : "(an obstacle)",
          "does not work with contact yet");
    if (problem.formulation == "stiffness warping")
      arc("Problem/Formulation",
          problem.formulation,
          "does not work with stiffness warping (a linearization per "
          "step, not a path)");
  }

  void
  check_inverted_elements(const NewtonParameters   &newton,
                          const MaterialParameters &material)
  {
    // Accepting inverted equilibria needs a model defined at J <= 0.
    if (newton.inverted_elements != InvertedElements::warn)
      return;
    const bool defined =
      material_model(material.registered_model()).defined_for_inverted_elements;
    if (!defined)
      reject("Newton/Inverted elements at equilibrium",
             "warn",
             "the " + material.model +
               " model is not defined for inverted elements (its energy "
               "is infinite at J <= 0), so no state with them can be "
               "accepted; use 'automatic' or 'reject', or a model "
               "defined there (e.g. stable neo-Hookean or corotational)");
  }

  void
  check_viscoelasticity(const MaterialParameters        &material,
                        const LoadSteppingParameters    &load_stepping,
                        const TimeIntegrationParameters &time_integration)
  {
    // Viscoelasticity: the history is written at the solved state of a
    // step of known length.
    if (!material.viscoelasticity.active())
      return;
    const auto viscous = [&](const std::string &entry,
                             const std::string &value,
                             const std::string &why) {
      reject(entry,
             value,
             "'Material/Viscoelasticity' (Weights = '" +
               material.viscoelasticity.weights_text + "') " + why);
    };
    if (load_stepping.method == LoadControl::arc_length)
      viscous("Load stepping/Method",
              "arc length",
              "needs steps of known length (load control)");
    if (time_integration.scheme_name() == "implicit midpoint")
      viscous("Time integration/Scheme",
              "implicit midpoint",
              "needs a scheme that solves at the end of the step "
              "(backward Euler or Newmark)");
  }

  void
  check_checkpoints(const OutputParameters          &output,
                    const LoadSteppingParameters    &load_stepping,
                    const TimeIntegrationParameters &time_integration)
  {
    if (output.checkpoint_every > 0 &&
        load_stepping.method == LoadControl::arc_length &&
        !time_integration.dynamic())
      reject("Output/Checkpoint every",
             std::to_string(output.checkpoint_every),
             "checkpoints continue load control or time stepping; 'Load "
             "stepping/Method = arc length' is not supported");
  }

  void
  check_loaded_reference(const ProblemParameters &problem,
                         const MeshParameters    &mesh,
                         const ContactParameters &contact,
                         const OutputParameters  &output)
  {
    if (!problem.reference_loaded)
      return;
    if (mesh.source != MeshSource::file || mesh.file.size() < 4 ||
        mesh.file.substr(mesh.file.size() - 4) != ".msh")
      reject("Problem/Reference",
             "loaded",
             "the loaded configuration must be a gmsh .msh mesh file "
             "('Mesh/Source = file'), which the reference mesh is written "
             "like");
    if (contact.active())
      reject("Problem/Reference",
             "loaded",
             "contact is not available with the search for the unloaded "
             "shape (its gaps belong to the loaded configuration)");
    if (mesh.global_refinements > 0)
      reject("Problem/Reference",
             "loaded",
             "the loaded mesh is searched as it is in the file: 'Mesh/Global "
             "refinements' must be 0 (the written reference would lose the "
             "refined vertices)");
    if (output.checkpoint_every > 0)
      reject("Problem/Reference",
             "loaded",
             "checkpoints belong to one reference configuration; the search "
             "runs one per iterate");
  }
} // namespace hyperelastic
