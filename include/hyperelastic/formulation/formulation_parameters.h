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
