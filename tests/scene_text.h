// Helpers that write scene (.prm) text for the tests.
#pragma once

#include <sstream>
#include <string>

namespace hyperelastic::testing
{
  inline std::string
  subsection(const std::string &name, const std::string &body)
  {
    return "subsection " + name + "\n" + body + "end\n";
  }

  inline std::string
  entry(const std::string &name, const std::string &value)
  {
    return "  set " + name + " = " + value + "\n";
  }

  inline std::string
  dirichlet(const int          slot,
            const int          id,
            const std::string &components,
            const std::string &value)
  {
    return subsection("Dirichlet " + std::to_string(slot),
                      entry("Boundary id", std::to_string(id)) +
                        entry("Components", components) +
                        entry("Displacement", value));
  }

  /// Tight solver settings so that results are limited by round-off.
  inline std::string
  tight_solver(const std::string &linear_solver)
  {
    return subsection("Newton",
                      entry("Max iterations", "25") +
                        entry("Absolute residual tolerance", "1e-14") +
                        entry("Relative residual tolerance", "1e-12") +
                        entry("Update tolerance", "1e-10")) +
           subsection("Linear solver",
                      entry("Type",
                            linear_solver == "direct" ? "direct"
                                                      : "CG with AMG") +
                        entry("Relative tolerance", "1e-10"));
  }
} // namespace hyperelastic::testing
