// Orchestration of a scene: set-up, the steps the driver asks for, the
// summary and output of each converged step. What the unknowns are comes from
// the formulation (formulation/), how steps follow each other from the
// time-stepping driver (dynamics/time_stepping.h), what a step measures from
// the step post-processor (output/step_postprocessor.h).
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_simplex_p.h>

#include <hyperelastic/assembly/assembly_tools.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/contact/contact_layer.h>
#include <hyperelastic/formulation/formulation_registry.h>
#include <hyperelastic/mesh/bodies.h>
#include <hyperelastic/mesh/boundary_regions.h>
#include <hyperelastic/mesh/mesh.h>
#include <hyperelastic/problem.h>
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
      , formulation(create_formulation<dim>({parameters.problem,
                                             parameters.material,
                                             parameters.linear_solver,
                                             parameters.time_integration}))
      , triangulation(
          Utilities::MPI::n_mpi_processes(comm) == 1
            ? std::unique_ptr<Triangulation<dim>>(
                std::make_unique<SerialTriangulation<dim>>(comm))
            : std::make_unique<parallel::fullydistributed::Triangulation<dim>>(
                comm))
      , fe(formulation->finite_element())
      , mapping(FE_SimplexP<dim>(1))
      , dof_handler(*triangulation)
      , linear_solver(parameters.linear_solver)
      , newton(parameters.newton, pcout, parameters.output.verbose)
  {
    AssertThrow(parameters.problem.dimension == dim,
                ExcMessage("Problem<dim> built for the wrong dimension"));
  }

  template <int dim>
  void
  Problem<dim>::setup()
  {
    if (is_set_up)
      return;
    is_set_up = true;
    TimerOutput::Scope                 scope(timer, "mesh and setup");
    std::set<types::boundary_id> mesh_ids = setup_mesh();
    // The stages after the mesh, each from the end of the one before.
    Timer      stage_timer;
    const auto end_stage = [&](const std::string &name) {
      setup_stages.emplace_back(name, stage_timer.wall_time());
      stage_timer.restart();
    };

    material     = create_material<dim>(parameters.material);
    cell_regions = assign_cell_regions(*triangulation, parameters.regions);
    std::vector<const Material<dim> *> models{material.get()};
    for (const RegionParameters &region : parameters.regions)
      {
        region_models.push_back(create_material<dim>(region.material));
        models.push_back(region_models.back().get());
      }
    materials =
      std::make_unique<MaterialRegions<dim>>(models, cell_regions.of_cell);
    LoadingParameters loading = parameters.loading;
    boundary_regions = assign_boundary_regions(*triangulation, loading, mesh_ids);
    boundary_conditions =
      std::make_unique<BoundaryConditions<dim>>(loading, mesh_ids);
    if (load_editor)
      load_editor(*boundary_conditions);
    dof_handler.distribute_dofs(fe);
    const IndexSet pressure_dofs = formulation->pressure_dofs(dof_handler);
    end_stage("dofs");
    setup_system(pressure_dofs);
    end_stage("system");
    if (parameters.linear_solver.type == LinearSolverType::cg_amg)
      {
        linear_solver.set_near_null_space(rigid_body_modes(mapping,
                                                           dof_handler),
                                          n_rigid_body_modes<dim>,
                                          dim);
        linear_solver.set_stiffness_contrast(stiffness_contrast());
      }
    end_stage("null space");
    elasticity = std::make_unique<ElasticityOperator<dim>>(
      dof_handler,
      mapping,
      *materials,
      *boundary_conditions,
      parameters.problem.fast_p1_assembly,
      formulation->material_part(dof_handler, mapping, *materials));
    end_stage("operator");
    setup_stepping(pressure_dofs);
    setup_output();
    end_stage("rest");
    print_header();
  }

  template <int dim>
  std::set<types::boundary_id>
  Problem<dim>::setup_mesh()
  {
    MeshStatistics mesh_stats;
    const auto     mesh_ids =
      Utilities::MPI::n_mpi_processes(comm) == 1
            ? create_serial_mesh(parameters.mesh,
                             static_cast<SerialTriangulation<dim> &>(
                               *triangulation),
                             &mesh_stats)
            : create_mesh(
            parameters.mesh,
            static_cast<parallel::fullydistributed::Triangulation<dim> &>(
              *triangulation),
            &mesh_stats);
    setup_stages = {{"read", mesh_stats.read_time},
                    {"order", mesh_stats.order_time},
                    {"check", mesh_stats.check_time},
                    {"build", mesh_stats.build_time},
                    {"partition", mesh_stats.partition_time},
                    {"wait", mesh_stats.wait_time},
                    {"describe", mesh_stats.describe_time},
                    {"distribute", mesh_stats.distribute_time}};
    generated_mesh = mesh_stats.generated_mesh;
    return mesh_ids;
  }

  template <int dim>
  void
  Problem<dim>::setup_system(const IndexSet &pressure_dofs)
  {
    postprocessor =
      std::make_unique<StepPostprocessor<dim>>(dof_handler,
                                               mapping,
                                               *boundary_conditions,
                                               parameters.output,
                                               pressure_dofs);
    system = std::make_unique<EquilibriumSystem<dim>>(
      typename EquilibriumSystem<dim>::Parts{parameters.newton,
                                             parameters.linear_solver,
                                             parameters.material.model,
                                             dof_handler,
                                             mapping,
                                             *materials,
                                             *boundary_conditions,
                                             *formulation,
                                             linear_solver,
                                             timer,
                                             pcout,
                                             parameters.contact.has_friction()});
  }

  template <int dim>
  void
  Problem<dim>::setup_stepping(const IndexSet &pressure_dofs)
  {
    contact_reporter =
      add_contact_terms<dim>({parameters.contact,
                              parameters.loading.constants,
                              dof_handler,
                              contact_moduli(),
                              parameters.time_integration.dynamic(),
                              pressure_dofs.n_elements() > 0,
                              timer},
                             *elasticity);
    stepping = create_time_stepping<dim>(
      {parameters.time_integration,
       parameters.load_stepping,
       parameters.loading,
       parameters.contact,
       parameters.material.viscoelasticity.quasi_static_duration,
       dof_handler,
       mapping,
       *materials,
       *elasticity,
       system->free_dofs(),
       timer,
       region_densities()});
    reporters = {stepping.get(), postprocessor.get()};
    if (contact_reporter)
      reporters.push_back(contact_reporter.get());
    if (stepping->needs_supports())
      check_supports(dof_handler,
                     boundary_conditions->dirichlet_ids(),
                     contact_reporter != nullptr,
                     LoadingParameters::max_dirichlet);
    stepping->initialize(system->solution());
    system->attach(*elasticity, *stepping);
    // A load without a potential makes the tangent non-symmetric.
    linear_solver.set_symmetric(elasticity->is_conservative());
    formulation->configure_linear_solver(
      linear_solver, dof_handler, mapping, *materials, pressure_dofs);
  }

  template <int dim>
  double
  Problem<dim>::stiffness_contrast() const
  {
    // The small-strain stiffness lambda + 2 mu of each region with cells
    // (an incompressible region's is infinite: its own stiffness then
    // comes from the mixed formulation's pressure, and mu decides).
    double smallest = std::numeric_limits<double>::infinity(), largest = 0.;
    for (unsigned int r = 0; r < materials->n_regions(); ++r)
      if (cell_regions.n_cells[r] > 0)
        {
          const LameParameters m = materials->model(r).small_strain_moduli();
          const double         stiffness =
            std::isfinite(m.lambda) ? m.lambda + 2. * m.mu : 2. * m.mu;
          smallest = std::min(smallest, stiffness);
          largest  = std::max(largest, stiffness);
        }
    return smallest > 0. ? largest / smallest : 1.;
  }

  template <int dim>
  LameParameters
  Problem<dim>::contact_moduli() const
  {
    if (parameters.regions.empty())
      return material->small_strain_moduli();
    // The regions with a cell at the boundary (where contact acts).
    std::vector<double> touches(materials->n_regions(), 0.);
    for (const auto &cell : triangulation->active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        touches[cell_regions(cell->active_cell_index())] = 1.;
    touches = summed_over_ranks(touches, comm);
    std::vector<const Material<dim> *> on_boundary;
    for (unsigned int r = 0; r < touches.size(); ++r)
      if (touches[r] > 0.)
        on_boundary.push_back(&materials->model(r));
    return MaterialRegions<dim>(on_boundary, {}).stiffest_moduli();
  }

  template <int dim>
  std::vector<double>
  Problem<dim>::region_densities() const
  {
    std::vector<double> densities;
    if (parameters.regions.empty())
      return densities;
    densities.push_back(parameters.time_integration.density);
    for (const RegionParameters &region : parameters.regions)
      densities.push_back(region.own_density
                            ? region.density
                            : parameters.time_integration.density);
    return densities;
  }

  template <int dim>
  void
  Problem<dim>::setup_output()
  {
    const SurfaceFormat surface_format = parameters.output.surface_format;
    if (parameters.output.write_vtu || parameters.output.write_hdf5 ||
        surface_format == SurfaceFormat::ply)
      {
        material3d = material->three_dimensional_twin();
        std::vector<const Material<3> *> twins{material3d.get()};
        for (const auto &model : region_models)
          {
            region_models3d.push_back(model->three_dimensional_twin());
            twins.push_back(region_models3d.back().get());
          }
        materials3d =
          std::make_unique<MaterialRegions<3>>(materials->with_models(twins));
      }
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
        std::make_unique<SurfaceWriter<dim>>(dof_handler,
                                             surface_format,
                                             parameters.output.directory,
                                             parameters.output.base_name);
  }

  // ------------------------------------------------------------- results
  template <int dim>
  StepSummary<dim>
  Problem<dim>::summarize(const LoadStep &step, const NewtonResult &result)
  {
    TimerOutput::Scope scope(timer, "postprocessing");
    StepSummary<dim>   s;
    s.step              = step.step;
    s.load_factor       = system->load_factor();
    s.load_increment    = step.increment;
    s.cut_backs         = step.cut_backs;
    s.newton_iterations = result.iterations();
    s.linear_iterations = result.linear_iterations();
    s.backtracks        = result.backtracks();
    if (parameters.linear_solver.type == LinearSolverType::cg_amg)
      s.amg_setups = linear_solver.n_preconditioner_setups();
    s.newton_history = result.history;
    s.residual       = result.history.back().residual;
    s.energy = elasticity->total_energy(system->solution(), s.load_factor);
    s.min_J  = system->converged_min_J();
    s.inverted_cells = system->converged_inverted_cells();
    const ReportedState state{system->solution(),
                              system->residual_forces(),
                              s.load_factor};
    for (StepReporter<dim> *reporter : reporters)
      reporter->add_columns(state, s);
    // Arc length: where the path became unstable.
    if (parameters.load_stepping.method == LoadControl::arc_length)
      s.more.push_back({"stability", result.stability});
    // Regions: the stored energy of each (the top-level Material's cells
    // are region 0).
    if (!parameters.regions.empty())
      {
        const std::vector<double> energies =
          elasticity->region_energies(system->solution());
        for (unsigned int r = 0; r < energies.size(); ++r)
          s.more.push_back(
            {"energy_region_" +
               std::to_string(r == 0 ? 0 : parameters.regions[r - 1].number),
             energies[r]});
      }

    scope.stop();
    if (writes_frames() && stepping->writes_fields(step.step, s.load_factor))
      write_fields(step.step);
    return s;
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
    pcout << "\nSummary per load step: " << writer->csv_file();
    if (parameters.output.write_vtu)
      pcout << "; fields for ParaView: " << parameters.output.directory << "/"
            << parameters.output.base_name << ".pvd";
    pcout << std::endl;
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace hyperelastic
