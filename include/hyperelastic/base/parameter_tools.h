// Small helpers shared by the parameter subsections: rejecting a value with a
// message naming the entry, reading a finite number, splitting expression
// lists.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  /// The entry patterns the subsections' declare() functions use; a
  /// parameter file says `using namespace entry_patterns;`.
  namespace entry_patterns
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::FileName;
    using dealii::Patterns::Integer;
    using dealii::Patterns::List;
    using dealii::Patterns::MultipleSelection;
    using dealii::Patterns::Selection;
  } // namespace entry_patterns

  /// Throws InputError "scene entry 'entry' = 'value': why".
  [[noreturn]] void
  reject(const std::string &entry,
         const std::string &value,
         const std::string &why);

  /// The double entry @p name of the current subsection @p section; rejected
  /// if not finite.
  double
  get_finite(dealii::ParameterHandler &prm,
             const std::string        &section,
             const std::string        &name);

  /// The bulk-modulus entry @p name of the current subsection @p section
  /// (declared with Patterns::Anything): a positive number, or 'inf' for an
  /// exactly incompressible material (mixed formulation only: the
  /// displacement formulation's scene check rejects it). Anything else is
  /// rejected naming section/name.
  double
  get_bulk_modulus(dealii::ParameterHandler &prm,
                   const std::string        &section,
                   const std::string        &name);

  /// "a, b, c": @p names joined by commas (for messages).
  std::string
  listed(const std::vector<std::string> &names);

  /// Splits "a; b; c" into trimmed expressions; an all-blank string gives {}.
  std::vector<std::string>
  split_expressions(const std::string &text);

  /// The 2 or 3 finite numbers of "x, y[, z]"; empty if @p text is not
  /// such a list.
  std::vector<double>
  parse_coordinates(const std::string &text);

  /// A list entry @p text of a scene in dimension @p dim: where it is the
  /// 3D default @p default_3d (spaces aside: the scene did not set it, or
  /// set it to the default), its first two items in 2D (their separator
  /// @p separator: ',' or ';'); otherwise @p text as written.
  std::string
  list_for_dimension(const std::string &text,
                     const std::string &default_3d,
                     unsigned int       dim,
                     char               separator);

  /// 0, 1, 2 for "x", "y", "z".
  unsigned int
  component_index(const std::string &name);
} // namespace hyperelastic
