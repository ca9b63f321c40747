// Drucker stability along the standard modes (see the header).
#include <hyperelastic/calibration/drucker_stability.h>

#include <cmath>
#include <sstream>

namespace hyperelastic
{
  namespace calibration
  {
    bool
    positive_definite(const std::vector<std::vector<double>> &D)
    {
      // Sylvester's criterion on the symmetric part.
      const unsigned int n = D.size();
      if (n == 0)
        return false;
      double S[3][3];
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          S[i][j] = 0.5 * (D[i][j] + D[j][i]);
      const double m1 = S[0][0];
      const double m2 = S[0][0] * S[1][1] - S[0][1] * S[1][0];
      if (!(m1 > 0.) || !(m2 > 0.))
        return false;
      if (n == 2)
        return true;
      const double m3 = S[0][0] * (S[1][1] * S[2][2] - S[1][2] * S[2][1]) -
                        S[0][1] * (S[1][0] * S[2][2] - S[1][2] * S[2][0]) +
                        S[0][2] * (S[1][0] * S[2][1] - S[1][1] * S[2][0]);
      return m3 > 0.;
    }

    std::vector<std::vector<double>>
    incremental_stiffness(const Material<3> &material,
                          const TestState   &state,
                          const bool         incompressible)
    {
      const std::vector<double> l =
        principal_stretches(material, state, incompressible);
      if (!std::isfinite(l[2]))
        return {};
      Tensor<2, 3> F;
      for (unsigned int i = 0; i < 3; ++i)
        F[i][i] = l[i];
      Tensor<2, 3>     P;
      StressTangent<3> A;
      material.stress_and_tangent(F, P, A);
      double K[3][3];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          K[i][j] =
            (i == j ? l[i] * P[i][i] : 0.) + l[i] * l[j] * A[i][i][j][j];
      if (incompressible)
        {
          std::vector<std::vector<double>> D(2, std::vector<double>(2));
          for (unsigned int a = 0; a < 2; ++a)
            for (unsigned int b = 0; b < 2; ++b)
              D[a][b] = K[a][b] - K[a][2] - K[2][b] + K[2][2];
          return D;
        }
      const double                     J = l[0] * l[1] * l[2];
      std::vector<std::vector<double>> D(3, std::vector<double>(3));
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          D[i][j] = K[i][j] / J - l[i] * P[i][i] / J;
      return D;
    }

    std::vector<StabilityVerdict>
    drucker_stability(const Material<3> &material,
                      const bool         incompressible,
                      const double       lowest,
                      const double       highest,
                      const unsigned int samples)
    {
      std::vector<StabilityVerdict> verdicts;
      const bool                    uniaxial = isotropic_about_x(material);
      for (const TestType mode :
           {TestType::uniaxial, TestType::equibiaxial, TestType::planar})
        {
          if (mode == TestType::uniaxial && !uniaxial)
            continue;
          StabilityVerdict verdict;
          verdict.mode = mode;
          for (const double end : {highest, lowest})
            for (unsigned int k = 1; k <= samples; ++k)
              {
                TestState state;
                state.type      = mode;
                state.stretch_1 = std::pow(end, double(k) / samples);
                if (!positive_definite(
                      incremental_stiffness(material, state, incompressible)))
                  {
                    (end > 1. ? verdict.first_unstable_in_tension
                              : verdict.first_unstable_in_compression) =
                      state.stretch_1;
                    break;
                  }
              }
          verdicts.push_back(verdict);
        }
      return verdicts;
    }

    std::string
    StabilityVerdict::text() const
    {
      std::ostringstream out;
      out << test_type_name(mode) << ": ";
      if (stable())
        out << "stable";
      else
        {
          out << "UNSTABLE";
          if (first_unstable_in_tension > 0.)
            out << " in tension from stretch " << first_unstable_in_tension;
          if (first_unstable_in_compression > 0.)
            out << (first_unstable_in_tension > 0. ? "," : "")
                << " in compression from stretch "
                << first_unstable_in_compression;
        }
      return out.str();
    }
  } // namespace calibration
} // namespace hyperelastic
