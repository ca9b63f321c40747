// Newton iteration with a backtracking line search on the total potential
// energy (or the residual norm), residual and update tests, and a printed
// table.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/solvers/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
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
                             const double residual_target) const
  {
    if (!parameters.inexact)
      return 0.;
    const double eta_max = parameters.max_forcing;
    // The first two iterations of a load step have no residual ratio yet.
    if (history.size() < 2)
      return eta_max;
    const double gamma = 0.9;
    const double r_new = history.back().residual;
    const double r_old = history[history.size() - 2].residual;
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
                            const bool        test_merit,
                            const TrialPoint &current,
                            NewtonIteration  &row,
                            std::string      &failure) const
  {
    using Check               = NonlinearSystem::TrialCheck;
    const bool  test_residual = test_merit && !system.has_potential();
    const bool  test_energy   = test_merit && !test_residual;
    const Check check         = !parameters.line_search ? Check::none
                                : test_energy           ? Check::energy
                                : test_residual         ? Check::residual
                                                        : Check::admissibility;
    // Sufficient decrease E(alpha) <= E(0) + c alpha dE/dalpha(0).
    const double slope = test_energy ? system.directional_derivative() : 0.;
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
            row.step_length    = alpha;
            row.energy_tested  = test_energy;
            row.energy_before  = current.energy;
            row.energy         = trial.energy;
            row.energy_noise   = trial.energy_noise;
            row.min_J          = trial.min_J;
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

  NewtonResult
  NewtonSolver::solve(NonlinearSystem &system) const
  {
    const ConvergenceTest convergence(parameters);
    NewtonResult          result;
    result.residual_merit = parameters.line_search && !system.has_potential();
    if (verbose)
      {
        if (result.residual_merit)
          pcout << "   (line search on the residual norm: "
                << system.why_no_potential() << ")" << std::endl;
        pcout << header(result.residual_merit) << std::endl;
      }

    // True until a full step has moved the constrained unknowns to their
    // prescribed values. Until then the energy cannot be compared between
    // iterates (each satisfies different constraints), so the line search
    // only keeps the iterates admissible.
    bool       moving_constraints = true;
    TrialPoint current; // the current iterate, energy unknown yet
    // The residual the convergence test asks for (from the last iteration).
    double target = 0.;
    // Each solve of the (lagged) equations has the full iteration budget;
    // the table counts on through them.
    unsigned int budget_start = 0;
    for (unsigned int it = 1; it - budget_start <= parameters.max_iterations;
         ++it)
      {
        const bool automatic = parameters.tangent == NewtonTangent::automatic;
        const bool fallback =
          automatic ||
          parameters.tangent == NewtonTangent::exact_then_projected;
        NewtonIteration row;
        row.projected = parameters.tangent == NewtonTangent::projected;
        // The automatic tangent: projected where elements are inverted while
        // far from the solution (the exact tangent is indefinite there and
        // Newton would climb to a saddle), exact near it (quadratic end).
        TangentProjection projection = row.projected
                                         ? TangentProjection::every_point
                                         : TangentProjection::none;
        if (automatic &&
            (it == budget_start + 1 ||
             current.residual > NewtonParameters::automatic_switch_ratio *
                                  result.history[budget_start].residual))
          projection = TangentProjection::inverted_points;
        unsigned int linear_its = 0;
        // Whether @p p projects anything at this iterate: the points with
        // J <= 0 only matter once the iterate has some.
        const auto projects_inverted_points = [&](const TangentProjection p) {
          return p == TangentProjection::inverted_points &&
                 !result.history.empty() && result.history.back().min_J <= 0.;
        };
        const double eisenstat_walker = forcing_term(result.history, target);
        const bool   predictor        = moving_constraints;
        for (;;)
          {
            // The iteration that imposes the prescribed-displacement
            // increment is the load step's predictor: solved fully. So is
            // a projected tangent's: far from the solution among inverted
            // cells, loose solves give directions that wander between
            // minima (the crush of stress test 25: 36 iterations inexact,
            // 18 exact).
            row.forcing =
              (system.is_linear() || predictor ||
               projection == TangentProjection::every_point ||
               projects_inverted_points(projection))
                ? 0.
                : eisenstat_walker;
            std::string failure;
            try
              {
                moving_constraints =
                  system.assemble_linearization(moving_constraints, projection);
                linear_its += system.solve_linearization(row.forcing);
                unsigned int extension_its = 0;
                if (automatic && moving_constraints)
                  row.softened_predictor =
                    system.soften_inverting_predictor(extension_its);
                linear_its += extension_its;

                const bool test_merit =
                  parameters.line_search && !moving_constraints;
                // The merit of the current iterate, where not known yet.
                if (test_merit && system.has_potential() &&
                    !std::isfinite(current.energy))
                  current =
                    system.evaluate_trial(0.,
                                          NonlinearSystem::TrialCheck::energy);
                if (test_merit && !system.has_potential() &&
                    !std::isfinite(current.residual))
                  current = system.evaluate_trial(
                    0., NonlinearSystem::TrialCheck::residual);
                if (line_search(system, test_merit, current, row, failure))
                  break;
              }
            catch (const ConvergenceFailure &e)
              {
                // A Krylov failure (an indefinite tangent can break CG).
                failure = e.what();
              }
            if (!fallback || row.projected)
              throw ConvergenceFailure(failure + " in Newton iteration " +
                                       std::to_string(it) + "\n" +
                                       table(result));
            // Repeat this iteration from the same iterate with the projected
            // tangent, whose direction descends.
            system.evaluate_trial(0., NonlinearSystem::TrialCheck::none);
            if (automatic && projection == TangentProjection::none)
              projection = TangentProjection::inverted_points;
            else
              {
                projection    = TangentProjection::every_point;
                row.projected = true;
              }
          }
        row.projected_where_inverted = projects_inverted_points(projection);
        row.iteration         = it;
        row.linear_iterations = linear_its;
        row.update            = system.accept_trial();
        if (moving_constraints && row.step_length == 1.)
          moving_constraints = false;
        current.energy       = row.energy;
        current.energy_noise = row.energy_noise;

        const ResidualNorms norms = system.residual_norms();
        row.residual              = norms.residual;
        current.residual          = norms.residual;
        current.residual_noise    = norms.noise;
        result.history.push_back(row);
        if (verbose)
          pcout << format_row(row) << std::endl;

        if (!std::isfinite(norms.residual) || !std::isfinite(row.update))
          throw ConvergenceFailure(
            "Newton produced a non-finite residual or update (an element may "
            "have inverted with a model undefined there)\n" +
            table(result));

        target = convergence.residual_target(norms);
        // A linear problem is solved by its first full step (to the linear
        // solver's tolerance): a second solve would only polish round-off.
        const bool linear_done = system.is_linear() && row.step_length == 1.;
        if (!moving_constraints &&
            (convergence.converged(norms, row.update, system.solution_scale()) ||
             linear_done))
          {
            if (system.update_lagged_quantities())
              {
                // The equations changed (lagged friction): their energy at
                // the current iterate is new.
                current      = TrialPoint();
                budget_start = it;
                if (verbose)
                  pcout << "   (lagged quantities updated)" << std::endl;
                continue;
              }
            system.verify_converged_state();
            return result;
          }
      }
    throw ConvergenceFailure("Newton did not converge in " +
                             std::to_string(parameters.max_iterations) +
                             " iterations (Newton/Max iterations)\n" +
                             table(result));
  }
} // namespace hyperelastic
