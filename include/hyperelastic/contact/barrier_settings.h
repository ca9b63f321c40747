// The settings every contact term shares: the barrier distance d_hat, the
// barrier stiffness kappa and friction's smoothing eps, from the scene's
// 'Contact' entries or, where these are 0, from the body, its boundary's
// reference gaps (self contact) and the material.
#pragma once

#include <hyperelastic/contact/contact_parameters.h>
#include <hyperelastic/materials/material.h>

#include <mpi.h>

#include <limits>
#include <string>
#include <vector>

namespace hyperelastic
{
  struct BarrierSettings
  {
    /// Where d_hat comes from.
    enum class Origin
    {
      given,        ///< 'Barrier distance'
      diagonal,     ///< 1e-3 of the body's bounding-box diagonal
      reference_gap ///< half the smallest reference gap of the boundary
    };
    /// d_hat: 'Barrier distance', or the smaller of 1e-3 of the body's
    /// bounding-box diagonal and half the smallest gap between non-adjacent
    /// boundary features in the reference configuration (self contact).
    double d_hat  = 0.;
    Origin origin = Origin::given;
    /// The smallest reference gap the automatic d_hat saw (+infinity if
    /// none within twice the diagonal's rule, or without self contact).
    double reference_gap = std::numeric_limits<double>::infinity();
    /// kappa: 'Barrier stiffness', or automatic: quasi-statically
    /// kappa_0 (lambda + 2 mu) / d_hat, the P-wave modulus over d_hat, times
    /// operating_factor = d_hat / (g(1/2) h), h the boundary's mean element
    /// size: the pressure (lambda + 2 mu) d_hat / h that compresses a
    /// boundary element by d_hat then holds a pair at d = d_hat / 2, the
    /// middle of the barrier's range (BarrierStiffness); in dynamics kappa_0
    /// itself.
    double kappa = 0.;
    double kappa_0 = 0., operating_factor = 1., element_size = 0.;
    /// Whether kappa is re-targeted between steps (BarrierStiffness): the
    /// automatic kappa of a quasi-static scene.
    bool adaptive_kappa = false;
    /// Friction's smoothing: 'Friction smoothing', or a slip length per
    /// step of 0.1 d_hat (quasi-static) or a slip velocity of d_hat per unit
    /// time (dynamics).
    double eps = 0.;
  };

  /// The automatic d_hat's rule for a body whose bounding box has the
  /// diagonal @p diagonal: 1e-3 of it.
  double
  diagonal_barrier_distance(double diagonal);

  /// The settings for a body whose bounding box has the diagonal
  /// @p diagonal and whose boundary's mean element size is
  /// @p element_size, of a material with the small-strain @p moduli; with
  /// 'Barrier distance = 0' and a finite, positive @p reference_gap (the
  /// smallest distance between non-adjacent boundary features in the
  /// reference configuration, measured by self contact up to twice
  /// diagonal_barrier_distance()), d_hat is at most half of it.
  BarrierSettings
  barrier_settings(
    const ContactParameters &parameters,
    double                   diagonal,
    const LameParameters    &moduli,
    bool                     dynamic,
    double                   element_size  = 0.,
    double reference_gap = std::numeric_limits<double>::infinity());

  /// The mean element size of a boundary whose vertices have the shares
  /// @p areas of its measure (2D: lengths, h = the share; 3D: areas, h =
  /// sqrt of the share, exact for a regular mesh of right triangles), over
  /// all ranks of @p comm if @p distributed (each rank holds its own
  /// vertices). Collective if @p distributed.
  double
  mean_element_size(const std::vector<double> &areas,
                    int                        dim,
                    bool                       distributed,
                    MPI_Comm                   comm);

  /// The barrier stiffness @p kappa for the run header, with the automatic
  /// one's factors.
  std::string
  barrier_stiffness_text(const BarrierSettings &settings, double kappa);

  /// "d_hat = <value> (<where it comes from>)" for the run header.
  std::string
  barrier_distance_text(const BarrierSettings &settings);
} // namespace hyperelastic
