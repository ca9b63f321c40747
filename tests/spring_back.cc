// Spring-back of the example scene parameters/squashed_block_2d.prm: the
// plate moves by -0.2 sin(pi t), so the states at t and 1 - t coincide for a
// hyperelastic (path-independent) model and the block returns exactly to its
// rest shape at t = 1. Asserts, on the scene file as shipped:
//   energy(t) = energy(1 - t) and reactions(t) = reactions(1 - t) to 1e-8,
//   energy(1) <= 1e-12 max energy, min J(1) = 1 and |u(1)| <= 1e-10.
//
// Usage: mpirun -np N spring_back SCENE.prm
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace hyperelastic;
using hyperelastic::testing::Checker;

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               print =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  Checker checker(print);
  const int status = run_and_report(
    [&]() {
      Parameters parameters;
      parameters.read(argc > 1 ? argv[1] : "");
      parameters.output.write_vtu = false;
      parameters.output.base_name = "spring_back";
      Problem<2> problem(parameters, MPI_COMM_WORLD, false);
      problem.run();
      const auto &steps = problem.summaries();
      const auto  n     = steps.size();

      double max_energy = 0.;
      for (const auto &s : steps)
        max_energy = std::max(max_energy, std::abs(s.energy));
      for (unsigned int k = 0; k + 1 < n / 2; ++k)
        {
          const auto       &a = steps[k], &b = steps[n - 2 - k]; // t and 1 - t
          const std::string at = " at t = " + std::to_string(a.load_factor);
          checker.at_most("energy(t) - energy(1 - t)" + at,
                std::abs(a.energy - b.energy) / max_energy,
                1e-8);
          for (unsigned int r = 0; r < a.reactions.size(); ++r)
            checker.at_most("reaction(t) - reaction(1 - t)" + at,
                  (a.reactions[r].second - b.reactions[r].second).norm() /
                    std::max(a.reactions[r].second.norm(), 1e-300),
                  1e-8);
        }
      checker.at_most("energy at t = 1",
            std::abs(steps.back().energy) / max_energy,
            1e-12);
      checker.at_most("min J - 1 at t = 1", std::abs(steps.back().min_J - 1.), 1e-10);
      checker.at_most("max |u| at t = 1", problem.solution().linfty_norm(), 1e-10);
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
