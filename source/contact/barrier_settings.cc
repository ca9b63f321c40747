// The contact terms' shared defaults for d_hat, kappa and eps.
#include <hyperelastic/contact/barrier_settings.h>

namespace hyperelastic
{
  BarrierSettings
  barrier_settings(const ContactParameters &parameters,
                   const double             diagonal,
                   const LameParameters    &moduli,
                   const bool               dynamic)
  {
    BarrierSettings s;
    s.d_hat = parameters.barrier_distance > 0. ? parameters.barrier_distance
                                               : 1e-3 * diagonal;
    s.kappa = parameters.barrier_stiffness > 0.
                ? parameters.barrier_stiffness
                : (moduli.lambda + 2. * moduli.mu) / s.d_hat;
    s.eps   = parameters.friction_smoothing > 0.
                ? parameters.friction_smoothing
                : (dynamic ? s.d_hat : 0.1 * s.d_hat);
    return s;
  }
} // namespace hyperelastic
