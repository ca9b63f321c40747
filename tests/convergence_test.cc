// Newton's convergence test (solvers/convergence_test.h) without a mesh:
//   a) the residual target is the largest of the absolute tolerance, the
//      relative tolerance times the force scale and the round-off level;
//   b) issue 41's free fall: gravity and inertia cancel, so the internal and
//      external sums are at round-off. With the inertial forces in the scale
//      and the cancellation of c M (u - w) in the round-off, a residual at
//      round-off is accepted at t = 0.24 and at t = 10 (50 units down),
//      while a residual 100 times the round-off and above the relative
//      target is not;
//   c) a small residual alone does not converge: the update must be small
//      against the run's displacements, and a small update alone does not
//      either.
#include <hyperelastic/solvers/convergence_test.h>

#include "support/checker.h"

#include <cmath>
#include <limits>
#include <iomanip>
#include <sstream>
#include <string>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  Checker checker;

  std::string
  sci(const double x)
  {
    std::ostringstream s;
    s << std::scientific << std::setprecision(2) << x;
    return s.str();
  }

  void
  target()
  {
    NewtonParameters p;
    p.absolute_residual_tolerance = 1e-9;
    p.relative_residual_tolerance = 1e-10;
    const ConvergenceTest test(p);
    checker.close("target: the absolute tolerance when it is largest",
                  test.residual_target({0., 1., 1e-12}),
                  1e-9,
                  1e-9,
                  1e-15);
    checker.close("target: 1e-10 times the force scale when it is largest",
                  test.residual_target({0., 1e3, 1e-12}),
                  1e-7,
                  1e-7,
                  1e-15);
    checker.close("target: the round-off level when it is largest",
                  test.residual_target({0., 1., 3e-8}),
                  3e-8,
                  3e-8,
                  1e-15);
  }

  /// The free fall of issue 41: a 3 x 3 x 3 cube (27 units of mass on 64
  /// nodes) falling under gravity 1 with Newmark, dt = 0.02 (c = 4/h^2 =
  /// 1e4), at time t: the inertial forces' norm m_node g sqrt(64) and the
  /// round-off bound c eps |M| (|u| + |w|) of c M (u - w), |u| ~ |w| ~ t^2/2.
  ResidualNorms
  free_fall_norms(const double t, const double residual)
  {
    const double eps = std::numeric_limits<double>::epsilon();
    const double m_node = 27. / 64., c = 1e4, fall = 0.5 * t * t;
    ResidualNorms norms;
    norms.residual = residual;
    norms.scale    = m_node * 8.; // the inertia term's forces (no others)
    norms.noise    = c * eps * m_node * 2. * fall * 8.;
    return norms;
  }

  void
  free_fall()
  {
    const ConvergenceTest test{NewtonParameters()};
    for (const double t : {0.24, 10.})
      {
        const ResidualNorms at_round_off = free_fall_norms(t, 0.);
        // The table: the residual sat at 3.6e-15 at t = 0.24; at
        // t = 10 round-off is (10 / 0.24)^2 times larger.
        const double observed = 3.6e-15 * std::pow(t / 0.24, 2);
        checker.is_true("free fall, t = " + sci(t) +
                          ": a residual at round-off (" +
                          sci(observed) + ") is converged",
                        test.converged(free_fall_norms(t, observed), 0., 1.));
        const double far =
          100. * std::max(at_round_off.noise, 1e-10 * at_round_off.scale);
        checker.is_true("free fall, t = " + sci(t) +
                          ": a residual 100 times its target (" +
                          sci(far) + ") is not",
                        !test.converged(free_fall_norms(t, far), 0., 1.));
      }
    // Without the inertial scale and round-off (the test before issue 41:
    // the force scale of the cancelled sums only), the t = 10 residual at
    // round-off would have been refused.
    ResidualNorms old = free_fall_norms(10., 3.6e-15 * std::pow(10. / 0.24, 2));
    old.scale         = 1e-14;
    old.noise         = 0.;
    checker.is_true("free fall, t = 10, without the inertial scale and "
                    "round-off: refused (the bug of issue 41)",
                    !test.converged(old, 0., 1.));
  }

  void
  update()
  {
    NewtonParameters p;
    p.update_tolerance = 1e-8;
    const ConvergenceTest test(p);
    const ResidualNorms   small{1e-20, 1., 0.};
    checker.is_true("small residual and update 1e-9 of the displacements: "
                    "converged",
                    test.converged(small, 1e-9, 1.));
    checker.is_true("small residual, update 1e-7 of the displacements: not "
                    "converged",
                    !test.converged(small, 1e-7, 1.));
    checker.is_true("zero update, residual 1e-9 of the forces: not converged",
                    !test.converged({1e-9, 1., 0.}, 0., 1.));
  }
} // namespace

int
main()
{
  target();
  free_fall();
  update();
  return checker.exit_code();
}
