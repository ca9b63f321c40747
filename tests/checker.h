// A small assertion helper for the test programs: one printed row per check
// (on rank 0), counts of passed and failed checks, and the exit status.
#pragma once

#include <iomanip>
#include <iostream>
#include <string>

namespace hyperelastic::testing
{
  class Checker
  {
  public:
    explicit Checker(const bool print)
        : print(print)
    {
    }

    /// Passes if @p value <= @p bound.
    void
    at_most(const std::string &what, const double value, const double bound)
    {
      report(what, value, "<=", bound, value <= bound);
    }

    /// Passes if @p value >= @p bound.
    void
    at_least(const std::string &what, const double value, const double bound)
    {
      report(what, value, ">=", bound, value >= bound);
    }

    void
    is_true(const std::string &what, const bool condition)
    {
      (condition ? passed : failed)++;
      if (print)
        std::cout << "  " << std::left << std::setw(60) << what << std::right
                  << (condition ? "  PASS" : "  FAIL") << std::endl;
    }

    /// 0 if every check passed, at least one ran, and @p status is 0.
    int
    exit_code(const int status = 0) const
    {
      if (print)
        std::cout << passed << " passed, " << failed << " failed" << std::endl;
      return (status != 0 || failed > 0 || passed == 0) ? 1 : 0;
    }

  private:
    void
    report(const std::string &what,
           const double       value,
           const char        *relation,
           const double       bound,
           const bool         ok)
    {
      (ok ? passed : failed)++;
      if (print)
        std::cout << "  " << std::left << std::setw(60) << what << std::right
                  << std::scientific << std::setprecision(4) << std::setw(12)
                  << value << ' ' << relation << ' ' << std::setw(11) << bound
                  << std::defaultfloat << (ok ? "  PASS" : "  FAIL")
                  << std::endl;
    }

    const bool   print;
    unsigned int passed = 0, failed = 0;
  };
} // namespace hyperelastic::testing
