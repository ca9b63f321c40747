// Gent's rubber model (Gent 1996), decoupled, with its scene entries
// (subsection Material/Gent: Shear modulus, Jm, Bulk modulus):
//   psi = -(mu Jm / 2) ln(1 - x / Jm) + kappa/4 (J^2 - 1 - 2 ln J),
//   x = Ib - 3,   Ib = J^(-2/3) tr(F^T F).
// W' = (mu/2) / (1 - x/Jm), W'' = (mu/2) / (Jm (1 - x/Jm)^2); P and dP/dF
// from first_invariant_model.h. Small strain: mu, lambda = kappa - 2 mu/3.
// Jm -> infinity is decoupled neo-Hookean. The chains lock at x = Jm: a
// state at or beyond it is outside the model's domain (energy +infinity,
// P NaN), like J <= 0, and the line search keeps the iterates inside.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/materials/constant_entries.h>
#include <hyperelastic/materials/first_invariant_model.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  struct GentLaw
  {
    struct Constants
    {
      double mu    = 1.;  ///< entry "Shear modulus"
      double jm    = 97.; ///< entry "Jm"
      double kappa = 2.;  ///< entry "Bulk modulus"

      /// mu, Jm = 97 (Gent's value for natural rubber), kappa = lambda +
      /// 2 mu / 3.
      static Constants
      from_small_strain(const LameParameters &lame)
      {
        Constants c;
        c.mu    = lame.mu;
        c.kappa = lame.lambda + 2. / 3. * lame.mu;
        return c;
      }

      static void
      declare(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Double;
        prm.declare_entry("Shear modulus",
                          "1",
                          Double(),
                          "mu > 0, the small-strain shear modulus.");
        prm.declare_entry("Jm",
                          "97",
                          Double(),
                          "Jm > 0, the largest Ib - 3 the chains reach "
                          "(locking); 97 is Gent's value for natural "
                          "rubber.");
        declare_bulk_modulus_entry(prm);
      }

      static Constants
      parse(dealii::ParameterHandler &prm, const std::string &section)
      {
        Constants c;
        c.mu    = get_finite(prm, section, "Shear modulus");
        c.jm    = get_finite(prm, section, "Jm");
        c.kappa = parse_bulk_modulus_entry(prm, section);
        if (!(c.mu > 0.))
          reject(section + "/Shear modulus",
                 prm.get("Shear modulus"),
                 "must be positive");
        if (!(c.jm > 0.))
          reject(section + "/Jm", prm.get("Jm"), "must be positive");
        return c;
      }

      std::vector<std::pair<std::string, std::string>>
      entries() const
      {
        const auto text = exact_entry_text;
        return {{"Shear modulus", text(mu)},
                {"Jm", text(jm)},
                {"Bulk modulus", text(kappa)}};
      }
    };

    static std::string
    name()
    {
      return "Gent";
    }

    static const char *
    documentation()
    {
      return "Gent's rubber model, decoupled: psi = -(mu Jm / 2) ln(1 - (Ib - "
             "3) / Jm) + kappa/4 (J^2 - 1 - 2 ln J), Ib = J^(-2/3) I1: the "
             "chains lock at Ib - 3 = Jm (states beyond are inadmissible). "
             "Constants: entries Shear modulus, Jm and Bulk modulus of the "
             "subsection Material/Gent. Undefined for inverted elements "
             "(J <= 0).";
    }

    static bool
    evaluate(const Constants &c,
             const double     Ib,
             double          &W,
             double          &W1,
             double          &W2)
    {
      // 1 - x/Jm, the distance to locking.
      const double room = 1. - (Ib - 3.) / c.jm;
      if (!(room > 0.))
        return false;
      W  = -0.5 * c.mu * c.jm * std::log(room);
      W1 = 0.5 * c.mu / room;
      W2 = W1 / (c.jm * room);
      return true;
    }

    /// dW'/dmu = 1 / (2 room), dW'/dJm = -mu x / (2 Jm^2 room^2), room = 1 -
    /// x / Jm, x = Ib - 3 (inside the admissible range).
    static std::vector<double>
    constant_derivatives(const Constants &c, const double Ib)
    {
      const double x    = Ib - 3.;
      const double room = 1. - x / c.jm;
      return {0.5 / room, -0.5 * c.mu * x / (c.jm * c.jm * room * room)};
    }
  };

  template <int dim>
  using Gent = FirstInvariantModel<dim, GentLaw>;
} // namespace hyperelastic
