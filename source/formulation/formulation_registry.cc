// The registered formulations, one line each.
#include <hyperelastic/formulation/formulation_parameters.h>
#include <hyperelastic/formulation/formulation_registry.h>

#include <stdexcept>

namespace hyperelastic
{
  // Each defined in its own file of source/formulation/.
  FormulationKind
  displacement_formulation_kind();
  FormulationKind
  mixed_formulation_kind();
  FormulationKind
  stiffness_warping_formulation_kind();

  const std::vector<FormulationKind> &
  formulation_kinds()
  {
    static const std::vector<FormulationKind> kinds = {
      displacement_formulation_kind(),
      mixed_formulation_kind(),
      stiffness_warping_formulation_kind(),
    };
    return kinds;
  }

  const FormulationKind &
  formulation_kind(const std::string &name)
  {
    for (const FormulationKind &kind : formulation_kinds())
      if (kind.name == name)
        return kind;
    throw std::logic_error("no formulation called '" + name + "'");
  }

  std::string
  formulation_names()
  {
    std::string names;
    for (const FormulationKind &kind : formulation_kinds())
      names += (names.empty() ? "" : "|") + kind.name;
    return names;
  }

  template <>
  std::unique_ptr<Formulation<2>>
  create_formulation<2>(const FormulationInputs &inputs)
  {
    return formulation_kind(inputs.problem.formulation).create_2d(inputs);
  }

  template <>
  std::unique_ptr<Formulation<3>>
  create_formulation<3>(const FormulationInputs &inputs)
  {
    return formulation_kind(inputs.problem.formulation).create_3d(inputs);
  }
} // namespace hyperelastic
