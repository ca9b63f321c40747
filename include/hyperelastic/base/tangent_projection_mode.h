// Which quadrature points' stress tangents dP/dF are projected to positive
// semi-definite before assembly: the choice Newton's tangent policy makes
// per iteration ('Newton/Tangent') and the assemblers carry out.
#pragma once

namespace hyperelastic
{
  enum class TangentProjection
  {
    none,            ///< the exact tangent
    inverted_points, ///< projected where J <= 0, exact elsewhere
    every_point      ///< projected everywhere (projected Newton)
  };
} // namespace hyperelastic
