// Newton's convergence test, on its own so that it can be read and tested
// without a mesh: the residual on the free unknowns must be small (in
// absolute terms, relative to the forces of the run, or at the round-off
// level of its own evaluation) and the last update small relative to the
// displacements of the run.
//
// Both scales know a dynamic step: the force scale includes the inertial
// forces (in a free fall they cancel gravity, so internal and external sums
// alone would be tiny), and the round-off includes the cancellation inside
// c M (u - w), which grows with the distance travelled (issue 41).
#pragma once

#include <hyperelastic/solvers/newton_parameters.h>

namespace hyperelastic
{
  /// Norms of the residual at the current iterate.
  struct ResidualNorms
  {
    double residual; ///< on the free (unconstrained) unknowns
    /// Size of the forces of the run so far, for the relative test (a
    /// running maximum, so that it does not vanish when loads are removed):
    /// the internal and external force vectors and the terms whose forces
    /// cancel in their sum (inertia).
    double scale;
    /// Round-off level of the residual (stiff materials: lambda ln J
    /// computed near J = 1; inertia: c M (u - w) of large u and w):
    /// residuals below it count as zero.
    double noise = 0.;
    /// Round-off level of the unknowns (for a displacement: a hundred
    /// machine epsilons of the body's size per unknown, in the l2 norm):
    /// an update below it counts as zero, also where the solution itself
    /// stays at rest (a confined body growing, a body prestressed at rest),
    /// which the relative update test cannot measure against.
    double update_noise = 0.;
  };

  class ConvergenceTest
  {
  public:
    explicit ConvergenceTest(const NewtonParameters &parameters);

    /// The residual norm the test asks for: the largest of the absolute
    /// tolerance, the relative tolerance times the force scale, and the
    /// round-off level.
    double
    residual_target(const ResidualNorms &norms) const;

    /// Whether an iterate is converged: its residual is at most
    /// residual_target() and the last update (norm @p update) is at most
    /// the update tolerance times @p solution_scale, the largest
    /// displacement norm of the run. Both are needed: with small forces
    /// (soft materials, small bodies) a residual test alone would accept
    /// an unconverged state.
    bool
    converged(const ResidualNorms &norms,
              double               update,
              double               solution_scale) const;

  private:
    const double absolute_tolerance;
    const double relative_tolerance;
    const double update_tolerance;
  };
} // namespace hyperelastic
