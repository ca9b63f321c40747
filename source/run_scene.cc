// The entry of a scene run: the dimension chosen from the parameters, and
// the errors that all ranks raise together rethrown only after the problem is
// gone.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem.h>

namespace hyperelastic
{
  namespace
  {
    // Errors that all ranks raise together are rethrown only after the
    // problem (and its timer, which communicates when destroyed) is gone, so
    // that nothing is destroyed while an exception is in flight. Errors of a
    // single rank propagate at once: main() aborts the job.
    template <int dim>
    void
    run_problem(const Parameters &parameters, const MPI_Comm comm)
    {
      std::exception_ptr collective_error;
      {
        Problem<dim> problem(parameters, comm);
        try
          {
            problem.run();
          }
        catch (const InputError &)
          {
            collective_error = std::current_exception();
          }
        catch (const ConvergenceFailure &)
          {
            collective_error = std::current_exception();
          }
      }
      if (collective_error)
        std::rethrow_exception(collective_error);
    }
  } // namespace

  void
  run_scene(const Parameters &parameters, const MPI_Comm comm)
  {
    if (parameters.problem.dimension == 2)
      run_problem<2>(parameters, comm);
    else
      run_problem<3>(parameters, comm);
  }

} // namespace hyperelastic
