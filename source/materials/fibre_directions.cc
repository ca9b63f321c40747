// Parsing and evaluation of fibre directions (materials/fibre_directions.h).
#include <deal.II/base/function_parser.h>
#include <deal.II/base/numbers.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/materials/fibre_directions.h>

#include <cctype>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

namespace hyperelastic
{
  namespace
  {
    /// Whether @p text has the identifier x, y or z (a whole word).
    bool
    uses_coordinates(const std::string &text)
    {
      std::size_t i = 0;
      while (i < text.size())
        {
          const unsigned char c = text[i];
          if (std::isalpha(c) || c == '_')
            {
              std::size_t end = i;
              while (end < text.size() &&
                     (std::isalnum(static_cast<unsigned char>(text[end])) ||
                      text[end] == '_'))
                ++end;
              const std::string word = text.substr(i, end - i);
              if (word == "x" || word == "y" || word == "z")
                return true;
              i = end;
            }
          else if (std::isdigit(c) || c == '.')
            {
              // A number, with its exponent (1e-3 is not the variable e).
              while (i < text.size() &&
                     (std::isalnum(static_cast<unsigned char>(text[i])) ||
                      text[i] == '.'))
                ++i;
            }
          else
            ++i;
        }
      return false;
    }
  } // namespace

  FibreDirections::FibreDirections(const std::vector<std::string> &texts,
                                   const std::vector<std::string> &entries)
  {
    for (unsigned int i = 0; i < texts.size(); ++i)
      {
        const std::vector<std::string> expressions =
          split_expressions(texts[i]);
        if (expressions.empty())
          continue;
        if (expressions.size() != 3)
          reject(entries[i],
                 texts[i],
                 "a direction is three expressions of x, y, z separated by "
                 "';' (a_x; a_y; a_z), or empty for no such family");
        auto parser = std::make_shared<dealii::FunctionParser<3>>(3);
        // deal.II prints muParser's complaint itself; the message below
        // names the entry instead.
        std::ostringstream chatter;
        std::streambuf    *saved = std::cerr.rdbuf(chatter.rdbuf());
        try
          {
            parser->initialize("x,y,z",
                               expressions,
                               {{"pi", dealii::numbers::PI}});
            dealii::Vector<double> value(3);
            parser->vector_value(dealii::Point<3>(), value);
          }
        catch (...)
          {
            std::cerr.rdbuf(saved);
            reject(entries[i],
                   texts[i],
                   "cannot parse the expressions (variables x, y, z; "
                   "constant pi)");
          }
        std::cerr.rdbuf(saved);
        families.push_back(
          {entries[i], texts[i], parser, uses_coordinates(texts[i])});
      }
  }

  bool
  FibreDirections::depends_on_position() const
  {
    for (const Family &f : families)
      if (f.uses_position)
        return true;
    return false;
  }

  std::vector<dealii::Tensor<1, 3>>
  FibreDirections::at(const dealii::Point<3> &X, const int dim) const
  {
    std::vector<dealii::Tensor<1, 3>> directions;
    for (const Family &f : families)
      {
        dealii::Vector<double> value(3);
        f.expression->vector_value(X, value);
        dealii::Tensor<1, 3> a;
        for (unsigned int d = 0; d < 3; ++d)
          a[d] = value[d];
        const double       length = a.norm();
        std::ostringstream where;
        where << "at the reference point (" << X << ")";
        if (!std::isfinite(length) || length == 0.)
          reject(f.entry,
                 f.text,
                 "the direction is zero or not finite " + where.str());
        if (dim == 2 && std::abs(a[2]) > 1e-12 * length)
          reject(f.entry,
                 f.text,
                 "a 2D (plane-strain) scene needs fibres in the x-y plane "
                 "(a_z = 0); a_z is not 0 " +
                   where.str());
        directions.push_back(a / length);
      }
    return directions;
  }
} // namespace hyperelastic
