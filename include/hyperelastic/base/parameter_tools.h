// Small helpers shared by the parameter subsections: rejecting a value with a
// message naming the entry, reading a finite number, splitting expression lists.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  /// Throws InputError "scene entry 'entry' = 'value': why".
  [[noreturn]] void
  reject(const std::string &entry, const std::string &value, const std::string &why);

  /// The double entry @p name of the current subsection @p section; rejected
  /// if not finite.
  double
  get_finite(dealii::ParameterHandler &prm,
             const std::string        &section,
             const std::string        &name);

  /// Splits "a; b; c" into trimmed expressions; an all-blank string gives {}.
  std::vector<std::string>
  split_expressions(const std::string &text);

  /// 0, 1, 2 for "x", "y", "z".
  unsigned int
  component_index(const std::string &name);
} // namespace hyperelastic
