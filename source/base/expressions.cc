// Parsing of expression lists into deal.II functions (base/expressions.h).
#include <deal.II/base/function_parser.h>
#include <deal.II/base/numbers.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/expressions.h>

#include <iostream>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  std::unique_ptr<Function<dim>>
  parse_vector_function(const std::vector<std::string>      &expressions,
                        const std::map<std::string, double> &constants,
                        const std::string                   &entry)
  {
    std::map<std::string, double> all_constants = constants;
    all_constants.emplace("pi", numbers::PI);
    const std::string variables = dim == 2 ? "x,y,t" : "x,y,z,t";

    auto function = std::make_unique<FunctionParser<dim>>(expressions.size());
    std::string joined;
    for (const auto &x : expressions)
      joined += (joined.empty() ? "" : "; ") + x;
    const std::string what = "scene entry '" + entry + "' = '" + joined +
                             "': cannot parse the expression (variables are " +
                             variables + " and the Loading/Constants)";

    // deal.II prints muParser's complaint to std::cerr itself; keep it out of
    // the output (the message below names the entry). The guard restores
    // std::cerr however this scope is left.
    std::ostringstream parser_chatter;
    struct CerrRedirect
    {
      std::streambuf *saved;
      ~CerrRedirect()
      {
        std::cerr.rdbuf(saved);
      }
    } redirect{std::cerr.rdbuf(parser_chatter.rdbuf())};
    try
      {
        function->initialize(variables, expressions, all_constants, true);
        // muParser compiles lazily: evaluate once so that errors show now.
        Vector<double> value(expressions.size());
        function->vector_value(Point<dim>(), value);
      }
    catch (const std::exception &e)
      {
        throw InputError(what + ": " + exception_message(e));
      }
    catch (...)
      {
        // muParser's own exception type is not a std::exception.
        throw InputError(what);
      }
    return function;
  }

  template std::unique_ptr<Function<2>>
  parse_vector_function<2>(const std::vector<std::string> &,
                           const std::map<std::string, double> &,
                           const std::string &);
  template std::unique_ptr<Function<3>>
  parse_vector_function<3>(const std::vector<std::string> &,
                           const std::map<std::string, double> &,
                           const std::string &);
} // namespace hyperelastic
