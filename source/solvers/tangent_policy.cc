// Newton's tangent policy (see the header).
#include <hyperelastic/solvers/tangent_policy.h>

namespace hyperelastic
{
  TangentPolicy::TangentPolicy(const NewtonTangent tangent,
                               const bool          follow_negative_curvature)
      : tangent(tangent)
      , follow_negative_curvature(follow_negative_curvature &&
                                  tangent != NewtonTangent::projected)
  {
  }

  TangentProjection
  TangentPolicy::projection(const bool   first_of_solve,
                            const double residual,
                            const double first_residual) const
  {
    if (tangent == NewtonTangent::projected)
      return TangentProjection::every_point;
    if (tangent == NewtonTangent::automatic &&
        (first_of_solve ||
         residual > NewtonParameters::automatic_switch_ratio * first_residual))
      return TangentProjection::inverted_points;
    return TangentProjection::none;
  }

  std::optional<TangentProjection>
  TangentPolicy::fallback(const TangentProjection failed) const
  {
    const bool has_fallback =
      tangent == NewtonTangent::automatic ||
      tangent == NewtonTangent::exact_then_projected;
    if (!has_fallback || failed == TangentProjection::every_point)
      return std::nullopt;
    // The projected tangent's direction descends. The automatic tangent
    // first tries projecting where J <= 0 only.
    if (tangent == NewtonTangent::automatic &&
        failed == TangentProjection::none)
      return TangentProjection::inverted_points;
    return TangentProjection::every_point;
  }

  bool
  TangentPolicy::follows_negative_curvature(
    const TangentProjection projection) const
  {
    return follow_negative_curvature && projection == TangentProjection::none;
  }

  bool
  TangentPolicy::softens_inverting_predictor() const
  {
    return tangent == NewtonTangent::automatic;
  }

  bool
  TangentPolicy::projects_where_inverted(const TangentProjection projection,
                                         const double            min_J)
  {
    return projection == TangentProjection::inverted_points && min_J <= 0.;
  }

  bool
  TangentPolicy::projects_somewhere(const TangentProjection projection,
                                    const double            min_J)
  {
    return projection == TangentProjection::every_point ||
           projects_where_inverted(projection, min_J);
  }
} // namespace hyperelastic
