// The quasi-static driver: load steps over the load factor t in (0, 1], each
// an equilibrium; with 'Load stepping/Predictor = secant' a step starts from
// the last two converged states extrapolated to its load factor.
#pragma once

#include <hyperelastic/dynamics/time_stepping.h>

namespace hyperelastic
{
  template <int dim>
  class QuasiStatic : public TimeStepping<dim>
  {
  public:
    explicit QuasiStatic(const SteppingContext<dim> &context);

    LoadStepper
    stepper(dealii::ConditionalOStream pcout) const override;

    bool
    needs_supports() const override
    {
      return true;
    }

    void
    initialize(const VectorType &) override
    {
    }

    double
    begin_step(double                t,
               const ConvergedState &converged,
               const ConvergedState &previous,
               VectorType           &u,
               VectorType           &u_ghosted) override;

    double
    accept_step(double solved,
                const ConvergedState &,
                VectorType &,
                VectorType &u_ghosted) override
    {
      // A model with history writes the accepted state.
      context.elasticity.accept_material_step(u_ghosted);
      return solved;
    }

    /// No columns of its own: the energy is the total potential.
    void
    add_columns(const ReportedState &, StepSummary<dim> &) override
    {}

    unsigned int
    n_predictions() const override
    {
      return predictions;
    }

  private:
    /// Moves u from the last converged state along its last increment to
    /// load factor @p t, unless an element of the prediction has J <= 0.
    void
    predict(double                t,
            const ConvergedState &converged,
            const ConvergedState &previous,
            VectorType           &u,
            VectorType           &u_ghosted);

    const SteppingContext<dim> context;
    VectorType                 last_increment;
    unsigned int               predictions = 0;
  };
} // namespace hyperelastic
