// Drucker stability of a fitted material along the standard deformation
// modes: the incremental work d(sigma) : d(epsilon) must be positive
// (sigma Cauchy, epsilon logarithmic strain). With principal stretches l_i
// and P diagonal, K_ij = delta_ij l_i P_ii + l_i l_j A_iijj, and
//   incompressible: D_ab = K_ab - K_a3 - K_3b + K_33 (a, b = 1, 2; the
//                   increments keep J = 1, the pressure drops out),
//   compressible:   D_ij = K_ij / J - sigma_i (i, j = 1, 2, 3),
// must have a positive definite symmetric part. Checked along uniaxial,
// equibiaxial and planar paths (lateral stretches as in the tests:
// calibration/homogeneous_test.h), from stretch 1 outwards in tension and
// in compression, reporting the first unstable stretch of each.
#pragma once

#include <hyperelastic/calibration/homogeneous_test.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  namespace calibration
  {
    struct StabilityVerdict
    {
      TestType mode = TestType::uniaxial;
      /// The first unstable stretch met going from 1 to the range's upper
      /// (tension) and lower (compression) end; 0 if none.
      double first_unstable_in_tension     = 0.;
      double first_unstable_in_compression = 0.;

      bool
      stable() const
      {
        return first_unstable_in_tension == 0. &&
               first_unstable_in_compression == 0.;
      }

      /// "uniaxial: stable" or "uniaxial: unstable in tension at stretch
      /// 1.93".
      std::string
      text() const;
    };

    /// Uniaxial (where isotropic_about_x(), homogeneous_test.h),
    /// equibiaxial and planar over stretches in [@p lowest, @p highest]
    /// (lowest < 1 < highest), sampled at @p samples stretches per side,
    /// geometrically spaced.
    std::vector<StabilityVerdict>
    drucker_stability(const Material<3> &material,
                      bool               incompressible,
                      double             lowest,
                      double             highest,
                      unsigned int       samples = 400);

    /// The matrix D of the header at the deformation of @p state: 2 x 2
    /// with @p incompressible, 3 x 3 otherwise; empty where the lateral
    /// stretch cannot be solved.
    std::vector<std::vector<double>>
    incremental_stiffness(const Material<3> &material,
                          const TestState   &state,
                          bool               incompressible);

    /// True if the symmetric part of @p D is positive definite.
    bool
    positive_definite(const std::vector<std::vector<double>> &D);
  } // namespace calibration
} // namespace hyperelastic
