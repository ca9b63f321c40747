// The scene's Problem subsection: the dimension, the element degree, the
// assembly path and the formulation (with the mixed formulation's element
// pair). Declared with pattern, default and documentation (the formulations'
// from their registry); parsed with the values checked.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/assembly/mixed_element.h>

#include <string>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  /// The Problem subsection.
  struct ProblemParameters
  {
    unsigned int dimension = 3;
    /// The displacement's degree (the mixed formulation sets it from its
    /// element pair).
    unsigned int fe_degree = 1;
    /// Use the precomputed P1 kernel when the degree is 1 ("Assembly =
    /// automatic"); false: the generic FEValues loops for every degree.
    bool fast_p1_assembly = true;
    /// Problem/Formulation: a registered formulation's name
    /// (formulation/formulation_registry.h).
    std::string  formulation   = "displacement";
    MixedElement mixed_element = MixedElement::mini;
    /// Problem/Reference = loaded: the mesh is the deformed configuration
    /// under the scene's loads at t = 1, and the run first finds the
    /// reference configuration that deforms into it (unloaded_shape.h).
    bool reference_loaded = false;
    /// Problem/Reference tolerance: the largest vertex distance between the
    /// forward solution and the loaded mesh, relative to the mesh's
    /// diagonal, at which the unloaded shape is taken.
    double reference_tolerance = 1e-8;
    /// Problem/Reference iterations: at most this many forward solves.
    unsigned int reference_iterations = 50;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  struct MaterialParameters;

  /// Completes the Problem subsection from what other entries imply: the
  /// alias 'Material/Model = stiffness warping' names the stiffness warping
  /// formulation (rejected with 'Formulation = mixed'), and a formulation
  /// with an element of its own (the mixed pair) sets the displacement
  /// degree.
  void
  resolve_formulation(ProblemParameters        &problem,
                      const MaterialParameters &material);
} // namespace hyperelastic
