// The equilibrium system's trust region (TrustRegionSystem): the
// truncated CG's solve of the tangent's model and the probe for negative
// curvature, both preconditioned by the tangent projected everywhere.
#include <hyperelastic/equilibrium_system/equilibrium_system.h>

#include <cmath>
#include <limits>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  void
  EquilibriumSystem<dim>::prepare_projected_preconditioner()
  {
    // An AMG built on an indefinite tangent is not positive definite, and
    // truncated CG needs a preconditioner that is: the one of the tangent
    // projected everywhere (a matrix of its own, since ML's finest level
    // refers to the matrix it was built on).
    {
      TimerOutput::Scope scope(parts.timer, "assembly");
      VectorType         unused_rhs(rhs);
      renew_extension();
      assemble_linearization_into(*active_constraints,
                                  extension,
                                  unused_rhs,
                                  TangentProjection::every_point);
    }
    TimerOutput::Scope scope(parts.timer, "preconditioner setup");
    parts.linear_solver.prepare(extension);
  }

  template <int dim>
  bool
  EquilibriumSystem<dim>::has_negative_curvature()
  {
    // The exact tangent at the current iterate (the last linearization
    // was at the iterate before the last update).
    assemble_linearization(false, TangentProjection::none);
    prepare_projected_preconditioner();
    TimerOutput::Scope scope(parts.timer, "linear solve");
    // A fixed pseudo-random right-hand side on the free unknowns: its
    // Krylov space sees every eigenvector (one of the converged residual
    // could be zero, or blind to the unstable mode by symmetry).
    VectorType probe(rhs);
    for (const auto i : owned_dofs)
      {
        const double s = std::sin(12.9898 * static_cast<double>(i) + 4.1414);
        probe(i)       = 43758.5453 * s - std::floor(43758.5453 * s) - 0.5;
      }
    probe.compress(VectorOperation::insert);
    active_constraints->set_zero(probe);
    update = 0.;
    const LinearSolver::TrustRegionSolve probed =
      parts.linear_solver.solve_in_trust_region(
        tangent,
        update,
        probe,
        parts.linear_solver_parameters.relative_tolerance,
        std::numeric_limits<double>::infinity());
    update = 0.;
    return probed.negative_curvature;
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::solve_linearization_in_trust_region(
    const double        forcing,
    const double        radius,
    LinearizationSolve &solve,
    Step               &step)
  {
    prepare_projected_preconditioner();
    TimerOutput::Scope scope(parts.timer, "linear solve");
    const double       tolerance =
      std::max(forcing, parts.linear_solver_parameters.relative_tolerance);
    const VectorType                    &b = constrained_right_hand_side(rhs);
    const LinearSolver::TrustRegionSolve truncated =
      parts.linear_solver.solve_in_trust_region(
        tangent, update, b, tolerance, radius);
    solve.linear_iterations += truncated.iterations;
    active_constraints->distribute(update);
    // The truncated CG's step stays in the trust region: what the system's
    // constraints hold is only removed.
    project_out(u, update);
    step.negative_curvature = truncated.negative_curvature;
    step.on_boundary        = truncated.on_boundary;
    VectorType tangent_update(update);
    tangent.vmult(tangent_update, update);
    step.curvature = update * tangent_update;
    step.norm      = update.l2_norm();
  }

  template void
  EquilibriumSystem<2>::prepare_projected_preconditioner();
  template bool
  EquilibriumSystem<2>::has_negative_curvature();
  template void
  EquilibriumSystem<2>::solve_linearization_in_trust_region(
    double,
    double,
    NonlinearSystem::LinearizationSolve &,
    TrustRegionSystem::Step &);
  template void
  EquilibriumSystem<3>::prepare_projected_preconditioner();
  template bool
  EquilibriumSystem<3>::has_negative_curvature();
  template void
  EquilibriumSystem<3>::solve_linearization_in_trust_region(
    double,
    double,
    NonlinearSystem::LinearizationSolve &,
    TrustRegionSystem::Step &);
} // namespace hyperelastic
