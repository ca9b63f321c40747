// The settings every contact term shares: the barrier distance d_hat, the
// barrier stiffness kappa and friction's smoothing eps, from the scene's
// 'Contact' entries or, where these are 0, from the body and the material.
#pragma once

#include <hyperelastic/contact/contact_parameters.h>
#include <hyperelastic/materials/material.h>

namespace hyperelastic
{
  struct BarrierSettings
  {
    /// d_hat: 'Barrier distance', or 1e-3 of the body's bounding-box
    /// diagonal.
    double d_hat = 0.;
    /// kappa: 'Barrier stiffness', or the P-wave modulus lambda + 2 mu over
    /// d_hat (a barrier as stiff as the material over its reach).
    double kappa = 0.;
    /// Friction's smoothing: 'Friction smoothing', or a slip length per
    /// step of 0.1 d_hat (quasi-static) or a slip velocity of d_hat per unit
    /// time (dynamics).
    double eps = 0.;
  };

  /// The settings for a body whose bounding box has the diagonal
  /// @p diagonal, of a material with the small-strain @p moduli.
  BarrierSettings
  barrier_settings(const ContactParameters &parameters,
                   double                   diagonal,
                   const LameParameters    &moduli,
                   bool                     dynamic);
} // namespace hyperelastic
