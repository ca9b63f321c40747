// Holzapfel-Gasser-Ogden with fibre dispersion, in the form of Nolan et al.
// 2014 (the fibre term on the full invariants, which behaves correctly under
// volume change), with its scene entries (subsection
// Material/Holzapfel-Gasser-Ogden):
//   psi = mu/2 (Ib - 3) + kappa/4 (J^2 - 1 - 2 ln J)
//         + sum_i k1/(2 k2) (exp(k2 E_i^2) - 1)   for the families with I4_i >
//         1,
//   E_i = kd (I1 - 3) + (1 - 3 kd)(I4_i - 1),  I1 = tr C,  I4_i = a_i . C a_i,
// a_i the unit reference direction of family i (up to two), kd the
// dispersion in [0, 1/3] (0 aligned fibres, 1/3 isotropic).
//
// The matrix (the first two terms) is decoupled neo-Hookean, written with
// first_invariant_model.h. A fibre family adds, with e = exp(k2 E^2),
//   psi_f' = k1 E e,   psi_f'' = k1 e (1 + 2 k2 E^2),
//   G = dE/dF = 2 kd F + 2 (1 - 3 kd) (F a) (x) a,
//   P += psi_f' G,
//   A += psi_f'' G (x) G + psi_f' (2 kd delta_ik delta_JL
//                                 + 2 (1 - 3 kd) delta_ik a_J a_L).
// Fibres carry no compression: a family is off while I4 <= 1. At the switch
// I4 = 1 the energy is continuous with a continuous P when kd = 0 (E = 0
// there); with kd > 0, E = kd (I1 - 3) is not 0 at the switch, so psi and P
// jump there (a property of the model, as in the codes that implement it).
// The rest state has I4 = 1, so its tangent is the matrix's: the
// small-strain moduli are mu and lambda = kappa - 2 mu / 3, and tension along
// a fibre is stiffer from the first strain on (one-sided).
//
// Plane strain: the 3D model at diag(F, 1) with the fibres in the x-y
// plane: I1 gains 1 from F33 and I4 involves only the in-plane block.
//
// Fibre directions are expressions of the reference position: a model whose
// directions use x, y or z depends_on_position(), and the assemblers build
// at_position(X), with the directions evaluated at X, once per quadrature
// point. Evaluating such a model without a position is a programming error.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/materials/constant_entries.h>
#include <hyperelastic/materials/fibre_directions.h>
#include <hyperelastic/materials/first_invariant_model.h>
#include <hyperelastic/materials/model_capabilities.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  /// The matrix of the fibre model: W(Ib) = mu/2 (Ib - 3).
  struct FibreMatrixLaw
  {
    struct Constants
    {
      double mu    = 1.;
      double kappa = 2.;

      /// The matrix's own constants by the names of the model's entries.
      std::vector<std::pair<std::string, std::string>>
      entries() const
      {
        return {{"Shear modulus", exact_entry_text(mu)},
                {"Bulk modulus", exact_entry_text(kappa)}};
      }
    };

    static std::string
    name()
    {
      return "Holzapfel-Gasser-Ogden matrix";
    }

    static const char *
    documentation()
    {
      return "the neo-Hookean matrix of Holzapfel-Gasser-Ogden";
    }

    /// W = mu/2 (Ib - 3).
    static bool
    evaluate(const Constants &c,
             const double     Ib,
             double          &W,
             double          &W1,
             double          &W2)
    {
      W  = 0.5 * c.mu * (Ib - 3.);
      W1 = 0.5 * c.mu;
      W2 = 0.;
      return true;
    }

    /// dW'/dmu.
    static std::vector<double>
    constant_derivatives(const Constants &, const double)
    {
      return {0.5};
    }
  };

  struct HolzapfelGasserOgdenConstants
  {
    double mu    = 1.; ///< entry "Shear modulus"
    double k1    = 1.; ///< entry "k1"
    double k2    = 1.; ///< entry "k2"
    double kd    = 0.; ///< entry "Dispersion"
    double kappa = 2.; ///< entry "Bulk modulus"
    /// Entries "Fibre direction 1" and "Fibre direction 2" (text; empty:
    /// no such family) and their parsed form.
    std::string     direction_text[2] = {"1; 0; 0", ""};
    FibreDirections directions;

    static constexpr const char *direction_entry[2] = {"Fibre direction 1",
                                                       "Fibre direction 2"};

    /// Parses the direction texts (section: for error messages).
    void
    parse_directions(const std::string &section)
    {
      directions = FibreDirections({direction_text[0], direction_text[1]},
                                   {section + "/" + direction_entry[0],
                                    section + "/" + direction_entry[1]});
    }

    /// The matrix alone (k1 = 0): mu, kappa = lambda + 2 mu / 3, with one
    /// family along x that carries no stiffness. No isotropic (mu, lambda)
    /// pair describes stiff fibres (their small-strain stiffness is
    /// one-sided), so the registry's generic tests see the matrix, and
    /// tests/fibre_models.cc tests the fibres.
    static HolzapfelGasserOgdenConstants
    from_small_strain(const LameParameters &lame)
    {
      HolzapfelGasserOgdenConstants c;
      c.mu    = lame.mu;
      c.kappa = lame.lambda + 2. / 3. * lame.mu;
      c.k1    = 0.;
      c.parse_directions("Material/Holzapfel-Gasser-Ogden");
      return c;
    }

    static void
    declare(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Anything;
      using dealii::Patterns::Double;
      prm.declare_entry("Shear modulus",
                        "1",
                        Double(),
                        "mu > 0, the neo-Hookean matrix's shear modulus (the "
                        "small-strain shear modulus).");
      prm.declare_entry("k1",
                        "1",
                        Double(),
                        "k1 >= 0, the fibres' stiffness (stress units).");
      prm.declare_entry("k2",
                        "1",
                        Double(),
                        "k2 > 0, the fibres' dimensionless exponential "
                        "stiffening.");
      prm.declare_entry("Dispersion",
                        "0",
                        Double(),
                        "kappa_d in [0, 1/3]: 0 perfectly aligned fibres, 1/3 "
                        "isotropically dispersed.");
      prm.declare_entry(direction_entry[0],
                        "1; 0; 0",
                        Anything(),
                        "The reference direction of the first fibre family: "
                        "three expressions of the reference position x, y, z "
                        "(a_x; a_y; a_z; constant pi), normalised at each "
                        "quadrature point; empty: no such family. 2D "
                        "(plane strain): a_z must be 0.");
      prm.declare_entry(direction_entry[1],
                        "",
                        Anything(),
                        "The second fibre family, like the first; empty (the "
                        "default): none.");
      declare_bulk_modulus_entry(prm);
    }

    static HolzapfelGasserOgdenConstants
    parse(dealii::ParameterHandler &prm, const std::string &section)
    {
      HolzapfelGasserOgdenConstants c;
      c.mu                = get_finite(prm, section, "Shear modulus");
      c.k1                = get_finite(prm, section, "k1");
      c.k2                = get_finite(prm, section, "k2");
      c.kd                = get_finite(prm, section, "Dispersion");
      c.kappa             = parse_bulk_modulus_entry(prm, section);
      c.direction_text[0] = prm.get(direction_entry[0]);
      c.direction_text[1] = prm.get(direction_entry[1]);
      if (!(c.mu > 0.))
        reject(section + "/Shear modulus",
               prm.get("Shear modulus"),
               "must be positive");
      if (!(c.k1 >= 0.))
        reject(section + "/k1", prm.get("k1"), "must be zero or positive");
      if (!(c.k2 > 0.))
        reject(section + "/k2", prm.get("k2"), "must be positive");
      if (!(c.kd >= 0. && c.kd <= 1. / 3.))
        reject(section + "/Dispersion",
               prm.get("Dispersion"),
               "must lie in [0, 1/3]");
      c.parse_directions(section);
      return c;
    }

    std::vector<std::pair<std::string, std::string>>
    entries() const
    {
      const auto text = exact_entry_text;
      return {{"Shear modulus", text(mu)},
              {"k1", text(k1)},
              {"k2", text(k2)},
              {"Dispersion", text(kd)},
              {direction_entry[0], direction_text[0]},
              {direction_entry[1], direction_text[1]},
              {"Bulk modulus", text(kappa)}};
    }
  };

  template <int dim>
  class HolzapfelGasserOgden : public EvaluatedMaterial<dim>,
                               public ConstantDerivatives<dim>,
                               public FibreFamilies
  {
  public:
    using Constants = HolzapfelGasserOgdenConstants;

    /// The scene's model: the directions evaluated once if they are
    /// constant, at each point (at_position()) otherwise.
    explicit HolzapfelGasserOgden(const Constants &constants)
        : HolzapfelGasserOgden(constants,
                               constants.directions.depends_on_position()
                                 ? std::vector<dealii::Tensor<1, 3>>()
                                 : constants.directions.at(dealii::Point<3>(),
                                                           dim),
                               !constants.directions.depends_on_position())
    {
    }

    /// With the unit directions @p a (3D vectors, a_z = 0 in 2D) fixed.
    HolzapfelGasserOgden(const Constants                         &constants,
                         const std::vector<dealii::Tensor<1, 3>> &a,
                         const bool                               fixed = true)
        : constants(constants)
        , matrix({constants.mu, constants.kappa})
        , fixed(fixed)
    {
      for (const auto &a3 : a)
        {
          dealii::Tensor<1, dim> ad;
          for (unsigned int d = 0; d < dim; ++d)
            ad[d] = a3[d];
          directions.push_back(ad);
          directions3d.push_back(a3);
        }
    }

    std::string
    name() const override
    {
      return "Holzapfel-Gasser-Ogden";
    }

    static const char *
    documentation()
    {
      return "Holzapfel-Gasser-Ogden fibre-reinforced soft tissue with "
             "dispersion (Nolan et al. 2014): psi = mu/2 (Ib - 3) + kappa/4 "
             "(J^2 - 1 - 2 ln J) + sum_i k1/(2 k2) (exp(k2 E_i^2) - 1), E_i "
             "= kd (I1 - 3) + (1 - 3 kd)(I4_i - 1), for each of up to two "
             "fibre families a_i while it is stretched (I4_i = a_i . C a_i > "
             "1). Constants: entries Shear modulus, k1, k2, Dispersion, Fibre "
             "direction 1, Fibre direction 2 (expressions of x, y, z) and "
             "Bulk modulus of the subsection Material/Holzapfel-Gasser-Ogden. "
             "Undefined for inverted elements (J <= 0).";
    }

    LameParameters
    small_strain_moduli() const override
    {
      return matrix.small_strain_moduli();
    }

    std::vector<dealii::Tensor<1, 3>>
    fibre_directions() const override
    {
      return directions3d;
    }

    std::unique_ptr<Material<3>>
    three_dimensional_twin() const override
    {
      return std::make_unique<HolzapfelGasserOgden<3>>(constants,
                                                       directions3d,
                                                       fixed);
    }

    /// Isochoric part: the matrix without kappa plus the fibres (the mixed
    /// formulation replaces U(J) alone by the pressure).
    std::unique_ptr<VolumetricSplit<dim>>
    volumetric_split() const override
    {
      Constants isochoric = constants;
      isochoric.kappa     = 0.;
      return std::make_unique<VolumetricSplit<dim>>(
        VolumetricSplit<dim>{std::make_unique<HolzapfelGasserOgden<dim>>(
                               isochoric, directions3d, fixed),
                             LogVolumetricEnergy(constants.kappa)});
    }

    bool
    defined_for_inverted_elements() const override
    {
      return false;
    }

    bool
    depends_on_position() const override
    {
      return !fixed;
    }

    std::unique_ptr<Material<dim>>
    at_position(const dealii::Point<dim> &X) const override
    {
      dealii::Point<3> X3;
      for (unsigned int d = 0; d < dim; ++d)
        X3[d] = X[d];
      return std::make_unique<HolzapfelGasserOgden<dim>>(
        constants, constants.directions.at(X3, dim));
    }

    double
    energy_density(const Tensor<2, dim> &F) const override
    {
      require_directions();
      double psi = matrix.energy_density(F);
      if (!std::isfinite(psi))
        return psi;
      for_each_stretched_family(F, [&](const auto &, const auto &, double E) {
        psi +=
          0.5 * constants.k1 / constants.k2 * std::expm1(constants.k2 * E * E);
      });
      return psi;
    }

    /// The numeric entries (the fibre directions are not constants one
    /// differentiates by).
    std::vector<std::string>
    constant_names() const override
    {
      return {"Shear modulus", "k1", "k2", "Dispersion", "Bulk modulus"};
    }

    /// The matrix's dP/dmu and dP/dkappa (first_invariant_model.h), and per
    /// stretched family, with e = exp(k2 E^2), G = dE/dF:
    ///   dP/dk1 = E e G,   dP/dk2 = k1 E^3 e G,
    ///   dP/dkd = k1 e (1 + 2 k2 E^2) dE/dkd G + k1 E e dG/dkd,
    ///   dE/dkd = (I1 - 3) - 3 (I4 - 1),   dG/dkd = 2 F - 6 (F a) (x) a.
    std::vector<Tensor<2, dim>>
    stress_derivatives(const Tensor<2, dim> &F) const override
    {
      require_directions();
      const std::vector<Tensor<2, dim>> of_matrix =
        matrix.stress_derivatives(F);
      std::vector<Tensor<2, dim>> dP(5);
      dP[0] = of_matrix[0];
      dP[4] = of_matrix[1];
      if (!std::isfinite(dP[0][0][0]))
        return std::vector<Tensor<2, dim>>(
          5, Material<dim>::not_a_number_tensor());
      const double kd = constants.kd, k1 = constants.k1, k2 = constants.k2;
      const double I1 = first_invariant(F);
      for_each_stretched_family(
        F,
        [&](const dealii::Tensor<1, dim> &a,
            const dealii::Tensor<1, dim> &Fa,
            const double                  E) {
          const double   e  = std::exp(k2 * E * E);
          const double   dE = (I1 - 3.) - 3. * (Fa * Fa - 1.);
          Tensor<2, dim> G = 2. * kd * F, dG = 2. * F;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int J = 0; J < dim; ++J)
              {
                G[i][J] += 2. * (1. - 3. * kd) * Fa[i] * a[J];
                dG[i][J] -= 6. * Fa[i] * a[J];
              }
          dP[1] += E * e * G;
          dP[2] += k1 * E * E * E * e * G;
          dP[3] += k1 * e * (1. + 2. * k2 * E * E) * dE * G + k1 * E * e * dG;
        });
      return dP;
    }

  private:
    const Constants                                constants;
    const FirstInvariantModel<dim, FibreMatrixLaw> matrix;
    /// The directions are fixed (not evaluated per point).
    const bool                          fixed;
    std::vector<dealii::Tensor<1, dim>> directions;
    std::vector<dealii::Tensor<1, 3>>   directions3d;

    void
    require_directions() const
    {
      if (!fixed)
        throw std::logic_error(
          "Holzapfel-Gasser-Ogden: fibre directions that vary with x, y, z "
          "are evaluated at a point (Material::at_position) before use");
    }

    /// I1 = tr C of the 3D F (F33 = 1 in plane strain).
    static double
    first_invariant(const Tensor<2, dim> &F)
    {
      return scalar_product(F, F) + (dim == 2 ? 1. : 0.);
    }

    /// Calls @p f(a, F a, E) for every family stretched at @p F (I4 > 1),
    /// E = kd (I1 - 3) + (1 - 3 kd)(I4 - 1).
    template <typename Function>
    void
    for_each_stretched_family(const Tensor<2, dim> &F, Function &&f) const
    {
      const double I1 = first_invariant(F);
      for (const auto &a : directions)
        {
          const dealii::Tensor<1, dim> Fa = F * a;
          const double                 I4 = Fa * Fa;
          if (I4 > 1.)
            f(a,
              Fa,
              constants.kd * (I1 - 3.) + (1. - 3. * constants.kd) * (I4 - 1.));
        }
    }

    void
    evaluate(const Tensor<2, dim> &F,
             Tensor<2, dim>       &P,
             StressTangent<dim>   &A,
             const bool            with_tangent) const override
    {
      require_directions();
      if (with_tangent)
        matrix.stress_and_tangent(F, P, A);
      else
        P = matrix.first_piola_kirchhoff(F);
      if (!std::isfinite(P[0][0]))
        return;
      const double kd = constants.kd, k1 = constants.k1, k2 = constants.k2;
      for_each_stretched_family(
        F,
        [&](const dealii::Tensor<1, dim> &a,
            const dealii::Tensor<1, dim> &Fa,
            const double                  E) {
          const double   e     = std::exp(k2 * E * E);
          const double   first = k1 * E * e;
          Tensor<2, dim> G     = 2. * kd * F;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int J = 0; J < dim; ++J)
              G[i][J] += 2. * (1. - 3. * kd) * Fa[i] * a[J];
          P += first * G;
          if (!with_tangent)
            return;
          const double second = k1 * e * (1. + 2. * k2 * E * E);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int J = 0; J < dim; ++J)
              for (unsigned int k = 0; k < dim; ++k)
                for (unsigned int L = 0; L < dim; ++L)
                  A[i][J][k][L] +=
                    second * G[i][J] * G[k][L] +
                    (i == k ? first * (2. * kd * (J == L ? 1. : 0.) +
                                       2. * (1. - 3. * kd) * a[J] * a[L])
                            : 0.);
        });
    }
  };
} // namespace hyperelastic
