// The discrete equations of a scene as Newton and the load stepper see them:
// the core (NonlinearSystem, SteppedSystem) and the lagged quantities here;
// each other capability in a file of its own under equilibrium_system/
// (trust region, softened predictor, damping, continuation, checkpoint).
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <hyperelastic/assembly/assembly_tools.h>
#include <hyperelastic/equilibrium_system/equilibrium_system.h>
#include <hyperelastic/output/inverted_cell_policy.h>

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
        auto unheld = std::make_unique<UnheldRigidMotions<dim>>(
          parts.mapping,
          parts.dof_handler,
          parts.boundary_conditions.dirichlet_ids(),
          parts.sliding_resisted);
        if (!unheld->empty())
          system_constraints.push_back(std::move(unheld));
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
    // Stiff couplings (touching surfaces): the preconditioner solves on
    // their dofs exactly ('Linear solver/Exact solve on stiff couplings').
    if (parts.linear_solver_parameters.stiff_couplings_solve &&
        elasticity->has_stiff_terms())
      parts.linear_solver.set_stiff_unknowns(
        elasticity->stiff_dofs(tangent.m()));
    predictor_linearization = moves_constraints || moves_terms;
    return predictor_linearization;
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::solve_linearization(const double        forcing,
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
    const VectorType &b = constrained_right_hand_side(rhs);
    solve.linear_iterations +=
      parts.linear_solver.solve(tangent,
                                update,
                                b,
                                tolerance,
                                solve.watch_curvature
                                  ? &solve.negative_curvature
                                  : nullptr);
    // Indefinite: Newton repeats the iteration in a trust region.
    if (solve.negative_curvature)
      return;
    active_constraints->distribute(update);
    constrain_update(tolerance, update, solve.linear_iterations);
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
    properties.trust_region =
      parts.linear_solver.supports_trust_region() && properties.has_potential;
    // Not with system constraints: the damping would hold the rigid motions
    // of unheld bodies, which UnheldRigidMotions pins and projects out of
    // the residual
    // (measured: the frictionless squeezed ball of tests/contact_held.cc
    // drifted, the stacked blocks never reached an equilibrium).
    properties.damping = properties.has_potential && system_constraints.empty();
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
        point.energy       = e.energy;
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
    if (position_noise < 0.)
      position_noise = 1e2 * std::numeric_limits<double>::epsilon() *
                       reference_diameter(parts.dof_handler) *
                       std::sqrt(double(parts.dof_handler.n_dofs()));
    return {norm, force_scale, noise, position_noise};
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
    VectorType free_residual = residual;
    homogeneous_constraints.set_zero(free_residual);
    // The forces along what the system's constraints hold are their
    // reactions.
    project_out(u_ghosted, free_residual);
    return free_residual.l2_norm();
  }

  template <int dim>
  double
  EquilibriumSystem<dim>::solution_scale() const
  {
    return solution_size;
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::judge_converged_state()
  {
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
  }

  template <int dim>
  LaggedUpdate
  EquilibriumSystem<dim>::update_lagged(const LagMoment moment,
                                        const double    unbalanced_force)
  {
    return elasticity->update_lagged(u_ghosted,
                                     current_load_factor,
                                     moment,
                                     unbalanced_force);
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
  void
  EquilibriumSystem<dim>::assemble_linearization_into(
    const AffineConstraints<double> &constraints,
    MatrixType                      &matrix,
    VectorType                      &rhs,
    const TangentProjection          projection)
  {
    elasticity->assemble_system(
      u_ghosted, current_load_factor, constraints, matrix, rhs, projection);
    for (const auto &constraint : system_constraints)
      constraint->regularize(matrix);
  }

  template class EquilibriumSystem<2>;
  template class EquilibriumSystem<3>;
} // namespace hyperelastic
