// Expression lists of the scene (loads, supports, motions, growth) parsed
// into deal.II functions of the position and t.
#pragma once

#include <deal.II/base/function.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// A function of (x, y, (z,) t) with one component per expression.
  /// Throws InputError naming @p entry if an expression does not parse.
  template <int dim>
  std::unique_ptr<dealii::Function<dim>>
  parse_vector_function(const std::vector<std::string>      &expressions,
                        const std::map<std::string, double> &constants,
                        const std::string                   &entry);
} // namespace hyperelastic
