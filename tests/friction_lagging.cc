// Lagged friction's update trigger (issue 67, item 5;
// contact/friction_lagging.h) on hand-made changes, split over the ranks
// (the decision is the same on 1 and 2 ranks). 'single pair': a pair
// entering with 2e-3 of the largest normal force updates, with 5e-4 not;
// every normal force up by 1 % updates even without slip. 'friction
// force', on a slide of 100 pairs, each
// with normal force 1 and mu = 0.3, fully sliding (f1 = 1): their normal
// forces have l2 norm 10, and an update is taken where the friction force
// changes by more than 1e-3 of that, 0.01.
// - a pair entering with lambda = 0.02 (friction change 0.006): unchanged,
//   though its change is 2 % of the largest normal force (the rule before
//   issue 67 fired on it);
// - one pair entering with lambda = 0.05 (0.015): updated;
// - every pair's lambda up by 1 % (0.03): updated, and counted: after
//   'Friction lagging updates' = 2 of them, no more;
// - every lambda tripled (a change above half the normal forces' norm): a
//   large update, not counted against the budget (and as many as it);
// - the normal forces halved while sticking with no slip yet (f1 = 0): no
//   friction force changes, unchanged;
// - within the solve at an iterate whose unbalanced force is above half
//   the largest normal force: unchanged; at a prediction: updated and not
//   counted.
// Usage: mpirun -np N friction_lagging
#include <deal.II/base/mpi.h>

#include <hyperelastic/contact/friction_lagging.h>

#include "support/checker.h"

#include <cmath>
#include <functional>
#include <string>

using namespace hyperelastic;

namespace
{
  constexpr unsigned int n_pairs = 100;
  constexpr double       mu      = 0.3;

  /// The change of this rank's share of the pairs (rank r of n takes the
  /// pairs i with i % n == r): pair i's normal force goes from before(i) to
  /// after(i), with the friction force's factor f1 (1: sliding, 0: no
  /// slip); the entering pair is number n_pairs (its lambda from 0).
  FrictionLagging::Change
  change(const std::function<double(unsigned int)> &before,
         const std::function<double(unsigned int)> &after,
         const double                               f1,
         const MPI_Comm                             comm)
  {
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int size = dealii::Utilities::MPI::n_mpi_processes(comm);
    FrictionLagging::Change c;
    for (unsigned int i = 0; i <= n_pairs; ++i)
      if (i % size == rank)
        {
          c.add_normal_force(before(i), after(i));
          const double df = mu * (after(i) - before(i)) * f1;
          c.friction_squared += df * df;
        }
    return c;
  }

  /// The slide's normal forces: 1 for each of the 100, 0 for the entering
  /// pair.
  double
  sliding(const unsigned int i)
  {
    return i < n_pairs ? 1. : 0.;
  }

  /// The slide with the entering pair at @p lambda.
  std::function<double(unsigned int)>
  entering(const double lambda)
  {
    return [lambda](const unsigned int i) { return i < n_pairs ? 1. : lambda; };
  }

  std::function<double(unsigned int)>
  scaled(const double factor)
  {
    return [factor](const unsigned int i) { return factor * sliding(i); };
  }

  bool
  updated(FrictionLagging                &lagging,
          const FrictionLagging::Change  &c,
          const FrictionLagging::Iterate &at,
          const MPI_Comm                  comm)
  {
    return lagging.decide(c, at, comm) == LaggedUpdate::updated;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  testing::Checker checker(dealii::Utilities::MPI::this_mpi_process(comm) == 0);
  const FrictionLagging::Iterate converged{LagMoment::converged, 0.};
  // Checks that @p lagging decides @p expected on the change from the
  // slide to @p after (friction factor @p f1) taken at @p at.
  const auto expect = [&](const std::string                         &what,
                          FrictionLagging                           &lagging,
                          const std::function<double(unsigned int)> &after,
                          const double                               f1,
                          const FrictionLagging::Iterate            &at,
                          const bool                                 expected) {
    checker.is_true(
      what,
      updated(lagging, change(sliding, after, f1, comm), at, comm) == expected);
  };

  checker.section("'Friction lag trigger = single pair' (the default)");
  FrictionLagging per_pair(2, false);
  per_pair.begin_step();
  expect("a pair entering at lambda = 0.002: updated",
         per_pair,
         entering(0.002),
         1.,
         converged,
         true);
  expect("a pair entering at lambda = 0.0005: unchanged",
         per_pair,
         entering(0.0005),
         1.,
         converged,
         false);
  expect("every lambda up 1 % at f1 = 0: updated",
         per_pair,
         scaled(1.01),
         0.,
         converged,
         true);
  checker.is_true("the budget spent", !per_pair.may_update());

  checker.section("'friction force': the assembled friction force");
  FrictionLagging lagging(2, true);
  lagging.begin_step();
  expect("a pair entering at lambda = 0.02: unchanged",
         lagging,
         entering(0.02),
         1.,
         converged,
         false);
  expect("a pair entering at lambda = 0.05: updated",
         lagging,
         entering(0.05),
         1.,
         converged,
         true);
  checker.is_true("one update left", lagging.may_update());

  checker.section("the budget: 'Friction lagging updates' = 2 a step");
  expect(
    "every lambda up 1 %: updated", lagging, scaled(1.01), 1., converged, true);
  checker.is_true("the budget spent", !lagging.may_update());
  lagging.begin_step();
  checker.is_true("a new step may update again", lagging.may_update());

  checker.section("large updates apart from the budget");
  for (unsigned int k = 0; k < 2; ++k)
    expect("every lambda tripled: updated",
           lagging,
           scaled(3.),
           1.,
           converged,
           true);
  checker.is_true("two large updates leave the budget whole",
                  lagging.may_update());
  expect("a third large one", lagging, scaled(3.), 1., converged, true);
  checker.is_true("a third large one is counted", lagging.may_update());
  expect("a fourth large one", lagging, scaled(3.), 1., converged, true);
  checker.is_true("and a fourth spends the budget", !lagging.may_update());

  checker.section("no slip, no friction force to change");
  lagging.begin_step();
  expect("lambda halved at f1 = 0: unchanged",
         lagging,
         scaled(0.5),
         0.,
         converged,
         false);

  checker.section("where the new values are taken");
  expect("within the solve, unbalanced force 0.6 of the largest: unchanged",
         lagging,
         scaled(1.01),
         1.,
         {LagMoment::within_solve, 0.6 * 1.01},
         false);
  expect("within the solve, unbalanced force 0.4 of the largest: updated",
         lagging,
         scaled(1.01),
         1.,
         {LagMoment::within_solve, 0.4 * 1.01},
         true);
  for (unsigned int k = 0; k < 3; ++k)
    expect("at a prediction: updated",
           lagging,
           scaled(1.01),
           1.,
           {LagMoment::predicted, 0.},
           true);
  checker.is_true("predictions not counted (one update left)",
                  lagging.may_update());
  return checker.exit_code();
}
