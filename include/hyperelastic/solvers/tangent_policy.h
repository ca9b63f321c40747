// Newton's tangent policy ('Newton/Tangent'), on its own so that it can be
// read and tested without a mesh: which quadrature points' dP/dF are
// projected to positive semi-definite in each iteration, whether such a
// projection does anything at the current iterate, and what a failed
// iteration is repeated with.
#pragma once

#include <hyperelastic/base/tangent_projection_mode.h>
#include <hyperelastic/solvers/newton_parameters.h>

#include <optional>

namespace hyperelastic
{
  /// Decides the TangentProjection of every Newton iteration from plain
  /// numbers (residuals, min J): the exact tangent, the projected one, the
  /// exact one with the projected one as fallback, or the automatic choice
  /// (projected where J <= 0 far from the solution, exact near it,
  /// escalating on failure).
  class TangentPolicy
  {
  public:
    /// The policy of the setting @p tangent; with
    /// @p follow_negative_curvature (Newton/Follow negative curvature), the
    /// negative curvature CG meets on the exact tangent is followed in a
    /// trust region.
    explicit TangentPolicy(NewtonTangent tangent,
                           bool          follow_negative_curvature = false);

    /// The projection an iteration starts with. @p first_of_solve: the
    /// first iteration of a solve (or of a solve of lagged equations);
    /// @p residual: the current iterate's residual norm; @p first_residual:
    /// the residual after the first iteration of the solve (not read when
    /// @p first_of_solve). The automatic tangent projects where J <= 0
    /// while far from the solution (the first iteration, or @p residual
    /// above NewtonParameters::automatic_switch_ratio times
    /// @p first_residual), where the exact tangent is indefinite and Newton
    /// would climb to a saddle; it is exact near the solution (quadratic
    /// end).
    TangentProjection
    projection(bool first_of_solve, double residual, double first_residual)
      const;

    /// The projection to repeat a failed iteration with (from the same
    /// iterate), or none if the failure is final. The automatic tangent
    /// escalates none -> inverted_points -> every_point, exact then
    /// projected goes none -> every_point; the exact and the projected
    /// tangents have no fallback, and nothing follows every_point.
    std::optional<TangentProjection>
    fallback(TangentProjection failed) const;

    /// Whether the Krylov solve of an iteration with @p projection watches
    /// for negative curvature, and the iteration is repeated in a trust
    /// region (Steihaug-Toint truncated CG on the exact tangent) where it
    /// meets some: with Newton/Follow negative curvature, for the exact
    /// tangent (projection none).
    bool
    follows_negative_curvature(TangentProjection projection) const;

    /// Whether the predictor's update may be replaced by a gentler
    /// extension of the constraint increment where it would invert cells
    /// (PredictorSoftening): asked by the automatic
    /// tangent only.
    bool
    softens_inverting_predictor() const;

    /// Whether @p projection projects at the inverted points of an iterate
    /// whose smallest J is @p min_J (NaN if not known yet, e.g. before the
    /// first iteration): the points with J <= 0 only matter once the
    /// iterate has some.
    static bool
    projects_where_inverted(TangentProjection projection, double min_J);

    /// Whether @p projection changes the tangent anywhere at an iterate
    /// whose smallest J is @p min_J: every_point always, inverted_points
    /// as projects_where_inverted().
    static bool
    projects_somewhere(TangentProjection projection, double min_J);

  private:
    const NewtonTangent tangent;
    const bool          follow_negative_curvature;
  };
} // namespace hyperelastic
