// Newton iteration with a backtracking line search on the total potential
// energy (or the residual norm), the tangent policy's fallback after a failed
// iteration, residual and update tests, lagged equations, and a printed
// table.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/solvers/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

namespace hyperelastic
{
  unsigned int
  NewtonResult::linear_iterations() const
  {
    unsigned int n = 0;
    for (const auto &row : history)
      n += row.linear_iterations;
    return n;
  }

  unsigned int
  NewtonResult::backtracks() const
  {
    unsigned int n = 0;
    for (const auto &row : history)
      n += row.backtracks;
    return n;
  }

  NewtonSolver::NewtonSolver(const NewtonParameters    &parameters,
                             dealii::ConditionalOStream pcout,
                             const bool                 verbose)
      : parameters(parameters)
      , pcout(pcout)
      , verbose(verbose)
  {
  }

  NewtonSolver
  NewtonSolver::with_settings(const NewtonParameters &settings) const
  {
    return NewtonSolver(settings, pcout, verbose);
  }

  namespace
  {
    /// The table's header; its merit column is the energy, or the residual
    /// norm of the accepted trial when the line search tests that.
    std::string
    header(const bool residual_merit)
    {
      return std::string("   iteration      residual        update"
                         "      step") +
             (residual_merit ? "   merit |res|" : "        energy") +
             "     min J  lin.its";
    }

    std::string
    format_row(const NewtonIteration &row)
    {
      std::ostringstream s;
      s << std::setw(8) << row.iteration << std::scientific
        << std::setprecision(3) << std::setw(18) << row.residual
        << std::setw(14) << row.update << std::defaultfloat
        << std::setprecision(4) << std::setw(10) << row.step_length
        << std::scientific;
      // Quantities a plain Newton step does not compute are left blank.
      s << std::setprecision(6) << std::setw(14);
      if (std::isfinite(row.energy))
        s << row.energy;
      else if (std::isfinite(row.trial_residual))
        s << row.trial_residual;
      else
        s << "";
      s << std::defaultfloat << std::setprecision(3) << std::setw(10);
      if (std::isfinite(row.min_J))
        s << row.min_J;
      else
        s << "";
      s << std::setw(9) << row.linear_iterations
        << (row.projected                  ? "  projected"
            : row.projected_where_inverted ? "  projected where J <= 0"
                                           : "");
      if (row.feasible_step < 1.)
        s << "  feasible step " << row.feasible_step;
      if (std::isfinite(row.trust_radius))
        s << "  trust region " << std::scientific << std::setprecision(2)
          << row.trust_radius << std::defaultfloat
          << (row.negative_curvature ? " (negative curvature)" : "");
      if (row.softened_predictor)
        s << "  (predictor inverted cells: increment extended at zero "
             "Poisson's ratio)";
      return s.str();
    }
  } // namespace

  std::string
  NewtonSolver::table(const NewtonResult &result)
  {
    std::string text = header(result.residual_merit);
    for (const auto &row : result.history)
      text += "\n" + format_row(row);
    return text;
  }

  double
  NewtonSolver::forcing_term(const std::vector<NewtonIteration> &history,
                             const double step_start_residual,
                             const double residual_target) const
  {
    if (!parameters.inexact)
      return 0.;
    const double eta_max = parameters.max_forcing;
    // The first two iterations of a load step have no residual ratio yet.
    if (history.size() < 2)
      return eta_max;
    const double gamma = 0.9;
    // How far the last iteration took the residual of the equations it
    // solved: after a lagged update the residual before it is the new
    // equations' (the rows' residuals before and after an update belong to
    // different equations, and their ratio measures the update, not how
    // well the linearization predicted the step).
    const double r_new = history.back().residual;
    const double r_old = std::isfinite(step_start_residual)
                           ? step_start_residual
                           : history[history.size() - 2].residual;
    if (!(r_old > 0.) || !std::isfinite(r_new))
      return eta_max;
    double       eta      = gamma * (r_new / r_old) * (r_new / r_old);
    const double previous = history.back().forcing;
    // Safeguard: do not let the tolerance drop abruptly while the previous
    // one was still large (Eisenstat and Walker 1996).
    if (gamma * previous * previous > 0.1)
      eta = std::max(eta, gamma * previous * previous);
    // No oversolving: a linear residual below half the nonlinear target
    // buys nothing.
    if (r_new > 0.)
      eta = std::max(eta, 0.5 * residual_target / r_new);
    return std::min(eta, eta_max);
  }

  bool
  NewtonSolver::line_search(NonlinearSystem  &system,
                            const bool        has_potential,
                            const bool        test_merit,
                            const TrialPoint &current,
                            NewtonIteration  &row,
                            std::string      &failure) const
  {
    using Check               = NonlinearSystem::TrialCheck;
    const bool  test_residual = test_merit && !has_potential;
    const bool  test_energy   = test_merit && !test_residual;
    const Check check         = !parameters.line_search ? Check::none
                                : test_energy           ? Check::energy
                                : test_residual         ? Check::residual
                                                        : Check::admissibility;
    // Sufficient decrease E(alpha) <= E(0) + c alpha dE/dalpha(0).
    const double slope = test_energy ? system.directional_derivative() : 0.;
    if (test_energy && slope == 0.)
      {
        // Not an indefinite tangent: no direction at all, away from the
        // equilibrium (attempt() takes a state in equilibrium as it is).
        failure = "the Newton direction is zero at a residual above its "
                  "target (the linear solve returned no update)";
        return false;
      }
    if (test_energy && !(slope < 0.))
      {
        // An indefinite tangent can give a direction along which the energy
        // grows: no step length helps.
        failure = "the Newton direction is not a descent direction (the "
                  "tangent is indefinite)";
        return false;
      }

    row.backtracks = 0;
    // The first trial is the full step or, where it would leave the
    // feasible set (a vertex through an obstacle), the step cut to it.
    row.feasible_step = std::min(1., system.largest_feasible_step());
    for (double alpha = row.feasible_step;; alpha *= 0.5)
      {
        const TrialPoint trial = system.evaluate_trial(alpha, check);
        bool             ok    = trial.admissible;
        if (ok && test_energy)
          // Near the solution the decrease is below the energy's round-off;
          // the noise allowance keeps Newton's full steps there.
          ok = trial.energy <= current.energy +
                                 parameters.armijo_constant * alpha * slope +
                                 current.energy_noise + trial.energy_noise;
        if (ok && test_residual)
          // Without a potential: sufficient decrease of the residual norm,
          // which the Newton direction gives for small enough steps.
          ok = trial.residual <=
               (1. - parameters.armijo_constant * alpha) * current.residual +
                 current.residual_noise + trial.residual_noise;
        if (ok)
          {
            take_trial(alpha, test_energy, current, trial, row);
            row.trial_residual = trial.residual;
            return true;
          }
        ++row.backtracks;
        if (0.5 * alpha < parameters.minimum_step_length)
          {
            std::ostringstream reason;
            reason << "line search failed: no step length down to "
                   << parameters.minimum_step_length
                   << " (Newton/Minimum step length) gives "
                   << (trial.admissible
                         ? (test_residual
                              ? "enough decrease of the residual norm"
                              : "enough decrease of the energy")
                         : "an admissible state (elements would invert or the "
                           "energy is not finite)");
            failure = reason.str();
            return false;
          }
      }
  }

  bool
  NewtonSolver::in_equilibrium(NonlinearSystem &system) const
  {
    const ResidualNorms norms = system.residual_norms();
    return norms.residual <= ConvergenceTest(parameters).residual_target(norms);
  }

  bool
  NewtonSolver::attempt(NonlinearSystem                     &system,
                        const NonlinearSystem::Properties   &properties,
                        const TangentProjection              projection,
                        const bool                           soften_predictor,
                        SolveState                          &state,
                        NewtonIteration                     &row,
                        NonlinearSystem::LinearizationSolve &solve,
                        std::string                         &failure) const
  {
    try
      {
        state.moving_constraints =
          system.assemble_linearization(state.moving_constraints, projection);
        solve.watch_curvature =
          solve.watch_curvature && !state.moving_constraints;
        system.solve_linearization(row.forcing, solve);
        if (solve.negative_curvature)
          {
            failure = "the tangent is indefinite (negative curvature in "
                      "the Krylov solve)";
            return false;
          }
        if (soften_predictor && state.moving_constraints && state.softening)
          {
            unsigned int extension_iterations = 0;
            solve.softened_predictor =
              state.softening->soften_predictor(extension_iterations);
            solve.linear_iterations += extension_iterations;
          }

        // A state already in equilibrium (an unloaded scene, a body at
        // rest, a load that starts later): the residual meets its target
        // and the direction does not descend (zero at a zero residual).
        // Newton stays where it is; no step length is searched for.
        if (!state.moving_constraints &&
            !(system.directional_derivative() < 0.) && in_equilibrium(system))
          {
            system.evaluate_trial(0., NonlinearSystem::TrialCheck::none);
            take_trial(0., false, state.current, state.current, row);
            return true;
          }
        const bool test_merit =
          parameters.line_search && !state.moving_constraints;
        // The merit of the current iterate, where not known yet.
        if (test_merit && properties.has_potential &&
            !std::isfinite(state.current.energy))
          state.current =
            system.evaluate_trial(0., NonlinearSystem::TrialCheck::energy);
        if (test_merit && !properties.has_potential &&
            !std::isfinite(state.current.residual))
          state.current =
            system.evaluate_trial(0., NonlinearSystem::TrialCheck::residual);
        return line_search(system,
                           properties.has_potential,
                           test_merit,
                           state.current,
                           row,
                           failure);
      }
    catch (const ConvergenceFailure &e)
      {
        // A Krylov failure (an indefinite tangent can break CG).
        failure = e.what();
        return false;
      }
  }

  bool
  NewtonSolver::attempt_trust_region(NonlinearSystem        &system,
                                     const TangentProjection projection,
                                     SolveState             &state,
                                     NewtonIteration        &row,
                                     NonlinearSystem::LinearizationSolve &solve,
                                     std::string &failure) const
  {
    using Check = NonlinearSystem::TrialCheck;
    try
      {
        if (system.assemble_linearization(false, projection))
          {
            // A term's admissible set is still on its way: a predictor.
            state.moving_constraints = true;
            failure = "a load term still moves within the step";
            return false;
          }
        TrustRegionSystem::Step step;
        state.trust_region->solve_linearization_in_trust_region(
          row.forcing, state.trust_radius, solve, step);
        row.trust_radius       = state.trust_radius;
        row.negative_curvature = step.negative_curvature;
        if (!std::isfinite(state.current.energy))
          state.current = system.evaluate_trial(0., Check::energy);
        const double slope = system.directional_derivative();
        if (!(slope < 0.) || !(step.norm > 0.))
          {
            // Only round-off can make the truncated CG's step ascend.
            failure = "the trust-region step is not a descent direction";
            return false;
          }
        row.backtracks    = 0;
        row.feasible_step = std::min(1., system.largest_feasible_step());
        for (double alpha = row.feasible_step;; alpha *= 0.5)
          {
            const TrialPoint trial =
              system.evaluate_trial(alpha, Check::energy);
            const double predicted =
              -(alpha * slope + 0.5 * alpha * alpha * step.curvature);
            const double actual = state.current.energy - trial.energy;
            const double noise =
              state.current.energy_noise + trial.energy_noise;
            if (trial.admissible &&
                actual + noise >= parameters.armijo_constant * predicted)
              {
                // The radius follows how far the model can be trusted.
                const double length = alpha * step.norm;
                // Shortened (backtracked): the model held to about the
                // step taken; at most a factor 4 per iteration, so that
                // one sharp barrier or cut does not stall the descent.
                if (row.backtracks > 0)
                  state.trust_radius =
                    std::max(length, 0.25 * state.trust_radius);
                else if (actual < 0.25 * predicted)
                  state.trust_radius = 0.25 * length;
                else if (actual > 0.75 * predicted && step.on_boundary &&
                         alpha == 1.)
                  state.trust_radius *= 2.;
                take_trial(alpha, true, state.current, trial, row);
                return true;
              }
            ++row.backtracks;
            if (0.5 * alpha < parameters.minimum_step_length)
              {
                state.trust_radius *= 0.25;
                failure = "the trust-region step found no decrease of the "
                          "energy down to the step length " +
                          std::to_string(parameters.minimum_step_length) +
                          " (Newton/Minimum step length)";
                return false;
              }
          }
      }
    catch (const ConvergenceFailure &e)
      {
        failure = e.what();
        return false;
      }
  }

  NewtonIteration
  NewtonSolver::iterate(NonlinearSystem                   &system,
                        const NonlinearSystem::Properties &properties,
                        const TangentPolicy               &policy,
                        const unsigned int                 it,
                        SolveState                        &state,
                        const NewtonResult                &result) const
  {
    const std::vector<NewtonIteration> &history = result.history;
    const double nan            = std::numeric_limits<double>::quiet_NaN();
    const bool   first_of_solve = it == state.budget_start + 1;
    IterationPlan plan;
    plan.projection =
      policy.projection(first_of_solve,
                        state.current.residual,
                        first_of_solve ? nan
                                       : history[state.budget_start].residual);
    // The smallest J of the current iterate (not known before the first
    // iteration).
    plan.min_J = history.empty() ? nan : history.back().min_J;
    plan.eisenstat_walker =
      forcing_term(history, state.step_start_residual, state.target);
    state.step_start_residual = state.equations_residual;
    plan.predictor            = state.moving_constraints;
    // In the trust region the tangent is exact: the truncated CG copes
    // with its negative curvature, and near the minimum its steps are
    // Newton's (quadratic convergence).
    plan.in_trust_region = state.in_trust_region &&
                           trust_region_allowed(properties,
                                                policy,
                                                state,
                                                TangentProjection::none) &&
                           start_trust_region(system, state, history);
    if (plan.in_trust_region)
      plan.projection = TangentProjection::none;
    plan.trust_region_tried = plan.in_trust_region;

    NewtonIteration                     row;
    NonlinearSystem::LinearizationSolve solve;
    attempt_until_taken(
      system, properties, policy, it, state, result, plan, row, solve);
    state.in_trust_region = plan.in_trust_region;
    row.projected         = plan.projection == TangentProjection::every_point;
    row.projected_where_inverted =
      TangentPolicy::projects_where_inverted(plan.projection, plan.min_J);
    row.softened_predictor = solve.softened_predictor;
    row.iteration          = it;
    row.linear_iterations  = solve.linear_iterations;
    row.update             = system.accept_trial();
    if (state.moving_constraints && row.step_length == 1.)
      state.moving_constraints = false;
    state.current.energy       = row.energy;
    state.current.energy_noise = row.energy_noise;
    return row;
  }

  double
  NewtonSolver::iteration_forcing(const NonlinearSystem::Properties &properties,
                                  const IterationPlan               &plan) const
  {
    // The iteration that imposes the prescribed-displacement increment is
    // the load step's predictor: solved fully. So is a projected tangent's:
    // far from the solution among inverted cells, loose solves give
    // directions that wander between minima (the crush of stress test 25:
    // 36 iterations inexact, 18 exact).
    return (properties.linear || plan.predictor ||
            TangentPolicy::projects_somewhere(plan.projection, plan.min_J))
             ? 0.
             : plan.eisenstat_walker;
  }

  bool
  NewtonSolver::trust_region_allowed(
    const NonlinearSystem::Properties &properties,
    const TangentPolicy               &policy,
    const SolveState                  &state,
    const TangentProjection            projection) const
  {
    // Newton/Follow negative curvature: a Krylov solve of the exact
    // tangent that meets negative curvature stops, and the iteration is
    // repeated in a trust region (the curvature followed, not projected
    // away); once that has worked, the solve's later iterations start
    // there. Not for the predictor, whose energy does not compare.
    return policy.follows_negative_curvature(projection) &&
           !state.moving_constraints && properties.has_potential &&
           parameters.line_search && properties.trust_region &&
           state.trust_region;
  }

  bool
  NewtonSolver::start_trust_region(
    NonlinearSystem                    &system,
    SolveState                         &state,
    const std::vector<NewtonIteration> &history) const
  {
    // The trust region starts as large as the last step taken or a tenth
    // of the solution's size, whichever is larger: the energy then cuts it
    // to what the model predicts well (trials cost no Krylov solve).
    if (!std::isfinite(state.trust_radius) && !history.empty())
      state.trust_radius =
        std::max(history.back().update, 0.1 * system.solution_scale());
    if (!(state.trust_radius > 0.))
      state.trust_radius = std::numeric_limits<double>::quiet_NaN();
    return std::isfinite(state.trust_radius);
  }

  void
  NewtonSolver::attempt_until_taken(
    NonlinearSystem                     &system,
    const NonlinearSystem::Properties   &properties,
    const TangentPolicy                 &policy,
    const unsigned int                   it,
    SolveState                          &state,
    const NewtonResult                  &result,
    IterationPlan                       &plan,
    NewtonIteration                     &row,
    NonlinearSystem::LinearizationSolve &solve) const
  {
    // Each fallback projects at more points than the tangent before it:
    // at most three attempts (and the trust region).
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::string  failure;
    row.forcing = iteration_forcing(properties, plan);
    solve.watch_curvature =
      trust_region_allowed(properties, policy, state, plan.projection);
    while (!(plan.in_trust_region
               ? attempt_trust_region(
                   system, plan.projection, state, row, solve, failure)
               : attempt(system,
                         properties,
                         plan.projection,
                         policy.softens_inverting_predictor(),
                         state,
                         row,
                         solve,
                         failure)))
      {
        row.trust_radius       = nan;
        row.negative_curvature = false;
        solve.watch_curvature  = false;
        solve.negative_curvature = false;
        if (!plan.trust_region_tried &&
            trust_region_allowed(properties, policy, state, plan.projection) &&
            start_trust_region(system, state, result.history))
          {
            system.evaluate_trial(0., NonlinearSystem::TrialCheck::none);
            plan.trust_region_tried = plan.in_trust_region = true;
            plan.projection = TangentProjection::none;
            row.forcing     = iteration_forcing(properties, plan);
            continue;
          }
        plan.in_trust_region = false;
        const std::optional<TangentProjection> next =
          policy.fallback(plan.projection);
        if (!next)
          throw ConvergenceFailure(failure + " in Newton iteration " +
                                     std::to_string(it) + "\n" + table(result),
                                   it);
        // Repeat this iteration from the same iterate with a tangent that
        // projects more (the projected tangent's direction descends).
        system.evaluate_trial(0., NonlinearSystem::TrialCheck::none);
        plan.projection = *next;
        row.forcing     = iteration_forcing(properties, plan);
      }
  }

  void
  NewtonSolver::take_trial(const double      alpha,
                           const bool        energy_tested,
                           const TrialPoint &current,
                           const TrialPoint &trial,
                           NewtonIteration  &row)
  {
    row.step_length   = alpha;
    row.energy_tested = energy_tested;
    row.energy_before = current.energy;
    row.energy        = trial.energy;
    row.energy_noise  = trial.energy_noise;
    row.min_J         = trial.min_J;
  }

  bool
  NewtonSolver::finished(NonlinearSystem                   &system,
                         const NonlinearSystem::Properties &properties,
                         const ConvergenceTest             &convergence,
                         const ResidualNorms               &norms,
                         NewtonIteration                   &row,
                         const unsigned int                 it,
                         SolveState                        &state,
                         const TangentPolicy               &policy) const
  {
    // A linear problem is solved by its first full step (to the linear
    // solver's tolerance): a second solve would only polish round-off.
    const bool linear_done = properties.linear && row.step_length == 1.;
    if (state.moving_constraints)
      return false;
    // solve_loosely(): the residual has fallen far enough.
    const bool loose_done =
      state.loose_target > 0. && norms.residual <= state.loose_target;
    if (!(convergence.converged(norms, row.update, system.solution_scale()) ||
          linear_done || loose_done))
      {
        update_lagged_early(system, norms, row.step_length == 1., it, state);
        return false;
      }
    // A saddle is no equilibrium to stop at when the curvature is
    // followed: from it Newton goes on in the trust region (the snap).
    if (policy.follows_negative_curvature(TangentProjection::none) &&
        properties.has_potential && parameters.line_search &&
        properties.trust_region && state.trust_region && !properties.linear)
      {
        if (state.trust_region->has_negative_curvature())
          {
            if (verbose)
              pcout << "   (converged to a saddle: the exact tangent has "
                       "negative curvature there; on in the trust region)"
                    << std::endl;
            state.in_trust_region = true;
            return false;
          }
        row.probed_stable = true;
        if (verbose)
          pcout << "   (no negative curvature at the converged state)"
                << std::endl;
      }
    // The lagged quantities at the converged state: if they changed, the
    // equations are new and Newton goes on from here.
    if (state.lagged &&
        state.lagged->update_lagged(LagMoment::converged, norms.residual) ==
          LaggedUpdate::updated)
      {
        row.probed_stable = false;
        lagged_quantities_updated(system, it, state);
        return false;
      }
    system.judge_converged_state();
    return true;
  }

  void
  NewtonSolver::lagged_quantities_updated(NonlinearSystem   &system,
                                          const unsigned int it,
                                          SolveState        &state) const
  {
    // The equations changed (lagged friction): their energy at the current
    // iterate is new, and they get the full budget. Their residual there
    // is what the next iteration starts from (for its forcing term).
    state.current            = TrialPoint();
    state.budget_start       = it;
    state.early_lag_residual = -1.;
    state.equations_residual = system.residual_norms().residual;
    if (verbose)
      pcout << "   (lagged quantities updated)" << std::endl;
  }

  void
  NewtonSolver::update_lagged_early(NonlinearSystem     &system,
                                    const ResidualNorms &norms,
                                    const bool           full_step,
                                    const unsigned int   it,
                                    SolveState          &state) const
  {
    // Lagged friction: re-solving the step to full convergence for each
    // update of the normal forces costs a solve an update. The normal
    // forces follow Newton's iterates instead: they are taken again after
    // each full step (the fixed point of the normal forces contracts by
    // about a tenth an update at mu = 0.5), and the convergence test checks
    // them once more when it passes. After a step the line search
    // shortened, they are taken once the residual has fallen to
    // early_lag_reduction of the first one of the current equations. An
    // update that changed nothing does not stop the following: the
    // iterates move on, and a change found only at the converged state
    // costs the new equations' whole convergence (block between plates,
    // step 3: 12 Newton iterations against 9). The system is told the
    // iterate's residual: it may find the iterate too far from equilibrium
    // for its lagged quantities (FrictionLagging) and keep them.
    if (state.early_lag_residual < 0.)
      {
        state.early_lag_residual = early_lag_reduction * norms.residual;
        if (!full_step)
          return;
      }
    else if (!(norms.residual <= state.early_lag_residual || full_step))
      return;
    const LaggedUpdate outcome =
      state.lagged ? state.lagged->update_lagged(LagMoment::within_solve,
                                                 norms.residual)
                   : LaggedUpdate::unchanged;
    if (outcome == LaggedUpdate::unchanged)
      {
        // From here on, full steps only.
        state.early_lag_residual = 0.;
        return;
      }
    lagged_quantities_updated(system, it, state);
  }

  NewtonResult
  NewtonSolver::solve(NonlinearSystem &system) const
  {
    return solve(system, parameters.max_iterations);
  }

  NewtonResult
  NewtonSolver::solve(NonlinearSystem   &system,
                      const unsigned int max_iterations) const
  {
    return solve(system, max_iterations, 0.);
  }

  NewtonResult
  NewtonSolver::solve_loosely(NonlinearSystem &system,
                              const double     reduction) const
  {
    return solve(system, parameters.max_iterations, reduction);
  }

  NewtonResult
  NewtonSolver::solve(NonlinearSystem   &system,
                      const unsigned int max_iterations,
                      const double       reduction) const
  {
    const ConvergenceTest             convergence(parameters);
    const TangentPolicy               policy(parameters.tangent,
                               parameters.follow_negative_curvature);
    const NonlinearSystem::Properties properties = system.properties();
    NewtonResult                      result;
    result.residual_merit = parameters.line_search && !properties.has_potential;
    if (verbose)
      {
        if (result.residual_merit)
          pcout << "   (line search on the residual norm: "
                << properties.why_no_potential << ")" << std::endl;
        pcout << header(result.residual_merit) << std::endl;
      }

    SolveState state;
    state.loose_reduction = reduction;
    state.trust_region    = dynamic_cast<TrustRegionSystem *>(&system);
    state.lagged          = dynamic_cast<LaggedSystem *>(&system);
    state.softening       = dynamic_cast<PredictorSoftening *>(&system);
    for (unsigned int it = 1;
         it - state.budget_start <= max_iterations;
         ++it)
      {
        NewtonIteration row =
          iterate(system, properties, policy, it, state, result);
        const ResidualNorms norms    = system.residual_norms();
        row.residual                 = norms.residual;
        state.equations_residual     = norms.residual;
        state.current.residual       = norms.residual;
        state.current.residual_noise = norms.noise;
        result.history.push_back(row);
        if (verbose)
          pcout << format_row(row) << std::endl;

        if (!std::isfinite(norms.residual) || !std::isfinite(row.update))
          throw ConvergenceFailure(
            "Newton produced a non-finite residual or update (an element may "
            "have inverted with a model undefined there)\n" +
              table(result),
            result.iterations());

        state.target = convergence.residual_target(norms);
        if (it == 1 && state.loose_reduction > 0.)
          state.loose_target = state.loose_reduction * norms.residual;
        try
          {
            if (finished(system,
                         properties,
                         convergence,
                         norms,
                         result.history.back(),
                         it,
                         state,
                         policy))
              return result;
          }
        catch (const ConvergenceFailure &failure)
          {
            // The system rejected the converged state: the solve used the
            // iterations so far.
            if (failure.newton_iterations() > 0)
              throw;
            throw ConvergenceFailure(failure.what(), it);
          }
      }
    throw ConvergenceFailure("Newton did not converge in " +
                               std::to_string(max_iterations) +
                               (max_iterations == parameters.max_iterations
                                  ? " iterations (Newton/Max iterations)\n"
                                  : " iterations (a snap step's budget, "
                                    "'Load stepping/Snap iterations')\n") +
                               table(result),
                             result.iterations());
  }
} // namespace hyperelastic
