// The one PASS/FAIL reporter of the test programs (and the benchmark's
// accuracy checks): one printed row per check, on the printing rank only,
// counts of passed and failed checks, and the exit status. Every check
// returns whether it passed, so that a caller can print more about a failure
// (note()). A NaN fails every numeric check.
#pragma once

#include <mpi.h>

#include <string>

namespace hyperelastic::testing
{
  class Checker
  {
  public:
    /// @p print: whether this process prints (rank 0 of the test's
    /// communicator, as a rule).
    explicit Checker(bool print = true);

    bool
    printing() const
    {
      return print;
    }

    /// Passes if @p value <= @p bound.
    bool
    at_most(const std::string &what, double value, double bound);

    /// Passes if @p value < @p bound.
    bool
    below(const std::string &what, double value, double bound);

    /// Passes if @p value >= @p bound.
    bool
    at_least(const std::string &what, double value, double bound);

    /// Passes if @p value > @p bound.
    bool
    above(const std::string &what, double value, double bound);

    /// Passes if |@p computed - @p exact| / @p scale < @p tolerance; the row
    /// shows both numbers to 14 digits and the relative error.
    bool
    close(const std::string &what,
          double             computed,
          double             exact,
          double             scale,
          double             tolerance);

    /// Passes if @p condition holds.
    bool
    is_true(const std::string &what, bool condition);

    /// A heading line ("== title") before a group of rows.
    void
    section(const std::string &title) const;

    /// A free line of explanation (indented), e.g. the worst case of a
    /// failed check.
    void
    note(const std::string &text) const;

    unsigned int
    n_passed() const
    {
      return passed;
    }

    unsigned int
    n_failed() const
    {
      return failed;
    }

    /// Prints "N passed, M failed" and returns the exit status: 0 if every
    /// check passed, at least one ran, and @p status (of the code under test,
    /// e.g. from run_and_report) is 0; 1 otherwise.
    int
    exit_code(int status = 0) const;

    /// The same, with the counts summed over @p comm first: for programs
    /// whose checks run on one rank only, so that every rank exits alike.
    int
    exit_code(int status, MPI_Comm comm) const;

  private:
    bool
    record(const std::string &what,
           double             value,
           const char        *relation,
           double             bound,
           bool               ok);

    int
    finish(unsigned int n_pass, unsigned int n_fail, int status) const;

    const bool   print;
    unsigned int passed = 0, failed = 0;
  };
} // namespace hyperelastic::testing
