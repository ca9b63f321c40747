// Adaptive load stepping: the load factor t goes from 0 to 1 in increments
// that are halved when Newton fails (the system returns to its last converged
// state and retries) and grow back after easy steps. Knows nothing of
// elasticity.
#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <hyperelastic/base/linear_algebra.h>
#include <hyperelastic/solvers/continuation_system.h>
#include <hyperelastic/solvers/load_stepping_parameters.h>
#include <hyperelastic/solvers/newton_solver.h>
#include <hyperelastic/solvers/nonlinear_system.h>
#include <hyperelastic/solvers/tangent_system.h>

#include <functional>
#include <optional>
#include <string>

namespace hyperelastic
{
  /// The first line of a failure message: the reason, without the Newton
  /// table a convergence failure carries after it (the stepper's and the
  /// snap sub-steps' log lines).
  inline std::string
  first_line(const std::string &text)
  {
    return text.substr(0, text.find('\n'));
  }

  /// The tangent's stiffness along the path at the system's state: du/dt
  /// from K du_t = -dr/dt into @p du_t (assembling the tangent; @p r_t
  /// holds -dr/dt after), and the Rayleigh quotient du_t . K du_t /
  /// |du_t|^2 = -du_t . dr/dt / |du_t|^2 (|.| by path_product(); with a
  /// mixed formulation du_t . K du_t is the energy of the pressure-condensed
  /// tangent, dr/dt being zero on the pressure rows) as the result: positive on
  /// a stable path, zero at a maximum of the load, negative beyond (Bergan's
  /// current stiffness parameter, unnormalized). Collective.
  double
  stiffness_along_path(ContinuationSystem &continuation,
                       TangentSystem      &tangent,
                       VectorType         &r_t,
                       VectorType         &du_t);

  /// A nonlinear system that depends on a load factor and can return to its
  /// last converged state: what the load stepper drives.
  class SteppedSystem : public NonlinearSystem
  {
  public:
    /// Starts a step to the load factor (or time) @p t from the last
    /// converged state: the step's predictor becomes the iterate.
    virtual void
    set_load_factor(double t) = 0;
    /// The current iterate becomes the last converged state.
    virtual void
    store_converged_state() = 0;
    /// Back to the last converged state (after a failed attempt).
    virtual void
    restore_converged_state() = 0;
    /// u of the current iterate (owned entries).
    virtual const VectorType &
    state() const = 0;
  };

  /// How a converged load step was reached.
  struct LoadStep
  {
    unsigned int step        = 0; ///< count of converged steps, from 1
    double       load_factor = 0.;
    double       increment   = 0.;
    /// Failed attempts (each followed by halving the increment) before this
    /// step converged.
    unsigned int cut_backs = 0;
    /// Where the step landed on a stop of 'Load stepping/Stop at load
    /// factors': its index in that list (none between stops). Readers find
    /// their load factors by it, not by comparing doubles.
    std::optional<unsigned int> stop;
    /// The stepper's state after this step (a checkpoint resumes from it).
    double       next_increment = 0.;
    unsigned int easy_steps     = 0; ///< easy steps in a row
    /// Newton iterations of the run so far (from its start or restart),
    /// failed attempts included: what the run cost.
    unsigned int newton_in_all = 0;
    /// The nominal increment and the load factor (or time) the run started
    /// from: newton_in_all / ((load_factor - start) / nominal) is the cost
    /// per nominal step (newton_per_nominal_step()).
    double nominal = 0.;
    double start   = 0.;
    /// The smallest increment of a converged step so far.
    double smallest_increment = 0.;

    /// Newton iterations per nominal step so far (failed attempts
    /// included); 0 before any step.
    double
    newton_per_nominal_step() const
    {
      const double nominal_steps =
        nominal > 0. ? (load_factor - start) / nominal : 0.;
      return nominal_steps > 0. ? newton_in_all / nominal_steps : 0.;
    }
  };

  /// Where a resumed run starts (a restart from a checkpoint): the system
  /// already holds that converged state.
  struct ResumePoint
  {
    double       t          = 0.;
    double       increment  = 0.;
    unsigned int step       = 0;
    unsigned int easy_steps = 0;
  };

  /// What the steps advance: the load factor (quasi-static, "Load step
  /// k") or time (implicit dynamics, "Time step k").
  enum class StepVariable
  {
    load_factor,
    time
  };

  /// The steps of a scene: load control (LoadControl: cut-backs, snap
  /// steps and sub-steps) or arc-length continuation (ArcLengthStepper)
  /// over the load factor, load control over time.
  class LoadStepper
  {
  public:
    LoadStepper(const LoadSteppingParameters &parameters,
                unsigned int                  n_nominal_steps,
                dealii::ConditionalOStream    pcout);

    /// The same control of a time variable t from 0 to @p end in steps of
    /// @p nominal_increment (implicit dynamics: "Time step k").
    LoadStepper(const LoadSteppingParameters &parameters,
                double                        end,
                double                        nominal_increment,
                dealii::ConditionalOStream    pcout);

    /// Runs t from 0 to 1 and calls @p on_converged after each converged
    /// step. Throws ConvergenceFailure (with the last failure's reason) when
    /// the increment would fall below the minimum, or at the first failure
    /// if adaptive stepping is off.
    /// @p resume: continue from there instead of t = 0 (load control only).
    void
    run(const NewtonSolver &newton,
        SteppedSystem      &system,
        const std::function<void(const LoadStep &, const NewtonResult &)>
                          &on_converged,
        const ResumePoint *resume = nullptr) const;

  private:
    const LoadSteppingParameters parameters;
    const StepVariable           variable;
    const double                 end;
    const double                 nominal;
    dealii::ConditionalOStream   pcout;
  };
} // namespace hyperelastic
