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
#include <hyperelastic/assembly/snap_damping.h>
#include <hyperelastic/constraints/system_constraint.h>
#include <hyperelastic/constraints/unheld_rigid_motions.h>
#include <hyperelastic/dynamics/time_stepping.h>
#include <hyperelastic/formulation/formulation.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/solvers/continuation_system.h>
#include <hyperelastic/solvers/convergence_test.h>
#include <hyperelastic/solvers/damped_system.h>
#include <hyperelastic/solvers/lagged_system.h>
#include <hyperelastic/solvers/linear_solver.h>
#include <hyperelastic/solvers/linear_solver_parameters.h>
#include <hyperelastic/solvers/load_stepping.h>
#include <hyperelastic/solvers/newton_parameters.h>
#include <hyperelastic/solvers/predictor_softening.h>
#include <hyperelastic/solvers/tangent_system.h>
#include <hyperelastic/solvers/trust_region_system.h>

#include <memory>
#include <string>

namespace hyperelastic
{
  template <int dim>
  class EquilibriumSystem : public SteppedSystem,
                            public TrustRegionSystem,
                            public LaggedSystem,
                            public PredictorSoftening,
                            public DampedSystem,
                            public ContinuationSystem,
                            public TangentSystem
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
      /// Whether a load term resists sliding along the surfaces that hold
      /// a body (it resists the rigid motions along them, however weakly;
      /// see UnheldRigidMotions).
      bool sliding_resisted = false;
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
    solve_linearization(double forcing, LinearizationSolve &solve) override;
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
    void
    judge_converged_state() override;

    // TrustRegionSystem
    bool
    has_negative_curvature() override;
    void
    solve_linearization_in_trust_region(double              forcing,
                                        double              radius,
                                        LinearizationSolve &solve,
                                        Step               &step) override;

    // LaggedSystem: the load terms' lagged quantities (friction).
    LaggedUpdate
    update_lagged(LagMoment moment, double unbalanced_force) override;

    // PredictorSoftening: the predictor's update inverts cells of a state
    // without inverted ones (a large prescribed increment, the tangent's
    // linear extension far outside its range: the one-step crush): the
    // increment extended with linear elasticity at zero Poisson's ratio at
    // rest (which moves a clamped block's interior with its ends instead of
    // bulging it through itself) replaces it if its energy is lower.
    // Displacement formulation, models defined at J <= 0, with a potential.
    bool
    soften_predictor(unsigned int &linear_iterations) override;

    // SteppedSystem
    void
    set_load_factor(double t) override;
    void
    store_converged_state() override;
    void
    restore_converged_state() override;
    const VectorType &
    state() const override
    {
      return u;
    }

    // DampedSystem: the lumped mass of unit density on the free unknowns
    // (SnapDamping), with a potential and no unheld bodies
    // (Properties::damping).
    void
    set_damping(double c) override;
    double
    damping_force() override;
    double
    damping_scale() override;

    /// The adjoint of the last assemble_tangent(): solves K^T x = b on the
    /// free unknowns (0 on the constrained ones) with the scene's linear
    /// solver, K^T formed explicitly (a non-symmetric tangent: follower
    /// loads). Returns the Krylov iterations. Not with system constraints
    /// (has_system_constraints()): their projections belong to K. Collective.
    unsigned int
    solve_transposed_tangent(const VectorType &b, VectorType &x);

    /// Whether constraints beyond the Dirichlet ones act on the solves
    /// (pinned rigid motions of unheld bodies, prescribed resultants).
    bool
    has_system_constraints() const
    {
      return !system_constraints.empty();
    }

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
    void
    load_derivative(VectorType &r_t) override;
    double
    path_product(const VectorType &a, const VectorType &b) const override;

    // TangentSystem
    ResidualNorms
    free_residual(VectorType &r) override;
    void
    assemble_tangent() override;
    unsigned int
    solve_tangent(const VectorType &b, VectorType &x) override;

  private: /// Assembles the tangent projected everywhere at the current iterate
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

    /// The system constraints prepared for a solve at u with the tangent
    /// and the right-hand side @p b; returns @p b without its components
    /// along what they hold (in pinned_rhs; @p b itself without any).
    const VectorType &
    constrained_right_hand_side(const VectorType &b);

    /// Makes @p x, the tangent's solution for a constrained right-hand
    /// side, meet the system constraints (the extra solves at
    /// @p tolerance, their iterations added to @p iterations).
    void
    constrain_update(double tolerance, VectorType &x, unsigned int &iterations);

    /// Removes from @p v (at @p at) its components along what the system
    /// constraints hold.
    void
    project_out(const VectorType &at, VectorType &v) const;

    /// The linearization at u_ghosted into @p matrix and @p rhs: the
    /// operator's (ElasticityOperator::assemble_system with @p constraints
    /// and @p projection: the material, the terms, the snap damping where
    /// it acts), regularized by the system constraints. Collective.
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
    /// What changes the equations beyond the Dirichlet conditions, looped
    /// over (SystemConstraint): the unresisted rigid motions of
    /// quasi-static bodies held by contact alone.
    std::vector<std::unique_ptr<SystemConstraint>> system_constraints;

    /// Dirichlet constraints: with the increment to the prescribed values
    /// (first iteration of a load step) and homogeneous (later iterations);
    /// active_constraints points at the ones of the current linearization.
    dealii::AffineConstraints<double>        increment_constraints;
    dealii::AffineConstraints<double>        homogeneous_constraints;
    const dealii::AffineConstraints<double> *active_constraints = nullptr;

    MatrixType tangent;
    /// soften_predictor()'s system, and the tangent projected
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
    /// ResidualNorms::update_noise (computed on first use).
    double position_noise = -1.;
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

    /// The damping of snap sub-steps, an energy term of the operator added
    /// when first needed (null until then; inactive outside sub-steps).
    SnapDamping<dim> *damping = nullptr;
  };
} // namespace hyperelastic
