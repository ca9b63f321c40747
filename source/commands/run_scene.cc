// The entry of a scene run: the dimension chosen from the parameters, and
// the errors that all ranks raise together rethrown only after the problem is
// gone.
#include <deal.II/base/conditional_ostream.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>
#include <hyperelastic/inverse/unloaded_shape.h>

#include <iostream>

namespace hyperelastic
{
  namespace
  {
    /// Problem/Reference = loaded: the unloaded shape found (the problem
    /// then holds the forward run from it, with its output) and written.
    template <int dim>
    void
    run_from_loaded_shape(Problem<dim>     &problem,
                          const Parameters &parameters,
                          const MPI_Comm    comm)
    {
      dealii::ConditionalOStream pcout(
        std::cout, dealii::Utilities::MPI::this_mpi_process(comm) == 0);
      const UnloadedShape shape =
        find_unloaded_shape(problem, parameters.problem, pcout);
      const std::string path = parameters.output.directory + "/" +
                               parameters.output.base_name + "_reference.msh";
      write_reference_mesh(problem, shape.loaded, parameters.mesh.file, path);
      pcout << "Reference = loaded: the unloaded shape after "
            << shape.iterations << " forward solves (" << shape.seconds
            << " s; the first forward solve " << shape.first_solve_seconds
            << " s), written to " << path
            << "; the output above is the forward run from it." << std::endl;
    }

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
            if (parameters.problem.reference_loaded)
              run_from_loaded_shape(problem, parameters, comm);
            else
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
