// The automatic barrier stiffness at a sound operating point (issue 67,
// item 3; contact/barrier_stiffness.h, 'Contact/Barrier stiffness rule =
// operating point'). A block [0, 1]^DIM of neo-Hookean (E = 1, nu = 0.3)
// stands d_hat / 2 above a frictionless floor (a plane obstacle, d_hat =
// 1e-4 given, kappa automatic) and its top is pressed down by s = 1e-3,
// 1e-2 and 1e-1 in 10 load steps: contact pressures over two orders of
// magnitude. The rule 'modulus', (lambda + 2 mu) / d_hat, puts the
// lightest press at d / d_hat of about 0.99 (the edge of the barrier's
// range); started from the element size and re-targeted between steps, the
// last state's smallest distance over d_hat lies in [0.2, 0.8] at every
// pressure. Also: the barrier's
// force factor g(x) = -b'(x d_hat) / d_hat against central differences of
// b (1e-7), and a given 'Barrier stiffness' is never re-targeted.
// Usage: mpirun -np N barrier_operating_point DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/contact/barrier_stiffness.h>

#include "support/dimension_main.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <cmath>
#include <string>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  constexpr double d_hat = 1e-4;

  /// The block pressed by @p squash, with 'Barrier stiffness' @p kappa
  /// (0: automatic).
  template <int dim>
  std::string
  pressed_block(const double squash, const double kappa)
  {
    const bool        three = dim == 3;
    const std::string gap   = number(0.5 * d_hat);
    const std::string top   = three ? "0; 0; -" : "0; -";
    return unit_block(dim) +
           subsection("Loading", entry("Number of load steps", "10")) +
           dirichlet(1,
                     three ? 5 : 3,
                     three ? "x, y, z" : "x, y",
                     top + number(squash) + "*t") +
           subsection("Output",
                      entry("Write VTU", "false") + entry("Verbose", "false")) +
           subsection(
             "Contact",
             entry("Barrier distance", number(d_hat)) +
               entry("Barrier stiffness", number(kappa)) +
               entry("Barrier stiffness rule", "operating point") +
               subsection("Obstacle 1",
                          entry("Type", "plane") +
                            entry("Point", (three ? "0, 0, -" : "0, -") + gap) +
                            entry("Normal", three ? "0, 0, 1" : "0, 1")));
  }

  template <int dim>
  void
  run(Checker &checker)
  {
    const std::string tag = std::to_string(dim) + "D pressed block: ";
    for (const double squash : {1e-3, 1e-2, 1e-1})
      {
        const auto   problem = run_scene<dim>(pressed_block<dim>(squash, 0.));
        const auto  &rows    = problem->summaries();
        const double ratio =
          column(rows.back(), "contact_min_distance") / d_hat;
        const std::string what = tag + "squash " + number(squash);
        checker.at_least(what + ", last d / d_hat", ratio, 0.2);
        checker.at_most(what + ", last d / d_hat", ratio, 0.8);
      }
    // A given kappa stays: the same scene with kappa given as the start
    // value ends near d_hat at the lightest press.
    const double given_kappa = (1. / (1.3 * 0.4) * 0.3 + 2. / 2.6) / d_hat;
    const auto   fixed = run_scene<dim>(pressed_block<dim>(1e-3, given_kappa));
    checker.above(tag + "squash 0.001, kappa given: last d / d_hat",
                  column(fixed->summaries().back(),
                         "contact_min_distance") /
                    d_hat,
                  0.8);
  }

  void
  force_factor(Checker &checker)
  {
    // b(x) / d_hat^2 = -(x - 1)^2 ln x; g(x) = -db/dd / d_hat.
    const auto b = [](const double x) {
      return -(x - 1.) * (x - 1.) * std::log(x);
    };
    double worst = 0.;
    for (const double x : {0.05, 0.3, 0.5, 0.7, 0.9, 0.99})
      {
        const double h  = 1e-6;
        const double fd = -(b(x + h) - b(x - h)) / (2. * h);
        worst = std::max(worst,
                         std::abs(BarrierStiffness::force_factor(x) - fd) /
                           std::max(std::abs(fd), 1e-3));
      }
    checker.at_most("g(x) = -b'(x d_hat) / d_hat against differences",
                    worst,
                    1e-7);
    checker.close("g(1) (outside the barrier)",
                  BarrierStiffness::force_factor(1.),
                  0.,
                  1.,
                  1e-15);
    BarrierStiffness given(2., false);
    checker.is_true("a given kappa is not re-targeted",
                    !given.retarget(0.99) && given.value() == 2.);
    BarrierStiffness automatic(2., true);
    checker.is_true("an automatic kappa at d / d_hat = 0.99 falls",
                    automatic.retarget(0.99) && automatic.value() < 2.);
    checker.is_true("and at 0.5 stays",
                    !automatic.retarget(0.5) && automatic.n_retargets() == 1);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_for_dimension(argc,
                           argv,
                           1,
                           [](const int dim, Checker &checker, const bool print) {
                             if (print)
                               force_factor(checker);
                             if (dim == 2)
                               run<2>(checker);
                             else
                               run<3>(checker);
                           });
}
