// CG with the exact solve on the contact's stiff unknowns ('Linear solver/
// Exact solve on stiff couplings', issue 57 item 4) against CG without it,
// on a contact scene (2 ranks in ctest):
// - the same equilibria: the energy of every row within 1e-6 relative (both
//   runs converge to Newton's tolerance, not to each other), the same
//   number of rows;
// - CG iterations per Newton iteration with the solve at most BOUND times
//   those without (a ratio of counts, not a time);
// - Newton iterations in all at most 1.2 times those without (the solve
//   changes the inexact Newton steps, not the method).
//
// Usage: mpirun -np N contact_krylov SCENE.prm BOUND
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/scene/parameters.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"

#include <cmath>
#include <sstream>

using namespace dealii;
using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  struct Run
  {
    std::vector<double> energies;
    unsigned int        newton = 0;
    unsigned int        krylov = 0;
  };

  template <int dim>
  Run
  run(Parameters parameters, const bool stiff_solve)
  {
    parameters.linear_solver.stiff_couplings_solve = stiff_solve;
    parameters.output.directory =
      stiff_solve ? "contact_krylov_with" : "contact_krylov_without";
    parameters.output.write_vtu = false;
    Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
    problem.run();
    Run r;
    for (const auto &s : problem.summaries())
      {
        r.energies.push_back(s.energy);
        r.newton += s.newton_iterations;
        r.krylov += s.linear_iterations;
      }
    return r;
  }

  template <int dim>
  void
  compare(Checker &check, const Parameters &parameters, const double bound)
  {
    const Run with    = run<dim>(parameters, true);
    const Run without = run<dim>(parameters, false);
    check.is_true("rows: " + std::to_string(with.energies.size()) + " and " +
                    std::to_string(without.energies.size()),
                  with.energies.size() == without.energies.size());
    if (with.energies.size() != without.energies.size())
      return;
    double scale = 0., difference = 0.;
    for (unsigned int i = 0; i < with.energies.size(); ++i)
      {
        scale      = std::max(scale, std::abs(without.energies[i]));
        difference = std::max(difference,
                              std::abs(with.energies[i] - without.energies[i]));
      }
    check.at_most("energy of every row, with / without the stiff solve, "
                  "relative",
                  difference / scale,
                  1e-6);
    const double       rate_with    = double(with.krylov) / with.newton;
    const double       rate_without = double(without.krylov) / without.newton;
    std::ostringstream what;
    what << "CG per Newton iteration, with / without the stiff solve ("
         << rate_with << " / " << rate_without << ")";
    check.at_most(what.str(), rate_with / rate_without, bound);
    check.at_most("Newton iterations, with / without (" +
                    std::to_string(with.newton) + " / " +
                    std::to_string(without.newton) + ")",
                  double(with.newton) / without.newton,
                  1.2);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Checker   check(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  const int status = run_and_report(
    [&]() {
      if (argc != 3)
        throw InputError("usage: contact_krylov SCENE.prm BOUND");
      Parameters parameters;
      parameters.read(argv[1]);
      const double bound = std::stod(argv[2]);
      if (parameters.problem.dimension == 2)
        compare<2>(check, parameters, bound);
      else
        compare<3>(check, parameters, bound);
    },
    MPI_COMM_WORLD);
  return check.exit_code(status);
}
