// Problem's output: the run's header, the summary, lines and CSV row of each
// converged step, the frames (VTU/HDF5 fields and surface files), and what
// the run shows its callers (the solution, the tangent, the counts).
#include <deal.II/base/mpi.h>

#include <hyperelastic/dynamics/time_stepping.h>
#include <hyperelastic/equilibrium_system/equilibrium_system.h>
#include <hyperelastic/materials/region_properties.h>
#include <hyperelastic/problem/problem.h>

#include <chrono>
#include <iomanip>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  void
  Problem<dim>::print_header() const
  {
    pcout << "hyperelastic: " << dim << "D" << (dim == 2 ? " plane strain" : "")
          << ", " << model.formulation->element_description() << ", "
          << model.triangulation->n_global_active_cells() << " cells, "
          << model.dof_handler.n_dofs() << " unknowns, "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)\n"
          << "material: " << parameters.material.model
          << model.formulation->material_note()
          << " (mu = " << model.material->small_strain_moduli().mu
          << ", lambda = " << model.material->small_strain_moduli().lambda
          << ")\n"
          << "linear solver: " << linear_solver->description() << std::endl;
    pcout << model.generated_mesh;
    print_regions();
    for (const BoundaryRegions::Region &region : model.boundary_regions.regions)
      {
        pcout << "boundary region '" << region.condition << "' (";
        for (const std::string &section : region.sections)
          pcout << (&section == &region.sections.front() ? "" : ", ")
                << section;
        pcout << "): boundary id " << region.id << ", " << region.n_faces
              << " faces" << std::endl;
      }
    if (!model.elasticity->energy_terms().empty())
      {
        pcout << "loads:";
        for (const auto &term : model.elasticity->energy_terms())
          pcout << (&term == &model.elasticity->energy_terms().front() ? " "
                                                                       : ", ")
                << term->name()
                << (term->kind() == TermKind::dead ? " (dead)"
                    : term->kind() == TermKind::conservative
                      ? " (follower, conservative)"
                      : " (follower)");
        pcout << std::endl;
      }
    if (pcout.is_active())
      for (const StepReporter<dim> *reporter : reporters)
        reporter->print_header(pcout.get_stream());
    // Without regions the top-level material; with them each region that
    // has cells.
    for (unsigned int r = 0; r < model.materials->n_regions(); ++r)
      if (r > 0 || parameters.regions.empty() ||
          model.cell_regions.n_cells[0] > 0)
        {
          const std::string warning =
            model.formulation->warning(model.materials->model(r));
          if (!warning.empty())
            pcout << (parameters.regions.empty()
                        ? std::string()
                        : (r == 0 ? std::string("top-level Material: ")
                                  : parameters.regions[r - 1].name() + ": "))
                  << warning << std::endl;
        }
  }

  template <int dim>
  void
  Problem<dim>::print_regions() const
  {
    if (parameters.regions.empty())
      return;
    const auto moduli = [](const Material<dim> &m) {
      std::ostringstream text;
      text << " (mu = " << m.small_strain_moduli().mu
           << ", lambda = " << m.small_strain_moduli().lambda << ")";
      return text.str();
    };
    pcout << "regions: region 0 (top-level Material, "
          << parameters.material.model << ") " << model.cell_regions.n_cells[0]
          << " cells";
    for (unsigned int r = 0; r < parameters.regions.size(); ++r)
      {
        const RegionParameters &region = parameters.regions[r];
        pcout << "\n  " << region.name() << " ("
              << (region.material_id >= 0
                    ? "Material id " + std::to_string(region.material_id)
                    : "Cells '" + region.cells + "'")
              << "): " << region.material.model
              << moduli(*model.region_models[r]) << ", "
              << model.cell_regions.n_cells[r + 1] << " cells";
      }
    if (model.contact_reporter)
      {
        const LameParameters contact = boundary_moduli(*model.materials,
                                                       model.cell_regions,
                                                       *model.triangulation);
        pcout << "\n  contact defaults from the stiffest region at the "
                 "boundary (mu = "
              << contact.mu << ", lambda = " << contact.lambda << ")";
      }
    pcout << std::endl;
  }

  template <int dim>
  unsigned int
  Problem<dim>::n_secant_predictions() const
  {
    return stepping->n_predictions();
  }

  template <int dim>
  const MatrixType &
  Problem<dim>::tangent_matrix() const
  {
    return system->tangent_matrix();
  }

  template <int dim>
  const VectorType &
  Problem<dim>::solution() const
  {
    return system->solution();
  }

  template <int dim>
  const VectorType &
  Problem<dim>::residual_forces() const
  {
    return system->residual_forces();
  }

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
    s.stop              = step.stop;
    s.newton_iterations = result.iterations();
    s.linear_iterations = result.linear_iterations();
    s.backtracks        = result.backtracks();
    if (parameters.linear_solver.type == LinearSolverType::cg_amg)
      s.amg_setups = linear_solver->n_preconditioner_setups();
    s.newton_history = result.history;
    s.residual       = result.history.back().residual;
    s.energy =
      model.elasticity->total_energy(system->solution(), s.load_factor);
    s.min_J          = system->converged_min_J();
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
          model.elasticity->region_energies(system->solution());
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
  Problem<dim>::report_step(const LoadStep                              &step,
                            const NewtonResult                          &result,
                            const std::chrono::steady_clock::time_point &start)
  {
    const StepSummary<dim> summary = summarize(step, result);
    writer->write_summary(summary.columns());
    const unsigned int every = parameters.output.checkpoint_every;
    if (every > 0 && step.step % every == 0)
      write_checkpoint(step);
    step_summaries.push_back(summary);
    if (step_observer)
      step_observer(summary);
    pcout << "   converged in " << result.iterations() << " Newton iterations ("
          << result.linear_iterations() << " linear";
    if (summary.backtracks > 0)
      pcout << ", " << summary.backtracks << " line-search backtracks";
    pcout << "); energy " << std::setprecision(10) << summary.energy
          << ", min J " << summary.min_J << std::setprecision(6) << std::endl;

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
    const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    // The fraction done since this run started (a restart: since the
    // checkpoint).
    const double t0   = resume_point ? resume_point->t : 0.;
    const double done = (step.load_factor - t0) / (t_end - t0);
    newton_in_all           = step.newton_in_all;
    newton_per_nominal_step = step.newton_per_nominal_step();
    smallest_step_fraction =
      step.nominal > 0. ? step.smallest_increment / step.nominal : 0.;
    pcout << "   progress: t = " << step.load_factor << " of " << t_end << ", "
          << std::fixed << std::setprecision(1) << elapsed << " s elapsed";
    if (!along_path && done > 0. && done < 1.)
      pcout << ", about " << elapsed * (1. - done) / done << " s to go";
    if (!along_path)
      pcout << "; " << newton_per_nominal_step
            << " Newton iterations per nominal step";
    pcout << std::defaultfloat << std::setprecision(6) << std::endl;
  }

  template <int dim>
  void
  Problem<dim>::write_fields(const unsigned int step)
  {
    TimerOutput::Scope output_scope(timer, "output");
    CellFields         fields;
    if (model.material3d)
      fields = compute_cell_fields(model.dof_handler,
                                   model.mapping,
                                   *model.materials,
                                   *model.materials3d,
                                   system->solution());
    if (!parameters.regions.empty())
      {
        // The number k of 'Region k' (0: the top-level Material).
        fields.region.reinit(model.triangulation->n_active_cells());
        for (const auto &cell : model.triangulation->active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const unsigned int r =
                model.cell_regions(cell->active_cell_index());
              fields.region[cell->active_cell_index()] =
                r == 0 ? 0. : parameters.regions[r - 1].number;
            }
      }
    if (surface)
      surface->write(n_frames,
                     system->load_factor(),
                     system->solution(),
                     model.material3d ? &fields.von_mises : nullptr);
    ++n_frames;
    if (!parameters.output.write_vtu && !parameters.output.write_hdf5)
      return;
    std::vector<NodalField> nodal;
    const ReportedState     state{system->solution(),
                              system->residual_forces(),
                              system->load_factor()};
    for (StepReporter<dim> *reporter : reporters)
      reporter->add_nodal_fields(state, nodal);
    writer->write_fields(step,
                         system->load_factor(),
                         model.dof_handler,
                         model.mapping,
                         system->solution(),
                         fields,
                         nodal);
  }

  template void
  Problem<2>::print_header() const;
  template void
  Problem<3>::print_header() const;
  template void
  Problem<2>::report_step(const LoadStep &,
                          const NewtonResult &,
                          const std::chrono::steady_clock::time_point &);
  template void
  Problem<3>::report_step(const LoadStep &,
                          const NewtonResult &,
                          const std::chrono::steady_clock::time_point &);
  template void
  Problem<2>::write_fields(unsigned int);
  template void
  Problem<3>::write_fields(unsigned int);
  template StepSummary<2>
  Problem<2>::summarize(const LoadStep &, const NewtonResult &);
  template StepSummary<3>
  Problem<3>::summarize(const LoadStep &, const NewtonResult &);
  template unsigned int
  Problem<2>::n_secant_predictions() const;
  template unsigned int
  Problem<3>::n_secant_predictions() const;
  template const MatrixType &
  Problem<2>::tangent_matrix() const;
  template const MatrixType &
  Problem<3>::tangent_matrix() const;
  template const VectorType &
  Problem<2>::solution() const;
  template const VectorType &
  Problem<3>::solution() const;
  template const VectorType &
  Problem<2>::residual_forces() const;
  template const VectorType &
  Problem<3>::residual_forces() const;
} // namespace hyperelastic
