// Newton iteration with residual and update tests and a printed table.
#include <hyperelastic/error_handling.h>
#include <hyperelastic/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace hyperelastic
{
  unsigned int
  NewtonResult::linear_iterations() const
  {
    unsigned int n = 0;
    for (const auto &row : history)
      n += row.linear_iterations;
    return n;
  }

  NewtonSolver::NewtonSolver(const NewtonParameters    &parameters,
                             dealii::ConditionalOStream pcout,
                             const bool                 verbose)
      : parameters(parameters)
      , pcout(pcout)
      , verbose(verbose)
  {
  }

  namespace
  {
    std::string
    format_row(const NewtonIteration &row)
    {
      std::ostringstream s;
      s << std::setw(8) << row.iteration << std::scientific
        << std::setprecision(3) << std::setw(14) << row.residual
        << std::setw(14) << row.update << std::setw(10)
        << row.linear_iterations;
      return s.str();
    }

    std::string
    history_text(const NewtonResult &result)
    {
      std::string text = "\n   iteration      residual        update  lin.its";
      for (const auto &row : result.history)
        text += "\n" + format_row(row);
      return text;
    }
  } // namespace

  NewtonResult
  NewtonSolver::solve(NonlinearSystem &system) const
  {
    NewtonResult result;
    if (verbose)
      pcout << "   iteration      residual        update  lin.its" << std::endl;

    system.assemble_linearization(true);
    for (unsigned int it = 1; it <= parameters.max_iterations; ++it)
      {
        const unsigned int  linear_its = system.solve_linearization();
        const double        update     = system.apply_update();
        const ResidualNorms norms      = system.residual_norms();
        result.history.push_back({it, norms.residual, update, linear_its});
        if (verbose)
          pcout << format_row(result.history.back()) << std::endl;

        if (!std::isfinite(norms.residual) || !std::isfinite(update))
          throw ConvergenceFailure(
            "Newton produced a non-finite residual or update (an element may "
            "have inverted with a model undefined there)" +
            history_text(result));

        // Converged when the residual is small, in absolute terms or
        // relative to the forces of the run, and the last update is small
        // relative to the displacements of the run. Both tests are needed:
        // with small forces (soft materials, small bodies) a residual test
        // alone would accept an unconverged state.
        const bool residual_small =
          norms.residual <=
          std::max(parameters.absolute_residual_tolerance,
                   parameters.relative_residual_tolerance * norms.scale);
        const bool update_small =
          update <= parameters.update_tolerance * system.solution_scale();
        if (residual_small && update_small)
          return result;

        system.assemble_linearization(false);
      }
    throw ConvergenceFailure("Newton did not converge in " +
                             std::to_string(parameters.max_iterations) +
                             " iterations (Newton/Max iterations)" +
                             history_text(result));
  }
} // namespace hyperelastic
