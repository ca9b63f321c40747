// CG (or GMRES for a non-symmetric tangent) + ML AMG and direct solves; ML is
// configured through a Teuchos list because deal.II 9.4 cannot pass rotational
// modes through AdditionalData.
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_solver.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/solvers/linear_solver.h>

#include <Teuchos_ParameterList.hpp>

#include <Amesos.h>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  LinearSolver::LinearSolver(const LinearSolverParameters &parameters)
      : parameters(parameters)
  {
    // Trilinos lists every Amesos solver but builds only some: ask before
    // the first solve rather than fail in every Newton iteration. Every
    // rank has the same library, so all throw together.
    if (parameters.type == LinearSolverType::direct)
      {
        Amesos            factory;
        std::string       available;
        const std::string names[] = {"Amesos_Klu",
                                     "Amesos_Umfpack",
                                     "Amesos_Mumps",
                                     "Amesos_Superludist"};
        for (const std::string &name : names)
          if (factory.Query(name))
            available += (available.empty() ? "" : ", ") + name;
        if (!factory.Query(parameters.direct_solver))
          throw InputError("scene entry 'Linear solver/Direct solver' = '" +
                           parameters.direct_solver +
                           "': this Trilinos build does not provide it; "
                           "available here: " +
                           available);
      }
  }

  void
  LinearSolver::set_near_null_space(std::vector<double> modes,
                                    const unsigned int  n_modes,
                                    const unsigned int  n_components)
  {
    null_space         = std::move(modes);
    this->n_modes      = n_modes;
    this->n_components = n_components;
  }

  void
  LinearSolver::prepare(const TrilinosWrappers::SparseMatrix &A)
  {
    if (parameters.type == LinearSolverType::direct)
      return;
    // A new matrix object (the tangent's sparsity grew: self-contact; the
    // trust region's projected tangent) needs a new hierarchy; the kept one
    // would refer to the old matrix. Whether the object is new is decided
    // over all ranks: a reallocated matrix may land at the old address on
    // one rank and not on another, and ranks that disagree would enter ML's
    // collective set-up out of step (seen as an ML error and a hang).
    const bool new_matrix = Utilities::MPI::max(
                              int(&A.trilinos_matrix() != amg_matrix),
                              A.get_mpi_communicator()) != 0;
    if (!amg_built || rebuild_requested ||
        parameters.amg_rebuild_growth == 0. || new_matrix)
      build_amg(A, !new_matrix, true);
    // The stiff couplings' unknowns (set for this tangent's terms): an
    // exact solve on them around the hierarchy.
    if (!saddle_point && parameters.stiff_couplings_solve)
      stiff_correction.initialize(A, stiff_unknowns);
  }

  void
  LinearSolver::set_stiffness_contrast(const double ratio)
  {
    stiffness_contrast = ratio;
  }

  bool
  LinearSolver::amg_for_contrast() const
  {
    using Contrast = LinearSolverParameters::Contrast;
    return parameters.amg_for_contrast == Contrast::on ||
           (parameters.amg_for_contrast == Contrast::automatic &&
            stiffness_contrast > LinearSolverParameters::contrast_threshold);
  }

  std::string
  LinearSolver::description() const
  {
    if (parameters.type == LinearSolverType::direct)
      return parameters.direct_solver + " (direct)";
    if (replacement)
      return krylov_name() + " with " + replacement->description() +
             (symmetric ? "" : "; the tangent is not symmetric");
    if (saddle_point)
      return "GMRES with a block-triangular preconditioner (ML AMG with "
             "rigid-body modes on the displacement block, lumped pressure "
             "mass for the Schur complement); saddle-point tangent";
    return krylov_name() + " with ML AMG (rigid-body near-null space" +
           (amg_for_contrast() ? "; for contrast: energy-minimizing "
                                 "prolongators"
                               : "") +
           ")" + (symmetric ? "" : "; the tangent is not symmetric");
  }

  namespace
  {
    /// ML smoothed aggregation with the full rigid-body near-null space
    /// (set by the caller): the options for 'Linear solver' and a tangent
    /// @p A of @p n_components unknowns per node; @p for_contrast: parts of
    /// very different stiffness.
    Teuchos::ParameterList
    ml_options(const LinearSolverParameters         &parameters,
               const bool                            for_contrast,
               const unsigned int                    n_components,
               const TrilinosWrappers::SparseMatrix &A)
    {
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic = true;
      data.aggregation_threshold =
        for_contrast
          ? std::max(parameters.aggregation_threshold,
                     LinearSolverParameters::contrast_aggregation_threshold)
          : parameters.aggregation_threshold;
      data.smoother_sweeps = parameters.smoother_sweeps;
      data.smoother_type   = "Chebyshev";
      data.coarse_type     = "Amesos-KLU";
      Teuchos::ParameterList              ml_list;
      std::unique_ptr<Epetra_MultiVector> unused_modes;
      data.set_parameters(ml_list, unused_modes, A);
      ml_list.set("PDE equations", static_cast<int>(n_components));
      if (!parameters.smoothed_aggregation)
        ml_list.set("aggregation: damping factor", 0.);
      // Parts of very different stiffness: prolongators that minimize the
      // energy of the coarse basis functions (across a stiff-soft interface
      // a damped-Jacobi step smears them into the stiff part).
      if (for_contrast && parameters.smoothed_aggregation)
        {
          ml_list.set("energy minimization: enable", true);
          ml_list.set("energy minimization: type", 2);
        }
      return ml_list;
    }

    /// A x = b with 'Linear solver/Direct solver'; a ConvergenceFailure
    /// naming it if it fails.
    void
    solve_directly(const LinearSolverParameters         &parameters,
                   const TrilinosWrappers::SparseMatrix &A,
                   TrilinosWrappers::MPI::Vector        &x,
                   const TrilinosWrappers::MPI::Vector  &b)
    {
      SolverControl                                  control(1, 0);
      TrilinosWrappers::SolverDirect::AdditionalData data(
        false, parameters.direct_solver);
      TrilinosWrappers::SolverDirect direct(control, data);
      try
        {
          direct.solve(A, x, b);
        }
      catch (const std::exception &e)
        {
          throw ConvergenceFailure("direct solver " + parameters.direct_solver +
                                   " failed: " + exception_message(e));
        }
    }

    /// The Krylov method @p name with AMG stopped short of its tolerance.
    [[noreturn]] void
    throw_krylov_failure(const std::string &name, const SolverControl &control)
    {
      std::ostringstream message;
      message << std::scientific << std::setprecision(3) << name
              << " with AMG did not converge: residual " << control.last_value()
              << " after " << control.last_step() << " iterations (target "
              << control.tolerance()
              << "); raise 'Linear solver/Max iterations' or use Type = "
                 "direct";
      throw ConvergenceFailure(message.str());
    }
  } // namespace

  void
  LinearSolver::build_amg(const TrilinosWrappers::SparseMatrix &A,
                          const bool may_reuse_aggregates,
                          const bool may_use_replacement)
  {
    const void *matrix = &A.trilinos_matrix();
    replacement_in_use = replacement && may_use_replacement;
    if (replacement_in_use)
      {
        replacement->initialize(A);
        amg_built         = true;
        amg_matrix        = matrix;
        rebuild_requested = false;
        baseline_rate     = -1.;
        ++n_setups;
        return;
      }
    if (saddle_point)
      saddle_point->extract_displacement_block(A);
    // (may_reuse_aggregates: the same matrix object on every rank.)
    if (may_reuse_aggregates && parameters.amg_reuse_aggregates && amg_built)
      {
        // The same matrix object (and, for the saddle point, the same
        // displacement block object) with new values: ML recomputes the
        // prolongators, coarse operators and smoothers on its aggregates.
        amg.reinit();
        rebuild_requested = false;
        baseline_rate     = -1.;
        ++n_setups;
        ++n_refreshes;
        return;
      }
    Teuchos::ParameterList ml_list =
      ml_options(parameters, amg_for_contrast(), n_components, A);
    // The mixed formulation: AMG on the displacement block only.
    if (saddle_point)
      block_null_space = saddle_point->displacement_rows(null_space, n_modes);
    std::vector<double> &modes = saddle_point ? block_null_space : null_space;
    if (n_modes > 0)
      {
        if (!saddle_point)
          AssertDimension(null_space.size(),
                          n_modes * A.local_range().second -
                            n_modes * A.local_range().first);
        ml_list.set("null space: type", "pre-computed");
        ml_list.set("null space: dimension", static_cast<int>(n_modes));
        // A rank without rows still must hand ML a valid pointer.
        static double no_rows = 0.;
        ml_list.set("null space: vectors",
                    modes.empty() ? &no_rows : modes.data());
      }
    if (saddle_point)
      {
        amg.initialize(saddle_point->displacement_block(), ml_list);
        saddle_point->set_amg(amg);
      }
    else
      amg.initialize(A, ml_list);
    amg_built         = true;
    amg_matrix        = matrix;
    rebuild_requested = false;
    baseline_rate     = -1.;
    ++n_setups;
  }

  unsigned int
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &A,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &b,
                      const double                          relative_tolerance,
                      bool                                 *negative_curvature)
  {
    Assert(!negative_curvature || supports_trust_region(), ExcInternalError());
    if (negative_curvature)
      *negative_curvature = false;
    if (parameters.type == LinearSolverType::direct)
      {
        solve_directly(parameters, A, x, b);
        return 0;
      }

    const bool fresh = baseline_rate < 0.;
    // Iterations per decade of residual reduction, so that solves to
    // different (inexact Newton) tolerances compare.
    const double decades = std::max(1., -std::log10(relative_tolerance));
    const double rate_limit =
      std::max(parameters.amg_rebuild_growth * baseline_rate,
               baseline_rate + 5. / decades);
    // An old hierarchy gets a few times the iterations that would ask for
    // a rebuild: if it has stopped working (its smoother tuned to another
    // tangent can even make CG diverge), waiting for the iteration limit
    // would cost more than the rebuild.
    const unsigned int limit =
      fresh ? parameters.max_iterations
            : std::min<unsigned int>(parameters.max_iterations,
                                     std::ceil(3. * rate_limit * decades));
    SolverControl control =
      run_cg(A, x, b, relative_tolerance, limit, negative_curvature);
    unsigned int iterations = control.last_step();
    // Indefinite: the caller follows the curvature (no rebuild helps).
    if (negative_curvature && *negative_curvature)
      return iterations;
    // Builds anew for this tangent and solves once more (the same decision
    // on every rank: CG's counts are global).
    const auto retry = [&](const bool with_replacement) {
      build_amg(A, false, with_replacement);
      x       = 0.;
      control = run_cg(A,
                       x,
                       b,
                       relative_tolerance,
                       parameters.max_iterations,
                       negative_curvature);
      iterations += control.last_step();
      baseline_rate = control.last_step() / decades;
    };
    const auto indefinite = [&]() {
      return negative_curvature && *negative_curvature;
    };
    // An old hierarchy failed: a new one.
    if (control.last_check() != SolverControl::success && !fresh)
      retry(true);
    // The replacement (two-level) failed for this tangent (CG near a limit
    // point, where the tangent is nearly singular or indefinite): ML AMG on
    // the whole tangent, until the next rebuild.
    if (control.last_check() != SolverControl::success && replacement_in_use &&
        !indefinite())
      retry(false);
    if (indefinite())
      return iterations;
    if (control.last_check() != SolverControl::success)
      throw_krylov_failure(krylov_name(), control);
    const double rate = control.last_step() / decades;
    if (fresh)
      baseline_rate = rate;
    else if (rate > rate_limit)
      rebuild_requested = true;
    return iterations;
  }

  LinearSolver::TrustRegionSolve
  LinearSolver::solve_in_trust_region(const TrilinosWrappers::SparseMatrix &A,
                                      TrilinosWrappers::MPI::Vector        &x,
                                      const TrilinosWrappers::MPI::Vector  &b,
                                      const double relative_tolerance,
                                      const double radius) const
  {
    Assert(supports_trust_region(), ExcInternalError());
    TrustRegionSolve result;
    x                   = 0.;
    const double b_norm = b.l2_norm();
    if (!(b_norm > 0.))
      return result;
    // x + tau p on the boundary |x + tau p| = radius (tau >= 0).
    const auto to_boundary = [&](const TrilinosWrappers::MPI::Vector &p) {
      const double pp = p * p, xp = x * p, xx = x * x;
      const double tau =
        (-xp + std::sqrt(std::max(0., xp * xp + pp * (radius * radius - xx)))) /
        pp;
      x.add(tau, p);
      result.on_boundary = true;
    };
    // r = b - A x, z = M^-1 r, p the search direction.
    TrilinosWrappers::MPI::Vector r(b), z(b), p(b), Ap(b);
    precondition(z, r);
    double rz = r * z;
    // The preconditioner must be positive (the caller builds it on a
    // positive semi-definite matrix); if it is not, the steepest descent
    // direction to the boundary.
    p = rz > 0. ? z : b;
    if (!(rz > 0.))
      {
        to_boundary(p);
        return result;
      }
    const double target = relative_tolerance * b_norm;
    for (unsigned int k = 0; k < parameters.max_iterations; ++k)
      {
        ++result.iterations;
        A.vmult(Ap, p);
        const double curvature = p * Ap;
        if (!(curvature > 0.))
          {
            result.negative_curvature = true;
            // Without a radius (a probe), x stays where CG had it.
            if (std::isfinite(radius))
              to_boundary(p);
            return result;
          }
        const double alpha = rz / curvature;
        // Beyond the radius: the step stops on the boundary. The
        // preconditioned iterates need not grow monotonically in this
        // norm, so every iterate is checked.
        const double xp = x * p, xx = x * x, pp = p * p;
        if (xx + 2. * alpha * xp + alpha * alpha * pp >= radius * radius)
          {
            to_boundary(p);
            return result;
          }
        x.add(alpha, p);
        r.add(-alpha, Ap);
        if (r.l2_norm() <= target)
          return result;
        precondition(z, r);
        const double rz_new = r * z;
        if (!(rz_new > 0.))
          return result;
        p.sadd(rz_new / rz, 1., z);
        rz = rz_new;
      }
    return result;
  }

  template <typename Preconditioner>
  void
  LinearSolver::krylov(const TrilinosWrappers::SparseMatrix &A,
                       TrilinosWrappers::MPI::Vector        &x,
                       const TrilinosWrappers::MPI::Vector  &b,
                       const Preconditioner                 &preconditioner,
                       SolverControl                        &control) const
  {
    if (symmetric)
      SolverCG<TrilinosWrappers::MPI::Vector>(control).solve(A,
                                                             x,
                                                             b,
                                                             preconditioner);
    else
      {
        // Restarted GMRES; right preconditioning, so that the residual it
        // tests is the true one, as for CG.
        SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData data(50,
                                                                        true);
        SolverGMRES<TrilinosWrappers::MPI::Vector>(control, data)
          .solve(A, x, b, preconditioner);
      }
  }

  void
  LinearSolver::precondition(TrilinosWrappers::MPI::Vector       &z,
                             const TrilinosWrappers::MPI::Vector &r) const
  {
    if (stiff_correction.active())
      stiff_correction.vmult(z, r, [this](VectorType &y, const VectorType &s) {
        whole_tangent_preconditioner(y, s);
      });
    else
      whole_tangent_preconditioner(z, r);
  }

  void
  LinearSolver::whole_tangent_preconditioner(
    TrilinosWrappers::MPI::Vector       &z,
    const TrilinosWrappers::MPI::Vector &r) const
  {
    if (replacement_in_use)
      replacement->vmult(z, r);
    else
      amg.vmult(z, r);
  }

  SolverControl
  LinearSolver::run_cg(const TrilinosWrappers::SparseMatrix &A,
                       TrilinosWrappers::MPI::Vector        &x,
                       const TrilinosWrappers::MPI::Vector  &b,
                       const double                          tolerance,
                       const unsigned int                    max_iterations,
                       bool *negative_curvature) const
  {
    SolverControl control(max_iterations, tolerance * b.l2_norm());
    if (negative_curvature)
      {
        // Preconditioned CG as deal.II's SolverCG runs it (from x, the
        // residual norm tested against the same control), watching the
        // curvature of every search direction.
        TrilinosWrappers::MPI::Vector r(b), z(b), p(b), Ap(b);
        A.vmult(Ap, x);
        r.add(-1., Ap);
        double rz = 0.;
        for (unsigned int k = 0;; ++k)
          {
            if (control.check(k, r.l2_norm()) != SolverControl::iterate)
              return control;
            precondition(z, r);
            const double rz_new = r * z;
            // A preconditioner that is not positive: an AMG built on an
            // indefinite tangent (this one or an earlier one). CG cannot
            // go on; the caller's trust region, preconditioned by a
            // positive AMG, finds out whether A is indefinite.
            if (!(rz_new > 0.))
              break;
            if (k == 0)
              p = z;
            else
              p.sadd(rz_new / rz, 1., z);
            rz = rz_new;
            A.vmult(Ap, p);
            const double curvature = p * Ap;
            if (!(curvature > 0.))
              break;
            x.add(rz / curvature, p);
            r.add(-rz / curvature, Ap);
          }
        *negative_curvature = true;
        return control;
      }
    try
      {
        if (saddle_point)
          {
            SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData data(
              100, true);
            SolverGMRES<TrilinosWrappers::MPI::Vector>(control, data)
              .solve(A, x, b, *saddle_point);
          }
        else if (stiff_correction.active())
          krylov(A, x, b, Preconditioning{*this}, control);
        else if (replacement_in_use)
          krylov(A, x, b, *replacement, control);
        else
          krylov(A, x, b, amg, control);
      }
    catch (const SolverControl::NoConvergence &)
      {
        // Reported by the caller, which may first retry.
      }
    return control;
  }
} // namespace hyperelastic
