// Decoupled (isochoric/volumetric split) compressible neo-Hookean, the model of
// the finite-strain literature's Cook's membrane benchmarks:
//   psi = kappa/4 (J^2 - 1 - 2 ln J) + mu/2 (J^(-2/3) I1 - 3),
//   I1 = tr(F^T F),   J = det F,   kappa = lambda + 2 mu / 3 (bulk modulus).
// Undefined for J <= 0: the energy is +infinity there, P and dP/dF are NaN.
//
// Derivation, with G = F^-T, s = mu J^(-2/3), dJ/dF = J G, dI1/dF = 2 F,
// dG_iJ/dF_kL = -G_iL G_kJ and d(J^a)/dF = a J^a G:
//   P = kappa/2 (J^2 - 1) G + s (F - I1/3 G),
//   A_iJkL = s delta_ik delta_JL - 2s/3 (G_iJ F_kL + F_iJ G_kL)
//            + (kappa J^2 + 2s/9 I1) G_iJ G_kL
//            + (s I1/3 - kappa/2 (J^2 - 1)) G_iL G_kJ.
// (The volumetric part gives kappa J^2 G (x) G - kappa/2 (J^2 - 1) G_iL G_kJ;
// the isochoric part is d s / dF_kL = -2s/3 G_kL times (F - I1/3 G), plus s
// times delta_ik delta_JL - 2/3 F_kL G_iJ + I1/3 G_iL G_kJ.)
//
// Rest state: at F = I, J = 1, I1 = 3, G = I, s = mu, so psi = 0, P = 0 and
//   A = mu (delta_ik delta_JL + delta_iL delta_kJ) + (kappa - 2 mu/3) I (x) I,
// the small-strain tensor with Lame lambda = kappa - 2 mu/3: kappa = lambda +
// 2 mu/3 reproduces the scene's (mu, lambda).
//
// Plane strain is the 3D model at diag(F, 1): I1 = in-plane tr(F^T F) + 1,
// J = det of the 2x2 F (F33 = 1), the exponent stays -2/3, and the 3D F^-T is
// diag(F^-T, 1), so P and A above hold verbatim with 2x2 F and G (the in-plane
// blocks of the 3D ones). At F = I the in-plane block of the 3D tangent is the
// plane-strain (mu, lambda) tensor, so the small-strain limit is again the
// scene's (mu, lambda) (I1 = 3 there as well).
//
// psi >= 0: J^2 - 1 - 2 ln J >= 0 (minimum 0 at J = 1) and J^(-2/3) I1 >= 3
// by the AM-GM inequality on the squared principal stretches (in plane strain
// on l1^2, l2^2, 1).
#pragma once

#include <hyperelastic/materials/material.h>
#include <hyperelastic/materials/volumetric_split.h>

#include <cmath>
#include <limits>

namespace hyperelastic
{
  template <int dim>
  class DecoupledNeoHookean : public LameBasedMaterial<dim, DecoupledNeoHookean>
  {
  public:
    using Material<dim>::not_a_number_tensor;

    /// @p lame are the scene's constants; the bulk modulus kappa = lambda +
    /// 2 mu / 3 is derived from them.
    explicit DecoupledNeoHookean(const LameParameters &lame)
        : LameBasedMaterial<dim, DecoupledNeoHookean>(lame)
        , kappa(lame.lambda + 2. / 3. * lame.mu)
    {
    }

    std::string
    name() const override
    {
      return "decoupled neo-Hookean";
    }

    /// One paragraph for the scene documentation (material_registry.h).
    static const char *
    documentation()
    {
      return "Decoupled neo-Hookean, psi = kappa/4 (J^2 - 1 - 2 ln J) + mu/2 "
             "(J^(-2/3) I1 - 3), the model of the finite-strain literature "
             "(e.g. Cook's membrane), with bulk modulus kappa = lambda + 2 mu "
             "/ 3 from the shared elastic constants. Undefined for inverted "
             "elements (J <= 0).";
    }

    double
    energy_density(const Tensor<2, dim> &F) const override
    {
      const double J = determinant(F);
      if (!(J > 0.))
        return std::numeric_limits<double>::infinity();
      return 0.25 * kappa * ((J - 1.) * (J + 1.) - 2. * std::log(J)) +
             0.5 * this->lame.mu *
               (isochoric_factor(J) * first_invariant(F) - 3.);
    }

    /// P = kappa/2 (J^2 - 1) F^-T + mu J^(-2/3) (F - I1/3 F^-T).
    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override
    {
      const double J = determinant(F);
      if (!(J > 0.))
        return not_a_number_tensor();
      const Tensor<2, dim> G  = transpose(invert(F));
      const double         I1 = first_invariant(F);
      const double         s  = this->lame.mu * isochoric_factor(J);
      return 0.5 * kappa * (J - 1.) * (J + 1.) * G + s * (F - I1 / 3. * G);
    }

    /// The A_iJkL of the header comment.
    StressTangent<dim>
    stress_tangent(const Tensor<2, dim> &F) const override
    {
      Tensor<2, dim>     P;
      StressTangent<dim> A;
      stress_and_tangent(F, P, A);
      return A;
    }

    /// P and A from one evaluation of J, I1, F^-T and J^(-2/3).
    void
    stress_and_tangent(const Tensor<2, dim> &F,
                       Tensor<2, dim>       &P,
                       StressTangent<dim>   &A) const override
    {
      const double J = determinant(F);
      if (!(J > 0.))
        {
          P = not_a_number_tensor();
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int J_ = 0; J_ < dim; ++J_)
              A[i][J_] = not_a_number_tensor();
          return;
        }
      const Tensor<2, dim> G        = transpose(invert(F));
      const double         I1       = first_invariant(F);
      const double         s        = this->lame.mu * isochoric_factor(J);
      const double         volume   = 0.5 * kappa * (J - 1.) * (J + 1.);
      const double         mixed    = -2. / 3. * s;
      const double         G_G      = kappa * J * J + 2. / 9. * s * I1;
      const double         G_G_swap = s * I1 / 3. - volume;
      P                             = volume * G + s * (F - I1 / 3. * G);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int J_ = 0; J_ < dim; ++J_)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int L = 0; L < dim; ++L)
              A[i][J_][k][L] =
                (i == k && J_ == L ? s : 0.) +
                mixed * (G[i][J_] * F[k][L] + F[i][J_] * G[k][L]) +
                G_G * G[i][J_] * G[k][L] + G_G_swap * G[i][L] * G[k][J_];
    }

    bool
    defined_for_inverted_elements() const override
    {
      return false;
    }

    /// Isochoric part: this model with kappa = 0 (lambda = -2 mu / 3).
    std::unique_ptr<VolumetricSplit<dim>>
    volumetric_split() const override
    {
      LameParameters isochoric = this->lame;
      isochoric.lambda         = -2. / 3. * isochoric.mu;
      return std::make_unique<VolumetricSplit<dim>>(VolumetricSplit<dim>{
        std::make_unique<DecoupledNeoHookean<dim>>(isochoric),
        LogVolumetricEnergy(kappa)});
    }

  private:
    /// The bulk modulus lambda + 2 mu / 3.
    const double kappa;

    /// I1 = tr(F^T F) of the 3D F; F33 = 1 adds 1 in plane strain.
    static double
    first_invariant(const Tensor<2, dim> &F)
    {
      return scalar_product(F, F) + (dim == 2 ? 1. : 0.);
    }

    /// J^(-2/3), for J > 0.
    static double
    isochoric_factor(const double J)
    {
      const double cube_root = std::cbrt(J);
      return 1. / (cube_root * cube_root);
    }
  };
} // namespace hyperelastic
