// Exact homogeneous uniaxial stretch of a bar with symmetry rollers and
// traction-free lateral faces (../shared/reference/analytic.md), written
// independently of the material classes so the tests compare against them.
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace hyperelastic::testing
{
  struct UniaxialState
  {
    double l2;  ///< lateral stretch
    double P11; ///< axial first Piola-Kirchhoff stress
  };

  /// Root of an increasing function on [a, b] by bisection, to round-off.
  template <typename Function>
  double
  bisect(Function f, double a, double b)
  {
    for (int i = 0; i < 200 && b - a > 1e-16 * b; ++i)
      {
        const double m      = 0.5 * (a + b);
        (f(m) > 0. ? b : a) = m;
      }
    return 0.5 * (a + b);
  }

  /// Decoupled Mooney-Rivlin, psi = c1 (J^(-2/3) I1 - 3) + c2 (J^(-4/3) I2
  /// - 3) + kappa/4 (J^2 - 1 - 2 ln J), F = diag(l1, l2, l2) (3D) or
  /// diag(l1, l2, 1) (plane strain).
  inline UniaxialState
  uniaxial_mooney_rivlin(const int    dim,
                         const double l1,
                         const double c1,
                         const double c2,
                         const double kappa)
  {
    // Principal stretches (l1, l2, l3) with l3 = l2 (3D) or 1 (2D).
    const auto l3 = [&](double l2) { return dim == 3 ? l2 : 1.; };
    // For a diagonal F the stress is diagonal, and with I1 = sum l_a^2,
    // I2 = sum over pairs l_a^2 l_b^2, dI1/dl_a = 2 l_a and dI2/dl_a =
    // 2 l_a (I1 - l_a^2):
    //   l_a P_aa = 2 c1 J^(-2/3) (l_a^2 - I1/3)
    //            + 2 c2 J^(-4/3) (l_a^2 (I1 - l_a^2) - 2/3 I2)
    //            + kappa/2 (J^2 - 1).
    const auto stretch_term = [&](double l2, double la) {
      const double a = l1 * l1, b = l2 * l2, c = l3(l2) * l3(l2);
      const double J  = l1 * l2 * l3(l2);
      const double I1 = a + b + c, I2 = a * b + b * c + a * c;
      const double J_23 = std::pow(J, -2. / 3.);
      return 2. * c1 * J_23 * (la * la - I1 / 3.) +
             2. * c2 * J_23 * J_23 * (la * la * (I1 - la * la) - 2. / 3. * I2) +
             0.5 * kappa * (J * J - 1.);
    };
    // P22 = 0 <=> g(l2) = l2 P22 = 0. Written out,
    //   3D: g = 2 c1 / 3 l1^(-2/3) (l2^(2/3) - l1^2 l2^(-4/3))
    //         + 2 c2 / 3 l1^(-4/3) (l2^(4/3) - l1^2 l2^(-2/3))
    //         + kappa/2 (l1^2 l2^4 - 1),
    //   2D: g = 2 c1 / 3 l1^(-2/3) (2 l2^(4/3) - (l1^2 + 1) l2^(-2/3))
    //         + 2 c2 / 3 l1^(-4/3) ((l1^2 + 1) l2^(2/3) - 2 l1^2 l2^(-4/3))
    //         + kappa/2 (l1^2 l2^2 - 1),
    // every term increasing in l2 > 0 (c1, c2 >= 0), g -> -infinity as
    // l2 -> 0 and without bound as l2 grows: exactly one root. The upper
    // end of the bracket is doubled until g changes sign.
    const auto g     = [&](double l2) { return stretch_term(l2, l2); };
    double     upper = 10.;
    while (!(g(upper) > 0.) && upper < 1e6)
      upper *= 2.;
    const double l2 = bisect(g, 1e-6, upper);
    return {l2, stretch_term(l2, l1) / l1};
  }

  /// A decoupled model psi = W(Ib) + kappa/4 (J^2 - 1 - 2 ln J), Ib =
  /// J^(-2/3) I1, given by W'(Ib) (NaN where its chains lock): with
  /// F = diag(l1, l2, l2) (3D) or diag(l1, l2, 1),
  ///   l_a P_aa = 2 W'(Ib) J^(-2/3) (l_a^2 - I1/3) + kappa/2 (J^2 - 1),
  /// and P22 = 0 solved for l2 by bisection; kappa = infinity: J = 1 and
  /// the pressure cancels l2 P22.
  inline UniaxialState
  uniaxial_first_invariant(const int                            dim,
                           const double                         l1,
                           const std::function<double(double)> &W1,
                           const double                         kappa)
  {
    const auto l3 = [&](const double l2) { return dim == 3 ? l2 : 1.; };
    if (std::isinf(kappa))
      {
        // J = 1; the pressure cancels l2 P22, leaving P11.
        const double l2 = dim == 3 ? 1. / std::sqrt(l1) : 1. / l1;
        const double I1 = l1 * l1 + l2 * l2 + l3(l2) * l3(l2);
        return {l2, 2. * W1(I1) * (l1 * l1 - l2 * l2) / l1};
      }
    const auto stretch_term = [&](const double l2, const double la) {
      const double J   = l1 * l2 * l3(l2);
      const double I1  = l1 * l1 + l2 * l2 + l3(l2) * l3(l2);
      const double J23 = std::pow(J, -2. / 3.);
      const double w   = W1(J23 * I1);
      const double iso = la * la - I1 / 3.;
      if (std::isnan(w)) // locked: W' -> +infinity
        return iso < 0. ? -1e300 : 1e300;
      return 2. * w * J23 * iso + 0.5 * kappa * (J * J - 1.);
    };
    const double l2 =
      bisect([&](const double l2) { return stretch_term(l2, l2); }, 1e-3, 10.);
    return {l2, stretch_term(l2, l1) / l1};
  }

  /// 3D: F = diag(l1, l2, l2); 2D plane strain: F = diag(l1, l2, 1).
  inline UniaxialState
  uniaxial(const std::string &model,
           const int          dim,
           const double       l1,
           const double       mu,
           const double       lambda)
  {
    const double E  = mu * (3. * lambda + 2. * mu) / (lambda + mu);
    const double nu = lambda / (2. * (lambda + mu));
    if (model == "neo-Hookean")
      {
        // mu (l2^2 - 1) + lambda ln J = 0 with J = l1 l2^(dim - 1).
        const auto   J  = [&](double l2) { return l1 * std::pow(l2, dim - 1); };
        const double l2 = bisect(
          [&](double l2) {
            return mu * (l2 * l2 - 1.) + lambda * std::log(J(l2));
          },
          1e-6,
          10.);
        return {l2, mu * (l1 - 1. / l1) + lambda * std::log(J(l2)) / l1};
      }
    if (model == "stable neo-Hookean")
      {
        // Model constants matching (mu, lambda) at small strain, and alpha.
        const double mu_s     = 4. / 3. * mu;
        const double lambda_s = lambda + 5. / 6. * mu;
        const double alpha    = 1. + 0.75 * mu_s / lambda_s;
        // I_C counts F33 = 1 in plane strain.
        const auto I_C = [&](double l2) {
          return l1 * l1 + l2 * l2 + (dim == 3 ? l2 * l2 : 1.);
        };
        const auto J = [&](double l2) { return l1 * std::pow(l2, dim - 1); };
        // P = mu_s (1 - 1/(I_C + 1)) F + lambda_s (J - alpha) cof F with
        // cof F = diag(l2^2, l1 l2, l1 l2) (3D) or diag(l2, l1) (2D).
        const auto shear = [&](double l2) {
          return mu_s * (1. - 1. / (I_C(l2) + 1.));
        };
        // P22 = 0. In 3D P22 = l2 g(l2) with g = shear + lambda_s (J - alpha)
        // l1; in 2D g = P22 = shear l2 + lambda_s (J - alpha) l1. Both g are
        // increasing in l2 > 0 (shear, shear l2 and J are), negative at
        // l2 -> 0 (there shear l2 -> 0, and in 3D shear -> mu_s l1^2 / (l1^2
        // + 1) <= mu_s l1 / 2 < 3/4 mu_s l1 <= lambda_s alpha l1) and grow
        // without bound, so there is exactly one root; the upper end of the
        // bracket is doubled until g changes sign.
        const auto g = [&](double l2) {
          return (dim == 3 ? shear(l2) : shear(l2) * l2) +
                 lambda_s * (J(l2) - alpha) * l1;
        };
        double upper = 10.;
        while (!(g(upper) > 0.) && upper < 1e6)
          upper *= 2.;
        const double l2  = bisect(g, 1e-6, upper);
        const double cof = dim == 3 ? l2 * l2 : l2;
        return {l2, shear(l2) * l1 + lambda_s * (J(l2) - alpha) * cof};
      }
    if (model == "decoupled neo-Hookean")
      {
        // psi = kappa/4 (J^2 - 1 - 2 ln J) + mu/2 (J^(-2/3) I1 - 3) gives
        // P = kappa/2 (J^2 - 1) F^-T + mu J^(-2/3) (F - I1/3 F^-T), with
        // kappa = lambda + 2 mu / 3 and the 3D I1 (F33 = 1 in plane strain).
        const double kappa = lambda + 2. / 3. * mu;
        const auto   J  = [&](double l2) { return l1 * std::pow(l2, dim - 1); };
        const auto   I1 = [&](double l2) {
          return l1 * l1 + l2 * l2 + (dim == 3 ? l2 * l2 : 1.);
        };
        // P_aa = (kappa/2 (J^2 - 1) + mu J^(-2/3) (l_a^2 - I1/3)) / l_a.
        const auto stretch_term = [&](double l2, double la) {
          return 0.5 * kappa * (J(l2) * J(l2) - 1.) +
                 mu * std::pow(J(l2), -2. / 3.) * (la * la - I1(l2) / 3.);
        };
        // P22 = 0 <=> g(l2) = l2 P22 = 0. With c = l1^(-2/3) / 3:
        //   3D: g = kappa/2 (J^2 - 1) + mu c (l2^(2/3) - l1^2 l2^(-4/3)),
        //   2D: g = kappa/2 (J^2 - 1) + mu c (2 l2^(4/3) - (l1^2 + 1)
        //                                      l2^(-2/3)),
        // every term increasing in l2 > 0, so g has at most one root. g <= 0
        // where J <= 1 and l2^2 <= I1/3 (both parts <= 0), g >= 0 where both
        // are >= 1 and >= I1/3; l2^2 <= I1/3 means l2 <= l1 (3D) or
        // l2^2 <= (l1^2 + 1)/2 (2D). So the root lies in [lower, upper]:
        const double l_J1    = std::pow(l1, -1. / (dim - 1)); // J = 1
        const double l_shear = dim == 3 ? l1 : std::sqrt(0.5 * (l1 * l1 + 1.));
        const double l2 =
          bisect([&](double l2) { return stretch_term(l2, l2); },
                 std::min(l_J1, l_shear),
                 std::max(l_J1, l_shear));
        return {l2, stretch_term(l2, l1) / l1};
      }
    if (model == "Mooney-Rivlin")
      {
        // The registry's small-strain split (mooney_rivlin.h).
        return uniaxial_mooney_rivlin(
          dim, l1, 3. / 8. * mu, 1. / 8. * mu, lambda + 2. / 3. * mu);
      }
    if (model == "St. Venant-Kirchhoff")
      {
        const double E11 = 0.5 * (l1 * l1 - 1.);
        if (dim == 3)
          return {std::sqrt(1. - nu * (l1 * l1 - 1.)), E * l1 * E11};
        // plane strain: S22 = 2 mu E22 + lambda (E11 + E22) = 0, E33 = 0.
        const double E22 = -lambda * E11 / (2. * mu + lambda);
        return {std::sqrt(1. + 2. * E22),
                l1 * ((2. * mu + lambda) * E11 + lambda * E22)};
      }
    if (model == "corotational" || model == "linear elastic")
      {
        // Both are linear in the principal stretches for a diagonal F > 0.
        const double e11 = l1 - 1.;
        if (dim == 3)
          return {1. - nu * e11, E * e11};
        const double e22 = -lambda * e11 / (2. * mu + lambda);
        return {1. + e22, (2. * mu + lambda) * e11 + lambda * e22};
      }
    // The registry's small-strain constants of the first-invariant rubber
    // models (yeoh.h, gent.h, arruda_boyce.h), kappa = lambda + 2 mu / 3.
    const double kappa = lambda + 2. / 3. * mu;
    // Yeoh from small strain: C10 = mu / 2, C20 = C30 = 0.
    // Ogden from small strain: mu1 = mu, alpha1 = 2 alone, i.e.
    // (mu/2) (sum lb_i^2 - 3) = (mu/2) (Ib - 3).
    // Holzapfel-Gasser-Ogden from small strain: the matrix mu/2 (Ib - 3)
    // alone (k1 = 0).
    if (model == "Yeoh" || model == "Ogden" ||
        model == "Holzapfel-Gasser-Ogden")
      return uniaxial_first_invariant(
        dim, l1, [&](double) { return 0.5 * mu; }, kappa);
    if (model == "Gent") // Jm = 97
      return uniaxial_first_invariant(
        dim,
        l1,
        [&](const double Ib) { return 0.5 * mu / (1. - (Ib - 3.) / 97.); },
        kappa);
    if (model == "Arruda-Boyce") // lm = 7, the series' mu from mu
      {
        const double c[5] = {
          0.5, 0.05, 11. / 1050., 19. / 7000., 519. / 673750.};
        const auto W1 = [&](const double m, const double Ib) {
          double sum = 0.;
          for (int i = 1; i <= 5; ++i)
            sum += m * c[i - 1] * i * std::pow(7., 2. - 2. * i) *
                   std::pow(Ib, i - 1.);
          return sum;
        };
        const double chains = mu / (2. * W1(1., 3.));
        return uniaxial_first_invariant(
          dim, l1, [&](const double Ib) { return W1(chains, Ib); }, kappa);
      }
    throw std::invalid_argument("no analytic solution for model " + model);
  }
} // namespace hyperelastic::testing
