// The displacement/pressure element pairs of the mixed formulation
// ('Problem/Mixed element'); the assembler is assembly/mixed_assembler.h.
#pragma once

namespace hyperelastic
{
  enum class MixedElement
  {
    mini,        ///< P1-bubble/P1, bubble condensed per cell
    stabilized,  ///< P1/P1 with pressure-projection stabilisation
    taylor_hood, ///< P2/P1
  };

  /// The displacement degree of @p element (2 for Taylor-Hood, else 1).
  inline unsigned int
  displacement_degree(const MixedElement element)
  {
    return element == MixedElement::taylor_hood ? 2 : 1;
  }
} // namespace hyperelastic
