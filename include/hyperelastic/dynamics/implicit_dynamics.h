// The implicit-dynamics driver ('Time integration/Scheme' other than
// quasi-static): time steps up to the end time; the inertia term (and the
// stiffness damping term) added to the operator, the scheme's target set at
// the start of every step, velocity and acceleration updated after it, the
// kinetic energy and momenta in the summary, the velocity in the fields.
#pragma once

#include <hyperelastic/dynamics/inertia.h>
#include <hyperelastic/dynamics/motion.h>
#include <hyperelastic/dynamics/stiffness_damping.h>
#include <hyperelastic/dynamics/time_integrator.h>
#include <hyperelastic/dynamics/time_stepping.h>

#include <memory>

namespace hyperelastic
{
  template <int dim>
  class ImplicitDynamics : public TimeStepping<dim>
  {
  public:
    explicit ImplicitDynamics(const SteppingContext<dim> &context);

    LoadStepper
    stepper(dealii::ConditionalOStream pcout) const override;

    /// The mass makes the problem regular without supports.
    bool
    needs_supports() const override
    {
      return false;
    }

    void
    initialize(const VectorType &u) override;

    double
    begin_step(double                t,
               const ConvergedState &converged,
               const ConvergedState &previous,
               VectorType           &u,
               VectorType           &u_ghosted) override;

    bool
    linear_steps() const override
    {
      return context.time_integration.linearize_once;
    }

    double
    accept_step(double                solved,
                const ConvergedState &converged,
                VectorType           &u,
                VectorType           &u_ghosted) override;

    /// The potential energy without the step's inertia and damping terms,
    /// the kinetic energy and the momenta.
    void
    add_columns(const ReportedState &state, StepSummary<dim> &summary) override;

    /// Every 'Output every' steps and the last one.
    bool
    writes_fields(unsigned int step, double t) const override;

    /// The velocity.
    void
    add_nodal_fields(const ReportedState &,
                     std::vector<NodalField> &fields) override
    {
      fields.push_back({"velocity", &velocity_ghosted});
    }

    void
    save_state(StateBlob &blob) const override
    {
      blob.put_owned(velocity);
      blob.put_owned(acceleration);
    }

    void
    load_state(StateBlob &blob) override
    {
      blob.get_owned(velocity);
      blob.get_owned(acceleration);
      velocity_ghosted = velocity;
    }

  private:
    /// Starts Newton at the guess held in new_velocity (the step's end at
    /// constant acceleration), with contact only if all of it is feasible; at u_n if the guess inverts a cell of a model undefined
    /// there. @p solved: the time the step is solved at.
    void
    start_from_guess(const ConvergedState &converged,
                     double                solved,
                     VectorType           &u,
                     VectorType           &u_ghosted);

    const SteppingContext<dim>       context;
    const TimeIntegrationParameters &parameters;
    /// Owned by the operator.
    InertiaTerm<dim> *inertia = nullptr;
    /// 'Time integration/Stiffness damping' > 0 only (owned by the
    /// operator).
    StiffnessDampingTerm<dim>      *stiffness_damping = nullptr;
    std::unique_ptr<TimeIntegrator> integrator;
    std::unique_ptr<Motion<dim>>    motion;
    /// Of the last converged state.
    VectorType velocity, acceleration;
    VectorType new_velocity, new_acceleration, scratch;
    /// Newmark: M^-1 times the contact forces at the end of a step.
    VectorType correction;
    /// The velocity with ghost entries (momenta and fields).
    VectorType velocity_ghosted;
    /// The end of the time step being solved (the load factor is the time
    /// the equations are solved at: the midpoint for implicit midpoint).
    double step_end_time = 0.;
  };
} // namespace hyperelastic
