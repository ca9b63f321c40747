// St. Venant-Kirchhoff: linear elasticity applied to the Green strain,
//   E = (F^T F - I)/2,  psi = mu E:E + lambda/2 (tr E)^2,
//   S = 2 mu E + lambda tr(E) I,  P = F S.
// Rotation invariant, but it softens in compression (a limit point at
// stretch 1/sqrt(3)) and resists inversion only weakly.
#pragma once

#include <hyperelastic/materials/material.h>

namespace hyperelastic
{
  template <int dim>
  class StVenantKirchhoff : public LameBasedMaterial<dim, StVenantKirchhoff>
  {
  public:
    using LameBasedMaterial<dim, StVenantKirchhoff>::LameBasedMaterial;

    std::string
    name() const override
    {
      return "St. Venant-Kirchhoff";
    }

    /// One paragraph for the scene documentation (material_registry.h).
    static const char *
    documentation()
    {
      return "Linear elasticity of the Green strain E = (F^T F - I)/2: psi = "
             "mu E:E + lambda/2 (tr E)^2. Rotation invariant, but it softens "
             "in compression (a limit point at stretch 1/sqrt(3)) and resists "
             "inversion only weakly. Constants: the shared elastic constants.";
    }

    double
    energy_density(const Tensor<2, dim> &F) const override
    {
      const Tensor<2, dim> E  = green_strain(F);
      const double         tr = trace(E);
      return this->lame.mu * scalar_product(E, E) +
             0.5 * this->lame.lambda * tr * tr;
    }

    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override
    {
      return F * second_piola_kirchhoff(F);
    }

    /// A_iJkL = delta_ik S_JL + mu (b_ik delta_JL + F_iL F_kJ)
    ///          + lambda F_iJ F_kL,  with b = F F^T.
    StressTangent<dim>
    stress_tangent(const Tensor<2, dim> &F) const override
    {
      const Tensor<2, dim> S  = second_piola_kirchhoff(F);
      const Tensor<2, dim> b  = F * transpose(F);
      const double         mu = this->lame.mu, lambda = this->lame.lambda;
      StressTangent<dim>   A;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int J = 0; J < dim; ++J)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int L = 0; L < dim; ++L)
              A[i][J][k][L] =
                (i == k ? S[J][L] : 0.) +
                mu * ((J == L ? b[i][k] : 0.) + F[i][L] * F[k][J]) +
                lambda * F[i][J] * F[k][L];
      return A;
    }

    bool
    defined_for_inverted_elements() const override
    {
      return true;
    }

  private:
    static Tensor<2, dim>
    green_strain(const Tensor<2, dim> &F)
    {
      Tensor<2, dim> E = 0.5 * (transpose(F) * F);
      for (unsigned int i = 0; i < dim; ++i)
        E[i][i] -= 0.5;
      return E;
    }

    Tensor<2, dim>
    second_piola_kirchhoff(const Tensor<2, dim> &F) const
    {
      const Tensor<2, dim> E  = green_strain(F);
      Tensor<2, dim>       S  = 2. * this->lame.mu * E;
      const double         tr = trace(E);
      for (unsigned int i = 0; i < dim; ++i)
        S[i][i] += this->lame.lambda * tr;
      return S;
    }
  };
} // namespace hyperelastic
