// The steps of a scene: arc length or the load-control loop, and the
// stiffness along the load path.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/solvers/arc_length.h>
#include <hyperelastic/solvers/load_control.h>
#include <hyperelastic/solvers/load_stepping.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace hyperelastic
{
  LoadStepper::LoadStepper(const LoadSteppingParameters &parameters,
                           const unsigned int            n_nominal_steps,
                           dealii::ConditionalOStream    pcout)
      : parameters(parameters)
      , variable(StepVariable::load_factor)
      , end(1.)
      , nominal(1. / n_nominal_steps)
      , pcout(pcout)
  {
  }

  LoadStepper::LoadStepper(const LoadSteppingParameters &parameters,
                           const double                  end,
                           const double                  nominal_increment,
                           dealii::ConditionalOStream    pcout)
      : parameters(parameters)
      , variable(StepVariable::time)
      , end(end)
      , nominal(nominal_increment)
      , pcout(pcout)
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
    if (parameters.method == LoadControl::arc_length &&
        variable == StepVariable::load_factor)
      {
        auto *const continuation = dynamic_cast<ContinuationSystem *>(&system);
        auto *const tangent      = dynamic_cast<TangentSystem *>(&system);
        if (!continuation || !tangent)
          throw ConvergenceFailure("arc length: the system cannot be "
                                   "continued (it has no states (u, t) to "
                                   "set from outside)");
        // A path along which the loads move nothing (no load at all) has
        // nothing to follow: its states are the load-controlled ones.
        if (ArcLengthStepper(parameters, newton.settings(), nominal, pcout)
              .run(system, *continuation, *tangent, on_converged))
          return;
      }
    LoadControlLoop(
      parameters, variable, end, nominal, pcout, newton, system, on_converged)
      .run(resume);
  }

  double
  stiffness_along_path(ContinuationSystem &continuation,
                       TangentSystem      &tangent,
                       VectorType         &r_t,
                       VectorType         &du_t)
  {
    tangent.assemble_tangent();
    continuation.load_derivative(r_t);
    r_t *= -1.;
    tangent.solve_tangent(r_t, du_t);
    const double length2 = continuation.path_product(du_t, du_t);
    return length2 > 0. ? (du_t * r_t) / length2
                        : std::numeric_limits<double>::quiet_NaN();
  }

} // namespace hyperelastic
