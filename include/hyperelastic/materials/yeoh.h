// Yeoh's rubber model (Yeoh 1993), decoupled, with its scene entries
// (subsection Material/Yeoh: C10, C20, C30, Bulk modulus):
//   psi = C10 x + C20 x^2 + C30 x^3 + kappa/4 (J^2 - 1 - 2 ln J),
//   x = Ib - 3,   Ib = J^(-2/3) tr(F^T F).
// W' = C10 + 2 C20 x + 3 C30 x^2, W'' = 2 C20 + 6 C30 x; P and dP/dF from
// first_invariant_model.h. Small strain: mu = 2 C10, lambda = kappa - 2 mu/3.
// C20 may be negative (most rubber fits: the S-shaped stress-stretch curve);
// C10 > 0 and C30 >= 0 keep the small-strain response stable and the energy
// bounded below at large stretch (with C30 = 0, C20 >= 0 is needed too).
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/materials/constant_entries.h>
#include <hyperelastic/materials/first_invariant_model.h>

#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  struct YeohLaw
  {
    struct Constants
    {
      double c10   = 0.5; ///< entry "C10"
      double c20   = 0.;  ///< entry "C20"
      double c30   = 0.;  ///< entry "C30"
      double kappa = 2.;  ///< entry "Bulk modulus"

      /// C10 = mu / 2, C20 = C30 = 0 (decoupled neo-Hookean), kappa =
      /// lambda + 2 mu / 3.
      static Constants
      from_small_strain(const LameParameters &lame)
      {
        Constants c;
        c.c10   = 0.5 * lame.mu;
        c.kappa = lame.lambda + 2. / 3. * lame.mu;
        return c;
      }

      static void
      declare(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Double;
        prm.declare_entry("C10",
                          "0.5",
                          Double(),
                          "C10 > 0, the constant of (Ib - 3); small-strain "
                          "shear modulus mu = 2 C10.");
        prm.declare_entry("C20",
                          "0",
                          Double(),
                          "The constant of (Ib - 3)^2; may be negative (as "
                          "in most rubber fits) if C30 > 0.");
        prm.declare_entry("C30",
                          "0",
                          Double(),
                          "C30 >= 0, the constant of (Ib - 3)^3.");
        declare_bulk_modulus_entry(prm);
      }

      static Constants
      parse(dealii::ParameterHandler &prm, const std::string &section)
      {
        Constants c;
        c.c10   = get_finite(prm, section, "C10");
        c.c20   = get_finite(prm, section, "C20");
        c.c30   = get_finite(prm, section, "C30");
        c.kappa = parse_bulk_modulus_entry(prm, section);
        if (!(c.c10 > 0.))
          reject(section + "/C10",
                 prm.get("C10"),
                 "must be positive: the small-strain shear modulus is 2 C10");
        if (c.c30 < 0.)
          reject(section + "/C30",
                 prm.get("C30"),
                 "must not be negative: with C30 < 0 the energy is "
                 "unbounded below at large stretch");
        if (c.c30 == 0. && c.c20 < 0.)
          reject(section + "/C20",
                 prm.get("C20"),
                 "a negative C20 needs C30 > 0: otherwise the energy is "
                 "unbounded below at large stretch");
        return c;
      }

      std::vector<std::pair<std::string, std::string>>
      entries() const
      {
        const auto text = exact_entry_text;
        return {{"C10", text(c10)},
                {"C20", text(c20)},
                {"C30", text(c30)},
                {"Bulk modulus", text(kappa)}};
      }
    };

    static std::string
    name()
    {
      return "Yeoh";
    }

    static const char *
    documentation()
    {
      return "Yeoh's rubber model, decoupled: psi = C10 (Ib - 3) + C20 (Ib - "
             "3)^2 + C30 (Ib - 3)^3 + kappa/4 (J^2 - 1 - 2 ln J), Ib = "
             "J^(-2/3) I1. Constants: entries C10, C20, C30 and Bulk modulus "
             "of the subsection Material/Yeoh; small-strain mu = 2 C10. "
             "Undefined for inverted elements (J <= 0).";
    }

    static bool
    evaluate(const Constants &c,
             const double     Ib,
             double          &W,
             double          &W1,
             double          &W2)
    {
      const double x = Ib - 3.;
      W              = ((c.c30 * x + c.c20) * x + c.c10) * x;
      W1             = (3. * c.c30 * x + 2. * c.c20) * x + c.c10;
      W2             = 6. * c.c30 * x + 2. * c.c20;
      return true;
    }

    /// dW'/dC10, dW'/dC20, dW'/dC30 at Ib.
    static std::vector<double>
    constant_derivatives(const Constants &, const double Ib)
    {
      const double x = Ib - 3.;
      return {1., 2. * x, 3. * x * x};
    }
  };

  template <int dim>
  using Yeoh = FirstInvariantModel<dim, YeohLaw>;
} // namespace hyperelastic
