// The choice of the driver: quasi-static or implicit dynamics.
#include <hyperelastic/dynamics/implicit_dynamics.h>
#include <hyperelastic/dynamics/quasi_static.h>
#include <hyperelastic/dynamics/time_stepping.h>

namespace hyperelastic
{
  template <int dim>
  std::unique_ptr<TimeStepping<dim>>
  create_time_stepping(const SteppingContext<dim> &context)
  {
    if (context.time_integration.dynamic())
      return std::make_unique<ImplicitDynamics<dim>>(context);
    return std::make_unique<QuasiStatic<dim>>(context);
  }

  template std::unique_ptr<TimeStepping<2>>
  create_time_stepping(const SteppingContext<2> &);
  template std::unique_ptr<TimeStepping<3>>
  create_time_stepping(const SteppingContext<3> &);
} // namespace hyperelastic
