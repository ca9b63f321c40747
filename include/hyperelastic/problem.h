// A scene run end to end: mesh, dofs, material and loads from the parameters,
// then for each load step a Newton solve, post-processing and output. This
// class is the SteppedSystem that the Newton solver and the load stepper
// drive.
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/affine_constraints.h>

#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/dynamics/inertia.h>
#include <hyperelastic/dynamics/motion.h>
#include <hyperelastic/dynamics/stiffness_damping.h>
#include <hyperelastic/dynamics/time_integrator.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/output/cell_fields.h>
#include <hyperelastic/output/output.h>
#include <hyperelastic/output/point_values.h>
#include <hyperelastic/parameters.h>
#include <hyperelastic/solvers/linear_solver.h>
#include <hyperelastic/solvers/load_stepping.h>
#include <hyperelastic/solvers/newton_solver.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class Problem : public SteppedSystem
  {
  public:
    /// @p print: whether rank 0 prints progress (tests may switch it off).
    Problem(const Parameters &parameters, MPI_Comm comm, bool print = true);

    /// Runs all load steps. Throws InputError or ConvergenceFailure.
    void
    run();

    /// Lets code change the scene's loads after they are parsed, before
    /// run() uses them: for example a manufactured solution's body force
    /// and boundary displacements, which no expression can write. Call
    /// before run().
    void
    set_load_editor(std::function<void(BoundaryConditions<dim> &)> editor)
    {
      load_editor = std::move(editor);
    }

    /// One entry per converged load step.
    const std::vector<StepSummary<dim>> &
    summaries() const
    {
      return step_summaries;
    }

    const dealii::DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /// Wall time in seconds spent so far in each phase on this rank
    /// ("mesh and setup", "assembly", "residual", "line search",
    /// "preconditioner setup", "linear solve", "postprocessing", "output").
    std::map<std::string, double>
    wall_times() const
    {
      return timer.get_summary_data(dealii::TimerOutput::total_wall_time);
    }

    /// How often the AMG hierarchy was computed (for benchmarks).
    unsigned int
    n_preconditioner_setups() const
    {
      return linear_solver.n_preconditioner_setups();
    }

    /// How many of those were refreshes on earlier aggregates.
    unsigned int
    n_preconditioner_refreshes() const
    {
      return linear_solver.n_preconditioner_refreshes();
    }

    /// How many load steps started from an (admissible) secant prediction.
    unsigned int
    n_secant_predictions() const
    {
      return secant_predictions;
    }

    /// Which linear solver runs (the run header's line).
    std::string
    linear_solver_description() const
    {
      return linear_solver.description();
    }

    /// The tangent matrix of the last linearization (for benchmarks).
    const MatrixType &
    tangent_matrix() const
    {
      return tangent;
    }

    /// The displacement with ghost entries.
    const VectorType &
    solution() const
    {
      return u_ghosted;
    }

    // NonlinearSystem
    bool
    assemble_linearization(bool impose_constraint_increment,
                           bool positive_semidefinite) override;
    unsigned int
    solve_linearization(double forcing) override;
    bool
    is_linear() const override;
    bool
    has_potential() const override;
    std::string
    why_no_potential() const override;
    double
    directional_derivative() const override;
    TrialPoint
    evaluate_trial(double alpha, TrialCheck check) override;
    double
    accept_trial() override;
    ResidualNorms
    residual_norms() override;
    double
    solution_scale() const override;
    void
    verify_converged_state() override;

    // SteppedSystem
    void
    set_load_factor(double t) override;
    void
    store_converged_state() override;
    void
    restore_converged_state() override;

  private:
    void
    solve_all_load_steps();
    void
    setup();
    void
    warn_about_volumetric_locking() const;
    /// The mixed formulation's block preconditioner for this mesh: the
    /// pressure unknowns and (1/mu) times the lumped pressure mass.
    std::unique_ptr<SaddlePointPreconditioner>
    saddle_point_preconditioner() const;
    StepSummary<dim>
    summarize(const LoadStep &step, const NewtonResult &newton_result);
    void
    write_fields(unsigned int step);
    /// Assembles the forces at u_ghosted into internal_force, external_force
    /// and residual; returns the residual norm on the free unknowns and its
    /// round-off level in @p noise.
    double
    free_residual_norm(double &noise);

    const Parameters           parameters;
    const MPI_Comm             comm;
    dealii::ConditionalOStream pcout;
    dealii::TimerOutput        timer;

    dealii::parallel::fullydistributed::Triangulation<dim> triangulation;
    /// (P_k)^dim, and for the mixed formulation a P1 pressure after it.
    const dealii::FESystem<dim> fe;
    const dealii::MappingFE<dim>                           mapping;
    dealii::DoFHandler<dim>                                dof_handler;
    dealii::IndexSet                                       owned_dofs;
    dealii::IndexSet                                       relevant_dofs;
    /// Mixed formulation: the pressure unknowns among the relevant ones.
    dealii::IndexSet pressure_dofs;

    std::unique_ptr<Material<dim>> material;
    /// The same model in 3D, for the plane-strain stress in the output
    /// (null without VTU output).
    std::unique_ptr<Material<3>>                   material3d;
    std::unique_ptr<BoundaryConditions<dim>>       boundary_conditions;
    std::function<void(BoundaryConditions<dim> &)> load_editor;
    std::unique_ptr<ElasticityOperator<dim>>       elasticity;
    std::unique_ptr<OutputWriter<dim>>             writer;
    /// The points of 'Output/Points', located once (null if there are none).
    std::unique_ptr<PointValues<dim>> point_values;
    LinearSolver                      linear_solver;
    NewtonSolver                      newton;

    /// Dirichlet constraints: with the increment to the prescribed values
    /// (first iteration of a load step) and homogeneous (later iterations);
    /// active_constraints points at the ones of the current linearization.
    dealii::AffineConstraints<double>        increment_constraints;
    dealii::AffineConstraints<double>        homogeneous_constraints;
    const dealii::AffineConstraints<double> *active_constraints = nullptr;

    /// The distinct Dirichlet boundary ids and, for each, the owned dofs on
    /// it whose component is prescribed there, with that component (for the
    /// reaction forces).
    std::vector<dealii::types::boundary_id> reaction_ids;
    std::vector<
      std::vector<std::pair<dealii::types::global_dof_index, unsigned int>>>
      reaction_dofs;

    MatrixType tangent;
    /// u: the current iterate; update: Newton's direction; trial: the
    /// line search's candidate u + alpha update; u_ghosted: whichever of u
    /// and trial was evaluated last, with ghost entries.
    VectorType u, u_ghosted, update, trial, rhs;
    VectorType internal_force, external_force, residual;
    double     load_factor = 0.;
    double     step_length = 1.; ///< of the last evaluated trial
    /// Running maxima of the force and displacement norms (Newton's scales).
    double force_scale   = 0.;
    double solution_size = 0.;
    /// Smallest J of the last converged state, and how many cells have
    /// J <= 0 there (non-zero only when such states are accepted).
    double                           converged_min_J          = 1.;
    dealii::types::global_cell_index converged_inverted_cells = 0;

    /// A converged state: the last one, to return to after a failed load
    /// step, and the one before it (the secant predictor's other point).
    struct ConvergedState
    {
      VectorType u;
      double     force_scale   = 0.;
      double     solution_size = 0.;
      double     load_factor   = 0.;
      bool       valid         = false;
    } converged, previous;

    /// 'Load stepping/Predictor = secant': moves u from the last converged
    /// state along its last increment to load factor @p t, unless an element
    /// of the prediction has J <= 0.
    void
    predict(double t);
    unsigned int secant_predictions = 0;

    /// Implicit dynamics ('Time integration/Scheme' other than
    /// quasi-static; nothing of it exists otherwise): the inertia term (owned
    /// by the operator), the scheme, velocity and acceleration of the last
    /// converged state, the momenta.
    void
    setup_dynamics();
    /// The time step to t: the inertia term's target.
    void
    begin_time_step(double t);
    InertiaTerm<dim>               *inertia = nullptr;
    /// 'Time integration/Stiffness damping' > 0 only (owned by the
    /// operator).
    StiffnessDampingTerm<dim> *stiffness_damping = nullptr;
    std::unique_ptr<TimeIntegrator> integrator;
    std::unique_ptr<Motion<dim>>    motion;
    VectorType velocity, acceleration, new_velocity, new_acceleration;
    /// The velocity with ghost entries (momenta and VTU), set once per
    /// converged step.
    VectorType velocity_ghosted;
    /// The end of the time step being solved (the load factor is the time
    /// the equations are solved at: the midpoint for implicit midpoint).
    double step_end_time = 0.;

    std::vector<StepSummary<dim>> step_summaries;
  };

  /// Reads the dimension from the parameters and runs the scene.
  void
  run_scene(const Parameters &parameters, MPI_Comm comm);
} // namespace hyperelastic
