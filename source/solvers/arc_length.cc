// Arc-length continuation: predictor, bordered corrector, step-length control.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/solvers/arc_length.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace hyperelastic
{
  ArcLengthStepper::ArcLengthStepper(const LoadSteppingParameters &parameters,
                                     const NewtonParameters       &newton,
                                     const double nominal_increment,
                                     dealii::ConditionalOStream pcout)
      : parameters(parameters)
      , newton(newton)
      , nominal(nominal_increment)
      , pcout(pcout)
  {
  }

  NewtonResult
  ArcLengthStepper::step(SteppedSystem      &system,
                         ContinuationSystem &continuation,
                         TangentSystem      &tangent,
                         Path               &path,
                         const double        ds,
                         const double        sign,
                         const double        land_at,
                         double             &t) const
  {
    const VectorType &u_n     = path.u_n;
    VectorType       &delta   = path.delta;
    const bool        landing = std::isfinite(land_at);
    // Predictor: along du/dt, |Delta u| = ds (landing: to t = land_at).
    const double dt0 =
      landing ? land_at - path.t_n
              : sign * ds / std::max(path_length(continuation, path), 1e-300);
    delta = path.du_t;
    delta *= dt0;
    t = path.t_n + dt0;
    VectorType   trial(u_n), r(u_n), r_t(u_n), du_r(u_n), du_t(u_n);
    NewtonResult result;
    double       last_update = std::numeric_limits<double>::infinity();
    pcout << "   iteration      residual        update          t  lin.its"
          << std::endl;
    for (unsigned int it = 1; it <= newton.max_iterations + 1; ++it)
      {
        trial = u_n;
        trial += delta;
        continuation.set_state(trial, t);
        const ResidualNorms norms = tangent.free_residual(r);
        NewtonIteration     row;
        row.iteration = it;
        row.residual  = norms.residual;
        row.update    = it == 1 ? 0. : last_update;
        if (!std::isfinite(norms.residual))
          throw ConvergenceFailure(
            "the residual is not finite (an element may have inverted with "
            "a model undefined there)");
        if (it > 1 &&
            ConvergenceTest(newton).converged(norms,
                                              last_update,
                                              std::max(system.solution_scale(),
                                                       trial.l2_norm())))
          {
            result.history.back().residual = norms.residual;
            return result;
          }
        if (it > newton.max_iterations)
          break;
        tangent.assemble_tangent();
        r *= -1.;
        unsigned int linear = tangent.solve_tangent(r, du_r);
        double       dt     = 0.;
        if (!landing)
          {
            continuation.load_derivative(r_t);
            r_t *= -1.;
            linear += tangent.solve_tangent(r_t, du_t);
            dt = constraint_root(continuation, delta, du_r, du_t, ds);
          }
        VectorType du(du_r);
        if (dt != 0.)
          du.add(dt, du_t);
        delta += du;
        t += dt;
        last_update           = du.l2_norm();
        row.linear_iterations = linear;
        result.history.push_back(row);
        pcout << std::setw(8) << it << std::scientific << std::setprecision(3)
              << std::setw(14) << row.residual << std::setw(14) << last_update
              << std::defaultfloat << std::setprecision(6) << std::setw(11) << t
              << std::setw(9) << linear << std::endl;
      }
    throw ConvergenceFailure("arc length: no convergence in " +
                             std::to_string(newton.max_iterations) +
                             " iterations (Newton/Max iterations)");
  }

  double
  ArcLengthStepper::constraint_root(const ContinuationSystem &continuation,
                                    const VectorType         &delta,
                                    const VectorType         &du_r,
                                    const VectorType         &du_t,
                                    const double              ds)
  {
    // |delta + du_r + dt du_t|^2 = ds^2.
    VectorType base(delta);
    base += du_r;
    const double a    = continuation.path_product(du_t, du_t);
    const double b    = 2. * continuation.path_product(du_t, base);
    const double c    = continuation.path_product(base, base) - ds * ds;
    const double disc = b * b - 4. * a * c;
    if (!(disc >= 0.) || !(a > 0.))
      throw ConvergenceFailure(
        "arc length: the constraint has no real root (the step "
        "leaves the linearized path)");
    const double q  = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    const double r1 = q / a, r2 = q != 0. ? c / q : r1;
    // The root whose increment turns least from the last one.
    const auto turn = [&](const double root) {
      return continuation.path_product(base, delta) +
             root * continuation.path_product(du_t, delta);
    };
    return turn(r1) >= turn(r2) ? r1 : r2;
  }

  double
  ArcLengthStepper::halved_length(const ConvergenceFailure &failure,
                                  const double              ds,
                                  const double              first_ds,
                                  const double              t_n,
                                  LoadStep                 &step) const
  {
    const double smaller = 0.5 * ds;
    if (smaller < parameters.minimum_increment * first_ds)
      {
        std::ostringstream message;
        message << "arc-length step from t = " << t_n << ": " << failure.what()
                << "\nthe arc length cannot be halved again: " << smaller
                << " < " << parameters.minimum_increment
                << " times the first one ('Load stepping/Minimum "
                   "increment'); the last converged state is t = "
                << t_n << " (step " << step.step << ")";
        throw ConvergenceFailure(message.str());
      }
    ++step.cut_backs;
    const std::string what = failure.what();
    pcout << "   cut-back " << step.cut_backs << ": "
          << what.substr(0, what.find('\n')) << "\n   arc length halved to "
          << smaller << std::endl;
    return smaller;
  }

  bool
  ArcLengthStepper::run(
    SteppedSystem      &system,
    ContinuationSystem &continuation,
    TangentSystem      &tangent,
    const std::function<void(const LoadStep &, const NewtonResult &)>
      &on_converged) const
  {
    system.store_converged_state();
    Path         path(system.state());
    const double first_ds = start(system, continuation, tangent, path);
    if (!(first_ds > 0.))
      return false;
    double   ds = first_ds;
    LoadStep step;
    // Set when a step passed the maximum load factor upwards although its
    // predictor did not (a stiffening path): it is solved again, landing.
    bool land = false;
    while (step.step < parameters.maximum_steps)
      {
        // Along the last step's way (the sign of det K changes at a limit
        // point, so the tangent alone cannot tell it).
        const double sign =
          path.have_last &&
              continuation.path_product(path.du_t, path.last_delta) < 0.
            ? -1.
            : 1.;
        const double land_at =
          announce_step(step.step + 1,
                        path,
                        ds,
                        sign * ds / path_length(continuation, path),
                        land);
        double       t = path.t_n;
        NewtonResult result;
        try
          {
            result = this->step(
              system, continuation, tangent, path, ds, sign, land_at, t);
            // Arc length does not lag quantities behind the iterate: the
            // converged state is only checked.
            system.judge_converged_state();
          }
        catch (const ConvergenceFailure &failure)
          {
            system.restore_converged_state();
            continuation.set_state(path.u_n, path.t_n);
            ds = halved_length(failure, ds, first_ds, path.t_n, step);
            // The predictor direction of u_n again (the tangent was
            // overwritten by the failed iterations).
            stiffness_along_path(continuation, tangent, path.r_t, path.du_t);
            continue;
          }
        if (!std::isfinite(land_at) &&
            path.t_n < parameters.maximum_load_factor &&
            t > parameters.maximum_load_factor)
          {
            system.restore_converged_state();
            continuation.set_state(path.u_n, path.t_n);
            land = true;
            pcout << "   passed the maximum load factor (t = " << t
                  << "): solved again, landing on it" << std::endl;
            stiffness_along_path(continuation, tangent, path.r_t, path.du_t);
            continue;
          }
        advance(system, continuation, tangent, t, path, step, result);
        on_converged(step, result);
        step.cut_backs = 0;
        if (std::isfinite(land_at))
          return true;
        const double ratio =
          std::sqrt(double(parameters.easy_step_iterations) /
                    std::max<std::size_t>(result.iterations(), 1));
        ds = std::min(first_ds, ds * std::clamp(ratio, 0.5, 2.));
      }
    pcout << "\nArc length: 'Load stepping/Maximum steps' = "
          << parameters.maximum_steps << " reached at t = " << path.t_n
          << std::endl;
    return true;
  }

  double
  ArcLengthStepper::start(SteppedSystem      &system,
                          ContinuationSystem &continuation,
                          TangentSystem      &tangent,
                          Path               &path) const
  {
    continuation.set_state(path.u_n, path.t_n);
    // The stiffness along the path, unloaded: the scale of 'stability'.
    path.unloaded =
      stiffness_along_path(continuation, tangent, path.r_t, path.du_t);
    // The first step: the tangent predictor of the first nominal load step
    // (and the longest step).
    const double first_ds =
      nominal * std::sqrt(continuation.path_product(path.du_t, path.du_t));
    if (!(first_ds > 0.))
      {
        // No load moves the free unknowns: the path is the state at rest
        // (or there is none to follow). Load control takes the steps.
        pcout << "Arc length: the loads do not move the free unknowns "
                 "(dr/dt = 0 at the start): nothing to follow; load control "
                 "takes the steps"
              << std::endl;
        system.restore_converged_state();
      }
    return first_ds;
  }

  double
  ArcLengthStepper::path_length(const ContinuationSystem &continuation,
                                const Path               &path)
  {
    return std::sqrt(continuation.path_product(path.du_t, path.du_t));
  }

  double
  ArcLengthStepper::announce_step(const unsigned int number,
                                  const Path        &path,
                                  const double       ds,
                                  const double       dt_predicted,
                                  const bool         land) const
  {
    const double t_n = path.t_n;
    // Land on the maximum load factor rather than pass it upwards.
    const double land_at =
      (t_n < parameters.maximum_load_factor &&
       (land || t_n + dt_predicted >= parameters.maximum_load_factor))
        ? parameters.maximum_load_factor
        : std::numeric_limits<double>::quiet_NaN();
    pcout << "\nArc-length step " << number << ": from t = " << t_n
          << ", length " << ds
          << (std::isfinite(land_at) ? " (landing on the maximum load "
                                       "factor)"
                                     : "")
          << std::endl;
    return land_at;
  }

  void
  ArcLengthStepper::advance(SteppedSystem      &system,
                            ContinuationSystem &continuation,
                            TangentSystem      &tangent,
                            const double        t,
                            Path               &path,
                            LoadStep           &step,
                            NewtonResult       &result) const
  {
    system.store_converged_state();
    path.last_delta = path.delta;
    path.have_last  = true;
    path.u_n        = system.state();
    step.step += 1;
    step.increment   = t - path.t_n;
    step.load_factor = t;
    path.t_n         = t;
    // The next predictor, and the stability of the converged state.
    continuation.set_state(path.u_n, path.t_n);
    result.stability =
      stiffness_along_path(continuation, tangent, path.r_t, path.du_t) /
      path.unloaded;
  }
} // namespace hyperelastic
