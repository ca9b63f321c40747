// The driver of a scene's steps: over the load factor (quasi-static, with the
// optional secant predictor) or over time (implicit dynamics: inertia and
// damping terms, the scheme, velocity and acceleration, kinetic energy and
// momenta). Problem calls these hooks and never asks which scheme runs;
// quasi-static is the trivial driver.
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/assembly/material_regions.h>
#include <hyperelastic/base/linear_algebra.h>
#include <hyperelastic/dynamics/time_integration_parameters.h>
#include <hyperelastic/loads/loading_parameters.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/output/checkpoint_file.h>
#include <hyperelastic/output/step_reporter.h>
#include <hyperelastic/output/step_summary.h>
#include <hyperelastic/solvers/load_stepping.h>
#include <hyperelastic/solvers/load_stepping_parameters.h>

#include <memory>

namespace hyperelastic
{
  /// A converged state: the last one (to return to after a failed step) or
  /// the one before it (the secant predictor's other point).
  struct ConvergedState
  {
    VectorType u;
    double     force_scale   = 0.;
    double     solution_size = 0.;
    double     load_factor   = 0.;
    bool       valid         = false;
  };

  /// What a driver must know of the operator's terms held at the end of a
  /// step (SteppedTerm and MovingAdmissibleSetTerm: the barrier terms).
  struct HeldTerms
  {
    /// There are such terms: they keep every state feasible (a step's
    /// guess must too), and their forces take the step's whole impulse
    /// (time_integrator.h).
    bool present = false;
    /// Their lagged quantities would be linearized on their stiff branch
    /// at u_n (a sliding vertex's zero slip): a step starts from the
    /// dynamics guess where it is feasible. Otherwise, with such terms, a
    /// step starts at u_n.
    bool start_from_guess = false;
  };

  /// What a driver works on; everything is owned by Problem and outlives
  /// the driver.
  template <int dim>
  struct SteppingContext
  {
    /// The scheme, or quasi-static ('Time integration').
    const TimeIntegrationParameters &time_integration;
    /// The step control ('Load stepping').
    const LoadSteppingParameters &load_stepping;
    /// The number of load steps and the expressions' constants ('Loading').
    const LoadingParameters &loading;
    /// The terms held at the end of a step.
    const HeldTerms held_terms;
    /// The time a quasi-static load path takes for a model with history
    /// ('Material/Viscoelasticity').
    const double                   quasi_static_duration;
    const dealii::DoFHandler<dim> &dof_handler;
    const dealii::Mapping<dim>    &mapping;
    /// The model of each cell.
    const MaterialRegions<dim> material;
    ElasticityOperator<dim>   &elasticity;
    /// The homogeneous Dirichlet constraints (the free dofs).
    const dealii::AffineConstraints<double> &homogeneous_constraints;
    /// The run's phase timer (the predictor has a phase of its own).
    dealii::TimerOutput &timer;
    /// Regions: the mass density of each (region 0, the top-level
    /// Material's cells, first); empty: 'Time integration/Density'
    /// everywhere.
    std::vector<double> region_densities = {};
  };

  /// A driver also reports (StepReporter): its columns of a converged step
  /// (the energy without its own terms; in dynamics the kinetic energy and
  /// momenta) and its nodal fields (the velocity).
  template <int dim>
  class TimeStepping : public StepReporter<dim>
  {
  public:
    virtual ~TimeStepping() = default;

    /// The steps: "Load step k" over t in (0, 1], or "Time step k" up to
    /// the end time.
    virtual LoadStepper
    stepper(dealii::ConditionalOStream pcout) const = 0;

    /// Whether the problem needs supports to be regular (quasi-static: the
    /// rigid-body motions are free without a Dirichlet condition).
    virtual bool
    needs_supports() const = 0;

    /// Sets the start up at the initial displacement @p u (ghosted): adds
    /// the driver's terms to the operator, the initial velocity and
    /// acceleration. Called once, after the operator exists.
    virtual void
    initialize(const VectorType &u) = 0;

    /// Begins the step to @p t from the last converged state (and the one
    /// before it); may move the iterate @p u (and @p u_ghosted with it) to a
    /// prediction. Returns the load factor the step's equations are solved
    /// at (the midpoint for implicit midpoint).
    virtual double
    begin_step(double                t,
               const ConvergedState &converged,
               const ConvergedState &previous,
               VectorType           &u,
               VectorType           &u_ghosted) = 0;

    /// Whether every step is one linear solve ('Linearize once per step').
    virtual bool
    linear_steps() const
    {
      return false;
    }

    /// Ends the converged step solved at load factor @p solved from
    /// @p converged: the end state replaces @p u (and @p u_ghosted) where it
    /// differs from the solved one. Returns the end's load factor or time.
    /// Also called at the start, with @p converged not yet valid.
    virtual double
    accept_step(double                solved,
                const ConvergedState &converged,
                VectorType           &u,
                VectorType           &u_ghosted) = 0;

    /// Whether converged step @p step at @p t writes the fields.
    virtual bool
    writes_fields(unsigned int step, double t) const
    {
      (void)step, (void)t;
      return true;
    }

    /// How many steps started from an (admissible) prediction.
    virtual unsigned int
    n_predictions() const
    {
      return 0;
    }

    /// The driver's state beyond the displacement (a checkpoint): the
    /// velocity and acceleration in dynamics.
    virtual void
    save_state(StateBlob &blob) const
    {
      (void)blob;
    }

    /// Restores what save_state() wrote.
    virtual void
    load_state(StateBlob &blob)
    {
      (void)blob;
    }
  };

  /// The scene's driver: quasi-static or implicit dynamics
  /// ('Time integration/Scheme').
  template <int dim>
  std::unique_ptr<TimeStepping<dim>>
  create_time_stepping(const SteppingContext<dim> &context);
} // namespace hyperelastic
