// Stable neo-Hookean (Smith, de Goes, Kim 2018, "Stable Neo-Hookean Flesh
// Simulation"), with model constants mu', lambda':
//   psi = mu'/2 (I_C - 3) + lambda'/2 (J - alpha)^2 - mu'/2 ln(I_C + 1)
//         - psi_0,
//   alpha = 1 + 3 mu' / (4 lambda'),   I_C = tr(F^T F),   J = det F,
//   P = mu' (1 - 1/(I_C + 1)) F + lambda' (J - alpha) cof F,   cof F = dJ/dF,
//   A_iJkL = mu' (1 - 1/(I_C + 1)) delta_ik delta_JL
//            + 2 mu' / (I_C + 1)^2 F_iJ F_kL
//            + lambda' cof_iJ cof_kL + lambda' (J - alpha) dcof_iJ/dF_kL,
//   dcof_iJ/dF_kL = eps_ikm eps_JLN F_mN (3D),   eps_ik eps_JL (2D).
//
// Why this model: neo-Hookean's ln J barrier makes psi infinite at J <= 0, so
// one inverted element in a Newton predictor ends the run. Here J enters only
// polynomially and I_C + 1 >= 1, so psi, P and A are finite for every F,
// including flat (J = 0) and inverted (J < 0) elements. cof F and its
// derivative are polynomials in F (never J F^-T), so nothing divides by J.
// Inversion still costs energy: for J <= 1 (so for every inverted element)
// psi >= lambda'/2 (J - 1)^2 - (3 - ln 4)/2 mu', which grows without bound as
// J -> -infinity.
//
// Why alpha: the ln term gives the shear part the factor 1 - 1/(I_C + 1),
// 3/4 at F = I, and alpha is chosen so that the volumetric part cancels it:
// P(I) = 3/4 mu' I + lambda' (1 - alpha) I = 0, F = I is stress free. The
// argument I_C + 1 (not I_C) keeps the logarithm finite at F = 0.
//
// Why mu' and lambda' differ from the scene's mu and lambda: linearising at
// F = I gives the small-strain tensor with mu = 3/4 mu' and
// lambda = lambda' - 5/8 mu'. The model therefore uses
//   mu' = 4/3 mu,   lambda' = lambda + 5/6 mu,
// so that its small-strain response is the user's (E, nu) or (mu, lambda).
// In 2D plane strain (F33 = 1, I_C = in-plane tr(F^T F) + 1, J = det of the
// 2x2 F, cof and dcof the 2D ones) the linearisation has the same form, so
// the same mapping holds. The scene check lambda + 2 mu / 3 > 0 implies
// lambda' > mu / 6 > 0; the code does not even need it, because it never
// forms alpha (see below).
//
// Why psi_0 and the rewritten form: the paper's energy is not zero at F = I.
// psi_0 = psi_paper(I) is subtracted so that psi(I) = 0 like every other
// model here (P and A are unchanged). Using lambda' (alpha - 1) = 3/4 mu' and
// d = I_C - 3, the energy and the volumetric stress factor are evaluated as
//   psi = mu'/2 (d - ln(1 + d/4)) + (J - 1) (lambda'/2 (J - 1) - 3/4 mu'),
//   lambda' (J - alpha) = lambda' (J - 1) - 3/4 mu',
// which vanish exactly at F = I (no cancellation of ln 4 or of
// (1 - alpha)^2) and contain no 1/lambda'.
#pragma once

#include <hyperelastic/materials/material.h>

#include <cmath>

namespace hyperelastic
{
  template <int dim>
  class StableNeoHookean : public LameBasedMaterial<dim, StableNeoHookean>
  {
  public:
    /// @p lame are the user's small-strain constants; the model constants
    /// mu' = 4/3 mu and lambda' = lambda + 5/6 mu are derived from them.
    explicit StableNeoHookean(const LameParameters &lame)
        : LameBasedMaterial<dim, StableNeoHookean>(lame)
        , mu_model(4. / 3. * lame.mu)
        , lambda_model(lame.lambda + 5. / 6. * lame.mu)
    {
    }

    std::string
    name() const override
    {
      return "stable neo-Hookean";
    }

    /// One paragraph for the scene documentation (material_registry.h).
    static const char *
    documentation()
    {
      return "Stable neo-Hookean (Smith, de Goes, Kim 2018): J enters "
             "polynomially, so psi, P and dP/dF are finite for inverted "
             "elements. Its constants mu' = 4/3 mu and lambda' = lambda + 5/6 "
             "mu are derived from the shared elastic constants so that the "
             "small-strain E and nu are the scene's.";
    }

    /// psi(F), zero at F = I and finite for every F.
    double
    energy_density(const Tensor<2, dim> &F) const override
    {
      const Invariants inv      = invariants(F);
      const double     J_minus1 = inv.J - 1.;
      return 0.5 * mu_model * (inv.d - std::log1p(0.25 * inv.d)) +
             J_minus1 * (0.5 * lambda_model * J_minus1 - 0.75 * mu_model);
    }

    /// P = mu' (1 - 1/(I_C + 1)) F + lambda' (J - alpha) cof F.
    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override
    {
      const Invariants inv = invariants(F);
      return shear_factor(inv) * F + volume_factor(inv) * inv.cof;
    }

    /// The A_iJkL of the header comment; finite for every F.
    StressTangent<dim>
    stress_tangent(const Tensor<2, dim> &F) const override
    {
      Tensor<2, dim>     P;
      StressTangent<dim> A;
      stress_and_tangent(F, P, A);
      return A;
    }

    /// P and A from one evaluation of I_C, J and cof F.
    void
    stress_and_tangent(const Tensor<2, dim> &F,
                       Tensor<2, dim>       &P,
                       StressTangent<dim>   &A) const override
    {
      const Invariants inv    = invariants(F);
      const double     shear  = shear_factor(inv);
      const double     volume = volume_factor(inv);
      P                       = shear * F + volume * inv.cof;

      const double r        = inv.d + 4.; // I_C + 1
      const double rank_one = 2. * mu_model / (r * r);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int J = 0; J < dim; ++J)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int L = 0; L < dim; ++L)
              A[i][J][k][L] = (i == k && J == L ? shear : 0.) +
                              rank_one * F[i][J] * F[k][L] +
                              lambda_model * inv.cof[i][J] * inv.cof[k][L] +
                              volume * cofactor_derivative(F, i, J, k, L);
    }

    bool
    defined_for_inverted_elements() const override
    {
      return true;
    }

  private:
    /// mu' and lambda', the constants of the energy (not the scene's).
    const double mu_model;
    const double lambda_model;

    struct Invariants
    {
      double         d; // I_C - 3 (3D invariant; F33 = 1 in plane strain)
      double         J;
      Tensor<2, dim> cof; // dJ/dF
    };

    static Invariants
    invariants(const Tensor<2, dim> &F)
    {
      Invariants inv;
      // In plane strain I_C = tr(F^T F) + 1, so I_C - 3 = tr(F^T F) - 2.
      inv.d   = scalar_product(F, F) - dim;
      inv.J   = determinant(F);
      inv.cof = cofactor(F);
      return inv;
    }

    /// mu' (1 - 1/(I_C + 1)); I_C + 1 >= 1, so this never divides by 0.
    double
    shear_factor(const Invariants &inv) const
    {
      return mu_model * (1. - 1. / (inv.d + 4.));
    }

    /// lambda' (J - alpha), written without alpha = 1 + 3 mu' / (4 lambda').
    double
    volume_factor(const Invariants &inv) const
    {
      return lambda_model * (inv.J - 1.) - 0.75 * mu_model;
    }

    /// cof F = dJ/dF as a polynomial in F (equal to J F^-T where J != 0).
    static Tensor<2, dim>
    cofactor(const Tensor<2, dim> &F)
    {
      Tensor<2, dim> C;
      if constexpr (dim == 2)
        {
          C[0][0] = F[1][1];
          C[0][1] = -F[1][0];
          C[1][0] = -F[0][1];
          C[1][1] = F[0][0];
        }
      else
        {
          // cof_iJ = F_(i+1)(J+1) F_(i+2)(J+2) - F_(i+1)(J+2) F_(i+2)(J+1),
          // indices modulo 3.
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int J = 0; J < 3; ++J)
              {
                const unsigned int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
                const unsigned int J1 = (J + 1) % 3, J2 = (J + 2) % 3;
                C[i][J] = F[i1][J1] * F[i2][J2] - F[i1][J2] * F[i2][J1];
              }
        }
      return C;
    }

    /// Levi-Civita symbol eps_ab in 2D, or eps_abc with c the third index in
    /// 3D (0 when a = b).
    static double
    permutation_sign(const unsigned int a, const unsigned int b)
    {
      if (a == b)
        return 0.;
      if constexpr (dim == 2)
        return a == 0 ? 1. : -1.;
      else
        return (b + 3 - a) % 3 == 1 ? 1. : -1.;
    }

    /// d cof_iJ / d F_kL: eps_ik eps_JL (2D), eps_ikm eps_JLN F_mN (3D).
    static double
    cofactor_derivative(const Tensor<2, dim> &F,
                        const unsigned int    i,
                        const unsigned int    J,
                        const unsigned int    k,
                        const unsigned int    L)
    {
      const double sign = permutation_sign(i, k) * permutation_sign(J, L);
      if constexpr (dim == 2)
        return sign;
      else
        return sign == 0. ? 0. : sign * F[3 - i - k][3 - J - L];
    }
  };
} // namespace hyperelastic
