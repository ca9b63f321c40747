#include "checker.h"

#include <cmath>
#include <iomanip>
#include <iostream>

namespace hyperelastic::testing
{
  namespace
  {
    constexpr int what_width = 62;

    const char *
    verdict(const bool ok)
    {
      return ok ? "  PASS" : "  FAIL";
    }
  } // namespace

  Checker::Checker(const bool print)
      : print(print)
  {
  }

  bool
  Checker::at_most(const std::string &what, const double value, const double bound)
  {
    return record(what, value, "<=", bound, value <= bound);
  }

  bool
  Checker::below(const std::string &what, const double value, const double bound)
  {
    return record(what, value, "< ", bound, value < bound);
  }

  bool
  Checker::at_least(const std::string &what,
                    const double       value,
                    const double       bound)
  {
    return record(what, value, ">=", bound, value >= bound);
  }

  bool
  Checker::above(const std::string &what, const double value, const double bound)
  {
    return record(what, value, "> ", bound, value > bound);
  }

  bool
  Checker::close(const std::string &what,
                 const double       computed,
                 const double       exact,
                 const double       scale,
                 const double       tolerance)
  {
    const double error = std::abs(computed - exact) / scale;
    const bool   ok    = error < tolerance;
    (ok ? passed : failed)++;
    if (print)
      std::cout << "  " << std::left << std::setw(40) << what << std::right
                << std::setprecision(14) << std::setw(22) << computed
                << std::setw(22) << exact << std::setprecision(2)
                << std::scientific << std::setw(10) << error << " < "
                << tolerance << std::defaultfloat << verdict(ok) << std::endl;
    return ok;
  }

  bool
  Checker::is_true(const std::string &what, const bool condition)
  {
    (condition ? passed : failed)++;
    if (print)
      std::cout << "  " << std::left << std::setw(what_width) << what
                << std::right << verdict(condition) << std::endl;
    return condition;
  }

  void
  Checker::section(const std::string &title) const
  {
    if (print)
      std::cout << "\n== " << title << std::endl;
  }

  void
  Checker::note(const std::string &text) const
  {
    if (print)
      std::cout << "    " << text << std::endl;
  }

  int
  Checker::exit_code(const int status) const
  {
    return finish(passed, failed, status);
  }

  int
  Checker::exit_code(const int status, const MPI_Comm comm) const
  {
    unsigned int counts[2] = {passed, failed};
    unsigned int sums[2]   = {0, 0};
    int          worst     = 0;
    MPI_Allreduce(counts, sums, 2, MPI_UNSIGNED, MPI_SUM, comm);
    MPI_Allreduce(&status, &worst, 1, MPI_INT, MPI_MAX, comm);
    return finish(sums[0], sums[1], worst);
  }

  bool
  Checker::record(const std::string &what,
                  const double       value,
                  const char        *relation,
                  const double       bound,
                  const bool         ok)
  {
    (ok ? passed : failed)++;
    if (print)
      std::cout << "  " << std::left << std::setw(what_width) << what
                << std::right << std::scientific << std::setprecision(4)
                << std::setw(12) << value << ' ' << relation << ' '
                << std::setw(11) << bound << std::defaultfloat << verdict(ok)
                << std::endl;
    return ok;
  }

  int
  Checker::finish(const unsigned int n_pass,
                  const unsigned int n_fail,
                  const int          status) const
  {
    if (print)
      std::cout << n_pass << " passed, " << n_fail << " failed" << std::endl;
    return (status != 0 || n_fail > 0 || n_pass == 0) ? 1 : 0;
  }
} // namespace hyperelastic::testing
