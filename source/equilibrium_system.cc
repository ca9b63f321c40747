// The discrete equations of a scene as Newton and the load stepper see them.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <hyperelastic/assembly/rest_stiffness.h>
#include <hyperelastic/dynamics/inertia.h>
#include <hyperelastic/equilibrium_system.h>
#include <hyperelastic/solvers/inverted_cell_policy.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  EquilibriumSystem<dim>::EquilibriumSystem(const Parts &parts)
      : parts(parts)
      , comm(parts.dof_handler.get_communicator())
      , owned_dofs(parts.dof_handler.locally_owned_dofs())
  {
    DoFTools::extract_locally_relevant_dofs(parts.dof_handler, relevant_dofs);
    parts.boundary_conditions.make_constraints(parts.mapping,
                                               parts.dof_handler,
                                               relevant_dofs,
                                               0.,
                                               u_ghosted,
                                               true,
                                               homogeneous_constraints);

    build_tangent_sparsity();

    for (VectorType *v : {&u,
                          &update,
                          &trial,
                          &rhs,
                          &internal_force,
                          &external_force,
                          &residual,
                          &converged.u,
                          &previous.u})
      v->reinit(owned_dofs, comm);
    u_ghosted.reinit(owned_dofs, relevant_dofs, comm);
    const IndexSet pressures =
      parts.formulation.pressure_dofs(parts.dof_handler);
    if (Utilities::MPI::max(pressures.n_elements(), comm) > 0)
      {
        displacement_mask.reinit(owned_dofs, comm);
        for (const auto i : owned_dofs)
          if (!pressures.is_element(i))
            displacement_mask(i) = 1.;
        displacement_mask.compress(VectorOperation::insert);
      }
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::build_tangent_sparsity()
  {
    // All couplings, constrained dofs included: the P1 kernel relies on
    // every node pair having a full dim x dim block in the matrix. The load
    // terms add theirs (self-contact pairs) on their owned rows.
    DynamicSparsityPattern dsp(relevant_dofs);
    DoFTools::make_sparsity_pattern(parts.dof_handler, dsp);
    if (elasticity)
      elasticity->add_couplings(dsp);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               owned_dofs,
                                               comm,
                                               relevant_dofs);
    // The new matrix is built while the old one still exists: it gets
    // another address, by which the assembler's cached entry positions and
    // the preconditioner know they belong to the old one.
    const MatrixType old(std::move(tangent));
    tangent.reinit(owned_dofs, owned_dofs, dsp, comm);
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::renew_extension()
  {
    const MatrixType old(std::move(extension));
    extension.reinit(tangent);
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::attach(ElasticityOperator<dim> &elasticity,
                                 TimeStepping<dim>       &stepping)
  {
    this->elasticity = &elasticity;
    this->stepping   = &stepping;
    // Quasi-static, the bodies no Dirichlet condition holds rest on contact
    // (the supports check let them through only then).
    if (stepping.needs_supports())
      {
        unheld = std::make_unique<UnheldRigidMotions<dim>>(
          parts.mapping,
          parts.dof_handler,
          parts.boundary_conditions.dirichlet_ids(),
          parts.frictional);
        if (unheld->empty())
          unheld.reset();
      }
  }

  // ------------------------------------------------------ NonlinearSystem
  template <int dim>
  bool
  EquilibriumSystem<dim>::assemble_linearization(
    const bool              impose_constraint_increment,
    const TangentProjection projection)
  {
    bool moves_constraints = false;
    if (impose_constraint_increment)
      {
        TimerOutput::Scope scope(parts.timer, "Dirichlet values");
        // Prescribed minus current values: after a shortened step the next
        // linearization carries what is still missing.
        parts.boundary_conditions.make_constraints(parts.mapping,
                                                   parts.dof_handler,
                                                   relevant_dofs,
                                                   current_load_factor,
                                                   u_ghosted,
                                                   false,
                                                   increment_constraints);
        double largest = 0.;
        for (const auto &line : increment_constraints.get_lines())
          largest = std::max(largest, std::abs(line.inhomogeneity));
        moves_constraints = Utilities::MPI::max(largest, comm) > 0.;
      }
    // A load term's admissible set on its way (an obstacle moving within
    // the step) makes this iteration a predictor too: the linearization
    // carries the rest of its motion.
    const bool moves_terms = elasticity->prepare_motion(current_load_factor);
    // Self-contact pairs between distant parts of the boundary couple dofs
    // the mesh does not: the tangent's sparsity grows with them (the
    // preconditioner is then built anew for the new matrix).
    if (elasticity->needs_new_couplings(u_ghosted, current_load_factor))
      {
        TimerOutput::Scope scope(parts.timer, "contact sparsity");
        build_tangent_sparsity();
      }
    TimerOutput::Scope scope(parts.timer, "assembly");
    // The update of this linearization must satisfy these constraints.
    active_constraints =
      moves_constraints ? &increment_constraints : &homogeneous_constraints;
    assemble_linearization_into(*active_constraints, tangent, rhs, projection);
    predictor_linearization = moves_constraints || moves_terms;
    return predictor_linearization;
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::solve_linearization(const double forcing,
                                              const bool   soften_predictor,
                                              LinearizationSolve &solve)
  {
    {
      TimerOutput::Scope scope(parts.timer, "preconditioner setup");
      parts.linear_solver.prepare(tangent);
    }
    TimerOutput::Scope scope(parts.timer, "linear solve");
    double             tolerance =
      std::max(forcing, parts.linear_solver_parameters.relative_tolerance);
    // A linear problem takes this one solve, and no Newton iteration
    // follows to correct it: it also meets Newton's relative residual
    // tolerance where that is the tighter one.
    if (properties().linear && forcing == 0.)
      tolerance = std::min(tolerance, parts.newton.relative_residual_tolerance);
    update = 0.;
    // The pinned motions' forces are their pins' reactions: the update
    // answers the rest of the residual.
    const VectorType &b = unheld ? pinned_right_hand_side(rhs) : rhs;
    solve.linear_iterations +=
      parts.linear_solver.solve(tangent,
                                update,
                                b,
                                tolerance,
                                solve.watch_curvature && supports_trust_region()
                                  ? &solve.negative_curvature
                                  : nullptr);
    // Indefinite: Newton repeats the iteration in a trust region.
    if (solve.negative_curvature)
      return;
    active_constraints->distribute(update);
    if (unheld)
      constrain_to_pins(tolerance, update, solve.linear_iterations);
    if (soften_predictor)
      {
        unsigned int extension_iterations = 0;
        const bool softened = soften_inverting_predictor(extension_iterations);
        solve.linear_iterations += extension_iterations;
        solve.softened_predictor = softened;
      }
  }

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
  bool
  EquilibriumSystem<dim>::supports_trust_region() const
  {
    return parts.linear_solver.supports_trust_region() &&
           properties().has_potential;
  }

  template <int dim>
  const VectorType &
  EquilibriumSystem<dim>::pinned_right_hand_side(const VectorType &b)
  {
    unheld->pin_unresisted(u, tangent, b, force_scale);
    pinned_rhs = b;
    unheld->project_out_pinned(u, pinned_rhs);
    return pinned_rhs;
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::constrain_to_pins(const double  tolerance,
                                            VectorType   &x,
                                            unsigned int &iterations)
  {
    unheld->constrain_update(
      u,
      [&](const VectorType &v, VectorType &z) {
        z = 0.;
        iterations += parts.linear_solver.solve(tangent, z, v, tolerance);
        homogeneous_constraints.distribute(z);
      },
      x);
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::solve_linearization_in_trust_region(
    const double        forcing,
    const double        radius,
    LinearizationSolve &solve,
    TrustRegionStep    &step)
  {
    prepare_projected_preconditioner();
    TimerOutput::Scope scope(parts.timer, "linear solve");
    const double       tolerance =
      std::max(forcing, parts.linear_solver_parameters.relative_tolerance);
    const VectorType &b = unheld ? pinned_right_hand_side(rhs) : rhs;
    const LinearSolver::TrustRegionSolve truncated =
      parts.linear_solver.solve_in_trust_region(
        tangent, update, b, tolerance, radius);
    solve.linear_iterations += truncated.iterations;
    active_constraints->distribute(update);
    // The truncated CG's step stays in the trust region: the pinned
    // components are only removed.
    if (unheld)
      unheld->project_out_pinned(u, update);
    step.negative_curvature = truncated.negative_curvature;
    step.on_boundary        = truncated.on_boundary;
    VectorType tangent_update(update);
    tangent.vmult(tangent_update, update);
    step.curvature = update * tangent_update;
    step.norm      = update.l2_norm();
  }

  template <int dim>
  NonlinearSystem::Properties
  EquilibriumSystem<dim>::properties() const
  {
    Properties properties;
    // 'Linearize once per step' treats each time step as linear: one full
    // step is accepted.
    properties.linear = parts.material.is_linear() || stepping->linear_steps();
    // Without one (a saddle point, forces without an energy, a load without
    // a potential) the line search tests the residual norm.
    properties.has_potential =
      elasticity->is_conservative() && parts.formulation.has_potential();
    if (!parts.formulation.has_potential())
      properties.why_no_potential = parts.formulation.why_no_potential();
    const BoundaryConditions<dim> &loads = parts.boundary_conditions;
    properties.displacement_controlled =
      properties.has_potential && loads.boundary_loads.empty() &&
      loads.point_loads.empty() && !loads.body_force;
    return properties;
  }

  template <int dim>
  double
  EquilibriumSystem<dim>::directional_derivative() const
  {
    // rhs = -(f_int - f_ext) on the free rows (zero on constrained rows,
    // where the update is zero too).
    return -(rhs * update);
  }

  template <int dim>
  bool
  EquilibriumSystem<dim>::soften_inverting_predictor(
    unsigned int &linear_iterations)
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

  template <int dim>
  double
  EquilibriumSystem<dim>::largest_feasible_step()
  {
    return elasticity->largest_feasible_step(u, update, current_load_factor);
  }

  template <int dim>
  TrialPoint
  EquilibriumSystem<dim>::evaluate_trial(const double     alpha,
                                         const TrialCheck check)
  {
    TimerOutput::Scope scope(parts.timer, "line search");
    trial = u;
    trial.add(alpha, update);
    // Along a Newton direction (not a predictor's, whose obstacles and
    // prescribed values move with it), the terms may project the trial
    // (lagged friction: no slip reversed across its stick zone).
    if (alpha > 0. && !predictor_linearization)
      elasticity->project_trial(u,
                                trial,
                                current_load_factor,
                                *active_constraints);
    u_ghosted   = trial;
    step_length = alpha;

    TrialPoint point;
    if (check == TrialCheck::none)
      return point;
    if (check == TrialCheck::residual)
      {
        point.residual = free_residual_norm(point.residual_noise);
        point.min_J =
          elasticity->evaluate(u_ghosted, current_load_factor, false).min_J;
        point.admissible = (parts.material.defined_for_inverted_elements() ||
                            point.min_J > 0.) &&
                           std::isfinite(point.residual);
        return point;
      }
    const EnergyEvaluation e =
      elasticity->evaluate(u_ghosted,
                           current_load_factor,
                           check == TrialCheck::energy);
    point.min_J = e.min_J;
    if (check == TrialCheck::energy)
      {
        point.energy = e.energy;
        if (damping.active())
          point.energy += damping.energy(u_ghosted);
        point.energy_noise = e.noise;
      }
    point.admissible =
      (parts.material.defined_for_inverted_elements() || e.min_J > 0.) &&
      (check != TrialCheck::energy || std::isfinite(e.energy));
    return point;
  }

  template <int dim>
  double
  EquilibriumSystem<dim>::accept_trial()
  {
    u             = trial;
    solution_size = std::max(solution_size, u.l2_norm());
    elasticity->advance(step_length, current_load_factor);
    return step_length * update.l2_norm();
  }

  template <int dim>
  ResidualNorms
  EquilibriumSystem<dim>::residual_norms()
  {
    TimerOutput::Scope scope(parts.timer, "residual");
    double             noise;
    const double       norm = free_residual_norm(noise);
    // The sizes of forces that cancel in the sum count too: in a free fall
    // gravity and inertia cancel, and the relative test measures the
    // residual against them (issue 41).
    force_scale = std::max({force_scale,
                            internal_force.l2_norm(),
                            external_force.l2_norm(),
                            force_size.magnitude});
    return {norm, force_scale, noise};
  }

  template <int dim>
  double
  EquilibriumSystem<dim>::residual_target() const
  {
    return ConvergenceTest(parts.newton)
      .residual_target({0., force_scale, force_size.round_off});
  }

  template <int dim>
  double
  EquilibriumSystem<dim>::free_residual_norm(double &noise)
  {
    force_size = elasticity->assemble_forces(u_ghosted,
                                             current_load_factor,
                                             internal_force,
                                             external_force);
    noise      = force_size.round_off;
    residual   = internal_force;
    residual -= external_force;
    if (damping.active())
      damping.add_forces(u_ghosted, residual);
    VectorType free_residual = residual;
    homogeneous_constraints.set_zero(free_residual);
    // The pinned rigid motions' forces are their pins' reactions.
    if (unheld)
      unheld->project_out_pinned(u_ghosted, free_residual);
    return free_residual.l2_norm();
  }

  template <int dim>
  double
  EquilibriumSystem<dim>::solution_scale() const
  {
    return solution_size;
  }

  template <int dim>
  NonlinearSystem::Verdict
  EquilibriumSystem<dim>::judge_converged_state(const bool update_lagged)
  {
    if (update_lagged &&
        elasticity->update_lagged(u_ghosted,
                                  current_load_factor,
                                  LagMoment::converged) ==
          LaggedUpdate::updated)
      return Verdict::continue_iterating;
    // Accepted with a warning, or rejected, by the scene's policy.
    const InvertedCells<dim> inverted =
      find_inverted_cells(parts.mapping, parts.dof_handler, u_ghosted);
    min_J          = inverted.min_J;
    inverted_cells = inverted.n_cells;
    judge_inverted_cells(inverted,
                         parts.newton,
                         parts.material_model,
                         parts.material.defined_for_inverted_elements(),
                         parts.pcout);
    return Verdict::accepted;
  }

  template <int dim>
  LaggedUpdate
  EquilibriumSystem<dim>::update_lagged()
  {
    return elasticity->update_lagged(u_ghosted,
                                     current_load_factor,
                                     LagMoment::within_solve);
  }

  // ------------------------------------------------------- SteppedSystem
  template <int dim>
  void
  EquilibriumSystem<dim>::set_load_factor(const double t)
  {
    // The terms' step state starts at the last converged one (before the
    // driver's predictor, which is checked against it).
    elasticity->begin_step(converged.u, converged.load_factor);
    if (previous.valid && previous.load_factor < converged.load_factor)
      elasticity->extrapolate_lagged(previous.u, previous.load_factor);
    current_load_factor =
      stepping->begin_step(t, converged, previous, u, u_ghosted);
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::store_converged_state()
  {
    current_load_factor =
      stepping->accept_step(current_load_factor, converged, u, u_ghosted);
    // The last converged state becomes the one before (the vectors swap;
    // no copy), then the current one is stored.
    std::swap(previous, converged);
    converged.valid         = true;
    converged.load_factor   = current_load_factor;
    converged.u             = u;
    converged.force_scale   = force_scale;
    converged.solution_size = solution_size;
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::restore_converged_state()
  {
    // The scales too: a diverging attempt must not loosen the tests of the
    // next one.
    u             = converged.u;
    u_ghosted     = u;
    force_scale   = converged.force_scale;
    solution_size = converged.solution_size;
  }

  template <int dim>
  bool
  EquilibriumSystem<dim>::supports_damping() const
  {
    // Not with unheld bodies: the damping would hold their rigid motions,
    // which UnheldRigidMotions pins and projects out of the residual
    // (measured: the frictionless squeezed ball of tests/contact_held.cc
    // drifted, the stacked blocks never reached an equilibrium).
    return properties().has_potential && !unheld;
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::set_damping(const double c)
  {
    if (!damping.initialized())
      {
        // The lumped mass of unit density (HRZ: diagonal, so its product
        // with ones is its diagonal) on the free displacement unknowns.
        const InertiaTerm<dim> mass(parts.dof_handler, 1., true);
        VectorType             ones(owned_dofs, comm), metric(owned_dofs, comm);
        ones = 1.;
        VectorType ones_ghosted(owned_dofs, relevant_dofs, comm);
        ones_ghosted = ones;
        mass.mass_product(ones_ghosted, metric);
        homogeneous_constraints.set_zero(metric);
        damping.initialize(metric);
      }
    damping.set(c, u);
  }

  template <int dim>
  double
  EquilibriumSystem<dim>::damping_force()
  {
    return damping.active() ? damping.force_norm(u) : 0.;
  }

  template <int dim>
  double
  EquilibriumSystem<dim>::damping_scale()
  {
    set_damping(0.);
    restore_converged_state();
    // At the converged state's own load factor (an obstacle at the next
    // one may be inside the body there).
    const double t      = current_load_factor;
    current_load_factor = converged.load_factor;
    assemble_tangent();
    current_load_factor = t;
    return damping.stiffness_ratio(tangent);
  }

  // ---------------------------------------------------------- checkpoint
  template <int dim>
  void
  EquilibriumSystem<dim>::save_state(StateBlob &blob) const
  {
    for (const ConvergedState *state : {&converged, &previous})
      {
        blob.put(state->valid ? 1. : 0.);
        blob.put(state->load_factor);
        blob.put(state->force_scale);
        blob.put(state->solution_size);
        if (state->valid)
          blob.put_owned(state->u);
      }
    stepping->save_state(blob);
    blob.put(elasticity->material_history());
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::load_state(StateBlob &blob)
  {
    for (ConvergedState *state : {&converged, &previous})
      {
        state->valid         = blob.get_double() != 0.;
        state->load_factor   = blob.get_double();
        state->force_scale   = blob.get_double();
        state->solution_size = blob.get_double();
        if (state->valid)
          {
            state->u.reinit(owned_dofs, comm);
            blob.get_owned(state->u);
          }
      }
    current_load_factor = converged.load_factor;
    restore_converged_state();
    stepping->load_state(blob);
    elasticity->restore_material_history(blob.get_doubles());
  }

  // -------------------------------------------------- ContinuationSystem
  template <int dim>
  void
  EquilibriumSystem<dim>::set_state(const VectorType &v, const double t)
  {
    current_load_factor = t;
    u                   = v;
    u_ghosted           = u;
    // The prescribed entries at their values at t: the constraints of the
    // increment from the current values, applied to a zero vector, give it.
    parts.boundary_conditions.make_constraints(parts.mapping,
                                               parts.dof_handler,
                                               relevant_dofs,
                                               t,
                                               u_ghosted,
                                               false,
                                               increment_constraints);
    VectorType increment(owned_dofs, comm);
    increment_constraints.distribute(increment);
    u += increment;
    u_ghosted = u;
  }

  template <int dim>
  ResidualNorms
  EquilibriumSystem<dim>::free_residual(VectorType &r)
  {
    const ResidualNorms norms = residual_norms();
    r                         = residual;
    homogeneous_constraints.set_zero(r);
    if (unheld)
      unheld->project_out_pinned(u_ghosted, r);
    return norms;
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::load_derivative(VectorType &r_t)
  {
    // Central differences in t at fixed free unknowns (exact to round-off
    // for loads linear in t).
    const VectorType at(u);
    const double     t = current_load_factor;
    const double     h = 1e-6 * std::max(1., std::abs(t));
    double           noise;
    set_state(at, t + h);
    free_residual_norm(noise);
    r_t = residual;
    set_state(at, t - h);
    free_residual_norm(noise);
    r_t -= residual;
    r_t *= 0.5 / h;
    homogeneous_constraints.set_zero(r_t);
    set_state(at, t);
    free_residual_norm(noise);
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::assemble_tangent()
  {
    TimerOutput::Scope scope(parts.timer, "assembly");
    active_constraints = &homogeneous_constraints;
    assemble_linearization_into(homogeneous_constraints,
                                tangent,
                                rhs,
                                TangentProjection::none);
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::assemble_linearization_into(
    const AffineConstraints<double> &constraints,
    MatrixType                      &matrix,
    VectorType                      &rhs,
    const TangentProjection          projection)
  {
    elasticity->assemble_system(
      u_ghosted, current_load_factor, constraints, matrix, rhs, projection);
    if (damping.active())
      damping.add_to_system(u_ghosted, matrix, rhs);
    if (unheld)
      unheld->regularize(matrix);
  }

  template <int dim>
  unsigned int
  EquilibriumSystem<dim>::solve_tangent(const VectorType &b, VectorType &x)
  {
    {
      TimerOutput::Scope scope(parts.timer, "preconditioner setup");
      parts.linear_solver.prepare(tangent);
    }
    TimerOutput::Scope scope(parts.timer, "linear solve");
    x                             = 0.;
    const unsigned int iterations = parts.linear_solver.solve(
      tangent,
      x,
      unheld ? pinned_right_hand_side(b) : b,
      parts.linear_solver_parameters.relative_tolerance);
    homogeneous_constraints.distribute(x);
    unsigned int pinning_iterations = 0;
    if (unheld)
      constrain_to_pins(parts.linear_solver_parameters.relative_tolerance,
                        x,
                        pinning_iterations);
    return iterations + pinning_iterations;
  }

  template <int dim>
  double
  EquilibriumSystem<dim>::path_product(const VectorType &a,
                                       const VectorType &b) const
  {
    if (displacement_mask.size() == 0)
      return a * b;
    VectorType masked(a);
    masked.scale(displacement_mask);
    return masked * b;
  }

  template class EquilibriumSystem<2>;
  template class EquilibriumSystem<3>;
} // namespace hyperelastic
