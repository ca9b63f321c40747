// Newton's convergence test (see the header).
#include <hyperelastic/solvers/convergence_test.h>

#include <algorithm>

namespace hyperelastic
{
  ConvergenceTest::ConvergenceTest(const NewtonParameters &parameters)
      : absolute_tolerance(parameters.absolute_residual_tolerance)
      , relative_tolerance(parameters.relative_residual_tolerance)
      , update_tolerance(parameters.update_tolerance)
  {
  }

  double
  ConvergenceTest::residual_target(const ResidualNorms &norms) const
  {
    return std::max(
      {absolute_tolerance, relative_tolerance * norms.scale, norms.noise});
  }

  bool
  ConvergenceTest::converged(const ResidualNorms &norms,
                             const double         update,
                             const double         solution_scale) const
  {
    return norms.residual <= residual_target(norms) &&
           update <= std::max(update_tolerance * solution_scale,
                              norms.update_noise);
  }
} // namespace hyperelastic
