// Newton's tangent policy (solvers/tangent_policy.h) without a mesh:
//   a) the exact and the projected tangents: always none, always
//      every_point, and no fallback;
//   b) exact then projected: exact first, the projected tangent after a
//      failure, and the failure of the projected one is final;
//   c) the automatic tangent: projected where J <= 0 in the first iteration
//      of a solve and while the residual is above 1e-3 times the first
//      residual of the solve, exact at and below it; the escalation
//      none -> inverted_points -> every_point, then final failure; only it
//      asks for the softened predictor;
//   d) projecting at inverted points counts only once the iterate has
//      min J <= 0 (and not while min J is unknown).
#include <hyperelastic/solvers/tangent_policy.h>

#include "support/checker.h"

#include <cmath>
#include <limits>
#include <optional>
#include <string>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  Checker checker;

  const double nan = std::numeric_limits<double>::quiet_NaN();

  std::string
  name(const TangentProjection projection)
  {
    switch (projection)
      {
        case TangentProjection::none:
          return "none";
        case TangentProjection::inverted_points:
          return "inverted_points";
        case TangentProjection::every_point:
          return "every_point";
      }
    return "?";
  }

  /// The projections a policy tries in one iteration that fails every
  /// time, from @p start: "none -> inverted_points -> ... -> final".
  std::string
  escalation(const TangentPolicy &policy, const TangentProjection start)
  {
    std::string                      sequence = name(start);
    std::optional<TangentProjection> next     = policy.fallback(start);
    // Four steps at most: a longer sequence is wrong anyway.
    for (unsigned int i = 0; next && i < 4; ++i)
      {
        sequence += " -> " + name(*next);
        next = policy.fallback(*next);
      }
    return sequence + (next ? " -> ..." : " -> final");
  }

  /// Checks that @p policy chooses @p expected (its name) for
  /// (@p first_of_solve, @p residual, @p first_residual).
  void
  check_projection(const std::string      &what,
                   const TangentPolicy    &policy,
                   const bool              first_of_solve,
                   const double            residual,
                   const double            first_residual,
                   const TangentProjection expected)
  {
    const TangentProjection chosen =
      policy.projection(first_of_solve, residual, first_residual);
    if (!checker.is_true(what + ": " + name(expected), chosen == expected))
      checker.note("chose " + name(chosen));
  }

  void
  check_escalation(const std::string      &what,
                   const TangentPolicy    &policy,
                   const TangentProjection start,
                   const std::string      &expected)
  {
    const std::string sequence = escalation(policy, start);
    if (!checker.is_true(what + ": " + expected, sequence == expected))
      checker.note("got " + sequence);
  }

  void
  exact_and_projected()
  {
    checker.section("exact and projected tangents");
    const TangentPolicy exact(NewtonTangent::exact);
    check_projection(
      "exact, first iteration", exact, true, nan, nan, TangentProjection::none);
    check_projection("exact, residual at the first one",
                     exact,
                     false,
                     1.,
                     1.,
                     TangentProjection::none);
    check_escalation("exact: no fallback",
                     exact,
                     TangentProjection::none,
                     "none -> final");
    checker.is_true("exact: no softened predictor",
                    !exact.softens_inverting_predictor());

    const TangentPolicy projected(NewtonTangent::projected);
    check_projection("projected, first iteration",
                     projected,
                     true,
                     nan,
                     nan,
                     TangentProjection::every_point);
    check_projection("projected, near the solution",
                     projected,
                     false,
                     1e-12,
                     1.,
                     TangentProjection::every_point);
    check_escalation("projected: failure is final",
                     projected,
                     TangentProjection::every_point,
                     "every_point -> final");
    checker.is_true("projected: no softened predictor",
                    !projected.softens_inverting_predictor());
  }

  void
  exact_then_projected()
  {
    checker.section("exact then projected");
    const TangentPolicy policy(NewtonTangent::exact_then_projected);
    check_projection("first iteration",
                     policy,
                     true,
                     nan,
                     nan,
                     TangentProjection::none);
    check_projection("far from the solution",
                     policy,
                     false,
                     1.,
                     1.,
                     TangentProjection::none);
    check_escalation("a failed exact iteration is repeated projected",
                     policy,
                     TangentProjection::none,
                     "none -> every_point -> final");
    checker.is_true("no softened predictor",
                    !policy.softens_inverting_predictor());
  }

  void
  automatic()
  {
    checker.section("automatic tangent");
    const TangentPolicy policy(NewtonTangent::automatic);
    checker.close("the switch ratio",
                  NewtonParameters::automatic_switch_ratio,
                  1e-3,
                  1e-3,
                  1e-14);
    check_projection("first iteration of a solve (residual unknown)",
                     policy,
                     true,
                     nan,
                     nan,
                     TangentProjection::inverted_points);
    check_projection("first iteration of a lagged solve, residual small",
                     policy,
                     true,
                     1e-12,
                     1.,
                     TangentProjection::inverted_points);
    check_projection("residual 1.1e-3 of the first: still far",
                     policy,
                     false,
                     0.22,
                     200.,
                     TangentProjection::inverted_points);
    check_projection("residual 0.9e-3 of the first: near, exact",
                     policy,
                     false,
                     0.18,
                     200.,
                     TangentProjection::none);
    check_projection("residual exactly 1e-3 of the first: exact",
                     policy,
                     false,
                     0.25,
                     250.,
                     TangentProjection::none);
    check_projection("residual unknown after the first iteration: exact",
                     policy,
                     false,
                     nan,
                     1.,
                     TangentProjection::none);
    check_escalation("escalation from the exact tangent",
                     policy,
                     TangentProjection::none,
                     "none -> inverted_points -> every_point -> final");
    check_escalation("escalation from projecting where J <= 0",
                     policy,
                     TangentProjection::inverted_points,
                     "inverted_points -> every_point -> final");
    check_escalation("projected everywhere: failure is final",
                     policy,
                     TangentProjection::every_point,
                     "every_point -> final");
    checker.is_true("asks for the softened predictor",
                    policy.softens_inverting_predictor());
  }

  void
  inverted_points()
  {
    checker.section("projecting where J <= 0");
    using P = TangentPolicy;
    const auto inverted = TangentProjection::inverted_points;
    checker.is_true("min J = -0.1: projects where inverted",
                    P::projects_where_inverted(inverted, -0.1));
    checker.is_true("min J = 0: projects where inverted",
                    P::projects_where_inverted(inverted, 0.));
    checker.is_true("min J = 0.2: nothing to project",
                    !P::projects_where_inverted(inverted, 0.2));
    checker.is_true("min J unknown (first iteration): nothing to project",
                    !P::projects_where_inverted(inverted, nan));
    checker.is_true("exact tangent, min J = -1: does not project",
                    !P::projects_where_inverted(TangentProjection::none, -1.));
    checker.is_true(
      "every point, min J = -1: not 'where inverted'",
      !P::projects_where_inverted(TangentProjection::every_point, -1.));
    checker.is_true("projects somewhere: every point, min J = 0.5",
                    P::projects_somewhere(TangentProjection::every_point, 0.5));
    checker.is_true("projects somewhere: inverted points, min J = -0.5",
                    P::projects_somewhere(inverted, -0.5));
    checker.is_true("projects nowhere: inverted points, min J = 0.5",
                    !P::projects_somewhere(inverted, 0.5));
    checker.is_true("projects nowhere: exact tangent, min J = -0.5",
                    !P::projects_somewhere(TangentProjection::none, -0.5));
  }
} // namespace

int
main()
{
  exact_and_projected();
  exact_then_projected();
  automatic();
  inverted_points();
  return checker.exit_code();
}
