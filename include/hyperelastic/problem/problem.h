// A scene run end to end: the orchestrator. It has the scene's Model built
// (mesh, dofs, loads, materials, operator and terms), builds what a run
// drives it with (the equilibrium system, the linear solver, the
// time-stepping driver, the output), lets the load stepper and Newton drive
// the system, and after each converged step has the summary measured and the
// output written. Every choice of formulation or scheme lives behind
// Formulation and TimeStepping; a calibration rebuilds the model's materials
// and runs again on the same mesh (rebuild_materials()).
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/affine_constraints.h>

#include <hyperelastic/assembly/material_regions.h>
#include <hyperelastic/formulation/formulation.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/mesh/boundary_regions.h>
#include <hyperelastic/mesh/cell_regions.h>
#include <hyperelastic/scene/model.h>
#include <hyperelastic/output/output.h>
#include <hyperelastic/output/step_postprocessor.h>
#include <hyperelastic/output/step_reporter.h>
#include <hyperelastic/output/step_summary.h>
#include <hyperelastic/output/surface_writer.h>
#include <hyperelastic/scene/parameters.h>
#include <hyperelastic/solvers/linear_solver.h>
#include <hyperelastic/solvers/newton_solver.h>

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace hyperelastic
{
  // What a run builds and drives (problem.cc includes them: a change to the
  // equations' parts does not recompile the users of Problem).
  template <int dim>
  class ElasticityOperator;
  template <int dim>
  class EquilibriumSystem;
  template <int dim>
  class TimeStepping;
  struct LoadStep;
  struct ResumePoint;

  template <int dim>
  class Problem
  {
  public:
    /// @p print: whether rank 0 prints progress (tests may switch it off).
    Problem(const Parameters &parameters, MPI_Comm comm, bool print = true);
    ~Problem();

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

    /// Lets code look at every converged state (tests: the boundary free of
    /// intersections at every step): @p observer is called with the step's
    /// summary after it is recorded, while solution() is that state.
    void
    set_step_observer(std::function<void(const StepSummary<dim> &)> observer)
    {
      step_observer = std::move(observer);
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
      return model.dof_handler;
    }

    /// Wall time in seconds spent so far in each phase on this rank
    /// ("mesh and setup", "assembly", "residual", "line search",
    /// "preconditioner setup", "linear solve", "postprocessing", "output").
    std::map<std::string, double>
    wall_times() const
    {
      return timer.get_summary_data(dealii::TimerOutput::total_wall_time);
    }

    /// Wall time in seconds of each stage of the last set-up on this rank,
    /// in order: the mesh's (read, order, check, build, partition, wait,
    /// describe, distribute: MeshStatistics) and "dofs" (regions, loads,
    /// numbering), where the mesh was built; then "operator" (materials,
    /// element kernels, contact terms), "system" (sparsity, matrix and
    /// vectors), "null space" (rigid-body modes for AMG), "rest" (stepping,
    /// checks, output set-up). Their sum is the set-up's part of the "mesh
    /// and setup" phase of wall_times().
    const std::vector<std::pair<std::string, double>> &
    setup_stage_times() const
    {
      return setup_stages;
    }

    /// How often the AMG hierarchy was computed (for benchmarks).
    unsigned int
    n_preconditioner_setups() const
    {
      return linear_solver->n_preconditioner_setups();
    }

    /// How many of those were refreshes on earlier aggregates.
    unsigned int
    n_preconditioner_refreshes() const
    {
      return linear_solver->n_preconditioner_refreshes();
    }

    /// How many load steps started from an (admissible) secant prediction.
    unsigned int
    n_secant_predictions() const;

    /// Which linear solver runs (the run header's line).
    std::string
    linear_solver_description() const
    {
      return linear_solver->description();
    }

    /// The tangent matrix of the last linearization (for benchmarks).
    const MatrixType &
    tangent_matrix() const;

    /// The displacement with ghost entries.
    const VectorType &
    solution() const;

    /// f_int - f_ext at solution() (owned entries): on the Dirichlet dofs
    /// the nodal forces of the supports (the reaction columns' terms).
    const VectorType &
    residual_forces() const;

    /// Builds the model (the mesh, the unknowns, the materials and the
    /// operator) and what a run drives it with: the "mesh and setup"
    /// phase. run() calls it; a benchmark of the set-up alone calls it
    /// directly (once; run() then does not repeat it).
    void
    setup();

    /// Builds the model's materials anew from @p material and @p regions
    /// (the scene's regions, with other constants: a calibration's trial),
    /// on the same mesh, dofs and loads; the next run() starts from the
    /// unloaded state with these materials and matches a run of a scene
    /// that had them. Collective.
    void
    rebuild_materials(const MaterialParameters            &material,
                      const std::vector<RegionParameters> &regions);

    /// Moves every vertex of the reference mesh by the displacement
    /// components of @p shift at it (laid out like solution(), with ghost
    /// entries); the next run() starts anew from the unloaded state on the
    /// moved mesh, with the same dofs and loads (an inverse problem's
    /// iterate, unloaded_shape.h). Collective.
    void
    move_reference(const VectorType &shift);

    /// At the converged state just reported (call it from the step
    /// observer): the derivatives of the CSV column reaction_<id>_<axis>
    /// with respect to the model's constants (in the order of its
    /// ConstantDerivatives) by the adjoint of the converged equilibrium
    /// r(u, c) = 0 (source/problem/sensitivity.cc), in the displacement
    /// (P1, P2) or the mixed formulation (every element). Empty where it
    /// does not apply: stiffness warping, contact, a non-symmetric tangent
    /// together with system constraints, a model without
    /// ConstantDerivatives. Collective.
    std::vector<double>
    reaction_sensitivities(dealii::types::boundary_id id, unsigned int axis);

  private:
    // The set-up's steps (setup()).
    /// The equilibrium system, the linear solver's configuration, the
    /// step post-processor, the time-stepping driver and the supports
    /// check: what a run drives the model with.
    void
    setup_run();
    /// The output writers (and a restart's checkpoint).
    void
    setup_output();
    /// Back to before setup_run() (the model's mesh, dofs and loads stay).
    void
    reset_run();
    void
    solve_all_load_steps();
    /// After converged step @p step: the summary, its row, the checkpoint,
    /// the observer and the progress lines; @p start: the run's start.
    void
    report_step(const LoadStep                              &step,
                const NewtonResult                          &result,
                const std::chrono::steady_clock::time_point &start);
    /// The run header: element, size, ranks, material, solver, loads.
    void
    print_header() const;
    /// The regions' lines of the run header (model and cells of each).
    void
    print_regions() const;
    StepSummary<dim>
    summarize(const LoadStep &step, const NewtonResult &newton_result);
    /// Whether output frames are written (VTU or a surface sequence).
    bool
    writes_frames() const
    {
      return parameters.output.write_vtu || parameters.output.write_hdf5 ||
             surface != nullptr;
    }
    /// One output frame: the VTU files of load step @p step and the
    /// surface file, as the scene asks.
    void
    write_fields(unsigned int step);

    // Checkpoint and restart (problem/checkpoint.cc).
    /// What must match between a checkpoint and the scene that resumes
    /// it, one "name: value" per line.
    std::string
    checkpoint_description() const;
    /// Writes the checkpoint after converged step @p step.
    void
    write_checkpoint(const LoadStep &step);
    /// Reads the checkpoint of 'restart_checkpoint' into the system, the
    /// solver's counts and the output state; sets resume_point. Before the
    /// output writer exists.
    void
    read_checkpoint();

    /// The scene (its materials as last rebuilt).
    Parameters                 parameters;
    const MPI_Comm             comm;
    dealii::ConditionalOStream pcout;
    dealii::TimerOutput        timer;

    /// What the scene builds; the run drives it.
    Model<dim>                                  model;
    bool                                        mesh_built = false;
    std::vector<std::pair<std::string, double>> setup_stages;
    bool                                        is_set_up = false;

    std::function<void(BoundaryConditions<dim> &)> load_editor;
    std::function<void(const StepSummary<dim> &)>  step_observer;
    std::unique_ptr<LinearSolver>                  linear_solver;
    std::unique_ptr<TimeStepping<dim>>             stepping;
    std::unique_ptr<EquilibriumSystem<dim>>        system;
    std::unique_ptr<StepPostprocessor<dim>>        postprocessor;
    /// The reporters of a step, in the order of their columns: the driver,
    /// the post-processor, then contact's.
    std::vector<StepReporter<dim> *>   reporters;
    std::unique_ptr<OutputWriter<dim>> writer;
    /// 'Output/Surface format' (null for none).
    std::unique_ptr<SurfaceWriter<dim>> surface;
    /// Output frames written so far (the next surface file's number).
    unsigned int n_frames = 0;
    /// A restart: where the steps resume, the CSV rows and PVD entries to
    /// keep (null: from the start).
    std::unique_ptr<ResumePoint>                resume_point;
    std::vector<std::pair<double, std::string>> resumed_series;
    std::string                                 resumed_xdmf;
    NewtonSolver                                newton;

    std::vector<StepSummary<dim>> step_summaries;
    /// What the run cost so far, from the stepper's report of the last
    /// converged step (LoadStep): Newton iterations in all (failed attempts
    /// included), per nominal step, and the smallest increment over the
    /// nominal one (0: no step yet, or arc length).
    unsigned int newton_in_all           = 0;
    double       newton_per_nominal_step = 0.;
    double       smallest_step_fraction  = 0.;
  };

  /// Reads the dimension from the parameters and runs the scene.
  void
  run_scene(const Parameters &parameters, MPI_Comm comm);
} // namespace hyperelastic
