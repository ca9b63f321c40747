// Ogden's model with up to three terms (Ogden 1972), decoupled, with its
// scene entries (subsection Material/Ogden: mu1, alpha1, mu2, alpha2, mu3,
// alpha3, Bulk modulus):
//   psi = sum_p (mu_p / alpha_p) (lb1^a_p + lb2^a_p + lb3^a_p - 3)
//         + kappa/4 (J^2 - 1 - 2 ln J),
// lb_i = J^(-1/3) l_i the isochoric principal stretches (plane strain: the
// third stretch is 1, so lb3 = J^(-1/3)). A term with mu_p = 0 is absent;
// each present term needs mu_p alpha_p > 0. Small strain: mu = 1/2 sum_p
// mu_p alpha_p, lambda = kappa - 2 mu / 3; mu1 = mu, alpha1 = 2 alone is
// decoupled neo-Hookean.
//
// Written in C = F^T F (3 x 3, C33 = 1 in plane strain) with m = alpha/2,
// u = det C = J^2, a = u^(-m/3) = J^(-alpha/3) and T = tr(C^m), so that
// sum_i lb_i^alpha = a T. With C^-1 and C^(m-1) the matrix functions:
//   S = 2 dpsi/dC = sum_p mu_p a (C^(m-1) - T/3 C^-1)
//                   + kappa/2 (u - 1) C^-1,
//   dS[dC] = sum_p mu_p { da (C^(m-1) - T/3 C^-1)
//                         + a (dC^(m-1) - dT/3 C^-1 - T/3 dC^-1) }
//            + kappa/2 (u (C^-1 : dC) C^-1 + (u - 1) dC^-1),
// da = -m/3 a (C^-1 : dC), dT = m C^(m-1) : dC, dC^-1 = -C^-1 dC C^-1, and
// the derivative of the matrix function f(C) = C^q (Daleckii-Krein), in the
// eigenbasis C = sum_i c_i n_i n_i^T:
//   df[dC] = sum_ij f[c_i, c_j] (n_i . dC n_j) n_i n_j^T,
// f[a, b] = (a^q - b^q) / (a - b) and f[a, a] = q a^(q-1). The divided
// difference is evaluated as b^(q-1) expm1(q log1p(r)) / r, r = (a - b)/b,
// accurate for every a != b, so the tangent is exact and continuous at
// equal stretches (where the eigenvectors are not unique, f[.,.] is the
// same for all of them). Then P = F S and
//   A_iJkL = delta_ik S_JL + (F dS[dC_kL])_iJ,
//   (dC_kL)_MN = delta_ML F_kN + F_kM delta_NL.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/materials/constant_derivatives.h>
#include <hyperelastic/materials/constant_entries.h>
#include <hyperelastic/materials/evaluated_material.h>
#include <hyperelastic/materials/tangent_projection.h>
#include <hyperelastic/materials/volumetric_split.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  struct OgdenConstants
  {
    std::array<double, 3> mu    = {{1., 0., 0.}};  ///< entries "mu1" ...
    std::array<double, 3> alpha = {{2., -2., 4.}}; ///< entries "alpha1" ...
    double                kappa = 2.;              ///< entry "Bulk modulus"

    /// mu1 = mu, alpha1 = 2 (decoupled neo-Hookean), kappa = lambda +
    /// 2 mu / 3.
    static OgdenConstants
    from_small_strain(const LameParameters &lame)
    {
      OgdenConstants c;
      c.mu    = {{lame.mu, 0., 0.}};
      c.alpha = {{2., -2., 4.}};
      c.kappa = lame.lambda + 2. / 3. * lame.mu;
      return c;
    }

    static void
    declare(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Double;
      const char *mu_default[3]    = {"1", "0", "0"};
      const char *alpha_default[3] = {"2", "-2", "4"};
      for (unsigned int p = 0; p < 3; ++p)
        {
          const std::string k = std::to_string(p + 1);
          prm.declare_entry("mu" + k,
                            mu_default[p],
                            Double(),
                            "mu_" + k +
                              " of the term (mu/alpha) (lb1^alpha "
                              "+ lb2^alpha + lb3^alpha - 3); 0: no such term. "
                              "mu alpha > 0.");
          prm.declare_entry("alpha" + k,
                            alpha_default[p],
                            Double(),
                            "alpha_" + k + " (may be negative, with mu_" + k +
                              " of the same sign).");
        }
      declare_bulk_modulus_entry(prm);
    }

    static OgdenConstants
    parse(dealii::ParameterHandler &prm, const std::string &section)
    {
      OgdenConstants c;
      bool           any = false;
      for (unsigned int p = 0; p < 3; ++p)
        {
          const std::string k = std::to_string(p + 1);
          c.mu[p]             = get_finite(prm, section, "mu" + k);
          c.alpha[p]          = get_finite(prm, section, "alpha" + k);
          if (c.mu[p] != 0. && !(c.mu[p] * c.alpha[p] > 0.))
            reject(section + "/alpha" + k,
                   prm.get("alpha" + k),
                   "mu" + k + " alpha" + k +
                     " must be positive (a term with mu" + k +
                     " = 0 is absent)");
          any = any || c.mu[p] != 0.;
        }
      if (!any)
        reject(section + "/mu1",
               prm.get("mu1"),
               "at least one term needs a non-zero mu");
      c.kappa = parse_bulk_modulus_entry(prm, section);
      return c;
    }

    std::vector<std::pair<std::string, std::string>>
    entries() const
    {
      std::vector<std::pair<std::string, std::string>> list;
      for (unsigned int p = 0; p < 3; ++p)
        {
          const std::string k = std::to_string(p + 1);
          list.emplace_back("mu" + k, exact_entry_text(mu[p]));
          list.emplace_back("alpha" + k, exact_entry_text(alpha[p]));
        }
      list.emplace_back("Bulk modulus", exact_entry_text(kappa));
      return list;
    }
  };

  template <int dim>
  class Ogden : public EvaluatedMaterial<dim>, public ConstantDerivatives<dim>
  {
  public:
    using Constants = OgdenConstants;

    explicit Ogden(const OgdenConstants &constants)
        : constants(constants)
    {
    }

    std::string
    name() const override
    {
      return "Ogden";
    }

    static const char *
    documentation()
    {
      return "Ogden's model, up to three terms, decoupled: psi = sum_p "
             "(mu_p/alpha_p) (lb1^alpha_p + lb2^alpha_p + lb3^alpha_p - 3) + "
             "kappa/4 (J^2 - 1 - 2 ln J), lb_i the isochoric principal "
             "stretches. Constants: entries mu1, alpha1, mu2, alpha2, mu3, "
             "alpha3 and Bulk modulus of the subsection Material/Ogden (mu_p "
             "= 0: no term; mu_p alpha_p > 0); small-strain mu = 1/2 sum "
             "mu_p alpha_p. Undefined for inverted elements (J <= 0).";
    }

    LameParameters
    small_strain_moduli() const override
    {
      LameParameters lame;
      lame.mu = 0.;
      for (unsigned int p = 0; p < 3; ++p)
        lame.mu += 0.5 * constants.mu[p] * constants.alpha[p];
      lame.lambda = constants.kappa - 2. / 3. * lame.mu;
      return lame;
    }

    std::unique_ptr<Material<3>>
    three_dimensional_twin() const override
    {
      return std::make_unique<Ogden<3>>(constants);
    }

    /// Isochoric part: this model with kappa = 0.
    std::unique_ptr<VolumetricSplit<dim>>
    volumetric_split() const override
    {
      return decoupled_split<dim, Ogden<dim>>(constants);
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
      if (!(J > 0.))
        return std::numeric_limits<double>::infinity();
      const Spectrum c = spectrum(embed(F));
      double         psi =
        constants.kappa == 0.
                  ? 0.
                  : 0.25 * constants.kappa * ((J - 1.) * (J + 1.) - 2. * std::log(J));
      for (unsigned int p = 0; p < 3; ++p)
        if (constants.mu[p] != 0.)
          {
            const double m = 0.5 * constants.alpha[p];
            double       T = 0.;
            for (unsigned int i = 0; i < 3; ++i)
              T += std::pow(c.values[i], m);
            psi += constants.mu[p] / constants.alpha[p] *
                   (std::pow(J, -constants.alpha[p] / 3.) * T - 3.);
          }
      return psi;
    }

    std::vector<std::string>
    constant_names() const override
    {
      return entry_names(constants);
    }

    /// In the order mu1, alpha1, ..., alpha3, Bulk modulus, from one
    /// spectral decomposition. P is linear in mu_p and kappa: dP/dmu_p =
    /// F a (C^(m-1) - T/3 C^-1), dP/dkappa = F (u - 1)/2 C^-1. With m =
    /// alpha_p / 2 and C = sum_i c_i n_i n_i^T,
    /// S_p = mu_p a (C^(m-1) - T/3 C^-1), a = u^(-m/3), T = sum_i c_i^m:
    ///   dS_p/dm = mu_p sum_i [da (c_i^(m-1) - T / (3 c_i))
    ///                         + a (c_i^(m-1) ln c_i - dT / (3 c_i))] n_i n_i^T,
    /// da = -ln(u)/3 a, dT = sum_i c_i^m ln c_i; dP/dalpha_p = 1/2 F dS_p/dm.
    std::vector<Tensor<2, dim>>
    stress_derivatives(const Tensor<2, dim> &F) const override
    {
      std::vector<Tensor<2, dim>> dP(7, Material<dim>::not_a_number_tensor());
      const double                J = determinant(F);
      if (!(J > 0.))
        return dP;
      const Matrix3  F3 = embed(F);
      const Spectrum s  = spectrum(F3);
      const double   log_u = 2. * std::log(J);
      const auto     in_plane = [&](const Matrix3 &S) {
        const Matrix3  P3 = F3 * S;
        Tensor<2, dim> P;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            P[i][j] = P3[i][j];
        return P;
      };
      std::array<double, 3> inverse;
      for (unsigned int i = 0; i < 3; ++i)
        inverse[i] = 1. / s.values[i];
      for (unsigned int p = 0; p < 3; ++p)
        {
          const double m  = 0.5 * constants.alpha[p];
          const double a  = std::exp(-m / 3. * log_u);
          const double da = -log_u / 3. * a;
          double       T = 0., dT = 0.;
          std::array<double, 3> power; // c_i^(m-1)
          for (unsigned int i = 0; i < 3; ++i)
            {
              power[i] = std::pow(s.values[i], m - 1.);
              T += power[i] * s.values[i];
              dT += power[i] * s.values[i] * std::log(s.values[i]);
            }
          std::array<double, 3> unit_mu, d_alpha;
          for (unsigned int i = 0; i < 3; ++i)
            {
              unit_mu[i] = a * (power[i] - T / 3. * inverse[i]);
              d_alpha[i] = da * (power[i] - T / 3. * inverse[i]) +
                           a * (power[i] * std::log(s.values[i]) -
                                dT / 3. * inverse[i]);
            }
          dP[2 * p]     = in_plane(function_of(s, unit_mu));
          dP[2 * p + 1] = 0.5 * constants.mu[p] * in_plane(function_of(s, d_alpha));
        }
      const double u = J * J;
      for (double &c_inverse : inverse)
        c_inverse *= 0.5 * (u - 1.);
      dP[6] = in_plane(function_of(s, inverse));
      return dP;
    }

  private:
    const OgdenConstants constants;

    using Matrix3 = Tensor<2, 3>;

    /// C = sum_i values[i] n_i n_i^T, n_i = column i of vectors.
    struct Spectrum
    {
      std::array<double, 3> values;
      SmallMatrix<3>        vectors;
    };

    /// F as a 3 x 3 matrix (F33 = 1 in plane strain).
    static Matrix3
    embed(const Tensor<2, dim> &F)
    {
      Matrix3 F3;
      F3[2][2] = 1.;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F3[i][j] = F[i][j];
      return F3;
    }

    static Spectrum
    spectrum(const Matrix3 &F3)
    {
      const Matrix3  C = transpose(F3) * F3;
      SmallMatrix<3> c;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          c[i][j] = C[i][j];
      Spectrum s;
      jacobi_eigen_decomposition<3>(c, s.values, s.vectors);
      return s;
    }

    /// sum_i g_i n_i n_i^T.
    static Matrix3
    function_of(const Spectrum &s, const std::array<double, 3> &g)
    {
      Matrix3 M;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int r = 0; r < 3; ++r)
          for (unsigned int q = 0; q < 3; ++q)
            M[r][q] += g[i] * s.vectors[r][i] * s.vectors[q][i];
      return M;
    }

    /// (a^q - b^q) / (a - b), q a^(q-1) at a = b; a, b > 0.
    static double
    divided_difference(const double a, const double b, const double q)
    {
      if (a == b)
        return q * std::pow(a, q - 1.);
      const double r = (a - b) / b;
      return std::pow(b, q - 1.) * std::expm1(q * std::log1p(r)) / r;
    }

    /// d(C^q)[dC] by the Daleckii-Krein formula.
    static Matrix3
    power_derivative(const Spectrum &s, const double q, const Matrix3 &dC)
    {
      // dC in the eigenbasis: N^T dC N.
      Matrix3 N;
      for (unsigned int r = 0; r < 3; ++r)
        for (unsigned int i = 0; i < 3; ++i)
          N[r][i] = s.vectors[r][i];
      Matrix3 D = transpose(N) * dC * N;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          D[i][j] *= divided_difference(s.values[i], s.values[j], q);
      return N * D * transpose(N);
    }

    void
    evaluate(const Tensor<2, dim> &F,
             Tensor<2, dim>       &P,
             StressTangent<dim>   &A,
             const bool            with_tangent) const override
    {
      const double J = determinant(F);
      if (!(J > 0.))
        {
          EvaluatedMaterial<dim>::undefined_at(P, A, with_tangent);
          return;
        }
      const Matrix3  F3 = embed(F);
      const Spectrum s  = spectrum(F3);
      const Matrix3  C_inverse =
        function_of(s,
                    {{1. / s.values[0], 1. / s.values[1], 1. / s.values[2]}});
      const double u = J * J;

      // Per present term: a, T and C^(m-1).
      struct Term
      {
        double  mu, m, a, T;
        Matrix3 power; // C^(m-1)
      };
      std::array<Term, 3> terms;
      unsigned int        n_terms = 0;
      Matrix3 S = 0.5 * constants.kappa * (u - 1.) * C_inverse; // volumetric
      for (unsigned int p = 0; p < 3; ++p)
        if (constants.mu[p] != 0.)
          {
            Term &t = terms[n_terms++];
            t.mu    = constants.mu[p];
            t.m     = 0.5 * constants.alpha[p];
            t.a     = std::pow(J, -constants.alpha[p] / 3.);
            std::array<double, 3> g;
            t.T = 0.;
            for (unsigned int i = 0; i < 3; ++i)
              {
                g[i] = std::pow(s.values[i], t.m - 1.);
                t.T += g[i] * s.values[i];
              }
            t.power = function_of(s, g);
            S += t.mu * t.a * (t.power - t.T / 3. * C_inverse);
          }
      const Matrix3 P3 = F3 * S;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          P[i][j] = P3[i][j];
      if (!with_tangent)
        return;

      for (unsigned int k = 0; k < dim; ++k)
        for (unsigned int L = 0; L < dim; ++L)
          {
            // dC for dF = e_k e_L^T.
            Matrix3 dC;
            for (unsigned int M = 0; M < 3; ++M)
              {
                dC[L][M] += F3[k][M];
                dC[M][L] += F3[k][M];
              }
            const double  Cinv_dC    = scalar_product(C_inverse, dC);
            const Matrix3 dC_inverse = -(C_inverse * dC * C_inverse);
            Matrix3       dS         = 0.5 * constants.kappa *
                         (u * Cinv_dC * C_inverse + (u - 1.) * dC_inverse);
            for (unsigned int p = 0; p < n_terms; ++p)
              {
                const Term   &t      = terms[p];
                const double  da     = -t.m / 3. * t.a * Cinv_dC;
                const double  dT     = t.m * scalar_product(t.power, dC);
                const Matrix3 dpower = power_derivative(s, t.m - 1., dC);
                dS += t.mu * (da * (t.power - t.T / 3. * C_inverse) +
                              t.a * (dpower - dT / 3. * C_inverse -
                                     t.T / 3. * dC_inverse));
              }
            const Matrix3 F_dS = F3 * dS;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int J_ = 0; J_ < dim; ++J_)
                A[i][J_][k][L] = (i == k ? S[J_][L] : 0.) + F_dS[i][J_];
          }
    }
  };
} // namespace hyperelastic
