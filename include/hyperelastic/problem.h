// A scene run end to end: the orchestrator. It builds the mesh, the
// formulation's element and dofs, the material, the loads, the operator, the
// time-stepping driver and the equilibrium system, lets the load stepper and
// Newton drive that system, and after each converged step has the summary
// measured and the output written. Every choice of formulation or scheme
// lives behind Formulation and TimeStepping.
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/affine_constraints.h>

#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/assembly/material_regions.h>
#include <hyperelastic/dynamics/time_stepping.h>
#include <hyperelastic/equilibrium_system.h>
#include <hyperelastic/formulation/formulation.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/mesh/boundary_regions.h>
#include <hyperelastic/mesh/cell_regions.h>
#include <hyperelastic/output/output.h>
#include <hyperelastic/output/step_postprocessor.h>
#include <hyperelastic/output/step_reporter.h>
#include <hyperelastic/output/step_summary.h>
#include <hyperelastic/output/surface_writer.h>
#include <hyperelastic/parameters.h>
#include <hyperelastic/solvers/linear_solver.h>
#include <hyperelastic/solvers/load_stepping.h>
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
  template <int dim>
  class Problem
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

    /// Wall time in seconds of each stage of the set-up on this rank, in
    /// order: the mesh's (read, order, check, build, partition, wait,
    /// describe, distribute: MeshStatistics), then "dofs" (numbering),
    /// "system" (sparsity, matrix and vectors), "null space" (rigid-body
    /// modes for AMG), "operator" (element kernels), "rest" (loads,
    /// stepping, checks, output set-up). Their sum is the "mesh and setup"
    /// phase of wall_times().
    const std::vector<std::pair<std::string, double>> &
    setup_stage_times() const
    {
      return setup_stages;
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
      return stepping->n_predictions();
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
      return system->tangent_matrix();
    }

    /// The displacement with ghost entries.
    const VectorType &
    solution() const
    {
      return system->solution();
    }

    /// Builds the mesh, the unknowns, the system and the operators: the
    /// "mesh and setup" phase. run() calls it; a benchmark of the set-up
    /// alone calls it directly (once; run() then does not repeat it).
    void
    setup();

  private:
    // The set-up's steps (setup()).
    /// The mesh of 'Mesh'; returns its boundary ids.
    std::set<dealii::types::boundary_id>
    setup_mesh();
    /// The equilibrium system and the step post-processor.
    void
    setup_system(const dealii::IndexSet &pressure_dofs);
    /// The energy terms beyond the scene's loads (contact, the driver's),
    /// the time-stepping driver, the supports check and the linear
    /// solver's configuration.
    void
    setup_stepping(const dealii::IndexSet &pressure_dofs);
    /// The output writers (and a restart's checkpoint).
    void
    setup_output();
    /// The moduli the automatic contact defaults take: the stiffest of the
    /// regions with a cell at the boundary (the only material's without
    /// regions). Collective.
    LameParameters
    contact_moduli() const;
    /// The largest over the smallest small-strain stiffness lambda + 2 mu of
    /// the materials with cells (1 for one material): the linear solver's
    /// 'AMG for contrast = auto'.
    double
    stiffness_contrast() const;
    /// The density of each region (region 0 first); empty without regions.
    std::vector<double>
    region_densities() const;

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

    // Checkpoint and restart (problem_checkpoint.cc).
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

    const Parameters           parameters;
    const MPI_Comm             comm;
    dealii::ConditionalOStream pcout;
    dealii::TimerOutput        timer;

    const std::unique_ptr<Formulation<dim>> formulation;
    /// Fully distributed on several ranks; on one, a SerialTriangulation
    /// (built in about half the time, the same cells in the same order).
    std::unique_ptr<dealii::Triangulation<dim>> triangulation;
    std::vector<std::pair<std::string, double>> setup_stages;
    bool                                        is_set_up = false;
    const dealii::FESystem<dim>                 fe;
    const dealii::MappingFE<dim>                mapping;
    dealii::DoFHandler<dim>                     dof_handler;

    /// The top-level Material (region 0).
    std::unique_ptr<Material<dim>> material;
    /// The models of Region 1 ... (parameters.regions' order), the region
    /// of each cell, and both as the material of every cell.
    std::vector<std::unique_ptr<Material<dim>>> region_models;
    CellRegions                                 cell_regions;
    /// The faces selected by 'Boundary region' conditions and their ids.
    BoundaryRegions boundary_regions;
    std::unique_ptr<MaterialRegions<dim>>       materials;
    /// The same models in 3D, for the plane-strain stress in the output
    /// (null without VTU output), region 0 first.
    std::unique_ptr<Material<3>>                   material3d;
    std::vector<std::unique_ptr<Material<3>>>      region_models3d;
    std::unique_ptr<MaterialRegions<3>>            materials3d;
    std::unique_ptr<BoundaryConditions<dim>>       boundary_conditions;
    std::function<void(BoundaryConditions<dim> &)> load_editor;
    std::function<void(const StepSummary<dim> &)>  step_observer;
    std::unique_ptr<ElasticityOperator<dim>>       elasticity;
    std::unique_ptr<TimeStepping<dim>>             stepping;
    std::unique_ptr<EquilibriumSystem<dim>>        system;
    std::unique_ptr<StepPostprocessor<dim>>        postprocessor;
    /// What the contact terms report (null without contact).
    std::unique_ptr<StepReporter<dim>> contact_reporter;
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
    LinearSolver                                linear_solver;
    NewtonSolver                                newton;

    std::vector<StepSummary<dim>> step_summaries;
  };

  /// Reads the dimension from the parameters and runs the scene.
  void
  run_scene(const Parameters &parameters, MPI_Comm comm);
} // namespace hyperelastic
