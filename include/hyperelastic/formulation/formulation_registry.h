// The registry of formulations (Problem/Formulation): for each, its name,
// its documentation, the checks of a scene against it, the displacement
// degree it implies and its factory for 2D and 3D. One line per formulation
// in source/formulation/formulation_registry.cc. A formulation sees the
// subsections it reads (FormulationInputs), not the whole scene.
#pragma once

#include <hyperelastic/formulation/formulation.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hyperelastic
{
  struct LinearSolverParameters;
  struct MaterialParameters;
  struct ProblemParameters;
  struct TimeIntegrationParameters;

  /// The subsections a formulation is built from and checked against: its
  /// own (Problem) and the others it reads (the material model, the linear
  /// solver's type, whether the scene is dynamic).
  struct FormulationInputs
  {
    const ProblemParameters         &problem;
    const MaterialParameters        &material;
    const LinearSolverParameters    &linear_solver;
    const TimeIntegrationParameters &time_integration;
  };

  /// One registered formulation.
  struct FormulationKind
  {
    /// The value of Problem/Formulation.
    std::string name;
    /// One paragraph for --print-parameters and the manual.
    std::string documentation;
    /// Checks the scene's other entries against this formulation (an
    /// InputError naming the entry).
    std::function<void(const FormulationInputs &)> check;
    /// The displacement degree the formulation implies (the mixed element
    /// pair's); empty: the entry 'Problem/Finite element degree'.
    std::function<unsigned int(const ProblemParameters &)> displacement_degree;
    std::function<std::unique_ptr<Formulation<2>>(const FormulationInputs &)>
      create_2d;
    std::function<std::unique_ptr<Formulation<3>>(const FormulationInputs &)>
      create_3d;

    /// A kind whose factory builds Class<dim>(inputs).
    template <template <int> class Class>
    static FormulationKind
    of(std::string                                            name,
       std::string                                            documentation,
       std::function<void(const FormulationInputs &)>         check,
       std::function<unsigned int(const ProblemParameters &)> degree = {})
    {
      return {std::move(name),
              std::move(documentation),
              std::move(check),
              std::move(degree),
              [](const FormulationInputs &inputs) {
                return std::unique_ptr<Formulation<2>>(
                  std::make_unique<Class<2>>(inputs));
              },
              [](const FormulationInputs &inputs) {
                return std::unique_ptr<Formulation<3>>(
                  std::make_unique<Class<3>>(inputs));
              }};
    }
  };

  /// Every formulation, in registration order.
  const std::vector<FormulationKind> &
  formulation_kinds();

  /// The formulation called @p name (std::logic_error if none: the
  /// parameter pattern admits registered names only).
  const FormulationKind &
  formulation_kind(const std::string &name);

  /// The names joined by '|' (the entry's Selection pattern).
  std::string
  formulation_names();

  /// The scene's formulation ('Problem/Formulation') in @p dim dimensions.
  template <int dim>
  std::unique_ptr<Formulation<dim>>
  create_formulation(const FormulationInputs &inputs);
} // namespace hyperelastic
