// Compressible neo-Hookean:
//   psi = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,   I1 = tr(F^T F),
//   P = mu (F - F^-T) + lambda ln(J) F^-T.
// In 2D plane strain F33 = 1, so I1 - 3 is the in-plane tr(F^T F) - 2.
// Undefined for J <= 0: the energy is +infinity there and P is NaN.
#pragma once

#include <hyperelastic/materials/material.h>

#include <cmath>
#include <limits>

namespace hyperelastic
{
  template <int dim>
  class NeoHookean : public LameBasedMaterial<dim, NeoHookean>
  {
  public:
    using LameBasedMaterial<dim, NeoHookean>::LameBasedMaterial;
    using Material<dim>::not_a_number_tensor;

    std::string
    name() const override
    {
      return "neo-Hookean";
    }

    /// One paragraph for the scene documentation (material_registry.h).
    static const char *
    documentation()
    {
      return "Compressible neo-Hookean, psi = mu/2 (I1 - 3) - mu ln J + "
             "lambda/2 (ln J)^2. The log barrier makes it undefined for "
             "inverted elements (J <= 0). Constants: the shared elastic "
             "constants.";
    }

    double
    energy_density(const Tensor<2, dim> &F) const override
    {
      const double J = determinant(F);
      if (!(J > 0.))
        return std::numeric_limits<double>::infinity();
      const double lnJ = std::log(J);
      return 0.5 * this->lame.mu * (scalar_product(F, F) - dim) -
             this->lame.mu * lnJ + 0.5 * this->lame.lambda * lnJ * lnJ;
    }

    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override
    {
      const double J = determinant(F);
      if (!(J > 0.))
        return not_a_number_tensor();
      const Tensor<2, dim> F_inv_T = transpose(invert(F));
      return this->lame.mu * (F - F_inv_T) +
             this->lame.lambda * std::log(J) * F_inv_T;
    }

    /// A_iJkL = mu delta_ik delta_JL + (mu - lambda ln J) G_iL G_kJ
    ///          + lambda G_iJ G_kL,  with G = F^-T.
    StressTangent<dim>
    stress_tangent(const Tensor<2, dim> &F) const override
    {
      StressTangent<dim> A;
      const double       J = determinant(F);
      if (!(J > 0.))
        {
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int J_ = 0; J_ < dim; ++J_)
              A[i][J_] = not_a_number_tensor();
          return A;
        }
      const Tensor<2, dim> G      = transpose(invert(F));
      const double         mu     = this->lame.mu;
      const double         lambda = this->lame.lambda;
      const double         c      = mu - lambda * std::log(J);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int J_ = 0; J_ < dim; ++J_)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int L = 0; L < dim; ++L)
              A[i][J_][k][L] = (i == k && J_ == L ? mu : 0.) +
                               c * G[i][L] * G[k][J_] +
                               lambda * G[i][J_] * G[k][L];
      return A;
    }

    bool
    defined_for_inverted_elements() const override
    {
      return false;
    }
  };
} // namespace hyperelastic
