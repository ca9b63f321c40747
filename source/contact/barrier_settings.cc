// The contact terms' shared defaults for d_hat, kappa and eps.
#include <hyperelastic/contact/barrier_settings.h>

#include <sstream>

namespace hyperelastic
{
  double
  diagonal_barrier_distance(const double diagonal)
  {
    return 1e-3 * diagonal;
  }

  BarrierSettings
  barrier_settings(const ContactParameters &parameters,
                   const double             diagonal,
                   const LameParameters    &moduli,
                   const bool               dynamic,
                   const double             reference_gap)
  {
    BarrierSettings s;
    if (parameters.barrier_distance > 0.)
      s.d_hat = parameters.barrier_distance;
    else
      {
        // A gap of 0 (features touching at the start) keeps the diagonal's
        // rule, so that the start check names the place.
        s.d_hat         = diagonal_barrier_distance(diagonal);
        s.origin        = BarrierSettings::Origin::diagonal;
        s.reference_gap = reference_gap;
        if (reference_gap > 0. && 0.5 * reference_gap < s.d_hat)
          {
            s.d_hat  = 0.5 * reference_gap;
            s.origin = BarrierSettings::Origin::reference_gap;
          }
      }
    s.kappa = parameters.barrier_stiffness > 0.
                ? parameters.barrier_stiffness
                : (moduli.lambda + 2. * moduli.mu) / s.d_hat;
    s.eps   = parameters.friction_smoothing > 0.
                ? parameters.friction_smoothing
                : (dynamic ? s.d_hat : 0.1 * s.d_hat);
    return s;
  }

  std::string
  barrier_distance_text(const BarrierSettings &settings)
  {
    std::ostringstream s;
    s << "d_hat = " << settings.d_hat;
    switch (settings.origin)
      {
      case BarrierSettings::Origin::given:
        s << " (given)";
        break;
      case BarrierSettings::Origin::diagonal:
        s << " (automatic: 1e-3 of the diagonal)";
        break;
      case BarrierSettings::Origin::reference_gap:
        s << " (automatic: half the smallest reference gap between boundary "
             "features, "
          << settings.reference_gap << ")";
        break;
      }
    return s.str();
  }
} // namespace hyperelastic
