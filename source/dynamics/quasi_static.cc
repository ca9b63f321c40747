// The quasi-static driver: the load stepper over t in (0, 1] and the secant
// predictor.
#include <hyperelastic/dynamics/quasi_static.h>

#include <algorithm>

namespace hyperelastic
{
  template <int dim>
  QuasiStatic<dim>::QuasiStatic(const SteppingContext<dim> &context)
      : context(context)
  {
  }

  template <int dim>
  LoadStepper
  QuasiStatic<dim>::stepper(dealii::ConditionalOStream pcout) const
  {
    return LoadStepper(context.load_stepping,
                       context.loading.n_load_steps,
                       pcout);
  }

  template <int dim>
  double
  QuasiStatic<dim>::begin_step(const double          t,
                               const ConvergedState &converged,
                               const ConvergedState &previous,
                               VectorType           &u,
                               VectorType           &u_ghosted)
  {
    if (context.load_stepping.secant_predictor && previous.valid &&
        !context.material.is_linear())
      predict(t, converged, previous, u, u_ghosted);
    // A model with history (viscoelasticity): the step lasts its increment
    // times the scene's quasi-static duration.
    context.elasticity.begin_material_step((t - converged.load_factor) *
                                           context.quasi_static_duration);
    return t;
  }

  template <int dim>
  void
  QuasiStatic<dim>::predict(const double          t,
                            const ConvergedState &converged,
                            const ConvergedState &previous,
                            VectorType           &u,
                            VectorType           &u_ghosted)
  {
    const double increment = converged.load_factor - previous.load_factor;
    if (!(increment > 0.))
      return;
    dealii::TimerOutput::Scope scope(context.timer, "predictor");
    // u = u_n + (t - t_n) / (t_n - t_n-1) (u_n - u_n-1); the prescribed
    // displacements are extrapolated too, and the first Newton iteration
    // imposes whatever of them is still missing.
    last_increment = converged.u;
    last_increment -= previous.u;
    last_increment *= (t - converged.load_factor) / increment;
    // Obstacles move with the prediction, from their place at t_n to the
    // one at t: a prediction that would cross one is shortened (and the
    // obstacles stop as far along their way).
    const double feasible = std::min(
      1.,
      context.elasticity.largest_feasible_step(converged.u, last_increment, t));
    u = converged.u;
    u.add(feasible, last_increment);
    u_ghosted = u;
    if (!(feasible > 0.) ||
        !(context.elasticity.evaluate(u_ghosted, t, false).min_J > 0.))
      {
        u         = converged.u;
        u_ghosted = u;
        return;
      }
    context.elasticity.advance(feasible, t);
    ++predictions;
  }

  template class QuasiStatic<2>;
  template class QuasiStatic<3>;
} // namespace hyperelastic
