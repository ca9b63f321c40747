// The load-control loop of LoadStepper, as the algorithm reads: take a step
// from the last converged state; on failure, ask the recovery strategies in
// order for the next attempt:
//   1. cut back: halve the increment (down to 'Minimum increment'); it
//      doubles again after two steps in a row that cost no more than the
//      scene's own full-size steps (easy_threshold());
//   2. snap step: where a cut-back would go below 1/16 of the nominal
//      increment under displacement control, once from each converged
//      state, the nominal increment with the larger budget 'Snap
//      iterations';
//   3. snap sub-steps: after a failed snap step, pseudo-transient
//      continuation at the snap's load factor (SnapSequence), where the
//      system can be damped; a failed sequence hands back to the cut-backs
//      where they stopped.
// Knows nothing of elasticity.
#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/solvers/damped_system.h>
#include <hyperelastic/solvers/load_stepping.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hyperelastic
{
  class LoadControlLoop
  {
  public:
    using Callback =
      std::function<void(const LoadStep &, const NewtonResult &)>;

    /// t from 0 (or @p resume's t) to @p end in steps of @p nominal for
    /// @p system, whose capabilities (damping, continuation) it finds
    /// itself; calls @p on_converged after each converged step.
    LoadControlLoop(const LoadSteppingParameters &parameters,
                    StepVariable                  variable,
                    double                        end,
                    double                        nominal,
                    dealii::ConditionalOStream    pcout,
                    const NewtonSolver           &newton,
                    SteppedSystem                &system,
                    const Callback               &on_converged);

    /// The loop. Throws ConvergenceFailure when no strategy is left.
    void
    run(const ResumePoint *resume);

  private:
    /// What the next attempt is.
    enum class Attempt
    {
      step, ///< a Newton solve with the current increment
      snap  ///< a snap step: the nominal increment, the snap budget
    };

    /// The next step's end: t + increment, or the end or the next stop
    /// ('Load stepping/Stop at load factors') that it would pass or nearly
    /// reach; with the index of the stop it lands on (a stop at the end
    /// too).
    struct Target
    {
      double                      t;
      std::optional<unsigned int> stop;
    };
    Target
    next_target() const;

    /// One attempt from the last converged state to @p t_next (increment
    /// @p attempted): Newton's solve, a snap step's with its sub-steps.
    /// Returns false where snap sub-steps took the snap over (their states
    /// are already reported).
    bool
    attempt(double t_next, double attempted, NewtonResult &result);

    /// Strategy 3: snap sub-steps after the snap step failed with
    /// @p failure. Throws the snap's failure where no sub-step was
    /// accepted, the sub-steps' otherwise.
    void
    snap_sub_steps(const ConvergenceFailure &failure,
                   double                    t_next,
                   double                    attempted);

    /// A converged state at @p t_next: the bookkeeping, the growth of the
    /// increment after easy steps, the report.
    void
    accept(const NewtonResult &result, double t_next, double attempted);

    /// The most Newton iterations a step may take and still count as easy
    /// (two easy steps in a row double a cut-back increment): the scene's
    /// own cost of a full-size step, the most that one of the last
    /// full_size_memory converged steps at the nominal increment took (snap
    /// steps aside), and at least 'Easy step iterations'. A sliding contact
    /// whose every step takes 10 iterations grows back after a cut-back;
    /// with the fixed 6 alone it stayed at 1/16 (issue 67).
    unsigned int
    easy_threshold() const;

    /// After a failed attempt to @p t_next: the next attempt from the
    /// strategies (a snap step, or a cut-back), or a ConvergenceFailure.
    void
    recover(const ConvergenceFailure &failure, double t_next, double attempted);

    /// Strategy 2: whether a snap step comes next (and, if so, announces
    /// it); @p smaller is the cut-back's increment it replaces.
    bool
    begin_snap(const ConvergenceFailure &failure, double smaller);

    /// Strategy 1: halves the increment to @p smaller, or throws where it
    /// may not (adaptive stepping off, below the minimum increment).
    void
    cut_back(const ConvergenceFailure &failure, double t_next, double smaller);

    /// After the step from t failed for good: if the tangent's stiffness
    /// along the path (stiffness_along_path()) at the last converged state
    /// has fallen below a tenth of the unloaded one's, the load passed a
    /// maximum: a sentence saying so (empty otherwise, or without
    /// continuation).
    std::string
    limit_point_diagnosis() const;

    /// The step header of the log ("Load step k: t = ... (increment ...)").
    void
    print_header(double t_next, double attempted, const char *kind) const;

    const LoadSteppingParameters parameters;
    const StepVariable           variable;
    const double                 end;
    const double                 nominal;
    dealii::ConditionalOStream   pcout;
    const NewtonSolver          &newton;
    SteppedSystem               &system;
    const Callback              &on_converged;
    /// The system's capabilities the snap sub-steps and the diagnosis use
    /// (null where it has none).
    DampedSystem *const       damped;
    ContinuationSystem *const continuation;
    TangentSystem *const      tangent;
    /// Snap steps may be tried (displacement control, 'Snap iterations'),
    /// and snap sub-steps after them ('Snap sub-step iterations', a
    /// system that can be damped).
    const bool may_snap;
    const bool sub_steps;

    /// The last converged load factor, the next increment, the step's
    /// report so far, the easy steps in a row.
    double       t         = 0.;
    double       increment = 0.;
    LoadStep     step;
    unsigned int easy_steps_in_a_row = 0;
    Attempt      next                = Attempt::step;
    /// The Newton iterations of the last converged full-size steps (snap
    /// steps aside), the newest last; at most full_size_memory of them.
    static constexpr unsigned int full_size_memory = 3;
    std::vector<unsigned int>     full_size_costs;
    /// The converged state a snap step was last tried from (once each),
    /// and the increment the cut-backs resume with if it fails.
    double snapped_from = -1.;
    double before_snap  = 0.;
    /// The system's converged state is a snap sub-step's (a pseudo time
    /// step of the current snap), not an equilibrium.
    bool pseudo_state = false;
  };
} // namespace hyperelastic
