// The discrete equations of a scene as the Newton solver and the load stepper
// see them (a SteppedSystem): the iterate u and the line search's trial
// points, the Dirichlet constraints of the current linearization, the tangent
// and its solve, Newton's force and displacement scales, the converged
// states to return to after a failed step, and the verdict on inverted cells
// at a converged state. What a step solves (its load factor, inertia,
// predictor) comes from the time-stepping driver; Problem builds all parts
// and reads the converged state for the summary and the output.
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/assembly/material_regions.h>
#include <hyperelastic/dynamics/time_stepping.h>
#include <hyperelastic/formulation/formulation.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/solvers/convergence_test.h>
#include <hyperelastic/solvers/linear_solver.h>
#include <hyperelastic/solvers/linear_solver_parameters.h>
#include <hyperelastic/solvers/damped_system.h>
#include <hyperelastic/solvers/load_stepping.h>
#include <hyperelastic/solvers/newton_parameters.h>
#include <hyperelastic/solvers/snap_damping.h>
#include <hyperelastic/solvers/unheld_rigid_motions.h>

#include <memory>
#include <string>

namespace hyperelastic
{
  template <int dim>
  class EquilibriumSystem : public SteppedSystem, public DampedSystem
  {
  public:
    /// The parts the system works on, owned by Problem (they outlive it).
    struct Parts
    {
      /// Newton's tolerances and its policy on inverted cells ('Newton').
      const NewtonParameters &newton;
      /// The linear solves' relative tolerance ('Linear solver').
      const LinearSolverParameters &linear_solver_parameters;
      /// 'Material/Model', named in the verdict on inverted cells.
      const std::string             &material_model;
      const dealii::DoFHandler<dim> &dof_handler;
      const dealii::Mapping<dim>    &mapping;
      /// The model of each cell.
      const MaterialRegions<dim>     material;
      const BoundaryConditions<dim> &boundary_conditions;
      const Formulation<dim>        &formulation;
      LinearSolver                  &linear_solver;
      dealii::TimerOutput           &timer;
      dealii::ConditionalOStream     pcout;
      /// Whether a contact has friction (which resists the rigid motions
      /// along the contact surfaces of the bodies it holds, however
      /// weakly; see UnheldRigidMotions).
      bool frictional = false;
    };

    /// The constraints, the tangent's sparsity and the vectors (u = 0).
    /// Collective.
    explicit EquilibriumSystem(const Parts &parts);

    /// Completes the system with the operator and the driver, which must
    /// outlive it.
    void
    attach(ElasticityOperator<dim> &elasticity, TimeStepping<dim> &stepping);

    /// The homogeneous Dirichlet constraints (the free dofs).
    const dealii::AffineConstraints<double> &
    free_dofs() const
    {
      return homogeneous_constraints;
    }

    /// The last evaluated state (after convergence: the converged one),
    /// with ghost entries.
    const VectorType &
    solution() const
    {
      return u_ghosted;
    }

    /// f_int - f_ext at the last residual evaluation (owned entries): at a
    /// converged state, the support forces on the Dirichlet dofs.
    const VectorType &
    residual_forces() const
    {
      return residual;
    }

    /// The tangent matrix of the last linearization.
    const MatrixType &
    tangent_matrix() const
    {
      return tangent;
    }

    /// The load factor (or time) of the current state.
    double
    load_factor() const
    {
      return current_load_factor;
    }

    /// Smallest J at the last converged state, and the number of cells with
    /// J <= 0 there (non-zero only when such states are accepted).
    double
    converged_min_J() const
    {
      return min_J;
    }
    dealii::types::global_cell_index
    converged_inverted_cells() const
    {
      return inverted_cells;
    }

    // NonlinearSystem
    bool
    assemble_linearization(bool              impose_constraint_increment,
                           TangentProjection projection) override;
    void
    solve_linearization(double              forcing,
                        bool                soften_predictor,
                        LinearizationSolve &solve) override;
    bool
    supports_trust_region() const override;
    bool
    has_negative_curvature() override;
    void
    solve_linearization_in_trust_region(double              forcing,
                                        double              radius,
                                        LinearizationSolve &solve,
                                        TrustRegionStep    &step) override;
    Properties
    properties() const override;
    double
    directional_derivative() const override;
    double
    largest_feasible_step() override;
    TrialPoint
    evaluate_trial(double alpha, TrialCheck check) override;
    double
    accept_trial() override;
    ResidualNorms
    residual_norms() override;
    double
    solution_scale() const override;
    Verdict
    judge_converged_state(bool update_lagged) override;
    LaggedUpdate
    update_lagged() override;

    // SteppedSystem
    void
    set_load_factor(double t) override;
    void
    store_converged_state() override;
    void
    restore_converged_state() override;

    // DampedSystem: the lumped mass of unit density on the free unknowns
    // (SnapDamping), with a potential only.
    bool
    supports_damping() const override;
    void
    set_damping(double c) override;
    double
    damping_force() override;
    double
    damping_scale() override;

    /// What a restart needs (a checkpoint): the last converged state and
    /// the one before it (the secant predictor's), the driver's state and
    /// the materials' history.
    void
    save_state(StateBlob &blob) const;

    /// Restores what save_state() wrote: the system is then at the
    /// checkpoint's converged state. Collective.
    void
    load_state(StateBlob &blob);

    // ContinuationSystem
    void
    set_state(const VectorType &u, double t) override;
    const VectorType &
    state() const override
    {
      return u;
    }
    ResidualNorms
    free_residual(VectorType &r) override;
    void
    load_derivative(VectorType &r_t) override;
    void
    assemble_tangent() override;
    unsigned int
    solve_tangent(const VectorType &b, VectorType &x) override;
    double
    path_product(const VectorType &a, const VectorType &b) const override;

  private:
    /// The predictor's update inverts cells of a state without inverted
    /// ones (a large prescribed increment, the tangent's linear extension
    /// far outside its range: the one-step crush): the increment extended
    /// with linear elasticity at zero Poisson's ratio at rest (which moves
    /// a clamped block's interior with its ends instead of bulging it
    /// through itself) replaces it if its energy is lower. Displacement
    /// formulation, models defined at J <= 0, with a potential. Called by
    /// solve_linearization() when asked to; returns whether it replaced the
    /// update, @p linear_iterations gets the Krylov iterations spent on
    /// trying.
    bool
    soften_inverting_predictor(unsigned int &linear_iterations);
    /// Assembles the tangent projected everywhere at the current iterate
    /// into `extension` and prepares the linear solver's preconditioner on
    /// it: positive, as truncated CG needs, where the tangent is not.
    void
    prepare_projected_preconditioner();
    /// Assembles the forces at u_ghosted into internal_force, external_force
    /// and residual; returns the residual norm on the free unknowns and its
    /// round-off level in @p noise.
    double
    free_residual_norm(double &noise);
    /// The residual Newton's convergence test asks for at the last
    /// residual evaluation.
    double
    residual_target() const;

    /// Pins the unresisted rigid motions of the unheld bodies (at u, from
    /// the tangent and the right-hand side @p b) and returns @p b without
    /// its components along them (in pinned_rhs).
    const VectorType &
    pinned_right_hand_side(const VectorType &b);

    /// Makes @p x, the tangent's solution for a pinned right-hand side,
    /// the one without components along the pinned motions (the extra
    /// solves at @p tolerance, their iterations added to @p iterations).
    void
    constrain_to_pins(double tolerance, VectorType &x, unsigned int &iterations);

    /// The linearization at u_ghosted into @p matrix and @p rhs: the load
    /// terms' (ElasticityOperator::assemble_system with @p constraints and
    /// @p projection), plus the snap damping where it acts, regularized
    /// for unheld bodies. Collective.
    void
    assemble_linearization_into(
      const dealii::AffineConstraints<double> &constraints,
      MatrixType                              &matrix,
      VectorType                              &rhs,
      TangentProjection                        projection);

    /// (Re)builds the tangent's sparsity: the mesh's couplings and the load
    /// terms' (CouplingTerm::add_couplings). Collective.
    void
    build_tangent_sparsity();
    /// Makes `extension` a new matrix with the tangent's sparsity, built
    /// while the old one still exists, so that it has another address and
    /// the linear solver builds a new hierarchy on it every time. (A reinit
    /// in place lands at the old address on some runs and not on others: a
    /// kept hierarchy then refers to a destroyed matrix, and runs differ.)
    void
    renew_extension();

    const Parts              parts;
    const MPI_Comm           comm;
    dealii::IndexSet         owned_dofs, relevant_dofs;
    ElasticityOperator<dim> *elasticity = nullptr;
    TimeStepping<dim>       *stepping   = nullptr;
    /// Quasi-static bodies held by contact alone: their unresisted rigid
    /// motions (null if every body has a Dirichlet condition).
    std::unique_ptr<UnheldRigidMotions<dim>> unheld;

    /// Dirichlet constraints: with the increment to the prescribed values
    /// (first iteration of a load step) and homogeneous (later iterations);
    /// active_constraints points at the ones of the current linearization.
    dealii::AffineConstraints<double>        increment_constraints;
    dealii::AffineConstraints<double>        homogeneous_constraints;
    const dealii::AffineConstraints<double> *active_constraints = nullptr;

    MatrixType tangent;
    /// soften_inverting_predictor()'s system, and the tangent projected
    /// everywhere that preconditions the trust region's truncated CG
    /// (empty until first needed).
    MatrixType extension;
    /// u: the current iterate; update: Newton's direction; trial: the
    /// line search's candidate u + alpha update (projected by the terms,
    /// ElasticityOperator::project_trial); u_ghosted: whichever of u
    /// and trial was evaluated last, with ghost entries.
    VectorType u, u_ghosted, update, trial, rhs;
    VectorType internal_force, external_force, residual;
    double     current_load_factor = 0.;
    double     step_length         = 1.; ///< of the last evaluated trial
    /// Whether the last linearization was a predictor (prescribed values
    /// or obstacles moving with its direction).
    bool predictor_linearization = false;
    /// Running maxima of the force and displacement norms (Newton's scales).
    double force_scale = 0.;
    /// The right-hand side without the pinned motions' forces.
    VectorType pinned_rhs;
    /// The load terms' ForceSize at the last force assembly.
    ForceSize                        force_size;
    double                           solution_size  = 0.;
    double                           min_J          = 1.;
    dealii::types::global_cell_index inverted_cells = 0;

    /// 1 on the displacement dofs, 0 on a mixed formulation's pressures
    /// (empty without pressures): arc length's inner product.
    VectorType displacement_mask;

    /// The last converged state and the one before it.
    ConvergedState converged, previous;

    /// The damping of snap sub-steps (inactive otherwise; its metric is
    /// made when first needed).
    SnapDamping damping;
  };
} // namespace hyperelastic
