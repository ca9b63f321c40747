// Adaptive load stepping: the load factor t goes from 0 to 1 in increments
// that are halved when Newton fails (the system returns to its last converged
// state and retries) and grow back after easy steps. Knows nothing of
// elasticity.
#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <hyperelastic/solvers/load_stepping_parameters.h>
#include <hyperelastic/solvers/newton_solver.h>

#include <functional>

namespace hyperelastic
{
  /// A nonlinear system that depends on a load factor and can return to its
  /// last converged state.
  class SteppedSystem : public NonlinearSystem
  {
  public:
    virtual void
    set_load_factor(double t) = 0;
    virtual void
    store_converged_state() = 0;
    virtual void
    restore_converged_state() = 0;
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
  };

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
    void
    run(const NewtonSolver &newton,
        SteppedSystem      &system,
        const std::function<void(const LoadStep &, const NewtonResult &)>
          &on_converged) const;

  private:
    const LoadSteppingParameters parameters;
    const double                 end;
    const double                 nominal;
    dealii::ConditionalOStream   pcout;
    /// "Load step" or "Time step".
    const std::string label;
  };
} // namespace hyperelastic
