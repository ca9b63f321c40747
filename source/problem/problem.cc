// Orchestration of a scene: set-up, the steps the driver asks for, the
// summary and output of each converged step. What the unknowns are comes from
// the formulation (formulation/), how steps follow each other from the
// time-stepping driver (dynamics/time_stepping.h), what a step measures from
// the step post-processor (output/step_postprocessor.h).
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_simplex_p.h>

#include <hyperelastic/assembly/assembly_tools.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/dynamics/time_stepping.h>
#include <hyperelastic/equilibrium_system/equilibrium_system.h>
#include <hyperelastic/formulation/formulation_registry.h>
#include <hyperelastic/materials/region_properties.h>
#include <hyperelastic/mesh/bodies.h>
#include <hyperelastic/mesh/boundary_regions.h>
#include <hyperelastic/mesh/mesh.h>
#include <hyperelastic/problem/problem.h>
#include <hyperelastic/solvers/rigid_body_modes.h>

#include <chrono>
#include <iomanip>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  Problem<dim>::Problem(const Parameters &parameters,
                        const MPI_Comm    comm,
                        const bool        print)
      : parameters(parameters)
      , comm(comm)
      , pcout(std::cout, print && Utilities::MPI::this_mpi_process(comm) == 0)
      // Not synchronised over ranks: a timer that communicates would block in
      // the destructor of a TimerOutput::Scope while a rank-local exception
      // unwinds, before main() can abort the job. Times are rank 0's.
      , timer(pcout,
              print ? TimerOutput::summary : TimerOutput::never,
              TimerOutput::wall_times)
      , model(parameters, comm)
      , newton(parameters.newton, pcout, parameters.output.verbose)
  {
    AssertThrow(parameters.problem.dimension == dim,
                ExcMessage("Problem<dim> built for the wrong dimension"));
  }

  template <int dim>
  Problem<dim>::~Problem()
  {
    // The run's parts refer to the model's operator and terms.
    reset_run();
  }

  template <int dim>
  void
  Problem<dim>::setup()
  {
    if (is_set_up)
      return;
    is_set_up = true;
    TimerOutput::Scope scope(timer, "mesh and setup");
    setup_stages.clear();
    if (!mesh_built)
      {
        setup_stages = model.build_mesh(parameters, load_editor);
        mesh_built   = true;
      }
    // The stages after the mesh, each from the end of the one before.
    Timer      stage_timer;
    const auto end_stage = [&](const std::string &name) {
      setup_stages.emplace_back(name, stage_timer.wall_time());
      stage_timer.restart();
    };
    model.build_materials(parameters,
                          parameters.output.write_vtu ||
                            parameters.output.write_hdf5 ||
                            parameters.output.surface_format ==
                              SurfaceFormat::ply,
                          timer);
    end_stage("operator");
    linear_solver = std::make_unique<LinearSolver>(parameters.linear_solver);
    system        = std::make_unique<EquilibriumSystem<dim>>(
      typename EquilibriumSystem<dim>::Parts{
        parameters.newton,
        parameters.linear_solver,
        parameters.material.model,
        model.dof_handler,
        model.mapping,
        *model.materials,
        *model.boundary_conditions,
        *model.formulation,
        *linear_solver,
        timer,
        pcout,
        parameters.contact.has_friction()});
    end_stage("system");
    if (parameters.linear_solver.type == LinearSolverType::cg_amg)
      {
        linear_solver->set_near_null_space(rigid_body_modes(model.mapping,
                                                            model.dof_handler),
                                           n_rigid_body_modes<dim>,
                                           dim);
        linear_solver->set_stiffness_contrast(
          stiffness_contrast(*model.materials, model.cell_regions));
      }
    end_stage("null space");
    setup_run();
    setup_output();
    end_stage("rest");
    print_header();
  }

  template <int dim>
  void
  Problem<dim>::rebuild_materials(const MaterialParameters            &material,
                                  const std::vector<RegionParameters> &regions)
  {
    if (regions.size() != parameters.regions.size())
      throw InputError("rebuilt materials: " + std::to_string(regions.size()) +
                       " regions given, the scene's mesh has " +
                       std::to_string(parameters.regions.size()));
    reset_run();
    parameters.material = material;
    parameters.regions  = regions;
    step_summaries.clear();
    n_frames  = 0;
    is_set_up = false;
  }

  template <int dim>
  void
  Problem<dim>::move_reference(const VectorType &shift)
  {
    reset_run();
    std::vector<bool> moved(model.triangulation->n_vertices(), false);
    for (const auto &cell : model.dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          if (!moved[cell->vertex_index(v)])
            {
              moved[cell->vertex_index(v)] = true;
              for (unsigned int d = 0; d < dim; ++d)
                cell->vertex(v)[d] += shift(cell->vertex_dof_index(v, d));
            }
    step_summaries.clear();
    n_frames  = 0;
    is_set_up = false;
  }

  template <int dim>
  void
  Problem<dim>::reset_run()
  {
    // In the reverse order of their set-up: each refers to those before.
    surface.reset();
    writer.reset();
    reporters.clear();
    stepping.reset();
    system.reset();
    postprocessor.reset();
    linear_solver.reset();
  }

  template <int dim>
  void
  Problem<dim>::setup_run()
  {
    postprocessor =
      std::make_unique<StepPostprocessor<dim>>(model.dof_handler,
                                               model.mapping,
                                               *model.boundary_conditions,
                                               parameters.output,
                                               model.pressure_dofs);
    stepping = create_time_stepping<dim>(
      {parameters.time_integration,
       parameters.load_stepping,
       parameters.loading,
       {parameters.contact.active(), parameters.contact.has_friction()},
       parameters.material.viscoelasticity.quasi_static_duration,
       model.dof_handler,
       model.mapping,
       *model.materials,
       *model.elasticity,
       system->free_dofs(),
       timer,
       region_densities(parameters.regions,
                        parameters.time_integration.density)});
    reporters = {stepping.get(), postprocessor.get()};
    if (model.contact_reporter)
      reporters.push_back(model.contact_reporter.get());
    if (stepping->needs_supports())
      check_supports(model.dof_handler,
                     model.boundary_conditions->dirichlet_ids(),
                     model.contact_reporter != nullptr,
                     LoadingParameters::max_dirichlet);
    stepping->initialize(system->solution());
    system->attach(*model.elasticity, *stepping);
    // A load without a potential makes the tangent non-symmetric.
    linear_solver->set_symmetric(model.elasticity->is_conservative());
    model.formulation->configure_linear_solver(*linear_solver,
                                               model.dof_handler,
                                               model.mapping,
                                               *model.materials,
                                               model.pressure_dofs);
  }

  template <int dim>
  void
  Problem<dim>::setup_output()
  {
    const SurfaceFormat surface_format = parameters.output.surface_format;
    if (!parameters.restart_checkpoint.empty())
      read_checkpoint();
    writer = std::make_unique<OutputWriter<dim>>(
      parameters.output, comm, resume_point ? int(resume_point->step) : -1);
    if (resume_point)
      {
        writer->resume_series(resumed_series);
        writer->resume_xdmf_entries(resumed_xdmf);
      }
    if (surface_format != SurfaceFormat::none)
      surface =
        std::make_unique<SurfaceWriter<dim>>(model.dof_handler,
                                             surface_format,
                                             parameters.output.directory,
                                             parameters.output.base_name);
  }

  template <int dim>
  void
  Problem<dim>::run()
  {
    try
      {
        solve_all_load_steps();
      }
    catch (const InputError &)
      {
        // A timing table would only bury the message.
        timer.disable_output();
        throw;
      }
    catch (const ConvergenceFailure &failure)
      {
        timer.disable_output();
        if (!writer)
          throw;
        // Every converged step has been written: say where the last one is.
        std::ostringstream where;
        where << failure.what() << "\nlast converged state (t = "
              << (step_summaries.empty() ? 0.
                                         : step_summaries.back().load_factor)
              << "): ";
        if (parameters.output.write_vtu)
          where << writer->pvtu_file(step_summaries.size()) << " (series "
                << parameters.output.directory << "/"
                << parameters.output.base_name << ".pvd), ";
        where << "summary " << writer->csv_file();
        throw ConvergenceFailure(where.str());
      }
  }

  template <int dim>
  void
  Problem<dim>::solve_all_load_steps()
  {
    setup();
    if (writes_frames() && !resume_point)
      write_fields(0);
    const auto start = std::chrono::steady_clock::now();
    stepping->stepper(pcout).run(
      newton,
      *system,
      [&](const LoadStep &step, const NewtonResult &result) {
        report_step(step, result, start);
      },
      resume_point.get());
    if (pcout.is_active())
      for (const StepReporter<dim> *reporter : reporters)
        reporter->print_cost(pcout.get_stream());
    if (newton_per_nominal_step > 0.)
      pcout << "\nNewton iterations: " << newton_in_all
            << " in all (failed attempts included), " << std::fixed
            << std::setprecision(2) << newton_per_nominal_step
            << " per nominal step; smallest step " << std::defaultfloat
            << std::setprecision(3) << smallest_step_fraction
            << " of the nominal one" << std::setprecision(6) << std::endl;
    pcout << "\nSummary per load step: " << writer->csv_file();
    if (parameters.output.write_vtu)
      pcout << "; fields for ParaView: " << parameters.output.directory << "/"
            << parameters.output.base_name << ".pvd";
    pcout << std::endl;
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace hyperelastic
