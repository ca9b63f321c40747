// The solvers without the physics (issue 56): a 2-unknown snap-through truss
// implementing only SteppedSystem (NonlinearSystem and load steps), driven by
// the scenes' NewtonSolver and LoadStepper through its snap. The apex
// w = h + u1 of a shallow truss, E_t = a/4 (w^2 - h^2)^2, hangs on a spring k
// to a point moved by the prescribed u2 = -2 h t: E = E_t + k/2 (u1 - u2)^2.
// With k < a h^2 the path u2 = u1 + a w (w^2 - h^2) / k folds back at
// 3 w^2 = h^2 - k / a: Newton fails past it, the stepper cuts back to 1/16 and
// snaps to the far branch. Every converged state is on the analytic path
// (1e-10), on a stable branch.
#include <deal.II/base/mpi.h>

#include <hyperelastic/solvers/load_stepping.h>
#include <hyperelastic/solvers/newton_solver.h>

#include "support/checker.h"

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace hyperelastic;

namespace
{
  constexpr double a = 1., h = 1., k = 0.3;

  class Truss : public SteppedSystem
  {
  public:
    bool
    assemble_linearization(bool impose, TangentProjection projection) override
    {
      du2            = impose ? -2. * h * t - u2 : 0.;
      const double w = h + u1;
      // Projected: the truss's negative stiffness dropped (convexified).
      const double truss     = a * (3. * w * w - h * h);
      const bool   projected = projection == TangentProjection::every_point;
      stiffness              = k + (projected ? std::max(truss, 0.) : truss);
      return du2 != 0.;
    }
    void
    solve_linearization(double, LinearizationSolve &solve) override
    {
      du1 = (-residual(u1, u2) + k * du2) / stiffness; // K du1 - k du2 = -r
      ++solve.linear_iterations;
    }
    TrialPoint
    evaluate_trial(double alpha, TrialCheck check) override
    {
      trial_alpha = alpha;
      TrialPoint   p;
      const double v1 = u1 + alpha * du1, v2 = u2 + alpha * du2, w = h + v1;
      if (check == TrialCheck::energy)
        p.energy =
          a / 4. * std::pow(w * w - h * h, 2) + k / 2. * std::pow(v1 - v2, 2);
      if (check == TrialCheck::residual)
        p.residual = std::abs(residual(v1, v2));
      return p;
    }
    double
    accept_trial() override
    {
      u1 += trial_alpha * du1;
      u2 += trial_alpha * du2;
      scale = std::max({scale, std::abs(u1), std::abs(u2)});
      return trial_alpha * std::hypot(du1, du2);
    }
    ResidualNorms
    residual_norms() override
    {
      const double w = h + u1;
      force_scale    = std::max({force_scale,
                                 std::abs(a * w * (w * w - h * h)),
                                 k * std::abs(u1 - u2)});
      return {std::abs(residual(u1, u2)), force_scale, 1e-15 * force_scale};
    }
    // The toy's trivial parts, one line each (t moves u2 only: displacement
    // control).
    // clang-format off
    Truss() { state_vector.reinit(dealii::complete_index_set(2), MPI_COMM_SELF); }
    Properties properties() const override { Properties p; p.displacement_controlled = true; return p; }
    double largest_feasible_step() override { return 1.; }
    double solution_scale() const override { return scale; }
    void judge_converged_state() override {}
    void set_load_factor(double load_factor) override { t = load_factor; }
    void store_converged_state() override { saved = {{u1, u2}}; }
    void restore_converged_state() override { u1 = saved[0], u2 = saved[1]; }
    double directional_derivative() const override { return residual(u1, u2) * du1; }
    // clang-format on
    const VectorType &
    state() const override
    {
      state_vector(0) = u1;
      state_vector(1) = u2;
      return state_vector;
    }

    static double
    residual(double v1, double v2)
    {
      const double w = h + v1;
      return a * w * (w * w - h * h) + k * (v1 - v2);
    }
    double u1 = 0., u2 = 0.;

  private:
    double t = 0., du1 = 0., du2 = 0., stiffness = 1., trial_alpha = 0.;
    double scale = 0., force_scale = 0.;
    std::array<double, 2> saved{{0., 0.}};
    mutable VectorType    state_vector;
  };
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker(true);
  NewtonParameters                         newton_parameters;
  newton_parameters.max_iterations              = 6;
  newton_parameters.relative_residual_tolerance = 1e-13;
  newton_parameters.inexact                     = false;
  const dealii::ConditionalOStream pcout(std::cout, true);
  const NewtonSolver               newton(newton_parameters, pcout, true);
  Truss                            truss;
  double                           largest_miss = 0., least_k = 1e300;
  unsigned int                     snaps = 0, cut_backs = 0;
  double                           last_w = h, last_t = 0.;
  LoadStepper(LoadSteppingParameters(), 10, pcout)
    .run(newton, truss, [&](const LoadStep &step, const NewtonResult &) {
      const double w = h + truss.u1;
      // On the analytic path at this load factor, on a stable branch.
      const double path = truss.u1 + a * w * (w * w - h * h) / k;
      largest_miss      = std::max({largest_miss,
                                    std::abs(truss.u2 + 2. * h * step.load_factor),
                                    std::abs(truss.u2 - path)});
      least_k           = std::min(least_k, a * (3. * w * w - h * h) + k);
      snaps += (last_w > 0.) != (w > 0.);
      cut_backs += step.cut_backs;
      last_w = w;
      last_t = step.load_factor;
    });
  checker.close("load factor reached", last_t, 1., 1., 1e-14);
  checker.at_most("off the analytic path (largest)", largest_miss, 1e-10);
  checker.above("dr/du1 at the converged states (least)", least_k, 0.);
  checker.close("snaps to the far branch", snaps, 1., 1., 1e-14);
  checker.at_least("cut-backs before the snap step", cut_backs, 4.);
  checker.below("apex at the end (w < -h / sqrt 3)", last_w, -0.57735);
  return checker.exit_code(0);
}
