// Helpers shared by the parameter subsections.
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace hyperelastic
{
  [[noreturn]] void
  reject(const std::string &entry,
         const std::string &value,
         const std::string &why)
  {
    throw InputError("scene entry '" + entry + "' = '" + value + "': " + why);
  }

  double
  get_finite(dealii::ParameterHandler &prm,
             const std::string        &section,
             const std::string        &name)
  {
    const double v = prm.get_double(name);
    if (!std::isfinite(v))
      reject(section + "/" + name, prm.get(name), "must be a finite number");
    return v;
  }

  double
  get_bulk_modulus(dealii::ParameterHandler &prm,
                   const std::string        &section,
                   const std::string        &name)
  {
    const std::string text = dealii::Utilities::trim(prm.get(name));
    if (text == "inf" || text == "infinity")
      return std::numeric_limits<double>::infinity();
    char        *end   = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() ||
        !std::isfinite(value))
      reject(section + "/" + name,
             text,
             "must be a positive number, or 'inf' (exactly incompressible, "
             "with 'Problem/Formulation = mixed')");
    if (!(value > 0.))
      reject(section + "/" + name,
             text,
             "must be positive (or 'inf': exactly incompressible, with "
             "'Problem/Formulation = mixed')");
    return value;
  }

  std::vector<std::string>
  split_expressions(const std::string &text)
  {
    if (dealii::Utilities::trim(text).empty())
      return {};
    return dealii::Utilities::split_string_list(text, ';');
  }

  std::vector<double>
  parse_coordinates(const std::string &text)
  {
    std::vector<double> coordinates;
    for (const auto &c : dealii::Utilities::split_string_list(text, ','))
      {
        std::istringstream in(c);
        double             x = 0.;
        in >> x;
        if (in.fail() || !std::isfinite(x) || !(in >> std::ws).eof())
          return {};
        coordinates.push_back(x);
      }
    if (coordinates.size() < 2 || coordinates.size() > 3)
      return {};
    return coordinates;
  }

  std::string
  list_for_dimension(const std::string &text,
                     const std::string &default_3d,
                     const unsigned int dim,
                     const char         separator)
  {
    const auto squeezed = [](const std::string &s) {
      std::string result;
      for (const char c : s)
        if (!std::isspace(static_cast<unsigned char>(c)))
          result += c;
      return result;
    };
    if (dim != 2 || squeezed(text) != squeezed(default_3d))
      return text;
    const std::string s = squeezed(text);
    return s.substr(0, s.rfind(separator));
  }

  unsigned int
  component_index(const std::string &name)
  {
    return name == "x" ? 0 : (name == "y" ? 1 : 2);
  }
  std::string
  listed(const std::vector<std::string> &names)
  {
    std::string text;
    for (const std::string &name : names)
      text += (text.empty() ? "" : ", ") + name;
    return text;
  }
} // namespace hyperelastic
