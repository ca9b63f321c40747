// Error types with their exit codes, and the MPI-safe way main() reports them.
//
// Errors that every rank detects identically (bad input, non-convergence, which
// is decided on global norms) are reported once by rank 0 and end the program
// with a distinct exit code. Anything else may have happened on one rank only:
// it is printed by the rank that saw it and the whole job is aborted, so that
// no rank is left waiting in a collective call.
#pragma once

#include <functional>
#include <mpi.h>
#include <stdexcept>
#include <string>

namespace hyperelastic
{
  enum ExitCode : int
  {
    success             = 0,
    input_error         = 1,
    internal_error      = 2,
    convergence_failure = 3
  };

  /// Invalid scene, parameter, mesh or boundary specification. Thrown
  /// collectively: every rank reaches the same conclusion.
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// Newton or the linear solver failed. Thrown collectively.
  class ConvergenceFailure : public std::runtime_error
  {
  public:
    /// @p newton_iterations: the Newton iterations the failed solve used,
    /// the failed one included (0 where no Newton solve failed).
    explicit ConvergenceFailure(const std::string &message,
                                unsigned int       newton_iterations = 0)
        : std::runtime_error(message)
        , iterations(newton_iterations)
    {
    }

    /// The Newton iterations the failed solve used (what a budget of
    /// iterations is charged).
    unsigned int
    newton_iterations() const
    {
      return iterations;
    }

  private:
    unsigned int iterations;
  };

  /// Throws InputError(message) on every rank if @p failed is true on any rank.
  /// Collective over @p comm.
  void
  throw_input_error_if_any(const bool         failed,
                           const std::string &message,
                           const MPI_Comm     comm);

  /// If @p local_error is non-empty on any rank, throws ConvergenceFailure on
  /// every rank with the message of the lowest such rank (naming it).
  /// Collective over @p comm.
  void
  throw_convergence_failure_if_any(const std::string &local_error,
                                   const MPI_Comm     comm);

  /// If @p local_problem is non-empty on any rank, throws InputError on every
  /// rank with the message of the lowest such rank. Collective over @p comm.
  void
  throw_input_error_of_first_rank(const std::string &local_problem,
                                  const MPI_Comm     comm);

  /// Runs @p body and turns exceptions into messages and exit codes as
  /// described above. Returns the exit code.
  int
  run_and_report(const std::function<void()> &body, const MPI_Comm comm);

  /// The short message of an exception: for deal.II exceptions only the
  /// "additional information", without file, line and stack trace.
  std::string
  exception_message(const std::exception &e);
} // namespace hyperelastic
