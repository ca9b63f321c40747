// The registry of formulations (Problem/Formulation): for each, its name,
// its documentation, the checks of a scene against it and its factory for 2D
// and 3D. One line per formulation in
// source/formulation/formulation_registry.cc.
#pragma once

#include <hyperelastic/formulation/formulation.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hyperelastic
{
  struct Parameters;

  /// One registered formulation.
  struct FormulationKind
  {
    /// The value of Problem/Formulation.
    std::string name;
    /// One paragraph for --print-parameters and the manual.
    std::string documentation;
    /// Checks the scene's other entries against this formulation (an
    /// InputError naming the entry) and completes what it implies (the
    /// mixed element's displacement degree).
    std::function<void(Parameters &)> check;
    std::function<std::unique_ptr<Formulation<2>>(const Parameters &)>
      create_2d;
    std::function<std::unique_ptr<Formulation<3>>(const Parameters &)>
      create_3d;

    /// A kind whose factory builds Class<dim>(parameters).
    template <template <int> class Class>
    static FormulationKind
    of(std::string                       name,
       std::string                       documentation,
       std::function<void(Parameters &)> check)
    {
      return {
        std::move(name),
        std::move(documentation),
        std::move(check),
        [](const Parameters &p) {
          return std::unique_ptr<Formulation<2>>(std::make_unique<Class<2>>(p));
        },
        [](const Parameters &p) {
          return std::unique_ptr<Formulation<3>>(std::make_unique<Class<3>>(p));
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

  /// The scene's formulation in @p dim dimensions.
  template <int dim>
  std::unique_ptr<Formulation<dim>>
  create_formulation(const Parameters &parameters);
} // namespace hyperelastic
