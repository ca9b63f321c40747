// The speed-ups of the solver strategy leave the answer alone:
// - inexact Newton (Eisenstat-Walker Krylov tolerances) and a reused AMG
//   hierarchy give the same state as exact solves with a hierarchy built
//   for every solve (energy, reactions, displacement), with fewer AMG
//   setups than solves and fewer CG iterations in all;
// - a hierarchy refreshed on the aggregates of its first build ("AMG reuse
//   aggregates", ML's ReComputePreconditioner) gives the same state as one
//   aggregated anew for every solve (1e-10), within 1.3x its CG iterations
//   on this small mesh (on 1.8e5 unknowns it took 5-9x: doc/performance.md,
//   which is why the option is off by default);
// - plain aggregation ("AMG smoothed aggregation = false") gives the same
//   state as smoothed aggregation (1e-10) with more CG iterations (at least
//   1.2x: the option reaches ML);
// - the secant predictor ('Load stepping/Predictor = secant') starts every
//   load step after the first from the extrapolated state and ends at the
//   same state (1e-7, as inexact Newton);
// - the linear elastic model takes one Newton iteration (one linear solve)
//   per load step, and that solve meets Newton's tolerance when the linear
//   solver's is looser (against a direct solve);
// on the ranks of MPI_COMM_WORLD.
//
// Usage: mpirun -np N solver_strategies
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/scene_text.h"

#include <iostream>

using namespace dealii;
using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  struct Run
  {
    std::vector<StepSummary<3>> steps;
    VectorType                  u;
    unsigned int setups = 0, refreshes = 0, newton = 0, krylov = 0;
    unsigned int predictions = 0;
  };

  Run
  run(const std::string &text)
  {
    Parameters parameters;
    parameters.read_from_string(text);
    parameters.output.directory = "solver_strategies_output";
    Problem<3> problem(parameters, MPI_COMM_WORLD, false);
    problem.run();
    Run r;
    r.steps  = problem.summaries();
    r.u      = problem.solution();
    r.setups    = problem.n_preconditioner_setups();
    r.refreshes = problem.n_preconditioner_refreshes();
    r.predictions = problem.n_secant_predictions();
    for (const auto &s : r.steps)
      {
        r.newton += s.newton_iterations;
        r.krylov += s.linear_iterations;
      }
    return r;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Checker check(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  const int status = run_and_report(
    [&]() {
      // 8019 unknowns: ML builds a real hierarchy (not only a coarse solve).
      const std::string scene = bar_3d(8) + twist_loading();
      const Run         fast  = run(scene);
      const Run         exact = run(
        scene + subsection("Newton", entry("Inexact Newton", "false")) +
        subsection("Linear solver", entry("AMG rebuild growth", "0")));

      const double energy = exact.steps.back().energy;
      check.at_most("inexact + reuse vs exact: energy, relative",
                    std::abs(fast.steps.back().energy - energy) /
                      std::abs(energy),
                    1e-9);
      const Tensor<1, 3> reaction = exact.steps.back().reactions[1].second;
      check.at_most("inexact + reuse vs exact: twisted-end reaction",
                    (fast.steps.back().reactions[1].second - reaction).norm() /
                      reaction.norm(),
                    1e-7);
      VectorType difference = fast.u;
      difference -= exact.u;
      check.at_most("inexact + reuse vs exact: displacement, relative",
                    difference.linfty_norm() / exact.u.linfty_norm(),
                    1e-7);
      check.is_true("exact run: one AMG setup per Newton iteration (" +
                      std::to_string(exact.setups) + ")",
                    exact.setups == exact.newton);
      // The CSV column amg_setups: the running count, step by step; with a
      // hierarchy per Newton iteration (and no cut-back) it is the running
      // sum of the Newton iterations.
      {
        bool         running = true, absent = false;
        unsigned int newton  = 0;
        for (const auto &s : exact.steps)
          {
            newton += s.newton_iterations;
            absent = absent || !s.amg_setups;
            running =
              running && s.cut_backs == 0 && s.amg_setups == newton;
          }
        check.is_true("CSV amg_setups, one setup per Newton iteration: the "
                      "running sum of newton_iterations",
                      !absent && running);
        check.is_true("CSV amg_setups, reuse: the last row counts every "
                      "setup of the run (" +
                        std::to_string(fast.setups) + ")",
                      fast.steps.back().amg_setups == fast.setups);
        unsigned int previous = 0;
        bool         rising   = true;
        for (const auto &s : fast.steps)
          {
            rising   = rising && s.amg_setups && *s.amg_setups >= previous;
            previous = s.amg_setups.value_or(0);
          }
        check.is_true("CSV amg_setups, reuse: never decreasing", rising);
      }
      check.at_most("reuse: AMG setups per Newton iteration",
                    double(fast.setups) / fast.newton,
                    0.5);
      check.at_most("inexact Newton: CG iterations, fraction of exact",
                    double(fast.krylov) / exact.krylov,
                    0.8);

      // A hierarchy for every solve, refreshed on the first aggregates or
      // aggregated anew; exact Newton to a tight tolerance.
      const std::string every_solve =
        scene +
        subsection("Newton",
                   entry("Inexact Newton", "false") +
                     entry("Relative residual tolerance", "1e-12")) +
        subsection("Linear solver",
                   entry("AMG rebuild growth", "0") +
                     entry("Relative tolerance", "1e-11"));
      const Run refreshed = run(
        every_solve +
        subsection("Linear solver", entry("AMG reuse aggregates", "true")));
      const Run rebuilt = run(every_solve);
      check.is_true("reuse aggregates: one full build, then refreshes (" +
                      std::to_string(refreshed.refreshes) + " of " +
                      std::to_string(refreshed.setups) + ")",
                    refreshed.setups == refreshed.newton &&
                      refreshed.refreshes + 1 == refreshed.setups);
      check.is_true("aggregated anew: no refreshes",
                    rebuilt.refreshes == 0 &&
                      rebuilt.setups == rebuilt.newton);
      VectorType change = refreshed.u;
      change -= rebuilt.u;
      check.at_most("refreshed vs aggregated anew: displacement, relative",
                    change.linfty_norm() / rebuilt.u.linfty_norm(),
                    1e-10);
      check.at_most("refreshed vs aggregated anew: energy, relative",
                    std::abs(refreshed.steps.back().energy -
                             rebuilt.steps.back().energy) /
                      std::abs(rebuilt.steps.back().energy),
                    1e-10);
      check.at_most("refreshed vs aggregated anew: CG iterations, ratio",
                    double(refreshed.krylov) / rebuilt.krylov,
                    1.3);

      // Plain aggregation: the same state, more CG iterations.
      const Run plain = run(
        every_solve +
        subsection("Linear solver", entry("AMG smoothed aggregation", "false")));
      VectorType plain_change = plain.u;
      plain_change -= rebuilt.u;
      check.at_most("plain vs smoothed aggregation: displacement, relative",
                    plain_change.linfty_norm() / rebuilt.u.linfty_norm(),
                    1e-10);
      check.at_least("plain vs smoothed aggregation: CG iterations, ratio "
                     "(the prolongator smoothing must have been dropped)",
                     double(plain.krylov) / rebuilt.krylov,
                     1.2);

      const Run predicted = run(
        scene + subsection("Load stepping", entry("Predictor", "secant")));
      check.is_true("secant predictor: used in every step after the first (" +
                      std::to_string(predicted.predictions) + " of " +
                      std::to_string(predicted.steps.size()) + " steps)",
                    predicted.predictions + 1 == predicted.steps.size() &&
                      fast.predictions == 0);
      VectorType moved = predicted.u;
      moved -= fast.u;
      check.at_most("secant predictor vs none: displacement, relative",
                    moved.linfty_norm() / fast.u.linfty_norm(),
                    1e-7);
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          std::cout << "  Newton iterations per step, predictor none / secant:";
          for (std::size_t k = 0; k < fast.steps.size(); ++k)
            std::cout << " " << fast.steps[k].newton_iterations << "/"
                      << predicted.steps[k].newton_iterations;
          std::cout << std::endl;
        }

      const Run linear =
        run(bar_3d(4) + twist_loading() +
            subsection("Material", entry("Model", "linear elastic")));
      for (const auto &s : linear.steps)
        check.is_true("linear elastic, step " + std::to_string(s.step) +
                        ": one Newton iteration",
                      s.newton_iterations == 1);
      // No Newton iteration corrects the one solve of a linear problem: it
      // goes to Newton's relative residual tolerance (default 1e-10) even
      // when the linear solver's is looser. (On the 16 x 4 x 4 bar AMG's
      // coarse level nearly solves the problem in two iterations: 32 x 8 x 8
      // boxes.)
      const std::string larger_scene =
        bar_3d(8) + twist_loading() +
        subsection("Material", entry("Model", "linear elastic"));
      const Run loose =
        run(larger_scene +
            subsection("Linear solver", entry("Relative tolerance", "1e-4")));
      const Run direct = run(
        larger_scene + subsection("Linear solver", entry("Type", "direct")));
      VectorType loose_error = loose.u;
      loose_error -= direct.u;
      check.at_most("linear elastic, CG tolerance 1e-4 (Newton's 1e-10): "
                    "displacement against a direct solve, relative",
                    loose_error.linfty_norm() / direct.u.linfty_norm(),
                    1e-8);
      check.is_true("linear elastic, CG tolerance 1e-4: one Newton iteration "
                    "per step",
                    loose.newton == loose.steps.size());
    },
    MPI_COMM_WORLD);
  return check.exit_code(status);
}
