// The load-control loop and its recovery strategies (see the header).
#include <hyperelastic/solvers/damped_system.h>
#include <hyperelastic/solvers/load_control.h>
#include <hyperelastic/solvers/snap_sequence.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace hyperelastic
{
  LoadControlLoop::LoadControlLoop(const LoadSteppingParameters &parameters,
                                   const StepVariable            variable,
                                   const double                  end,
                                   const double                  nominal,
                                   dealii::ConditionalOStream    pcout,
                                   const NewtonSolver           &newton,
                                   SteppedSystem                &system,
                                   const Callback               &on_converged)
      : parameters(parameters)
      , variable(variable)
      , end(end)
      , nominal(nominal)
      , pcout(pcout)
      , newton(newton)
      , system(system)
      , on_converged(on_converged)
      , damped(dynamic_cast<DampedSystem *>(&system))
      , continuation(dynamic_cast<ContinuationSystem *>(&system))
      , tangent(dynamic_cast<TangentSystem *>(&system))
      // Snap steps: under displacement control only (every load factor has
      // an energy minimum to snap to).
      , may_snap(variable == StepVariable::load_factor &&
                 parameters.snap_iterations > 0 &&
                 system.properties().displacement_controlled)
      , sub_steps(may_snap && parameters.snap_sub_step_iterations > 0 &&
                  damped && continuation && system.properties().damping)
      , increment(nominal)
  {
  }

  void
  LoadControlLoop::run(const ResumePoint *resume)
  {
    if (resume)
      {
        // The system holds the converged state of t already; a scene with
        // more nominal steps than the checkpointed one steps finer.
        t                   = resume->t;
        increment           = std::min(resume->increment, nominal);
        step.step           = resume->step;
        easy_steps_in_a_row = resume->easy_steps;
      }
    else
      system.store_converged_state();
    step.nominal            = nominal;
    step.start              = t;
    step.smallest_increment = std::numeric_limits<double>::infinity();
    while (t < end)
      {
        const Target target = next_target();
        const double t_next = target.t;
        step.stop           = target.stop;
        // The increment as halved and doubled, not t_next - t: summed load
        // factors carry round-off, and a cut-back to exactly 1/16 of the
        // nominal increment must compare as 1/16 (snap steps, the CSV). A
        // step shortened to the end or a stop is t_next - t.
        const double attempted =
          t_next == end || t_next != t + increment ? t_next - t : increment;
        print_header(t_next,
                     attempted,
                     next == Attempt::snap ? ", snap step" : "");
        system.set_load_factor(t_next);
        NewtonResult result;
        try
          {
            if (!attempt(t_next, attempted, result))
              continue;
          }
        catch (const ConvergenceFailure &failure)
          {
            recover(failure, t_next, attempted);
            continue;
          }
        next = Attempt::step;
        accept(result, t_next, attempted);
      }
  }

  LoadControlLoop::Target
  LoadControlLoop::next_target() const
  {
    // Land exactly on t = end (no sliver of a last step): a remainder
    // below a millionth of the nominal step is the round-off of the summed
    // steps (500 steps of 0.02 end at 9.99999999999988, and a last step of
    // 1.2e-13 would follow: issue 41). The same for each stop.
    const double               sliver = 1e-6 * nominal;
    const std::vector<double> &stops  = parameters.stops;
    for (unsigned int k = 0; k < stops.size(); ++k)
      if (stops[k] > t + sliver && stops[k] < end &&
          t + increment > stops[k] - sliver)
        return {stops[k], k};
    if (t + increment <= end - sliver)
      return {t + increment, std::nullopt};
    for (unsigned int k = 0; k < stops.size(); ++k)
      if (std::abs(stops[k] - end) <= sliver)
        return {end, k};
    return {end, std::nullopt};
  }

  bool
  LoadControlLoop::attempt(const double  t_next,
                           const double  attempted,
                           NewtonResult &result)
  {
    if (next == Attempt::step)
      {
        result = newton.solve(system);
        return true;
      }
    try
      {
        // Without sub-steps to follow, the one solve has their budget too.
        result =
          newton.solve(system,
                       sub_steps
                         ? parameters.snap_iterations
                         : std::max(parameters.snap_iterations,
                                    parameters.snap_sub_step_iterations));
        return true;
      }
    catch (const ConvergenceFailure &failure)
      {
        if (!sub_steps)
          throw;
        snap_sub_steps(failure, t_next, attempted);
        next = Attempt::step;
        return false;
      }
  }

  void
  LoadControlLoop::snap_sub_steps(const ConvergenceFailure &failure,
                                  const double              t_next,
                                  const double              attempted)
  {
    // The snap goes on in sub-steps from the last converged state; the
    // last one, an undamped equilibrium, ends the snap and is the step's
    // state. The sub-steps before it are pseudo time steps, no equilibria:
    // the sequence goes on from each, but none is reported (no CSV row, no
    // frame, no checkpoint); the log keeps them.
    system.restore_converged_state();
    pseudo_state = false;
    ++step.cut_backs;
    pcout << "   cut-back " << step.cut_backs
          << ": the snap step failed: " << first_line(failure.what())
          << "\n   snap sub-steps from t = " << t << " with up to "
          << parameters.snap_sub_step_iterations << " Newton iterations in all"
          << std::endl;
    try
      {
        SnapSequence(newton, parameters.snap_sub_step_iterations, pcout)
          .run(system,
               *damped,
               *continuation,
               t_next,
               [&](const NewtonResult &sub,
                   const unsigned int  failed,
                   const bool          final) {
                 step.cut_backs += failed;
                 if (final)
                   {
                     accept(sub, t_next, attempted);
                     return;
                   }
                 system.store_converged_state();
                 pseudo_state = true;
                 pcout << "   snap sub-step accepted after " << sub.iterations()
                       << " Newton iterations (" << sub.linear_iterations()
                       << " linear): a pseudo time step, not reported"
                       << std::endl;
               });
      }
    catch (const ConvergenceFailure &sub_failure)
      {
        if (pseudo_state)
          throw;
        // Sub-steps that fail before one is accepted leave the snap step's
        // own failure as the reason (the cut-backs go on, and the message
        // names what stopped the step).
        pcout << "   " << first_line(sub_failure.what()) << std::endl;
        throw failure;
      }
  }

  void
  LoadControlLoop::accept(const NewtonResult &result,
                          const double        t_next,
                          const double        attempted)
  {
    step.step += 1;
    step.load_factor = t_next;
    step.increment   = attempted;
    t                = t_next;
    system.store_converged_state();

    step.newton_in_all += result.iterations();
    step.smallest_increment = std::min(step.smallest_increment, increment);
    // A full-size step tells what a step of this scene costs (one without
    // cut-backs: not a snap step either, whose budget is larger).
    if (increment >= nominal && step.cut_backs == 0)
      {
        full_size_costs.push_back(result.iterations());
        if (full_size_costs.size() > full_size_memory)
          full_size_costs.erase(full_size_costs.begin());
      }
    // Grow back towards the nominal increment after two easy steps in a
    // row (one alone often follows a cut-back by luck).
    easy_steps_in_a_row =
      result.iterations() <= easy_threshold() ? easy_steps_in_a_row + 1 : 0;
    if (easy_steps_in_a_row >= 2 && increment < nominal)
      {
        increment           = std::min(2. * increment, nominal);
        easy_steps_in_a_row = 0;
      }
    step.next_increment = increment;
    step.easy_steps     = easy_steps_in_a_row;
    on_converged(step, result);
    step.cut_backs = 0;
  }

  unsigned int
  LoadControlLoop::easy_threshold() const
  {
    unsigned int threshold = parameters.easy_step_iterations;
    for (const unsigned int cost : full_size_costs)
      threshold = std::max(threshold, cost);
    return threshold;
  }

  void
  LoadControlLoop::recover(const ConvergenceFailure &failure,
                           const double              t_next,
                           const double              attempted)
  {
    step.newton_in_all += failure.newton_iterations();
    system.restore_converged_state();
    easy_steps_in_a_row = 0;
    double smaller      = 0.5 * attempted;
    if (next == Attempt::snap && pseudo_state)
      // Sub-steps were accepted, but no equilibrium follows them: the
      // system's state is a pseudo time step's, not one to go on from.
      throw ConvergenceFailure(
        "load step to t = " + std::to_string(t_next) +
        ": the snap sub-steps ended without an equilibrium: " +
        std::string(failure.what()) + "; the last equilibrium is t = " +
        std::to_string(t) + " (load step " + std::to_string(step.step) + ")");
    if (next == Attempt::snap)
      {
        // The snap did not work: the cut-backs go on where they stopped.
        next    = Attempt::step;
        smaller = before_snap;
      }
    else if (begin_snap(failure, smaller))
      return;
    cut_back(failure, t_next, smaller);
  }

  bool
  LoadControlLoop::begin_snap(const ConvergenceFailure &failure,
                              const double              smaller)
  {
    if (!may_snap || snapped_from == t ||
        !(smaller < LoadSteppingParameters::snap_fraction * nominal))
      return false;
    next         = Attempt::snap;
    snapped_from = t;
    before_snap  = smaller;
    ++step.cut_backs;
    increment = nominal;
    pcout << "   cut-back " << step.cut_backs << ": "
          << first_line(failure.what())
          << "\n   the increment would fall below 1/16 of the nominal one: a "
             "snap step from t = "
          << t << " with the nominal increment and up to "
          << parameters.snap_iterations << " Newton iterations" << std::endl;
    return true;
  }

  void
  LoadControlLoop::cut_back(const ConvergenceFailure &failure,
                            const double              t_next,
                            const double              smaller)
  {
    std::ostringstream where;
    where << "from t = " << t << " to t = " << t_next << ": " << failure.what();
    if (!parameters.adaptive)
      throw ConvergenceFailure(
        "load step " + where.str() +
        "\n(adaptive load stepping is off: 'Load stepping/Adaptive')");
    if (smaller < parameters.minimum_increment)
      {
        const std::string  limit = limit_point_diagnosis();
        std::ostringstream message;
        if (!limit.empty())
          message << limit << "\n";
        message << "load step " << where.str()
                << "\nthe increment cannot be halved again: " << smaller
                << " < " << parameters.minimum_increment
                << " ('Load stepping/Minimum increment') after "
                << step.cut_backs + 1
                << " failed attempts; the last converged state is t = " << t
                << " (load step " << step.step << ")";
        throw ConvergenceFailure(message.str());
      }
    ++step.cut_backs;
    increment = smaller;
    pcout << "   cut-back " << step.cut_backs << ": "
          << first_line(failure.what()) << "\n   back to t = " << t
          << ", increment halved to " << increment << std::endl;
  }

  std::string
  LoadControlLoop::limit_point_diagnosis() const
  {
    if (variable != StepVariable::load_factor || !continuation || !tangent)
      return "";
    // The stiffness along the path, unloaded and at the last converged
    // state.
    const VectorType converged(system.state());
    VectorType       r_t(converged), du(converged), zero(converged);
    zero             = 0.;
    const auto probe = [&](const VectorType &u, const double at) {
      continuation->set_state(u, at);
      try
        {
          return stiffness_along_path(*continuation, *tangent, r_t, du);
        }
      catch (const ConvergenceFailure &)
        {
          return std::numeric_limits<double>::quiet_NaN();
        }
    };
    const double unloaded = probe(zero, 0.);
    const double last     = probe(converged, t);
    system.restore_converged_state();
    if (!(unloaded > 0.) || !(last < 0.1 * unloaded))
      return "";
    std::ostringstream text;
    text << "the load passed a maximum at t = " << t
         << "; use Load stepping/Method = arc length (the tangent's "
            "stiffness along the path fell to "
         << last / unloaded << " of the unloaded one there)";
    return text.str();
  }

  void
  LoadControlLoop::print_header(const double t_next,
                                const double attempted,
                                const char  *kind) const
  {
    pcout << "\n"
          << (variable == StepVariable::load_factor ? "Load step" : "Time step")
          << " " << step.step + 1 << ": t = " << t_next << " (increment "
          << attempted << ")" << kind << std::endl;
  }
} // namespace hyperelastic
