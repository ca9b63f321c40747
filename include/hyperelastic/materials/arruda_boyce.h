// The Arruda-Boyce eight-chain model (Arruda and Boyce 1993) in its usual
// five-term series, decoupled, with its scene entries (subsection
// Material/Arruda-Boyce: Shear modulus, Locking stretch, Bulk modulus):
//   psi = mu sum_{i=1..5} c_i lm^(2 - 2i) (Ib^i - 3^i)
//         + kappa/4 (J^2 - 1 - 2 ln J),
//   c = 1/2, 1/20, 11/1050, 19/7000, 519/673750,   Ib = J^(-2/3) tr(F^T F),
// lm the chain locking stretch. W' = mu sum i c_i lm^(2-2i) Ib^(i-1),
// W'' = mu sum i (i-1) c_i lm^(2-2i) Ib^(i-2); P and dP/dF from
// first_invariant_model.h. Small strain: the shear modulus is
//   2 W'(3) = mu (1 + 3/(5 lm^2) + 99/(175 lm^4) + 513/(875 lm^6)
//                 + 42039/(67375 lm^8)),
// larger than mu (the series' mu is the chains' modulus), lambda = kappa -
// 2/3 of it. lm -> infinity is decoupled neo-Hookean.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/materials/constant_entries.h>
#include <hyperelastic/materials/first_invariant_model.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  struct ArrudaBoyceLaw
  {
    /// The series' coefficients c_1 ... c_5.
    static constexpr std::array<double, 5> c = {
      {1. / 2., 1. / 20., 11. / 1050., 19. / 7000., 519. / 673750.}};

    struct Constants
    {
      double mu    = 1.; ///< entry "Shear modulus"
      double lm    = 7.; ///< entry "Locking stretch"
      double kappa = 2.; ///< entry "Bulk modulus"

      /// The series' mu that gives the small-strain shear modulus
      /// lame.mu with lm = 7; kappa = lambda + 2 mu / 3.
      static Constants
      from_small_strain(const LameParameters &lame)
      {
        Constants unit;
        unit.mu  = 1.;
        double W = 0., W1 = 0., W2 = 0.;
        evaluate(unit, 3., W, W1, W2);
        Constants constants;
        constants.mu    = lame.mu / (2. * W1);
        constants.kappa = lame.lambda + 2. / 3. * lame.mu;
        return constants;
      }

      static void
      declare(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Double;
        prm.declare_entry("Shear modulus",
                          "1",
                          Double(),
                          "mu > 0, the chains' modulus of the series (the "
                          "small-strain shear modulus is slightly larger: "
                          "mu (1 + 3/(5 lm^2) + ...)).");
        prm.declare_entry("Locking stretch",
                          "7",
                          Double(),
                          "lm > 1, the chain locking stretch (7 is typical "
                          "for rubber).");
        declare_bulk_modulus_entry(prm);
      }

      static Constants
      parse(dealii::ParameterHandler &prm, const std::string &section)
      {
        Constants constants;
        constants.mu    = get_finite(prm, section, "Shear modulus");
        constants.lm    = get_finite(prm, section, "Locking stretch");
        constants.kappa = parse_bulk_modulus_entry(prm, section);
        if (!(constants.mu > 0.))
          reject(section + "/Shear modulus",
                 prm.get("Shear modulus"),
                 "must be positive");
        if (!(constants.lm > 1.))
          reject(section + "/Locking stretch",
                 prm.get("Locking stretch"),
                 "must be larger than 1");
        return constants;
      }

      std::vector<std::pair<std::string, std::string>>
      entries() const
      {
        const auto text = exact_entry_text;
        return {{"Shear modulus", text(mu)},
                {"Locking stretch", text(lm)},
                {"Bulk modulus", text(kappa)}};
      }
    };

    static std::string
    name()
    {
      return "Arruda-Boyce";
    }

    static const char *
    documentation()
    {
      return "Arruda-Boyce eight-chain model (five-term series), decoupled: "
             "psi = mu sum_i c_i lm^(2-2i) (Ib^i - 3^i) + kappa/4 (J^2 - 1 - "
             "2 ln J), c = 1/2, 1/20, 11/1050, 19/7000, 519/673750, Ib = "
             "J^(-2/3) I1. Constants: entries Shear modulus, Locking stretch "
             "and Bulk modulus of the subsection Material/Arruda-Boyce. "
             "Undefined for inverted elements (J <= 0).";
    }

    static bool
    evaluate(const Constants &constants,
             const double     Ib,
             double          &W,
             double          &W1,
             double          &W2)
    {
      const double inverse_lm2 = 1. / (constants.lm * constants.lm);
      // scale = mu lm^(2 - 2i), Ib^(i-2), Ib^(i-1), Ib^i and 3^i by recursion.
      double scale = constants.mu, power_2 = 1. / Ib, power_1 = 1., power = Ib,
             three = 3.;
      W = W1 = W2 = 0.;
      for (unsigned int i = 1; i <= 5; ++i)
        {
          W += scale * c[i - 1] * (power - three);
          W1 += scale * c[i - 1] * i * power_1;
          if (i >= 2)
            W2 += scale * c[i - 1] * i * (i - 1) * power_2;
          scale *= inverse_lm2;
          power_2 = power_1;
          power_1 = power;
          power *= Ib;
          three *= 3.;
        }
      return true;
    }

    /// dW'/dmu = sum i c_i lm^(2-2i) Ib^(i-1) and dW'/dlm = mu sum i c_i
    /// (2 - 2i) lm^(1-2i) Ib^(i-1).
    static std::vector<double>
    constant_derivatives(const Constants &constants, const double Ib)
    {
      const double inverse_lm2 = 1. / (constants.lm * constants.lm);
      double       scale = 1., power_1 = 1., d_mu = 0., d_lm = 0.;
      for (unsigned int i = 1; i <= 5; ++i)
        {
          d_mu += scale * c[i - 1] * i * power_1;
          d_lm += (2. - 2. * i) * scale / constants.lm * c[i - 1] * i * power_1;
          scale *= inverse_lm2;
          power_1 *= Ib;
        }
      return {d_mu, constants.mu * d_lm};
    }
  };

  template <int dim>
  using ArrudaBoyce = FirstInvariantModel<dim, ArrudaBoyceLaw>;
} // namespace hyperelastic
