// The implicit-dynamics driver: inertia and damping terms, the scheme's
// target per step, the end-of-step velocity and acceleration, the motion's
// measures.
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <hyperelastic/dynamics/implicit_dynamics.h>
#include <hyperelastic/loads/boundary_conditions.h>

namespace hyperelastic
{
  template <int dim>
  ImplicitDynamics<dim>::ImplicitDynamics(const SteppingContext<dim> &context)
      : context(context)
      , parameters(context.time_integration)
  {
  }

  template <int dim>
  LoadStepper
  ImplicitDynamics<dim>::stepper(dealii::ConditionalOStream pcout) const
  {
    return LoadStepper(context.load_stepping,
                       parameters.end_time,
                       parameters.time_step,
                       pcout);
  }

  template <int dim>
  void
  ImplicitDynamics<dim>::initialize(const VectorType &u)
  {
    const auto &dof_handler = context.dof_handler;
    // Regions of their own density: the density of each cell.
    std::vector<double> cell_density;
    if (!context.region_densities.empty())
      {
        cell_density.assign(dof_handler.get_triangulation().n_active_cells(),
                            parameters.density);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            cell_density[cell->active_cell_index()] =
              context.region_densities[context.material.region(
                cell->active_cell_index())];
      }
    auto term = std::make_unique<InertiaTerm<dim>>(dof_handler,
                                                   parameters.density,
                                                   parameters.lumped_mass,
                                                   std::move(cell_density));
    inertia   = term.get();
    context.elasticity.add_term(std::move(term));
    if (parameters.stiffness_damping > 0.)
      {
        auto damping =
          std::make_unique<StiffnessDampingTerm<dim>>(dof_handler,
                                                      context.mapping,
                                                      context.material);
        stiffness_damping = damping.get();
        context.elasticity.add_term(std::move(damping));
      }
    integrator = std::make_unique<TimeIntegrator>(parameters.scheme,
                                                  parameters.mass_damping);
    motion =
      std::make_unique<Motion<dim>>(dof_handler, context.mapping, *inertia);
    const dealii::IndexSet &owned = dof_handler.locally_owned_dofs();
    const MPI_Comm          comm  = dof_handler.get_communicator();
    for (VectorType *v : {&velocity,
                          &acceleration,
                          &new_velocity,
                          &new_acceleration,
                          &scratch,
                          &correction})
      v->reinit(owned, comm);
    if (!parameters.initial_velocity.empty())
      {
        const auto v0 =
          parse_vector_function<dim>(parameters.initial_velocity,
                                     context.loading.constants,
                                     "Time integration/Initial velocity");
        v0->set_time(0.);
        dealii::VectorTools::interpolate(context.mapping,
                                         dof_handler,
                                         *v0,
                                         velocity);
      }
    dealii::IndexSet relevant;
    dealii::DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    velocity_ghosted.reinit(owned, relevant, comm);
    velocity_ghosted = velocity;
    if (parameters.scheme == TimeScheme::newmark)
      {
        // M a_0 = f_ext(0) - f_int(u_0) on the free dofs (the inertia term's
        // scale is still 0); supported dofs start at rest.
        // Contact forces are not part of it (they take the whole impulse
        // of each step: time_integrator.h).
        VectorType internal(owned, comm);
        context.elasticity.assemble_forces(u, 0., internal, scratch);
        scratch -= internal;
        if (context.held_terms.present)
          {
            context.elasticity.end_state_forces(u, 0., internal);
            scratch -= internal;
          }
        inertia->solve_mass(scratch,
                            context.homogeneous_constraints,
                            acceleration);
      }
  }

  template <int dim>
  double
  ImplicitDynamics<dim>::begin_step(const double          t,
                                    const ConvergedState &converged,
                                    const ConvergedState &,
                                    VectorType &u,
                                    VectorType &u_ghosted)
  {
    // The step starts from the last converged state (u = u_n).
    step_end_time  = t;
    const double h = t - converged.load_factor;
    double       c = 0.;
    integrator->step_target(h, converged.u, velocity, acceleration, c, scratch);
    inertia->set_step(c, scratch);
    // Newton starts where the step would end if the acceleration stayed
    // a_n: c M (u - w) = M a_n, u = w + a_n / c (backward Euler u_n + h v_n
    // + h^2 a_n, Newmark u_n + h v_n + h^2/2 a_n, midpoint's solved state
    // u_n + h/2 v_n + h^2/4 a_n). A rigid motion under constant forces
    // starts at its answer, however far it has gone (issue 41). With
    // contact the guess could cross an obstacle, and the iterates must
    // stay on its side: frictionless contact starts at u_n; friction takes
    // the guess where all of it is feasible (below, once the end-state map
    // is set), since its first linearization at u_n would be the stiff
    // stick branch of every sliding vertex (zero slip).
    const bool guess = c > 0. && (!context.held_terms.present ||
                                  context.held_terms.start_from_guess);
    if (guess)
      {
        new_velocity = scratch;
        new_velocity.add(1. / c, acceleration);
      }
    if (stiffness_damping)
      {
        double kappa = 0.;
        integrator->velocity_map(h, converged.u, velocity, kappa, scratch);
        stiffness_damping->set_step(parameters.stiffness_damping * kappa,
                                    scratch);
      }
    // Terms held at the end of the step (contact) map the solved state to
    // it: implicit midpoint solves half way.
    const double solved = integrator->evaluation_time(converged.load_factor, t);
    context.elasticity.set_end_state_map(h / (solved - converged.load_factor),
                                         integrator->end_force_weight());
    if (guess)
      start_from_guess(converged, solved, u, u_ghosted);
    // A model with history (viscoelasticity): the step lasts h.
    context.elasticity.begin_material_step(h);
    return solved;
  }

  template <int dim>
  void
  ImplicitDynamics<dim>::start_from_guess(const ConvergedState &converged,
                                          const double          solved,
                                          VectorType           &u,
                                          VectorType           &u_ghosted)
  {
    // new_velocity holds the guess. With contact it is taken only if its
    // whole increment keeps every vertex off the obstacles (moving
    // jointly) and the boundary off itself: a guess cut short would stop
    // vertices just short of the obstacles, deep in the barrier (an
    // impact's acceleration extrapolated), where Newton crawls.
    double fraction = 1.;
    if (context.held_terms.present)
      {
        new_velocity -= converged.u;
        fraction = context.elasticity.largest_feasible_step(converged.u,
                                                            new_velocity,
                                                            solved);
        u = converged.u;
        u += new_velocity;
      }
    else
      u = new_velocity;
    u_ghosted = u;
    // A guess outside the model's domain (a cell inverted by a violent
    // extrapolation) is not taken either.
    if (!(fraction >= 1.) ||
        (!context.material.defined_for_inverted_elements() &&
         !(context.elasticity.evaluate(u_ghosted, solved, false).min_J > 0.)))
      {
        u         = converged.u;
        u_ghosted = u;
        return;
      }
    if (context.held_terms.present)
      {
        context.elasticity.advance(1., solved);
        // Obstacle friction's normal forces and tangents are taken at the
        // guess rather than at u_n: Newton starts there, and fewer updates
        // follow (self contact keeps those of u_n).
        context.elasticity.update_lagged(u_ghosted,
                                         solved,
                                         LagMoment::predicted,
                                         0.);
      }
  }

  template <int dim>
  double
  ImplicitDynamics<dim>::accept_step(const double          solved,
                                     const ConvergedState &converged,
                                     VectorType           &u,
                                     VectorType           &u_ghosted)
  {
    // The accepted state is the end state: the terms evaluate it as it is.
    context.elasticity.set_end_state_map(1., 1.);
    if (!converged.valid)
      return solved;
    // The step from converged (t_n, u_n) to its end (implicit midpoint: from
    // the solved midpoint state): new u, v and a.
    integrator->end_state(converged.u, u);
    u_ghosted = u;
    integrator->finish_step(step_end_time - converged.load_factor,
                            converged.u,
                            velocity,
                            acceleration,
                            u,
                            new_velocity,
                            new_acceleration);
    if (integrator->end_force_weight() != 1. && context.held_terms.present)
      {
        // Newmark: the acceleration kept is that of the forces other than
        // contact, which took the step's whole impulse (time_integrator.h).
        context.elasticity.end_state_forces(u_ghosted, step_end_time, scratch);
        if (scratch.linfty_norm() > 0.)
          {
            inertia->solve_mass(scratch,
                                context.homogeneous_constraints,
                                correction);
            new_acceleration.add(-integrator->end_force_weight(), correction);
          }
      }
    velocity.swap(new_velocity);
    acceleration.swap(new_acceleration);
    velocity_ghosted = velocity;
    context.elasticity.accept_material_step(u_ghosted);
    return step_end_time;
  }

  template <int dim>
  void
  ImplicitDynamics<dim>::add_columns(const ReportedState &state,
                                     StepSummary<dim>    &s)
  {
    const VectorType &u_ghosted = state.u;
    // Potential energy without the step's inertia and damping terms; kinetic
    // energy and momenta of the converged motion.
    s.energy -= inertia->energy(u_ghosted, s.load_factor);
    if (stiffness_damping)
      s.energy -= stiffness_damping->energy(u_ghosted, s.load_factor);
    const MotionMeasures m = motion->measure(u_ghosted, velocity_ghosted);
    s.dynamic              = true;
    s.kinetic_energy       = m.kinetic_energy;
    s.linear_momentum      = m.linear_momentum;
    s.angular_momentum     = m.angular_momentum;
  }

  template <int dim>
  bool
  ImplicitDynamics<dim>::writes_fields(const unsigned int step,
                                       const double       t) const
  {
    return step % parameters.output_every == 0 || t >= parameters.end_time;
  }

  template class ImplicitDynamics<2>;
  template class ImplicitDynamics<3>;
} // namespace hyperelastic
