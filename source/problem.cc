// Orchestration of a scene: setup, load stepping, post-processing, output.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <hyperelastic/assembly/mixed_assembler.h>
#include <hyperelastic/assembly/warped_assembler.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/mesh.h>
#include <hyperelastic/output/inverted_cells.h>
#include <hyperelastic/problem.h>
#include <hyperelastic/solvers/rigid_body_modes.h>

#include <iomanip>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// The scene's element: (P_k)^dim for the displacement formulation,
    /// (P_k)^dim x P1 for the mixed one (P_k of its 'Mixed element').
    template <int dim>
    FESystem<dim>
    make_finite_element(const ProblemParameters &problem)
    {
      if (!problem.mixed)
        return FESystem<dim>(FE_SimplexP<dim>(problem.fe_degree), dim);
      return FESystem<dim>(
        FE_SimplexP<dim>(displacement_degree(problem.mixed_element)),
        dim,
        FE_SimplexP<dim>(1),
        1);
    }

    /// The material part that replaces the P1 kernel and the generic
    /// loops, if the scene asks for one (null otherwise).
    template <int dim>
    std::unique_ptr<Assembler<dim>>
    make_material_part(const Parameters      &parameters,
                       const DoFHandler<dim> &dof_handler,
                       const Mapping<dim>    &mapping,
                       const Material<dim>   &material)
    {
      if (parameters.problem.mixed)
        return std::make_unique<MixedAssembler<dim>>(
          dof_handler, mapping, material, parameters.problem.mixed_element);
      if (parameters.material.stiffness_warping)
        return std::make_unique<WarpedAssembler<dim>>(dof_handler,
                                                      mapping,
                                                      material);
      return nullptr;
    }

    std::string
    mixed_element_name(const MixedElement element)
    {
      switch (element)
        {
          case MixedElement::mini:
            return "P1-bubble/P1 (MINI, bubble condensed)";
          case MixedElement::stabilized:
            return "P1/P1 stabilized";
          default:
            return "P2/P1 (Taylor-Hood)";
        }
    }
  } // namespace

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
      , triangulation(comm)
      , fe(make_finite_element<dim>(parameters.problem))
      , mapping(FE_SimplexP<dim>(1))
      , dof_handler(triangulation)
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
    TimerOutput::Scope scope(timer, "mesh and setup");
    const auto         mesh_ids = create_mesh(parameters.mesh, triangulation);

    material = create_material<dim>(parameters.material);
    boundary_conditions =
      std::make_unique<BoundaryConditions<dim>>(parameters.loading, mesh_ids);
    if (load_editor)
      load_editor(*boundary_conditions);
    if (boundary_conditions->dirichlet.empty() &&
        !parameters.time_integration.dynamic())
      throw InputError("no Dirichlet condition is set (sections 'Dirichlet 1' "
                       "... 'Dirichlet " +
                       std::to_string(LoadingParameters::max_dirichlet) +
                       "'): rigid-body motions would be free and the "
                       "quasi-static problem singular (in dynamics, "
                       "'Time integration/Scheme', the mass makes it regular)");

    dof_handler.distribute_dofs(fe);
    // Mixed formulation: the dofs are not renumbered by component (each
    // rank's owned dofs then stay one range; deal.II 9.4's DataOut hung on
    // two ranks with the split ranges); the blocks are index sets instead.
    owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);
    pressure_dofs = IndexSet(dof_handler.n_dofs());
    if (parameters.problem.mixed)
      {
        std::vector<types::global_dof_index> dofs(fe.dofs_per_cell);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                if (fe.system_to_component_index(i).first == dim)
                  pressure_dofs.add_index(dofs[i]);
            }
        pressure_dofs.compress();
      }
    // Located once; a point outside the mesh is an input error now, not
    // after the first load step.
    if (!parameters.output.points.empty())
      point_values = std::make_unique<PointValues<dim>>(
        output_points<dim>(parameters.output), dof_handler, mapping, comm);

    boundary_conditions->make_constraints(mapping,
                                          dof_handler,
                                          relevant_dofs,
                                          0.,
                                          u_ghosted,
                                          true,
                                          homogeneous_constraints);

    // All couplings, constrained dofs included: the P1 kernel relies on
    // every node pair having a full dim x dim block in the matrix.
    DynamicSparsityPattern dsp(relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               owned_dofs,
                                               comm,
                                               relevant_dofs);
    tangent.reinit(owned_dofs, owned_dofs, dsp, comm);

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

    if (parameters.linear_solver.type == LinearSolverType::cg_amg)
      linear_solver.set_near_null_space(rigid_body_modes(mapping, dof_handler),
                                        n_rigid_body_modes<dim>,
                                        dim);

    elasticity = std::make_unique<ElasticityOperator<dim>>(
      dof_handler,
      mapping,
      *material,
      *boundary_conditions,
      parameters.problem.fast_p1_assembly,
      make_material_part(parameters, dof_handler, mapping, *material));
    if (parameters.time_integration.dynamic())
      setup_dynamics();
    // A load without a potential makes the tangent non-symmetric.
    linear_solver.set_symmetric(elasticity->is_conservative());
    if (parameters.problem.mixed &&
        parameters.linear_solver.type == LinearSolverType::cg_amg)
      linear_solver.set_saddle_point(saddle_point_preconditioner());
    if (parameters.output.write_vtu)
      material3d = material->three_dimensional_twin();
    writer = std::make_unique<OutputWriter<dim>>(parameters.output, comm);

    // Dofs on each Dirichlet boundary id with the components prescribed there
    // (by one or several sections), for the reaction forces. Ghost cells are
    // visited too: a dof owned here may lie only on a neighbour's boundary
    // face.
    reaction_ids.clear();
    std::vector<std::vector<bool>> prescribed;
    for (const auto &d : boundary_conditions->dirichlet)
      {
        const auto it =
          std::find(reaction_ids.begin(), reaction_ids.end(), d.id);
        const unsigned int r = it - reaction_ids.begin();
        if (it == reaction_ids.end())
          {
            reaction_ids.push_back(d.id);
            prescribed.emplace_back(dim, false);
          }
        for (unsigned int c = 0; c < dim; ++c)
          prescribed[r][c] = prescribed[r][c] || d.mask[c];
      }
    reaction_dofs.assign(reaction_ids.size(), {});
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            for (unsigned int r = 0; r < reaction_ids.size(); ++r)
              if (cell->face(f)->boundary_id() == reaction_ids[r])
                {
                  cell->face(f)->get_dof_indices(face_dofs);
                  for (unsigned int i = 0; i < face_dofs.size(); ++i)
                    {
                      const unsigned int c =
                        fe.face_system_to_component_index(i, f).first;
                      if (c < dim && owned_dofs.is_element(face_dofs[i]) &&
                          prescribed[r][c])
                        reaction_dofs[r].emplace_back(face_dofs[i], c);
                    }
                }
    for (auto &dofs : reaction_dofs)
      {
        std::sort(dofs.begin(), dofs.end());
        dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
      }

    pcout << "hyperelastic: " << dim << "D" << (dim == 2 ? " plane strain" : "");
    if (parameters.problem.mixed)
      pcout << ", mixed u-p " << mixed_element_name(parameters.problem.mixed_element)
            << " simplices, ";
    else
      pcout << ", P" << parameters.problem.fe_degree << " simplices, ";
    pcout << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " unknowns, "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)\n"
          << "material: " << parameters.material.model
          << (parameters.material.stiffness_warping ?
                " of the linear elastic stiffness (no potential; energy and "
                "cell stresses: corotational)" :
                "")
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
    warn_about_volumetric_locking();
  }

  template <int dim>
  std::unique_ptr<SaddlePointPreconditioner>
  Problem<dim>::saddle_point_preconditioner() const
  {
    // The lumped pressure mass int psi_i dV on the owned pressure unknowns.
    VectorType                           mass(owned_dofs, comm);
    const QGaussSimplex<dim>             quadrature(2);
    FEValues<dim>                        values(mapping,
                         fe,
                         quadrature,
                         update_values | update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.dofs_per_cell);
    Vector<double>                       cell_mass(fe.dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          values.reinit(cell);
          cell_mass = 0.;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (fe.system_to_component_index(i).first == dim)
                cell_mass[i] += values.shape_value(i, q) * values.JxW(q);
          mass.add(dofs, cell_mass);
        }
    mass.compress(VectorOperation::add);
    const double mu    = material->small_strain_moduli().mu;
    std::vector<double> shear_schur;
    for (const auto i : owned_dofs)
      if (pressure_dofs.is_element(i))
        shear_schur.push_back(mass(i) / mu);
    return std::make_unique<SaddlePointPreconditioner>(owned_dofs,
                                                       pressure_dofs,
                                                       std::move(shear_schur),
                                                       comm);
  }

  template <int dim>
  void
  Problem<dim>::warn_about_volumetric_locking() const
  {
    // Linear simplices have too few displacement modes to deform at nearly
    // constant volume: when lambda >> mu they lock (far too stiff in
    // bending and shear). Warn; it is not an error.
    const double nu = material->small_strain_moduli().poisson_ratio();
    if (parameters.problem.fe_degree == 1 && nu > 0.45 &&
        !parameters.problem.mixed)
      pcout << "warning: Poisson's ratio " << nu
            << " > 0.45 with P1 elements: expect volumetric locking (too "
               "stiff in bending and shear). Use 'Problem/Formulation = "
               "mixed' (with decoupled neo-Hookean or Mooney-Rivlin), "
               "'Problem/Finite element degree = 2' or a finer mesh, and "
               "check the answer does not change."
            << std::endl;
  }

  // ------------------------------------------------------ NonlinearSystem
  template <int dim>
  bool
  Problem<dim>::assemble_linearization(const bool impose_constraint_increment,
                                       const bool positive_semidefinite)
  {
    bool moves_constraints = false;
    if (impose_constraint_increment)
      {
        TimerOutput::Scope scope(timer, "Dirichlet values");
        // Prescribed minus current values: after a shortened step the next
        // linearization carries what is still missing.
        boundary_conditions->make_constraints(mapping,
                                              dof_handler,
                                              relevant_dofs,
                                              load_factor,
                                              u_ghosted,
                                              false,
                                              increment_constraints);
        double largest = 0.;
        for (const auto &line : increment_constraints.get_lines())
          largest = std::max(largest, std::abs(line.inhomogeneity));
        moves_constraints = Utilities::MPI::max(largest, comm) > 0.;
      }
    TimerOutput::Scope scope(timer, "assembly");
    // The update of this linearization must satisfy these constraints.
    active_constraints =
      moves_constraints ? &increment_constraints : &homogeneous_constraints;
    elasticity->assemble_system(u_ghosted,
                                load_factor,
                                *active_constraints,
                                tangent,
                                rhs,
                                positive_semidefinite);
    return moves_constraints;
  }

  template <int dim>
  unsigned int
  Problem<dim>::solve_linearization(const double forcing)
  {
    {
      TimerOutput::Scope scope(timer, "preconditioner setup");
      linear_solver.prepare(tangent);
    }
    TimerOutput::Scope scope(timer, "linear solve");
    double tolerance =
      std::max(forcing, parameters.linear_solver.relative_tolerance);
    // A linear problem takes this one solve, and no Newton iteration
    // follows to correct it: it also meets Newton's relative residual
    // tolerance where that is the tighter one.
    if (is_linear() && forcing == 0.)
      tolerance =
        std::min(tolerance, parameters.newton.relative_residual_tolerance);
    update                        = 0.;
    const unsigned int iterations =
      linear_solver.solve(tangent, update, rhs, tolerance);
    active_constraints->distribute(update);
    return iterations;
  }

  template <int dim>
  bool
  Problem<dim>::is_linear() const
  {
    // 'Linearize once per step' treats each time step as linear: one full
    // step is accepted.
    return material->is_linear() ||
           (inertia && parameters.time_integration.linearize_once);
  }

  template <int dim>
  bool
  Problem<dim>::has_potential() const
  {
    // The mixed functional is a saddle point in the pressure: no minimum to
    // search along, so the line search tests the residual norm.
    return elasticity->is_conservative() && !parameters.problem.mixed;
  }

  template <int dim>
  std::string
  Problem<dim>::why_no_potential() const
  {
    if (parameters.problem.mixed)
      return "the mixed functional is a saddle point in the pressure";
    if (parameters.material.stiffness_warping)
      return "stiffness warping's forces are not the gradient of an energy";
    return "a load has no potential";
  }

  template <int dim>
  double
  Problem<dim>::directional_derivative() const
  {
    // rhs = -(f_int - f_ext) on the free rows (zero on constrained rows,
    // where the update is zero too).
    return -(rhs * update);
  }

  template <int dim>
  TrialPoint
  Problem<dim>::evaluate_trial(const double alpha, const TrialCheck check)
  {
    TimerOutput::Scope scope(timer, "line search");
    trial = u;
    trial.add(alpha, update);
    u_ghosted   = trial;
    step_length = alpha;

    TrialPoint point;
    if (check == TrialCheck::none)
      return point;
    if (check == TrialCheck::residual)
      {
        point.residual = free_residual_norm(point.residual_noise);
        point.min_J = elasticity->evaluate(u_ghosted, load_factor, false).min_J;
        point.admissible =
          (material->defined_for_inverted_elements() || point.min_J > 0.) &&
          std::isfinite(point.residual);
        return point;
      }
    const EnergyEvaluation e =
      elasticity->evaluate(u_ghosted, load_factor, check == TrialCheck::energy);
    point.min_J = e.min_J;
    if (check == TrialCheck::energy)
      {
        point.energy       = e.energy;
        point.energy_noise = e.noise;
      }
    point.admissible =
      (material->defined_for_inverted_elements() || e.min_J > 0.) &&
      (check != TrialCheck::energy || std::isfinite(e.energy));
    return point;
  }

  template <int dim>
  double
  Problem<dim>::accept_trial()
  {
    u             = trial;
    solution_size = std::max(solution_size, u.l2_norm());
    return step_length * update.l2_norm();
  }

  template <int dim>
  ResidualNorms
  Problem<dim>::residual_norms()
  {
    TimerOutput::Scope scope(timer, "residual");
    double             noise;
    const double       norm = free_residual_norm(noise);
    force_scale             = std::max(
      {force_scale, internal_force.l2_norm(), external_force.l2_norm()});
    return {norm, force_scale, noise};
  }

  template <int dim>
  double
  Problem<dim>::free_residual_norm(double &noise)
  {
    noise    = elasticity->assemble_forces(u_ghosted,
                                        load_factor,
                                        internal_force,
                                        external_force);
    residual = internal_force;
    residual -= external_force;
    VectorType free_residual = residual;
    homogeneous_constraints.set_zero(free_residual);
    return free_residual.l2_norm();
  }

  template <int dim>
  double
  Problem<dim>::solution_scale() const
  {
    return solution_size;
  }

  template <int dim>
  void
  Problem<dim>::verify_converged_state()
  {
    // A model defined at J <= 0 (stable neo-Hookean, corotational, St.
    // Venant-Kirchhoff, linear elastic) can have equilibria with inverted
    // elements as its correct discrete answer, for example near the clamped
    // edges of a crushed body: accepted with a warning unless the scene
    // asks to reject them. For a model undefined there such a state is
    // never a solution.
    const InvertedCells<dim> inverted =
      find_inverted_cells(mapping, dof_handler, u_ghosted);
    converged_min_J          = inverted.min_J;
    converged_inverted_cells = inverted.n_cells;
    if (inverted.n_cells == 0)
      return;

    const bool         defined = material->defined_for_inverted_elements();
    std::ostringstream where;
    where << inverted.n_cells << " inverted cell"
          << (inverted.n_cells == 1 ? "" : "s")
          << " (J <= 0; smallest J = " << inverted.min_J
          << " in the cell centred at (" << inverted.worst_cell_center << "))";
    if (parameters.newton.accepts_inverted_elements(defined))
      {
        pcout << "   warning: equilibrium with " << where.str()
              << ", accepted: the " << parameters.material.model
              << " model is defined there ('Newton/Inverted elements at "
                 "equilibrium = warn')"
              << std::endl;
        return;
      }
    std::ostringstream message;
    message << "Newton converged to an equilibrium with " << where.str();
    if (defined)
      message << ", rejected by 'Newton/Inverted elements at equilibrium = "
                 "reject'; the "
              << parameters.material.model
              << " model is defined for J <= 0 and this can be its correct "
                 "discrete answer: set that entry to 'warn' to accept it";
    else
      message << ", where the " << parameters.material.model
              << " model is not defined (infinite energy): not a solution; "
                 "keep 'Newton/Line search = true' (its J > 0 filter keeps "
                 "this model's iterates admissible) or use a model defined "
                 "for J <= 0 (stable neo-Hookean, corotational)";
    throw ConvergenceFailure(message.str());
  }

  // ------------------------------------------------------- SteppedSystem
  template <int dim>
  void
  Problem<dim>::set_load_factor(const double t)
  {
    load_factor = t;
    if (inertia)
      {
        step_end_time = t;
        load_factor   = integrator->evaluation_time(converged.load_factor, t);
        begin_time_step(t);
      }
    else if (parameters.load_stepping.secant_predictor && previous.valid &&
             !material->is_linear())
      predict(t);
  }

  template <int dim>
  void
  Problem<dim>::setup_dynamics()
  {
    const TimeIntegrationParameters &ti = parameters.time_integration;
    auto term = std::make_unique<InertiaTerm<dim>>(dof_handler,
                                                   ti.density,
                                                   ti.lumped_mass);
    inertia = term.get();
    elasticity->add_term(std::move(term));
    if (ti.stiffness_damping > 0.)
      {
        auto damping = std::make_unique<StiffnessDampingTerm<dim>>(
          dof_handler, mapping, material->small_strain_moduli());
        stiffness_damping = damping.get();
        elasticity->add_term(std::move(damping));
      }
    integrator = std::make_unique<TimeIntegrator>(ti.scheme, ti.mass_damping);
    motion = std::make_unique<Motion<dim>>(dof_handler, mapping, *inertia);
    for (VectorType *v :
         {&velocity, &acceleration, &new_velocity, &new_acceleration})
      v->reinit(owned_dofs, comm);
    if (!ti.initial_velocity.empty())
      {
        const auto v0 =
          parse_vector_function<dim>(ti.initial_velocity,
                                     parameters.loading.constants,
                                     "Time integration/Initial velocity");
        v0->set_time(0.);
        VectorTools::interpolate(mapping, dof_handler, *v0, velocity);
      }
    velocity_ghosted.reinit(owned_dofs, relevant_dofs, comm);
    velocity_ghosted = velocity;
    if (ti.scheme == TimeScheme::newmark)
      {
        // M a_0 = f_ext(0) - f_int(u_0) on the free dofs (the inertia term's
        // scale is still 0); supported dofs start at rest.
        u_ghosted = u;
        elasticity->assemble_forces(u_ghosted, 0., internal_force, external_force);
        residual = external_force;
        residual -= internal_force;
        inertia->solve_mass(residual, homogeneous_constraints, acceleration);
      }
  }

  template <int dim>
  void
  Problem<dim>::begin_time_step(const double t)
  {
    // The step starts from the last converged state (u = u_n).
    double c = 0.;
    integrator->step_target(t - converged.load_factor,
                            converged.u,
                            velocity,
                            acceleration,
                            c,
                            trial);
    inertia->set_step(c, trial);
    if (stiffness_damping)
      {
        double kappa = 0.;
        integrator->velocity_map(
          t - converged.load_factor, converged.u, velocity, kappa, trial);
        stiffness_damping->set_step(
          parameters.time_integration.stiffness_damping * kappa, trial);
      }
  }

  template <int dim>
  void
  Problem<dim>::predict(const double t)
  {
    const double last_increment = converged.load_factor - previous.load_factor;
    if (!(last_increment > 0.))
      return;
    TimerOutput::Scope scope(timer, "predictor");
    // u = u_n + (t - t_n) / (t_n - t_n-1) (u_n - u_n-1); the prescribed
    // displacements are extrapolated too, and the first Newton iteration
    // imposes whatever of them is still missing.
    trial = converged.u;
    trial -= previous.u;
    u = converged.u;
    u.add((t - converged.load_factor) / last_increment, trial);
    u_ghosted = u;
    if (!(elasticity->evaluate(u_ghosted, load_factor, false).min_J > 0.))
      {
        u         = converged.u;
        u_ghosted = u;
        return;
      }
    ++secant_predictions;
  }

  template <int dim>
  void
  Problem<dim>::store_converged_state()
  {
    // The last converged state becomes the one before (the vectors swap;
    // no copy), then the current one is stored.
    if (inertia && converged.valid)
      {
        // The step from converged (t_n, u_n) to its end (implicit
        // midpoint: from the solved midpoint state): new u, v and a.
        integrator->end_state(converged.u, u);
        u_ghosted   = u;
        load_factor = step_end_time;
        integrator->finish_step(load_factor - converged.load_factor,
                                converged.u,
                                velocity,
                                acceleration,
                                u,
                                new_velocity,
                                new_acceleration);
        velocity.swap(new_velocity);
        acceleration.swap(new_acceleration);
        velocity_ghosted = velocity;
      }
    std::swap(previous, converged);
    converged.valid         = true;
    converged.load_factor   = load_factor;
    converged.u             = u;
    converged.force_scale   = force_scale;
    converged.solution_size = solution_size;
  }

  template <int dim>
  void
  Problem<dim>::restore_converged_state()
  {
    // The scales too: a diverging attempt must not loosen the tests of the
    // next one.
    u             = converged.u;
    u_ghosted     = u;
    force_scale   = converged.force_scale;
    solution_size = converged.solution_size;
  }

  // ------------------------------------------------------------- results
  template <int dim>
  StepSummary<dim>
  Problem<dim>::summarize(const LoadStep &step, const NewtonResult &result)
  {
    TimerOutput::Scope scope(timer, "postprocessing");
    StepSummary<dim>   s;
    s.step              = step.step;
    s.load_factor       = load_factor;
    s.load_increment    = step.increment;
    s.cut_backs         = step.cut_backs;
    s.newton_iterations = result.iterations();
    s.linear_iterations = result.linear_iterations();
    s.backtracks        = result.backtracks();
    s.newton_history    = result.history;
    s.residual          = result.history.back().residual;
    s.energy            = elasticity->total_energy(u_ghosted, load_factor);
    if (inertia)
      {
        // Potential energy without the step's inertia and damping terms;
        // kinetic energy
        // and momenta of the converged motion.
        s.energy -= inertia->potential(u_ghosted, load_factor);
        if (stiffness_damping)
          s.energy -= stiffness_damping->potential(u_ghosted, load_factor);
        const MotionMeasures m = motion->measure(u_ghosted, velocity_ghosted);
        s.dynamic            = true;
        s.kinetic_energy     = m.kinetic_energy;
        s.linear_momentum    = m.linear_momentum;
        s.angular_momentum   = m.angular_momentum;
      }
    s.min_J             = converged_min_J;
    s.inverted_cells    = converged_inverted_cells;

    // residual = f_int - f_ext at the converged state: on supported dofs it
    // is the force the support exerts on the body.
    for (unsigned int r = 0; r < reaction_ids.size(); ++r)
      {
        Tensor<1, dim> force;
        for (const auto &[dof, component] : reaction_dofs[r])
          force[component] += residual(dof);
        s.reactions.emplace_back(reaction_ids[r],
                                 Utilities::MPI::sum(force, comm));
      }

    // Bounding box of the deformed vertices.
    for (unsigned int d = 0; d < dim; ++d)
      {
        s.deformed_min[d] = std::numeric_limits<double>::max();
        s.deformed_max[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double x =
                cell->vertex(v)[d] + u_ghosted(cell->vertex_dof_index(v, d));
              s.deformed_min[d] = std::min(s.deformed_min[d], x);
              s.deformed_max[d] = std::max(s.deformed_max[d], x);
            }
    for (unsigned int d = 0; d < dim; ++d)
      {
        s.deformed_min[d] = Utilities::MPI::min(s.deformed_min[d], comm);
        s.deformed_max[d] = Utilities::MPI::max(s.deformed_max[d], comm);
      }

    if (point_values)
      s.point_displacements = point_values->evaluate(u_ghosted);

    if (parameters.problem.mixed)
      {
        double low = std::numeric_limits<double>::max(), high = -low;
        for (const auto i : owned_dofs)
          if (pressure_dofs.is_element(i))
            {
              const double p = u_ghosted(i);
              low            = std::min(low, p);
              high           = std::max(high, p);
            }
        s.has_pressure = true;
        s.pressure_min = Utilities::MPI::min(low, comm);
        s.pressure_max = Utilities::MPI::max(high, comm);
      }

    scope.stop();
    // In dynamics every 'Output every' steps and the last one.
    const bool output_step =
      !inertia || step.step % parameters.time_integration.output_every == 0 ||
      load_factor >= parameters.time_integration.end_time;
    if (parameters.output.write_vtu && output_step)
      write_fields(step.step);
    return s;
  }

  template <int dim>
  void
  Problem<dim>::write_fields(const unsigned int step)
  {
    TimerOutput::Scope output_scope(timer, "output");
    const CellFields   fields = compute_cell_fields(
      dof_handler, mapping, *material, *material3d, u_ghosted);
    writer->write_fields(step,
                         load_factor,
                         dof_handler,
                         mapping,
                         u_ghosted,
                         fields,
                         inertia ? &velocity_ghosted : nullptr);
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
    if (parameters.output.write_vtu)
      write_fields(0);

    const TimeIntegrationParameters &ti = parameters.time_integration;
    const LoadStepper stepper =
      ti.dynamic() ? LoadStepper(parameters.load_stepping,
                                 ti.end_time,
                                 ti.time_step,
                                 pcout) :
                     LoadStepper(parameters.load_stepping,
                                 parameters.loading.n_load_steps,
                                 pcout);
    stepper.run(newton,
                *this,
                [&](const LoadStep &step, const NewtonResult &result) {
                  const StepSummary<dim> summary = summarize(step, result);
                  writer->write_summary(summary);
                  step_summaries.push_back(summary);
                  pcout << "   converged in " << result.iterations()
                        << " Newton iterations (" << result.linear_iterations()
                        << " linear";
                  if (summary.backtracks > 0)
                    pcout << ", " << summary.backtracks
                          << " line-search backtracks";
                  pcout << "); energy " << std::setprecision(10)
                        << summary.energy << ", min J " << summary.min_J
                        << std::setprecision(6) << std::endl;
                });
    pcout << "\nSummary per load step: " << writer->csv_file();
    if (parameters.output.write_vtu)
      pcout << "; fields for ParaView: " << parameters.output.directory << "/"
            << parameters.output.base_name << ".pvd";
    pcout << std::endl;
  }

  namespace
  {
    // Errors that all ranks raise together are rethrown only after the
    // problem (and its timer, which communicates when destroyed) is gone, so
    // that nothing is destroyed while an exception is in flight. Errors of a
    // single rank propagate at once: main() aborts the job.
    template <int dim>
    void
    run_problem(const Parameters &parameters, const MPI_Comm comm)
    {
      std::exception_ptr collective_error;
      {
        Problem<dim> problem(parameters, comm);
        try
          {
            problem.run();
          }
        catch (const InputError &)
          {
            collective_error = std::current_exception();
          }
        catch (const ConvergenceFailure &)
          {
            collective_error = std::current_exception();
          }
      }
      if (collective_error)
        std::rethrow_exception(collective_error);
    }
  } // namespace

  void
  run_scene(const Parameters &parameters, const MPI_Comm comm)
  {
    if (parameters.problem.dimension == 2)
      run_problem<2>(parameters, comm);
    else
      run_problem<3>(parameters, comm);
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace hyperelastic
