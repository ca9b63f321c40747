// Decoupled models whose isochoric energy depends on the first isochoric
// invariant alone (Yeoh, Gent, Arruda-Boyce: one law each, yeoh.h, gent.h,
// arruda_boyce.h), with the volumetric energy Mooney-Rivlin uses:
//   psi = W(Ib) + kappa/4 (J^2 - 1 - 2 ln J),
//   Ib = J^(-2/3) I1,   I1 = tr(F^T F),   J = det F.
// Undefined for J <= 0 (and where the law says so, Gent's locking): the
// energy is +infinity there, P and dP/dF are NaN.
//
// Derivation, with s = J^(-2/3), G = F^-T, dJ/dF = J G, ds/dF = -2/3 s G,
// dI1/dF = 2 F and dG_iJ/dF_kL = -G_iL G_kJ:
//   D = dIb/dF = 2 s (F - I1/3 G),
//   H = d2Ib/dF2, H_iJkL = 2 s [delta_ik delta_JL
//                               - 2/3 (G_iJ F_kL + F_iJ G_kL)
//                               + 2/9 I1 G_iJ G_kL + I1/3 G_iL G_kJ],
//   P = W'(Ib) D + kappa/2 (J^2 - 1) G,
//   A = W''(Ib) D (x) D + W'(Ib) H
//       + kappa J^2 G (x) G - kappa/2 (J^2 - 1) G_iL G_kJ.
// (H is twice the isochoric tangent of decoupled neo-Hookean with mu = 1,
// decoupled_neo_hookean.h; the volumetric part is the same as there.) A has
// the major symmetry term by term.
//
// Rest state: F = I gives Ib = 3, D = 0, H = 2 (delta_ik delta_JL +
// delta_iL delta_kJ - 2/3 delta_iJ delta_kL), so P = 0 and A is the
// small-strain tensor with mu = 2 W'(3), lambda = kappa - 2 mu / 3.
//
// Plane strain is the 3D model at diag(F, 1): I1 gains 1 from F33, J is the
// 2x2 determinant, and every in-plane entry above is the same expression of
// the in-plane blocks (as in decoupled_neo_hookean.h), so the formulas hold
// verbatim in 2D with this I1.
//
// Ib >= 3 by the AM-GM inequality on the squared principal stretches; each
// law gives W(Ib) with W(3) = 0 and its first two derivatives.
//
// A law is a struct with
//   Constants           its constants (with 'kappa'), their scene entries
//                       (declare, parse, entries) and from_small_strain;
//   name(), documentation();
//   evaluate(constants, Ib, W, W1, W2)  W, W', W'' at Ib; returns false where
//                       the law is undefined (Gent at or beyond locking);
//   constant_derivatives(constants, Ib)  dW'/dc at Ib for each entry of
//                       Constants::entries() but the last (Bulk modulus).
// The stress derivatives with respect to the constants (calibration,
// constant_derivatives.h) follow from P: dP/dc = dW'/dc D for the law's
// constants, dP/dkappa = 1/2 (J^2 - 1) G.
#pragma once

#include <hyperelastic/materials/constant_derivatives.h>
#include <hyperelastic/materials/constant_entries.h>
#include <hyperelastic/materials/evaluated_material.h>
#include <hyperelastic/materials/volumetric_split.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace hyperelastic
{
  template <int dim, typename Law>
  class FirstInvariantModel : public EvaluatedMaterial<dim>,
                              public ConstantDerivatives<dim>
  {
  public:
    using Constants = typename Law::Constants;

    explicit FirstInvariantModel(const Constants &constants)
        : constants(constants)
    {
    }

    std::string
    name() const override
    {
      return Law::name();
    }

    /// One paragraph for the scene documentation (material_registry.h).
    static const char *
    documentation()
    {
      return Law::documentation();
    }

    /// mu = 2 W'(3), lambda = kappa - 2 mu / 3.
    LameParameters
    small_strain_moduli() const override
    {
      double W = 0., W1 = 0., W2 = 0.;
      Law::evaluate(constants, 3., W, W1, W2);
      LameParameters lame;
      lame.mu     = 2. * W1;
      lame.lambda = constants.kappa - 2. / 3. * lame.mu;
      return lame;
    }

    std::unique_ptr<Material<3>>
    three_dimensional_twin() const override
    {
      return std::make_unique<FirstInvariantModel<3, Law>>(constants);
    }

    /// Isochoric part: this model with kappa = 0.
    std::unique_ptr<VolumetricSplit<dim>>
    volumetric_split() const override
    {
      return decoupled_split<dim, FirstInvariantModel<dim, Law>>(constants);
    }

    bool
    defined_for_inverted_elements() const override
    {
      return false;
    }

    double
    energy_density(const Tensor<2, dim> &F) const override
    {
      const double J = determinant(F);
      double       W = 0., W1 = 0., W2 = 0.;
      if (!(J > 0.) ||
          !Law::evaluate(constants, isochoric_invariant(F, J), W, W1, W2))
        return std::numeric_limits<double>::infinity();
      return W + volumetric_energy(J);
    }

    /// The constants the model was built from.
    const Constants &
    model_constants() const
    {
      return constants;
    }

    std::vector<std::string>
    constant_names() const override
    {
      return entry_names(constants);
    }

    /// dW'/dc D per law constant, then 1/2 (J^2 - 1) G (the bulk modulus);
    /// NaN where the model is undefined.
    std::vector<Tensor<2, dim>>
    stress_derivatives(const Tensor<2, dim> &F) const override
    {
      const double J  = determinant(F);
      double       W  = 0., W1 = 0., W2 = 0.;
      const double Ib = J > 0. ? isochoric_invariant(F, J) : 0.;
      std::vector<Tensor<2, dim>> dP(constants.entries().size(),
                                     Material<dim>::not_a_number_tensor());
      if (!(J > 0.) || !Law::evaluate(constants, Ib, W, W1, W2))
        return dP;
      const Tensor<2, dim>      G   = transpose(invert(F));
      const double              I1  = first_invariant(F);
      const Tensor<2, dim>      D   = 2. * Ib / I1 * (F - I1 / 3. * G);
      const std::vector<double> dW1 = Law::constant_derivatives(constants, Ib);
      for (unsigned int k = 0; k < dW1.size(); ++k)
        dP[k] = dW1[k] * D;
      dP.back() = 0.5 * (J - 1.) * (J + 1.) * G;
      return dP;
    }

  private:
    const Constants constants;

    /// I1 = tr(F^T F) of the 3D F; F33 = 1 adds 1 in plane strain.
    static double
    first_invariant(const Tensor<2, dim> &F)
    {
      return scalar_product(F, F) + (dim == 2 ? 1. : 0.);
    }

    /// Ib = J^(-2/3) I1, for J > 0.
    static double
    isochoric_invariant(const Tensor<2, dim> &F, const double J)
    {
      const double cube_root = std::cbrt(J);
      return first_invariant(F) / (cube_root * cube_root);
    }

    /// kappa/4 (J^2 - 1 - 2 ln J); 0 for the isochoric part (kappa = 0).
    double
    volumetric_energy(const double J) const
    {
      return constants.kappa == 0. ? 0.
                                   : 0.25 * constants.kappa *
                                       ((J - 1.) * (J + 1.) - 2. * std::log(J));
    }

    /// P and (with @p with_tangent) A of the header comment.
    void
    evaluate(const Tensor<2, dim> &F,
             Tensor<2, dim>       &P,
             StressTangent<dim>   &A,
             const bool            with_tangent) const override
    {
      const double J = determinant(F);
      double       W = 0., W1 = 0., W2 = 0.;
      const double Ib = J > 0. ? isochoric_invariant(F, J) : 0.;
      if (!(J > 0.) || !Law::evaluate(constants, Ib, W, W1, W2))
        {
          EvaluatedMaterial<dim>::undefined_at(P, A, with_tangent);
          return;
        }
      const Tensor<2, dim> G  = transpose(invert(F));
      const double         I1 = first_invariant(F);
      const double         s  = Ib / I1; // J^(-2/3)
      const Tensor<2, dim> D  = 2. * s * (F - I1 / 3. * G);
      // kappa/2 (J^2 - 1); exactly 0 for the isochoric part.
      const double volume = 0.5 * constants.kappa * (J - 1.) * (J + 1.);
      P                   = W1 * D + volume * G;
      if (!with_tangent)
        return;
      const double two_s_W1 = 2. * s * W1;
      const double F_G      = -2. / 3. * two_s_W1;
      const double G_G      = constants.kappa * J * J + 2. / 9. * I1 * two_s_W1;
      const double G_G_swap = I1 / 3. * two_s_W1 - volume;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int J_ = 0; J_ < dim; ++J_)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int L = 0; L < dim; ++L)
              A[i][J_][k][L] =
                W2 * D[i][J_] * D[k][L] + (i == k && J_ == L ? two_s_W1 : 0.) +
                F_G * (G[i][J_] * F[k][L] + F[i][J_] * G[k][L]) +
                G_G * G[i][J_] * G[k][L] + G_G_swap * G[i][L] * G[k][J_];
    }
  };
} // namespace hyperelastic
