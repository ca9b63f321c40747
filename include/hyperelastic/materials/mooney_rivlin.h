// Decoupled compressible Mooney-Rivlin, with its scene entries (subsection
// Material/Mooney-Rivlin: C1, C2, Bulk modulus):
//   psi = c1 (J^(-2/3) I1 - 3) + c2 (J^(-4/3) I2 - 3)
//         + kappa/4 (J^2 - 1 - 2 ln J),
//   C = F^T F,   I1 = tr C,   I2 = (I1^2 - tr(C^2)) / 2,   J = det F.
// c2 = 0 is the decoupled neo-Hookean model with mu = 2 c1. Undefined for
// J <= 0: the energy is +infinity there, P and dP/dF are NaN.
//
// Derivation, with G = F^-T, s1 = c1 J^(-2/3), s2 = c2 J^(-4/3), B = F F^T,
// dJ/dF = J G, d(J^a)/dF = a J^a G, dG_iJ/dF_kL = -G_iL G_kJ, dI1/dF = 2 F,
// dI2/dF = 2 (I1 F - F C) and d(F C)_iJ/dF_kL = delta_ik C_LJ + F_iL F_kJ
// + B_ik delta_JL:
//   P = 2 (s1 + s2 I1) F - 2 s2 F C
//       + (kappa/2 (J^2 - 1) - 2/3 s1 I1 - 4/3 s2 I2) G,
//   A_iJkL = 2 (s1 + s2 I1) delta_ik delta_JL
//            - 2 s2 (delta_ik C_JL + B_ik delta_JL + F_iL F_kJ)
//            + 4 s2 F_iJ F_kL
//            - 4/3 (s1 + 2 s2 I1) (F_iJ G_kL + G_iJ F_kL)
//            + 8/3 s2 ((F C)_iJ G_kL + G_iJ (F C)_kL)
//            + (kappa J^2 + 4/9 s1 I1 + 16/9 s2 I2) G_iJ G_kL
//            + (2/3 s1 I1 + 4/3 s2 I2 - kappa/2 (J^2 - 1)) G_iL G_kJ.
// (Each part: d/dF [s1 (2 F - 2/3 I1 G)] with ds1/dF = -2/3 s1 G, and
// d/dF [s2 (2 I1 F - 2 F C - 4/3 I2 G)] with ds2/dF = -4/3 s2 G; the
// volumetric part as in decoupled_neo_hookean.h.) A has the major symmetry
// A_iJkL = A_kLiJ term by term.
//
// Rest state: at F = I, J = 1, I1 = I2 = 3, C = B = G = I, so psi = 0, P = 0
// and A = 2 (c1 + c2) (delta_ik delta_JL + delta_iL delta_kJ)
//         + (kappa - 4/3 (c1 + c2)) delta_iJ delta_kL,
// the small-strain tensor with
//   mu = 2 (c1 + c2),   lambda = kappa - 2 mu / 3.
// Conversely, create_material("Mooney-Rivlin", (mu, lambda)) uses the split
// c1 = 3 mu / 8, c2 = mu / 8 (c2 / c1 = 1/3, both terms at work), kappa =
// lambda + 2 mu / 3, whose rest tangent is the (mu, lambda) tensor.
//
// Plane strain is the 3D model at diag(F, 1): C = diag(C2x2, 1), so I1 =
// in-plane tr C + 1, tr(C^2) = in-plane tr(C^2) + 1, J = det of the 2x2 F,
// and G, B, C, F C are block diagonal with 1 in the out-of-plane place. Every
// in-plane entry of P and A above is then the same expression of the in-plane
// blocks, so the formulas hold verbatim in 2D with these I1 and I2.
//
// psi >= 0 for c1, c2 >= 0: J^2 - 1 - 2 ln J >= 0, and by the AM-GM
// inequality on the squared principal stretches (1 as the third in plane
// strain) J^(-2/3) I1 >= 3 and J^(-4/3) I2 >= 3.
//
// Why c1 >= 0 and c2 >= 0 are required (not only c1 + c2 > 0, which is what
// the small-strain response needs): under isochoric uniaxial stretch l
// (stretches l, l^(-1/2), l^(-1/2)) I1 = l^2 + 2/l and I2 = 2 l + 1/l^2, so
// psi ~ c1 l^2 as l -> infinity and psi ~ c2 / l^2 as l -> 0. A negative c1
// or c2 (as some curve fits give) makes psi unbounded below in tension or in
// compression: there is no stable state at large strain, and Newton heads for
// it. Such constants are rejected, with this reason, rather than run.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/materials/constant_derivatives.h>
#include <hyperelastic/materials/constant_entries.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/materials/volumetric_split.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  /// The constants of the Mooney-Rivlin model and their scene entries, in the
  /// subsection Material/Mooney-Rivlin.
  struct MooneyRivlinConstants
  {
    double c1    = 0.375; ///< entry "C1"
    double c2    = 0.125; ///< entry "C2"
    double kappa = 2.;    ///< entry "Bulk modulus"

    /// mu = 2 (c1 + c2), lambda = kappa - 2 mu / 3: the rest-state tangent.
    LameParameters
    small_strain_moduli() const
    {
      LameParameters lame;
      lame.mu     = 2. * (c1 + c2);
      lame.lambda = kappa - 2. / 3. * lame.mu;
      return lame;
    }

    /// The documented split c1 = 3 mu / 8, c2 = mu / 8, kappa = lambda +
    /// 2 mu / 3 (rest tangent = the (mu, lambda) tensor).
    static MooneyRivlinConstants
    from_small_strain(const LameParameters &lame)
    {
      MooneyRivlinConstants constants;
      constants.c1    = 3. / 8. * lame.mu;
      constants.c2    = 1. / 8. * lame.mu;
      constants.kappa = lame.lambda + 2. / 3. * lame.mu;
      return constants;
    }

    /// Declares C1, C2 and Bulk modulus (the handler is inside
    /// Material/Mooney-Rivlin). The defaults give mu = 1, lambda = 4/3.
    static void
    declare(ParameterHandler &prm)
    {
      using dealii::Patterns::Double;
      prm.declare_entry(
        "C1",
        "0.375",
        Double(),
        "c1 >= 0, the constant of c1 (J^(-2/3) I1 - 3). The small-strain "
        "shear modulus is mu = 2 (C1 + C2), which must be positive.");
      prm.declare_entry(
        "C2",
        "0.125",
        Double(),
        "c2 >= 0, the constant of c2 (J^(-4/3) I2 - 3); C2 = 0 is the "
        "decoupled neo-Hookean model with mu = 2 C1. Negative C1 or C2 are "
        "rejected: psi would be unbounded below at large stretch (C1 < 0) or "
        "compression (C2 < 0).");
      prm.declare_entry("Bulk modulus",
                        "2",
                        dealii::Patterns::Anything(),
                        "kappa > 0, the constant of kappa/4 (J^2 - 1 - 2 ln "
                        "J); the small-strain lambda = kappa - 2 mu / 3. "
                        "'inf': exactly incompressible (J = 1 enforced by "
                        "the pressure; 'Problem/Formulation = mixed' only).");
    }

    /// Reads and validates the entries; an invalid value is an InputError
    /// naming @p section/entry.
    static MooneyRivlinConstants
    parse(ParameterHandler &prm, const std::string &section)
    {
      MooneyRivlinConstants constants;
      constants.c1    = get_finite(prm, section, "C1");
      constants.c2    = get_finite(prm, section, "C2");
      constants.kappa = parse_bulk_modulus_entry(prm, section);
      if (constants.c1 < 0.)
        reject(section + "/C1",
               prm.get("C1"),
               "must not be negative: with C1 < 0 the energy is unbounded "
               "below in uniaxial tension (psi ~ C1 l^2)");
      if (constants.c2 < 0.)
        reject(section + "/C2",
               prm.get("C2"),
               "must not be negative: with C2 < 0 the energy is unbounded "
               "below in uniaxial compression (psi ~ C2 / l^2)");
      if (!(constants.c1 + constants.c2 > 0.))
        reject(section + "/C1",
               prm.get("C1"),
               "C1 + C2 must be positive: the small-strain shear modulus is "
               "2 (C1 + C2)");
      return constants;
    }

    /// The scene entries that parse back to these constants exactly.
    std::vector<std::pair<std::string, std::string>>
    entries() const
    {
      const auto text = exact_entry_text;
      return {{"C1", text(c1)},
              {"C2", text(c2)},
              {"Bulk modulus", text(kappa)}};
    }
  };

  template <int dim>
  class MooneyRivlin : public Material<dim>, public ConstantDerivatives<dim>
  {
  public:
    using Constants = MooneyRivlinConstants;
    using Material<dim>::not_a_number_tensor;

    explicit MooneyRivlin(const MooneyRivlinConstants &constants)
        : constants(constants)
    {
    }

    std::string
    name() const override
    {
      return "Mooney-Rivlin";
    }

    /// One paragraph for the scene documentation (material_registry.h).
    static const char *
    documentation()
    {
      return "Decoupled compressible Mooney-Rivlin, psi = C1 (J^(-2/3) I1 - "
             "3) + C2 (J^(-4/3) I2 - 3) + kappa/4 (J^2 - 1 - 2 ln J), I2 = "
             "(I1^2 - tr(C^2))/2. Its constants are the entries C1, C2 and "
             "Bulk modulus of the subsection Material/Mooney-Rivlin (the "
             "shared elastic constants are not used); small-strain mu = 2 (C1 "
             "+ C2), lambda = kappa - 2 mu / 3; C2 = 0 is decoupled "
             "neo-Hookean with mu = 2 C1. Undefined for inverted elements (J "
             "<= 0).";
    }

    /// The constants the model was built from.
    const MooneyRivlinConstants &
    model_constants() const
    {
      return constants;
    }

    LameParameters
    small_strain_moduli() const override
    {
      return constants.small_strain_moduli();
    }

    std::vector<std::string>
    constant_names() const override
    {
      return {"C1", "C2", "Bulk modulus"};
    }

    /// P is linear in C1, C2 and kappa: each derivative is the stress with
    /// that constant 1 and the others 0.
    std::vector<Tensor<2, dim>>
    stress_derivatives(const Tensor<2, dim> &F) const override
    {
      std::vector<Tensor<2, dim>> dP;
      for (double MooneyRivlinConstants::*c : {&MooneyRivlinConstants::c1,
                                               &MooneyRivlinConstants::c2,
                                               &MooneyRivlinConstants::kappa})
        {
          MooneyRivlinConstants unit;
          unit.c1 = unit.c2 = unit.kappa = 0.;
          unit.*c                        = 1.;
          dP.push_back(MooneyRivlin<dim>(unit).first_piola_kirchhoff(F));
        }
      return dP;
    }

    std::unique_ptr<Material<3>>
    three_dimensional_twin() const override
    {
      return std::make_unique<MooneyRivlin<3>>(constants);
    }

    /// Isochoric part: this model with kappa = 0.
    std::unique_ptr<VolumetricSplit<dim>>
    volumetric_split() const override
    {
      MooneyRivlinConstants isochoric = constants;
      isochoric.kappa                 = 0.;
      return std::make_unique<VolumetricSplit<dim>>(
        VolumetricSplit<dim>{std::make_unique<MooneyRivlin<dim>>(isochoric),
                             LogVolumetricEnergy(constants.kappa)});
    }

    double
    energy_density(const Tensor<2, dim> &F) const override
    {
      const double J = determinant(F);
      if (!(J > 0.))
        return std::numeric_limits<double>::infinity();
      const Kinematics kin(F, J);
      return constants.c1 * (kin.J_23 * kin.I1 - 3.) +
             constants.c2 * (kin.J_23 * kin.J_23 * kin.I2 - 3.) +
             0.25 * constants.kappa * ((J - 1.) * (J + 1.) - 2. * std::log(J));
    }

    /// The P of the header comment.
    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override
    {
      const double J = determinant(F);
      if (!(J > 0.))
        return not_a_number_tensor();
      const Kinematics kin(F, J);
      const Factors    f(constants, kin);
      return f.F * F + f.FC * kin.FC + f.G * kin.G;
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

    /// P and A from one evaluation of J, the invariants, F^-T, C, B and F C.
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
      const Kinematics kin(F, J);
      const Factors    f(constants, kin);
      P = f.F * F + f.FC * kin.FC + f.G * kin.G;

      const Tensor<2, dim> &G = kin.G, &C = kin.C, &FC = kin.FC;
      const Tensor<2, dim>  B      = F * transpose(F);
      const double          two_s2 = 2. * f.s2;
      // The coefficients of the header's A, term by term.
      const double F_G  = -4. / 3. * (f.s1 + 2. * f.s2 * kin.I1);
      const double FC_G = 8. / 3. * f.s2;
      const double G_G  = constants.kappa * J * J + 4. / 9. * f.s1 * kin.I1 +
                         16. / 9. * f.s2 * kin.I2;
      // 2/3 s1 I1 + 4/3 s2 I2 - kappa/2 (J^2 - 1), the factor of G in P
      // with the sign changed.
      const double G_G_swap = -f.G;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int J_ = 0; J_ < dim; ++J_)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int L = 0; L < dim; ++L)
              A[i][J_][k][L] =
                (i == k ? (J_ == L ? f.F : 0.) - two_s2 * C[J_][L] : 0.) -
                (J_ == L ? two_s2 * B[i][k] : 0.) -
                two_s2 * F[i][L] * F[k][J_] + 2. * two_s2 * F[i][J_] * F[k][L] +
                F_G * (F[i][J_] * G[k][L] + G[i][J_] * F[k][L]) +
                FC_G * (FC[i][J_] * G[k][L] + G[i][J_] * FC[k][L]) +
                G_G * G[i][J_] * G[k][L] + G_G_swap * G[i][L] * G[k][J_];
    }

    bool
    defined_for_inverted_elements() const override
    {
      return false;
    }

  private:
    const MooneyRivlinConstants constants;

    /// The invariants and tensors P and A are made of, for J > 0.
    struct Kinematics
    {
      Kinematics(const Tensor<2, dim> &F, const double J)
          : J(J)
          , G(transpose(invert(F)))
          , C(transpose(F) * F)
          , FC(F * C)
          // The 3D C is diag(C, 1) in plane strain: 1 more in tr C and in
          // tr(C^2).
          , I1(trace(C) + (dim == 2 ? 1. : 0.))
          , I2(0.5 * (I1 * I1 - scalar_product(C, C) - (dim == 2 ? 1. : 0.)))
          , J_23(1. / (std::cbrt(J) * std::cbrt(J)))
      {
      }

      double         J;
      Tensor<2, dim> G;  ///< F^-T
      Tensor<2, dim> C;  ///< F^T F
      Tensor<2, dim> FC; ///< F C
      double         I1;
      double         I2;
      double         J_23; ///< J^(-2/3)
    };

    /// s1, s2 and the factors of F, F C and G in P.
    struct Factors
    {
      Factors(const MooneyRivlinConstants &c, const Kinematics &k)
          : s1(c.c1 * k.J_23)
          , s2(c.c2 * k.J_23 * k.J_23)
          , F(2. * (s1 + s2 * k.I1))
          , FC(-2. * s2)
          , G(0.5 * c.kappa * (k.J - 1.) * (k.J + 1.) - 2. / 3. * s1 * k.I1 -
              4. / 3. * s2 * k.I2)
      {
      }

      double s1; ///< c1 J^(-2/3)
      double s2; ///< c2 J^(-4/3)
      double F;  ///< 2 (s1 + s2 I1)
      double FC; ///< -2 s2
      double G;  ///< kappa/2 (J^2 - 1) - 2/3 s1 I1 - 4/3 s2 I2
    };
  };
} // namespace hyperelastic
