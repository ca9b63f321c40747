// Orchestration of a scene: set-up, the steps the driver asks for, the
// summary and output of each converged step. What the unknowns are comes from
// the formulation (formulation/), how steps follow each other from the
// time-stepping driver (dynamics/time_stepping.h), what a step measures from
// the step post-processor (output/step_postprocessor.h).
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_simplex_p.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/contact/self_contact.h>
#include <hyperelastic/formulation/formulation_registry.h>
#include <hyperelastic/mesh/bodies.h>
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
    TimerOutput::Scope scope(timer, "mesh and setup");
    MeshStatistics     mesh_stats;
    const auto         mesh_ids =
      Utilities::MPI::n_mpi_processes(comm) == 1 ?
        create_serial_mesh(parameters.mesh,
                           static_cast<SerialTriangulation<dim> &>(
                             *triangulation),
                           &mesh_stats) :
        create_mesh(parameters.mesh,
                    static_cast<parallel::fullydistributed::Triangulation<dim>
                                  &>(*triangulation),
                    &mesh_stats);
    setup_stages = {{"read", mesh_stats.read_time},
                    {"order", mesh_stats.order_time},
                    {"check", mesh_stats.check_time},
                    {"build", mesh_stats.build_time},
                    {"partition", mesh_stats.partition_time},
                    {"wait", mesh_stats.wait_time},
                    {"describe", mesh_stats.describe_time},
                    {"distribute", mesh_stats.distribute_time}};
    // The stages after the mesh, each from the end of the one before.
    Timer      stage_timer;
    const auto end_stage = [&](const std::string &name) {
      setup_stages.emplace_back(name, stage_timer.wall_time());
      stage_timer.restart();
    };

    material = create_material<dim>(parameters.material);
    boundary_conditions =
      std::make_unique<BoundaryConditions<dim>>(parameters.loading, mesh_ids);
    if (load_editor)
      load_editor(*boundary_conditions);

    dof_handler.distribute_dofs(fe);
    const IndexSet pressure_dofs = formulation->pressure_dofs(dof_handler);
    end_stage("dofs");
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
                                             *material,
                                             *boundary_conditions,
                                             *formulation,
                                             linear_solver,
                                             timer,
                                             pcout});
    end_stage("system");
    if (parameters.linear_solver.type == LinearSolverType::cg_amg)
      linear_solver.set_near_null_space(rigid_body_modes(mapping, dof_handler),
                                        n_rigid_body_modes<dim>,
                                        dim);
    end_stage("null space");

    elasticity = std::make_unique<ElasticityOperator<dim>>(
      dof_handler,
      mapping,
      *material,
      *boundary_conditions,
      parameters.problem.fast_p1_assembly,
      formulation->material_part(dof_handler, mapping, *material));
    end_stage("operator");
    if (!parameters.contact.obstacles.empty())
      {
        auto term = std::make_unique<ObstacleContact<dim>>(
          parameters.contact,
          parameters.loading.constants,
          dof_handler,
          material->small_strain_moduli(),
          parameters.time_integration.dynamic());
        term->set_timer(timer);
        contact = term.get();
        elasticity->add_term(std::move(term));
      }
    if (parameters.contact.self_contact)
      {
        if (pressure_dofs.n_elements() > 0)
          throw InputError(
            "'Contact/Self contact = true' needs 'Problem/Formulation = "
            "displacement' (the mixed formulation's block preconditioner "
            "keeps the tangent's sparsity, which self-contact pairs grow)");
        auto term = std::make_unique<SelfContact<dim>>(
          parameters.contact,
          dof_handler,
          material->small_strain_moduli(),
          parameters.time_integration.dynamic());
        term->set_timer(timer);
        self_contact = term.get();
        elasticity->add_term(std::move(term));
      }
    stepping = create_time_stepping<dim>(
      {parameters.time_integration,
       parameters.load_stepping,
       parameters.loading,
       parameters.contact,
       parameters.material.viscoelasticity.quasi_static_duration,
       dof_handler,
       mapping,
       *material,
       *elasticity,
       system->free_dofs(),
       timer});
    if (boundary_conditions->dirichlet.empty() && stepping->needs_supports())
      throw InputError("no Dirichlet condition is set (sections 'Dirichlet 1' "
                       "... 'Dirichlet " +
                       std::to_string(LoadingParameters::max_dirichlet) +
                       "'): rigid-body motions would be free and the "
                       "quasi-static problem singular (in dynamics, "
                       "'Time integration/Scheme', the mass makes it regular)");
    // Each body of a quasi-static scene must be held: a mesh may hold
    // several (a body clamped, another pressed onto it).
    if (stepping->needs_supports() && !parameters.contact.active())
      {
        std::set<types::boundary_id> ids;
        for (const auto &d : boundary_conditions->dirichlet)
          ids.insert(d.id);
        const std::vector<Body<dim>> bodies = find_bodies(dof_handler, ids);
        for (unsigned int k = 0; k < bodies.size(); ++k)
          if (!bodies[k].held)
            throw InputError(
              bodies[k].describe(k + 1) + " of the mesh's " +
              std::to_string(bodies.size()) +
              " has neither a Dirichlet condition nor a possible contact: it "
              "could move as a rigid body and the quasi-static problem is "
              "singular. Give one of its boundary faces a Dirichlet condition, "
              "or let contact hold it ('Contact/Self contact' or an obstacle)");
      }
    stepping->initialize(system->solution());
    system->attach(*elasticity, *stepping);
    // A load without a potential makes the tangent non-symmetric.
    linear_solver.set_symmetric(elasticity->is_conservative());
    formulation->configure_linear_solver(
      linear_solver, dof_handler, mapping, *material, pressure_dofs);
    const SurfaceFormat surface_format = parameters.output.surface_format;
    if (parameters.output.write_vtu || parameters.output.write_hdf5 ||
        surface_format == SurfaceFormat::ply)
      material3d = material->three_dimensional_twin();
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
      surface = std::make_unique<SurfaceWriter<dim>>(
        dof_handler,
        surface_format,
        parameters.output.directory,
        parameters.output.base_name);
    end_stage("rest");
    print_header();
  }

  template <int dim>
  void
  Problem<dim>::print_header() const
  {
    pcout << "hyperelastic: " << dim << "D" << (dim == 2 ? " plane strain" : "")
          << ", " << formulation->element_description() << ", "
          << triangulation->n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " unknowns, "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)\n"
          << "material: " << parameters.material.model
          << formulation->material_note()
          << " (mu = " << material->small_strain_moduli().mu
          << ", lambda = " << material->small_strain_moduli().lambda << ")\n"
          << "linear solver: " << linear_solver.description() << std::endl;
    if (!elasticity->load_terms().empty())
      {
        pcout << "loads:";
        for (const auto &term : elasticity->load_terms())
          pcout << (&term == &elasticity->load_terms().front() ? " " : ", ")
                << term->name()
                << (!term->depends_on_solution() ? " (dead)"
                    : term->is_conservative()    ? " (follower, conservative)"
                                                 : " (follower)");
        pcout << std::endl;
      }
    if (contact)
      pcout << "contact: " << parameters.contact.obstacles.size()
            << " obstacle(s), barrier distance d_hat = "
            << contact->barrier_distance()
            << ", barrier stiffness kappa = " << contact->barrier_stiffness()
            << (contact->has_friction()
                  ? (parameters.time_integration.dynamic()
                       ? ", friction smoothing eps_v = "
                       : ", friction smoothing eps = ") +
                      std::to_string(contact->friction_smoothing(1.))
                  : std::string())
            << std::endl;
    if (self_contact)
      {
        const auto size = self_contact->boundary_size();
        pcout << "self contact: " << size[0] << " boundary vertices, "
              << size[1] << (dim == 2 ? " segments" : " triangles");
        if (dim == 3)
          pcout << ", " << size[2] << " edges";
        pcout << " (connectivity on every rank; positions exchanged with "
                 "the ranks within reach), barrier distance d_hat = "
              << self_contact->barrier_distance()
              << ", barrier stiffness kappa = "
              << self_contact->barrier_stiffness() << std::endl;
      }
    const std::string warning = formulation->warning(*material);
    if (!warning.empty())
      pcout << warning << std::endl;
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
    s.newton_history    = result.history;
    s.residual          = result.history.back().residual;
    s.energy = elasticity->total_energy(system->solution(), s.load_factor);
    stepping->summarize(system->solution(), s);
    s.min_J          = system->converged_min_J();
    s.inverted_cells = system->converged_inverted_cells();
    postprocessor->measure(system->solution(), system->residual_forces(), s);
    if (contact)
      contact->summarize(system->solution(), s.load_factor, s);
    if (self_contact)
      self_contact->summarize(system->solution(), s);
    // Arc length: where the path became unstable.
    if (parameters.load_stepping.method == LoadControl::arc_length)
      s.more.push_back({"stability", result.stability});

    scope.stop();
    if (writes_frames() && stepping->writes_fields(step.step, s.load_factor))
      write_fields(step.step);
    return s;
  }

  template <int dim>
  void
  Problem<dim>::write_fields(const unsigned int step)
  {
    TimerOutput::Scope output_scope(timer, "output");
    CellFields         fields;
    if (material3d)
      fields = compute_cell_fields(
        dof_handler, mapping, *material, *material3d, system->solution());
    if (surface)
      surface->write(n_frames,
                     system->load_factor(),
                     system->solution(),
                     material3d ? &fields.von_mises : nullptr);
    ++n_frames;
    if (!parameters.output.write_vtu && !parameters.output.write_hdf5)
      return;
    std::vector<typename OutputWriter<dim>::NodalField> nodal;
    if (const VectorType *velocity = stepping->output_velocity())
      nodal.push_back({"velocity", velocity});
    // The force the obstacles and the rest of the boundary (self contact)
    // exert on the body, per boundary vertex.
    VectorType contact_force;
    if (contact || self_contact)
      {
        VectorType owned(dof_handler.locally_owned_dofs(),
                         dof_handler.get_communicator());
        if (contact)
          contact->contact_forces(system->solution(),
                                  system->load_factor(),
                                  owned);
        if (self_contact)
          self_contact->contact_forces(system->solution(),
                                       system->load_factor(),
                                       owned);
        owned.compress(VectorOperation::add);
        contact_force.reinit(system->solution());
        contact_force = owned;
        nodal.push_back({"contact_force", &contact_force});
      }
    writer->write_fields(step,
                         system->load_factor(),
                         dof_handler,
                         mapping,
                         system->solution(),
                         fields,
                         nodal);
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

    // Progress: the elapsed wall time, and the remaining time estimated
    // from the fraction of the load factor (or time) done, where the run's
    // end is known in t (not along an arc-length path, whose t may fall).
    const bool along_path =
      !parameters.time_integration.dynamic() &&
      parameters.load_stepping.method == LoadControl::arc_length;
    const double t_end =
      parameters.time_integration.dynamic()
        ? parameters.time_integration.end_time
        : (along_path ? parameters.load_stepping.maximum_load_factor : 1.);
    const auto start = std::chrono::steady_clock::now();
    stepping->stepper(pcout).run(
      newton,
      *system,
      [&](const LoadStep &step, const NewtonResult &result) {
        const StepSummary<dim> summary = summarize(step, result);
        writer->write_summary(summary.columns());
        const unsigned int every = parameters.output.checkpoint_every;
        if (every > 0 && step.step % every == 0)
          write_checkpoint(step);
        step_summaries.push_back(summary);
        if (step_observer)
          step_observer(summary);
        pcout << "   converged in " << result.iterations()
              << " Newton iterations (" << result.linear_iterations()
              << " linear";
        if (summary.backtracks > 0)
          pcout << ", " << summary.backtracks << " line-search backtracks";
        pcout << "); energy " << std::setprecision(10) << summary.energy
              << ", min J " << summary.min_J << std::setprecision(6)
              << std::endl;
        const double elapsed = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                 .count();
        // The fraction done since this run started (a restart: since the
        // checkpoint).
        const double t0   = resume_point ? resume_point->t : 0.;
        const double done = (step.load_factor - t0) / (t_end - t0);
        pcout << "   progress: t = " << step.load_factor << " of " << t_end
              << ", " << std::fixed << std::setprecision(1) << elapsed
              << " s elapsed";
        if (!along_path && done > 0. && done < 1.)
          pcout << ", about " << elapsed * (1. - done) / done << " s to go";
        pcout << std::defaultfloat << std::setprecision(6) << std::endl;
      },
      resume_point.get());
    if (self_contact)
      {
        // Where self-contact's time went (rank 0; the timing table below
        // holds all contact work in its section "contact").
        const auto &c = self_contact->cost();
        pcout << "\nself contact: " << c.evaluations
              << " evaluations; wall time: exchange " << c.exchange
              << " s, broad phase " << c.broad << " s, narrow phase "
              << c.narrow << " s, CCD " << c.ccd << " s; "
              << c.sparsity_rebuilds << " sparsity rebuilds; "
              << c.received / std::max(c.evaluations, 1u)
              << " doubles received per evaluation" << std::endl;
      }
    pcout << "\nSummary per load step: " << writer->csv_file();
    if (parameters.output.write_vtu)
      pcout << "; fields for ParaView: " << parameters.output.directory << "/"
            << parameters.output.base_name << ".pvd";
    pcout << std::endl;
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace hyperelastic
