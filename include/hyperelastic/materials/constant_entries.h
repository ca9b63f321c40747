// Scene-entry helpers shared by the models with constants of their own
// (Mooney-Rivlin, Yeoh, Gent, Arruda-Boyce): the bulk modulus of their
// volumetric energy kappa/4 (J^2 - 1 - 2 ln J), and constants written back
// as entries that parse to the same double.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/base/parameter_tools.h>

#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// Declares "Bulk modulus" (default 2; a number or 'inf').
  inline void
  declare_bulk_modulus_entry(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Bulk modulus",
                      "2",
                      dealii::Patterns::Anything(),
                      "kappa > 0, the constant of kappa/4 (J^2 - 1 - 2 ln J); "
                      "'inf': exactly incompressible ('Problem/Formulation = "
                      "mixed' only).");
  }

  /// The "Bulk modulus" of the current subsection @p section: positive, or
  /// +infinity for 'inf'; otherwise an InputError naming the entry.
  inline double
  parse_bulk_modulus_entry(dealii::ParameterHandler &prm,
                           const std::string        &section)
  {
    const double kappa = get_bulk_modulus(prm, section, "Bulk modulus");
    if (!(kappa > 0.))
      reject(section + "/Bulk modulus",
             prm.get("Bulk modulus"),
             "must be positive");
    return kappa;
  }

  /// The names of a constants struct's scene entries (its entries()), in
  /// their order: a model's ConstantDerivatives::constant_names().
  template <typename Constants>
  std::vector<std::string>
  entry_names(const Constants &constants)
  {
    std::vector<std::string> names;
    for (const auto &entry : constants.entries())
      names.push_back(entry.first);
    return names;
  }

  /// @p x with 17 significant digits: parses back to the same double.
  inline std::string
  exact_entry_text(const double x)
  {
    std::ostringstream s;
    s << std::setprecision(17) << x;
    return s.str();
  }
} // namespace hyperelastic
