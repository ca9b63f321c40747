// Finite-strain viscoelasticity (issue 29; materials/viscoelasticity.h) on
// the confined bar [0,3] x [0,1] (x [0,1]): rollers on every face, the end
// x = 3 moved, so F = diag(l(t), 1, 1) exactly (plane strain: F33 = 1) and
// the end reaction is P11 = l (S_eq11 + sum_j Q_j11). The equilibrium model
// is Yeoh with C10 = 1/2 alone (decoupled neo-Hookean, mu = 1, kappa = 5),
// whose isochoric stress is written out here:
//   S_iso11 = mu J^(-2/3) (1 - I1 / (3 l^2)),  S_vol11 = kappa/2 (J^2 - 1)
//   / l^2,  J = l, I1 = l^2 + 2.
//   viscoelasticity DIM relaxation  the stretch l = 1.4 applied in the
//       first of N = 10, 20, 40 load steps and held (one process, beta =
//       1.5, tau = 0.5, quasi-static duration 1): the long-term reaction
//       (beta = 0) and the first step's overstress l beta exp(-dt/(2 tau))
//       S_iso11 (1e-10), the decay after the first step exactly
//       exp(-(t_n - t_1)/tau) (1e-10), and the error against the exact
//       relaxation l beta exp(-t/tau) S_iso11 at t = 1 falling at order 1
//       in dt (the midpoint factor of the jump);
//   viscoelasticity DIM relaxation mixed  the same with the mixed
//       formulation (P1-bubble/P1, kappa = 5): the same numbers;
//   viscoelasticity DIM relaxation incompressible  Bulk modulus = inf,
//       lateral faces free: the reaction relaxes as (1 + beta g
//       exp(-(t - t1)/tau)) times the long-term P11 of the incompressible
//       bar (1e-10);
//   viscoelasticity DIM cut_back    two processes, the lateral faces free,
//       the stretch ramped to 1.4 over t in [0, 0.3] and held, Newton
//       limited to 4 iterations so that steps are cut back: every accepted
//       step's reaction and lateral stretch equal the recursion of the
//       issue over the accepted steps, with the lateral stretch solved here
//       from S22 = 0 (1e-10), so a rejected attempt leaves nothing in the
//       history.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using namespace hyperelastic;
  using namespace hyperelastic::testing;

  constexpr double mu = 1., kappa = 5., stretch = 1.4;

  double
  isochoric_S11(const double l)
  {
    const double J = l, I1 = l * l + 2.;
    return mu * std::pow(J, -2. / 3.) * (1. - I1 / (3. * l * l));
  }

  double
  equilibrium_P11(const double l)
  {
    const double J = l;
    return l * (isochoric_S11(l) + 0.5 * kappa * (J * J - 1.) / (l * l));
  }

  /// How the bar is modelled: the displacement formulation, confined; the
  /// mixed one (P1-bubble/P1), confined; the mixed one with Bulk modulus =
  /// inf, the lateral faces free but for the symmetry rollers y = 0, z = 0.
  enum class Variant
  {
    displacement,
    mixed,
    incompressible,
    lateral_free ///< the displacement formulation, lateral faces free
  };

  Variant
  variant(const std::string &name)
  {
    if (name.empty() || name == "displacement")
      return Variant::displacement;
    if (name == "mixed")
      return Variant::mixed;
    if (name == "incompressible")
      return Variant::incompressible;
    throw InputError("unknown variant '" + name + "'");
  }

  /// The bar with the end displacement @p end (an expression of t), the
  /// Prony series @p weights / @p times, @p steps load steps.
  template <int dim>
  std::string
  confined_bar(const std::string &end,
               const std::string &weights,
               const std::string &times,
               const unsigned int steps,
               const std::string &newton = "",
               const Variant      how    = Variant::displacement)
  {
    const bool three    = dim == 3;
    const bool confined = how == Variant::displacement || how == Variant::mixed;
    const bool mixed    = how == Variant::mixed || how == Variant::incompressible;
    return subsection("Problem",
                      entry("Dimension", std::to_string(dim)) +
                        entry("Formulation",
                              mixed ? "mixed" : "displacement")) +
           subsection("Mesh",
                      entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                        entry("Upper corner", three ? "3, 1, 1" : "3, 1") +
                        entry("Subdivisions", three ? "3, 1, 1" : "6, 2")) +
           subsection("Material",
                      entry("Model", "Yeoh") +
                        subsection("Yeoh",
                                   entry("C10", "0.5") +
                                     entry("Bulk modulus",
                                           how == Variant::incompressible
                                             ? "inf"
                                             : "5")) +
                        subsection("Viscoelasticity",
                                   entry("Weights", weights) +
                                     entry("Relaxation times", times))) +
           subsection("Loading",
                      entry("Number of load steps", std::to_string(steps))) +
           tight_solver("direct") + newton + dirichlet(1, 0, "x", "0") +
           dirichlet(2, 1, "x", end) + dirichlet(3, 2, "y", "0") +
           (confined ? dirichlet(4, 3, "y", "0") : "") +
           (three ? dirichlet(5, 4, "z", "0") +
                      (confined ? dirichlet(6, 5, "z", "0") : "")
                  : "") +
           subsection("Output", entry("Write VTU", "false"));
  }

  template <int dim>
  void
  relaxation(Checker &checker, const Variant how)
  {
    const std::string tag =
      std::to_string(dim) + "D relaxation" +
      (how == Variant::mixed ? " (mixed formulation)" : "") + ": ";
    const double      beta = 1.5, tau = 0.5;
    const std::string end   = std::to_string(3. * (stretch - 1.));
    const double      R_inf = equilibrium_P11(stretch);
    {
      const auto elastic =
        run_scene<dim>(confined_bar<dim>(end, "0", "0.5", 10, "", how));
      checker.close(tag + "beta = 0: reaction = long-term P11",
                    column(elastic->summaries().back(), "reaction_1_x"),
                    R_inf,
                    std::abs(R_inf),
                    1e-10);
    }
    std::vector<double> errors;
    for (const unsigned int steps : {10u, 20u, 40u})
      {
        const std::string run = tag + std::to_string(steps) + " steps, ";
        const auto        problem =
          run_scene<dim>(confined_bar<dim>(end, "1.5", "0.5", steps, "", how));
        const auto  &rows  = problem->summaries();
        const double dt    = 1. / steps;
        const double first = column(rows.front(), "reaction_1_x") - R_inf;
        checker.is_true(run + "reaches t = 1", rows.back().load_factor == 1.);
        checker.close(run + "first step's overstress l beta g S_iso11",
                      first,
                      stretch * beta * std::exp(-0.5 * dt / tau) *
                        isochoric_S11(stretch),
                      std::abs(first),
                      1e-10);
        double decay = 0.;
        for (const auto &row : rows)
          decay =
            std::max(decay,
                     std::abs((column(row, "reaction_1_x") - R_inf) / first -
                              std::exp(-(row.load_factor - dt) / tau)));
        checker.at_most(run + "decay after the first step = exp(-(t - t1)/tau)",
                        decay,
                        1e-10);
        const double exact =
          stretch * beta * std::exp(-1. / tau) * isochoric_S11(stretch);
        errors.push_back(
          std::abs(column(rows.back(), "reaction_1_x") - R_inf - exact));
      }
    for (unsigned int i = 1; i < errors.size(); ++i)
      {
        const double rate = std::log2(errors[i - 1] / errors[i]);
        checker.at_least(tag + "order in dt of the overstress at t = 1",
                         rate,
                         0.95);
        checker.at_most(tag + "order in dt of the overstress at t = 1",
                        rate,
                        1.05);
      }
  }

  /// Incompressible (mixed formulation, Bulk modulus = inf), lateral faces
  /// free: F = diag(l, l^-1/2, l^-1/2) (plane strain diag(l, 1/l)) is held
  /// after the first step, so every Q_j stays proportional to S_iso and the
  /// end reaction is (1 + beta g exp(-(t - t1)/tau)) times the long-term
  /// one, whatever the pressure that keeps J = 1.
  template <int dim>
  void
  incompressible(Checker &checker)
  {
    const std::string tag =
      std::to_string(dim) + "D relaxation, incompressible (mixed): ";
    const double      beta = 1.5, tau = 0.5, dt = 0.1;
    const std::string end = std::to_string(3. * (stretch - 1.));
    const auto        elastic = run_scene<dim>(
      confined_bar<dim>(end, "0", "0.5", 10, "", Variant::incompressible));
    const auto viscous = run_scene<dim>(
      confined_bar<dim>(end, "1.5", "0.5", 10, "", Variant::incompressible));
    const auto &rows_inf = elastic->summaries();
    const auto &rows     = viscous->summaries();
    checker.is_true(tag + "both reach t = 1",
                    rows.back().load_factor == 1. &&
                      rows_inf.back().load_factor == 1.);
    const double R_inf = column(rows_inf.back(), "reaction_1_x");
    // The long-term reaction of the incompressible neo-Hookean bar: P11 =
    // mu (l - l^-2) in 3D, mu (l - l^-3) in plane strain, over a unit area.
    const double l = stretch;
    checker.close(tag + "long-term reaction = incompressible P11",
                  R_inf,
                  dim == 3 ? mu * (l - 1. / (l * l)) : mu * (l - 1. / (l * l * l)),
                  std::abs(R_inf),
                  1e-10);
    checker.is_true(tag + "same steps", rows.size() == rows_inf.size());
    double worst = 0.;
    for (const auto &row : rows)
      worst = std::max(
        worst,
        std::abs(column(row, "reaction_1_x") / R_inf - 1. -
                 beta * std::exp(-0.5 * dt / tau) *
                   std::exp(-(row.load_factor - dt) / tau)));
    checker.at_most(tag + "reaction / long-term - 1 = beta g "
                          "exp(-(t - t1)/tau) at every step",
                    worst,
                    1e-10);
  }

  /// The bar with its lateral faces free (symmetry rollers y = 0, z = 0):
  /// F = diag(l, a, a) (plane strain diag(l, a, 1)) with the lateral
  /// stretch a from S22 = 0, which the test solves itself per step:
  /// S22 = S_iso22 + S_vol22 + sum_j Q_j22 with, for the neo-Hookean
  /// equilibrium part (mu = 1, kappa = 5),
  ///   S_iso = mu J^(-2/3) (I - I1/3 C^-1),  S_vol = kappa/2 (J^2 - 1) C^-1,
  /// every tensor diagonal, and each Q_j from the recursion of the issue.
  template <int dim>
  struct FreeBar
  {
    /// Diagonal of S_iso at (l, a).
    static std::array<double, 2>
    isochoric(const double l, const double a)
    {
      const double n  = dim == 3 ? 2. : 1.; // lateral stretches equal to a
      const double J  = l * std::pow(a, n);
      const double I1 = l * l + n * a * a + (dim == 3 ? 0. : 1.);
      const double c  = mu * std::pow(J, -2. / 3.);
      return {{c * (1. - I1 / (3. * l * l)), c * (1. - I1 / (3. * a * a))}};
    }

    static std::array<double, 2>
    volumetric(const double l, const double a)
    {
      const double J = l * std::pow(a, dim == 3 ? 2. : 1.);
      const double s = 0.5 * kappa * (J * J - 1.);
      return {{s / (l * l), s / (a * a)}};
    }
  };

  template <int dim>
  void
  cut_back(Checker &checker)
  {
    const std::string tag     = std::to_string(dim) + "D cut-back: ";
    const double      beta[2] = {1., 0.5}, tau[2] = {0.1, 0.8};
    const std::string end = "1.2*min(1, t/0.3)";
    const std::string scene = confined_bar<dim>(
      end,
      "1, 0.5",
      "0.1, 0.8",
      4,
      subsection("Newton", entry("Max iterations", "4")),
      Variant::lateral_free);
    const auto   problem   = run_scene<dim>(scene);
    const auto  &rows      = problem->summaries();
    double       cut_backs = 0.;
    for (const auto &row : rows)
      cut_backs += column(row, "cut_backs");
    checker.is_true(tag + "reaches t = 1", rows.back().load_factor == 1.);
    checker.at_least(tag + "cut-backs", cut_backs, 1.);
    // The recursion over the accepted steps, with the lateral stretch of
    // each solved here by bisection.
    const auto l_of = [](const double t) {
      return 1. + 0.4 * std::min(1., t / 0.3);
    };
    std::array<double, 2> Q[2] = {{{0., 0.}}, {{0., 0.}}}, S = {{0., 0.}};
    double t = 0., worst = 0., worst_a = 0.;
    for (const auto &row : rows)
      {
        const double dt = row.load_factor - t;
        t               = row.load_factor;
        const double l  = l_of(t);
        double       g[2];
        for (int j = 0; j < 2; ++j)
          g[j] = std::exp(-0.5 * dt / tau[j]);
        // S22 of the step at lateral stretch a.
        const auto S22 = [&](const double a) {
          const auto iso = FreeBar<dim>::isochoric(l, a);
          double     s   = iso[1] + FreeBar<dim>::volumetric(l, a)[1];
          for (int j = 0; j < 2; ++j)
            s += g[j] * g[j] * Q[j][1] - g[j] * beta[j] * S[1] +
                 g[j] * beta[j] * iso[1];
          return s;
        };
        double lo = 0.5, hi = 1.5;
        for (int k = 0; k < 200; ++k)
          {
            const double mid = 0.5 * (lo + hi);
            (S22(mid) > 0. ? hi : lo) = mid;
          }
        const double a     = 0.5 * (lo + hi);
        const auto   S_new = FreeBar<dim>::isochoric(l, a);
        double       S11   = S_new[0] + FreeBar<dim>::volumetric(l, a)[0];
        for (int j = 0; j < 2; ++j)
          {
            for (int c = 0; c < 2; ++c)
              Q[j][c] = g[j] * g[j] * Q[j][c] - g[j] * beta[j] * S[c] +
                        g[j] * beta[j] * S_new[c];
            S11 += Q[j][0];
          }
        S = S_new;
        // Reaction on the end face (reference area 1) and the lateral
        // extent a (the face y = 1 moves to y = a).
        const double expect = l * S11;
        worst               = std::max(worst,
                         std::abs(column(row, "reaction_1_x") - expect) /
                           std::abs(expect));
        worst_a = std::max(worst_a,
                           std::abs(column(row, "deformed_max_y") - a));
      }
    checker.note(tag + std::to_string(rows.size()) + " accepted steps");
    checker.at_most(tag + "every step's reaction = the recursion over the "
                          "accepted steps",
                    worst,
                    1e-10);
    checker.at_most(tag + "every step's lateral stretch = the recursion's",
                    worst_a,
                    1e-10);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_for_dimension(
    argc, argv, 1, [&](const int dim, Checker &checker, bool) {
      const std::string name = argc > 2 ? argv[2] : "";
      const Variant     how  = variant(argc > 3 ? argv[3] : "");
      if (name == "relaxation" && how == Variant::incompressible)
        dim == 2 ? incompressible<2>(checker) : incompressible<3>(checker);
      else if (name == "relaxation")
        dim == 2 ? relaxation<2>(checker, how) : relaxation<3>(checker, how);
      else if (name == "cut_back")
        dim == 2 ? cut_back<2>(checker) : cut_back<3>(checker);
      else
        throw InputError("unknown case '" + name + "'");
    });
}
