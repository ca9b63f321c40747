// The barrier stiffness and its re-targeting between steps (see the header).
#include <hyperelastic/contact/barrier_stiffness.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  double
  BarrierStiffness::force_factor(const double x)
  {
    if (!(x > 0.) || !(x < 1.))
      return 0.;
    return -2. * (1. - x) * std::log(x) + (1. - x) * (1. - x) / x;
  }

  BarrierStiffness::BarrierStiffness(const double kappa, const bool adaptive)
      : kappa(kappa)
      , start(kappa)
      , is_adaptive(adaptive)
  {
  }

  bool
  BarrierStiffness::retarget(const double ratio)
  {
    if (!(ratio < 1.) || !(ratio > 0.))
      return false;
    least = std::min(least, ratio);
    most  = std::max(most, ratio);
    if (!is_adaptive || (ratio >= lowest && ratio <= highest))
      return false;
    const double factor =
      std::clamp(force_factor(ratio) / force_factor(target),
                 1. / largest_factor,
                 largest_factor);
    const double next =
      std::clamp(kappa * factor, start / range, start * range);
    if (next == kappa)
      return false;
    kappa = next;
    ++retargets;
    return true;
  }
} // namespace hyperelastic
