// Mapping of exceptions to messages and exit codes without MPI deadlocks.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>

#include <iostream>
#include <sstream>

namespace hyperelastic
{
  std::string
  exception_message(const std::exception &e)
  {
    if (const auto *dealii_exception =
          dynamic_cast<const dealii::ExceptionBase *>(&e))
      {
        std::ostringstream info;
        dealii_exception->print_info(info);
        std::string text = info.str();
        // print_info indents every line; strip that for a compact message.
        std::string        out;
        std::istringstream lines(text);
        for (std::string line; std::getline(lines, line);)
          {
            const auto first = line.find_first_not_of(' ');
            if (first == std::string::npos)
              continue;
            out += (out.empty() ? "" : "\n") + line.substr(first);
          }
        if (out.rfind("The name and call sequence of the exception was:", 0) ==
            0)
          out = e.what();
        return out.empty() ? std::string(e.what()) : out;
      }
    return e.what();
  }

  void
  throw_input_error_if_any(const bool         failed,
                           const std::string &message,
                           const MPI_Comm     comm)
  {
    const int any = dealii::Utilities::MPI::max(failed ? 1 : 0, comm);
    if (any != 0)
      throw InputError(message);
  }

  void
  throw_convergence_failure_if_any(const std::string &local_error,
                                   const MPI_Comm     comm)
  {
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int first_failed =
      dealii::Utilities::MPI::min(local_error.empty() ? n_ranks : rank, comm);
    if (first_failed == n_ranks)
      return;
    const std::string message =
      dealii::Utilities::MPI::broadcast(comm, local_error, first_failed);
    throw ConvergenceFailure(
      (n_ranks > 1 ? "on MPI rank " + std::to_string(first_failed) + ", "
                   : std::string()) +
      message);
  }

  void
  throw_input_error_of_first_rank(const std::string &local_problem,
                                  const MPI_Comm     comm)
  {
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const unsigned int first   = dealii::Utilities::MPI::min(
      local_problem.empty() ? n_ranks
                              : dealii::Utilities::MPI::this_mpi_process(comm),
      comm);
    if (first < n_ranks)
      throw InputError(
        dealii::Utilities::MPI::broadcast(comm, local_problem, first));
  }

  int
  run_and_report(const std::function<void()> &body, const MPI_Comm comm)
  {
    const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    try
      {
        body();
        return success;
      }
    catch (const InputError &e)
      {
        if (root)
          std::cerr << "\nhyperelastic: input error: " << e.what() << std::endl;
        return input_error;
      }
    catch (const ConvergenceFailure &e)
      {
        if (root)
          std::cerr << "\nhyperelastic: convergence failure: " << e.what()
                    << std::endl;
        return convergence_failure;
      }
    catch (const std::exception &e)
      {
        std::cerr << "\nhyperelastic: error on MPI rank "
                  << dealii::Utilities::MPI::this_mpi_process(comm) << ": "
                  << exception_message(e) << std::endl;
      }
    catch (...)
      {
        std::cerr << "\nhyperelastic: unknown exception on MPI rank "
                  << dealii::Utilities::MPI::this_mpi_process(comm)
                  << std::endl;
      }
    // The failure may be local to this rank: abort the whole job rather than
    // leave other ranks blocked in a collective operation.
    if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
      MPI_Abort(comm, internal_error);
    return internal_error;
  }
} // namespace hyperelastic
