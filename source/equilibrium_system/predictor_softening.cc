// The equilibrium system's softened predictor (PredictorSoftening): the
// constraint increment extended at zero Poisson's ratio where the tangent's
// own predictor would invert cells.
#include <hyperelastic/assembly/rest_stiffness.h>
#include <hyperelastic/equilibrium_system/equilibrium_system.h>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  bool
  EquilibriumSystem<dim>::soften_predictor(unsigned int &linear_iterations)
  {
    linear_iterations = 0;
    if (active_constraints != &increment_constraints ||
        !parts.material.defined_for_inverted_elements() ||
        parts.dof_handler.get_fe().n_components() != dim ||
        !properties().has_potential)
      return false;
    const double J_now = evaluate_trial(0., TrialCheck::admissibility).min_J;
    const TrialPoint predicted = evaluate_trial(1., TrialCheck::energy);
    if (!(J_now > 0. && predicted.min_J <= 0.))
      return false;

    // The increment extended with linear elasticity at rest, lambda = 0.
    VectorType tangent_update(update), extension_rhs(rhs);
    {
      TimerOutput::Scope scope(parts.timer, "assembly");
      LameParameters     zero_poisson;
      zero_poisson.mu = parts.material.top().small_strain_moduli().mu;
      renew_extension();
      assemble_rest_system(parts.dof_handler,
                           parts.mapping,
                           zero_poisson,
                           increment_constraints,
                           extension,
                           extension_rhs);
    }
    {
      TimerOutput::Scope scope(parts.timer, "preconditioner setup");
      parts.linear_solver.prepare(extension);
    }
    {
      TimerOutput::Scope scope(parts.timer, "linear solve");
      update            = 0.;
      linear_iterations = parts.linear_solver.solve(
        extension,
        update,
        extension_rhs,
        parts.linear_solver_parameters.relative_tolerance);
      increment_constraints.distribute(update);
    }
    // Both updates meet the same prescribed values, so their energies
    // compare: the extension is kept only where it starts lower.
    const TrialPoint extended = evaluate_trial(1., TrialCheck::energy);
    if (extended.energy < predicted.energy)
      return true;
    update = tangent_update;
    return false;
  }

  template bool
  EquilibriumSystem<2>::soften_predictor(unsigned int &);
  template bool
  EquilibriumSystem<3>::soften_predictor(unsigned int &);
} // namespace hyperelastic
