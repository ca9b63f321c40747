// The contact terms' shared defaults for d_hat, kappa and eps.
#include <deal.II/base/mpi.h>

#include <hyperelastic/contact/barrier_settings.h>
#include <hyperelastic/contact/barrier_stiffness.h>

#include <cmath>

#include <sstream>

namespace hyperelastic
{
  double
  diagonal_barrier_distance(const double diagonal)
  {
    return 1e-3 * diagonal;
  }

  double
  mean_element_size(const std::vector<double> &areas,
                    const int                  dim,
                    const bool                 distributed,
                    const MPI_Comm             comm)
  {
    double sum = 0., count = 0.;
    for (const double a : areas)
      if (a > 0.)
        {
          sum += dim == 2 ? a : std::sqrt(a);
          count += 1.;
        }
    if (distributed)
      {
        sum   = dealii::Utilities::MPI::sum(sum, comm);
        count = dealii::Utilities::MPI::sum(count, comm);
      }
    return count > 0. ? sum / count : 0.;
  }

  BarrierSettings
  barrier_settings(const ContactParameters &parameters,
                   const double             diagonal,
                   const LameParameters    &moduli,
                   const bool               dynamic,
                   const double             element_size,
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
    s.kappa_0      = (moduli.lambda + 2. * moduli.mu) / s.d_hat;
    s.element_size = element_size;
    s.adaptive_kappa = !(parameters.barrier_stiffness > 0.) && !dynamic &&
                       parameters.operating_point;
    if (s.adaptive_kappa && element_size > 0.)
      s.operating_factor =
        s.d_hat / (BarrierStiffness::force_factor(BarrierStiffness::target) *
                   element_size);
    s.kappa = parameters.barrier_stiffness > 0.
                ? parameters.barrier_stiffness
                : s.kappa_0 * s.operating_factor;
    s.eps   = parameters.friction_smoothing > 0.
                ? parameters.friction_smoothing
                : (dynamic ? s.d_hat : 0.1 * s.d_hat);
    return s;
  }

  std::string
  barrier_stiffness_text(const BarrierSettings &settings, const double kappa)
  {
    std::ostringstream s;
    if (settings.operating_factor != 1. && settings.kappa == kappa)
      s << settings.kappa_0 << " x " << settings.operating_factor << " = "
        << kappa << " (automatic: (lambda + 2 mu) / d_hat times d_hat / ("
        << BarrierStiffness::force_factor(BarrierStiffness::target)
        << " h), h = " << settings.element_size
        << " the boundary's mean element size; re-targeted between steps)";
    else
      s << kappa;
    return s.str();
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
