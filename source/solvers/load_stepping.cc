// Load-step control with cut-back on failure and growth after easy steps.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/solvers/arc_length.h>
#include <hyperelastic/solvers/load_stepping.h>
#include <hyperelastic/solvers/snap_sequence.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace hyperelastic
{
  LoadStepper::LoadStepper(const LoadSteppingParameters &parameters,
                           const unsigned int            n_nominal_steps,
                           dealii::ConditionalOStream    pcout)
      : parameters(parameters)
      , end(1.)
      , nominal(1. / n_nominal_steps)
      , pcout(pcout)
      , label("Load step")
  {
  }

  LoadStepper::LoadStepper(const LoadSteppingParameters &parameters,
                           const double                  end,
                           const double                  nominal_increment,
                           dealii::ConditionalOStream    pcout)
      : parameters(parameters)
      , end(end)
      , nominal(nominal_increment)
      , pcout(pcout)
      , label("Time step")
  {
  }

  void
  LoadStepper::run(
    const NewtonSolver &newton,
    SteppedSystem      &system,
    const std::function<void(const LoadStep &, const NewtonResult &)>
                      &on_converged,
    const ResumePoint *resume) const
  {
    if (parameters.method == LoadControl::arc_length && label == "Load step")
      ArcLengthStepper(parameters, newton.settings(), nominal, pcout)
        .run(system, on_converged);
    else
      run_load_control(newton, system, on_converged, resume);
  }

  double
  stiffness_along_path(ContinuationSystem &system,
                       VectorType         &r_t,
                       VectorType         &du_t)
  {
    system.assemble_tangent();
    system.load_derivative(r_t);
    r_t *= -1.;
    system.solve_tangent(r_t, du_t);
    const double length2 = system.path_product(du_t, du_t);
    return length2 > 0. ? (du_t * r_t) / length2
                        : std::numeric_limits<double>::quiet_NaN();
  }

  std::string
  LoadStepper::limit_point_diagnosis(SteppedSystem &system,
                                     const double   t) const
  {
    if (label != "Load step")
      return "";
    // The stiffness along the path, unloaded and at the last converged
    // state.
    const VectorType converged(system.state());
    VectorType       r_t(converged), du(converged), zero(converged);
    zero             = 0.;
    const auto probe = [&](const VectorType &u, const double at) {
      system.set_state(u, at);
      try
        {
          return stiffness_along_path(system, r_t, du);
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
  LoadStepper::run_load_control(
    const NewtonSolver &newton,
    SteppedSystem      &system,
    const std::function<void(const LoadStep &, const NewtonResult &)>
                      &on_converged,
    const ResumePoint *resume) const
  {
    double       t         = 0.;
    double       increment = nominal;
    LoadStep     step;
    unsigned int easy_steps_in_a_row = 0;
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
    // Snap steps (Load stepping/Snap iterations): under displacement
    // control only, once from each converged state.
    const bool may_snap = label == "Load step" &&
                          parameters.snap_iterations > 0 &&
                          system.properties().displacement_controlled;
    // Snap sub-steps (Load stepping/Snap sub-step iterations) after a
    // failed snap step, where the system can add a damping energy
    // (SnapSequence).
    DampedSystem *const damped =
      may_snap && parameters.snap_sub_step_iterations > 0
        ? dynamic_cast<DampedSystem *>(&system)
        : nullptr;
    const bool sub_steps    = damped && damped->supports_damping();
    bool       snapping     = false;
    double     snapped_from = -1.;
    // The increment the cut-backs resume with after a failed snap step.
    double before_snap = 0.;
    while (t < end)
      {
        // Land exactly on t = end (no sliver of a last step): a remainder
        // below a millionth of the nominal step is the round-off of the
        // summed steps (500 steps of 0.02 end at 9.99999999999988, and a
        // last step of 1.2e-13 would follow: issue 41).
        const double t_next =
          (t + increment > end - 1e-6 * nominal) ? end : t + increment;
        // The increment as halved and doubled, not t_next - t: summed load
        // factors carry round-off, and a cut-back to exactly 1/16 of the
        // nominal increment must compare as 1/16 (snap steps, the CSV).
        const double attempted = t_next == end ? end - t : increment;
        pcout << "\n"
              << label << " " << step.step + 1 << ": t = " << t_next
              << " (increment " << attempted << ")"
              << (snapping ? ", snap step" : "") << std::endl;
        system.set_load_factor(t_next);
        // A converged state: the stepper's bookkeeping and the report.
        const auto converged = [&](const NewtonResult &result) {
          step.step += 1;
          step.load_factor = t_next;
          step.increment   = attempted;
          t                = t_next;
          system.store_converged_state();

          // Grow back towards the nominal increment after two easy steps in
          // a row (one alone often follows a cut-back by luck).
          easy_steps_in_a_row =
            result.iterations() <= parameters.easy_step_iterations
              ? easy_steps_in_a_row + 1
              : 0;
          if (easy_steps_in_a_row >= 2 && increment < nominal)
            {
              increment           = std::min(2. * increment, nominal);
              easy_steps_in_a_row = 0;
            }
          step.next_increment = increment;
          step.easy_steps     = easy_steps_in_a_row;
          on_converged(step, result);
          step.cut_backs = 0;
        };
        NewtonResult result;
        try
          {
            if (!snapping)
              result = newton.solve(system);
            else
              try
                {
                  // Without sub-steps to follow, the one solve has their
                  // budget too.
                  result = newton.solve(
                    system,
                    sub_steps ? parameters.snap_iterations
                              : std::max(parameters.snap_iterations,
                                         parameters.snap_sub_step_iterations));
                }
              catch (const ConvergenceFailure &failure)
                {
                  if (!sub_steps)
                    throw;
                  // The snap goes on in sub-steps from the last converged
                  // state, each a step of its own; the last one, an
                  // undamped equilibrium, ends the snap.
                  system.restore_converged_state();
                  ++step.cut_backs;
                  pcout << "   the snap step failed: "
                        << first_line(failure.what())
                        << "\n   snap sub-steps from t = " << t
                        << " with up to " << parameters.snap_sub_step_iterations
                        << " Newton iterations in all" << std::endl;
                  // Sub-steps that fail before one is accepted leave the
                  // snap step's own failure as the reason (the cut-backs go
                  // on, and the message names what stopped the step).
                  const ConvergenceFailure snap_failure = failure;
                  try
                    {
                      SnapSequence(newton,
                                   parameters.snap_sub_step_iterations,
                                   pcout)
                        .run(system,
                             *damped,
                             t_next,
                             [&](const NewtonResult &sub,
                                 const unsigned int  failed,
                                 const bool          final) {
                               step.cut_backs += failed;
                               step.snap_sub_step = !final;
                               converged(sub);
                               step.snap_sub_step = false;
                               if (!final)
                                 pcout << "\n"
                                       << label << " " << step.step + 1
                                       << ": t = " << t_next << " (increment "
                                       << attempted << "), snap sub-step"
                                       << std::endl;
                             });
                    }
                  catch (const ConvergenceFailure &sub_failure)
                    {
                      if (t != snapped_from)
                        throw;
                      pcout << "   " << first_line(sub_failure.what())
                            << std::endl;
                      throw snap_failure;
                    }
                  snapping = false;
                  continue;
                }
          }
        catch (const ConvergenceFailure &failure)
          {
            system.restore_converged_state();
            easy_steps_in_a_row = 0;
            double smaller      = 0.5 * attempted;
            if (snapping && t != snapped_from)
              // Sub-steps were accepted, but no equilibrium follows them:
              // the state at t is a pseudo time step's, not one to go on
              // from.
              throw ConvergenceFailure(
                "load step to t = " + std::to_string(t) +
                ": the snap sub-steps ended without an equilibrium: " +
                std::string(failure.what()) +
                "; the last accepted state is a snap sub-step's (load step " +
                std::to_string(step.step) + ")");
            if (snapping)
              {
                // The snap did not work: the cut-backs go on where they
                // stopped.
                snapping = false;
                smaller  = before_snap;
              }
            else if (may_snap && snapped_from != t &&
                     smaller < LoadSteppingParameters::snap_fraction * nominal)
              {
                snapping     = true;
                snapped_from = t;
                before_snap  = smaller;
                ++step.cut_backs;
                increment = nominal;
                pcout << "   cut-back " << step.cut_backs << ": "
                      << first_line(failure.what())
                      << "\n   the increment would fall below 1/16 of the "
                         "nominal one: a snap step from t = "
                      << t << " with the nominal increment and up to "
                      << parameters.snap_iterations << " Newton iterations"
                      << std::endl;
                continue;
              }
            std::ostringstream where;
            where << "from t = " << t << " to t = " << t_next << ": "
                  << failure.what();
            if (!parameters.adaptive)
              throw ConvergenceFailure(
                "load step " + where.str() +
                "\n(adaptive load stepping is off: 'Load stepping/Adaptive')");
            if (smaller < parameters.minimum_increment)
              {
                const std::string  limit = limit_point_diagnosis(system, t);
                std::ostringstream message;
                if (!limit.empty())
                  message << limit << "\n";
                message << "load step " << where.str()
                        << "\nthe increment cannot be halved again: " << smaller
                        << " < " << parameters.minimum_increment
                        << " ('Load stepping/Minimum increment') after "
                        << step.cut_backs + 1
                        << " failed attempts; the last converged state is t = "
                        << t << " (load step " << step.step << ")";
                throw ConvergenceFailure(message.str());
              }
            ++step.cut_backs;
            increment = smaller;
            pcout << "   cut-back " << step.cut_backs << ": "
                  << first_line(failure.what()) << "\n   back to t = " << t
                  << ", increment halved to " << increment << std::endl;
            continue;
          }

        snapping = false;
        converged(result);
      }
  }
} // namespace hyperelastic
