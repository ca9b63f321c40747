// Corotational elasticity with the rotation-variant polar decomposition F = R
// S:
//   psi = mu ||F - R||^2 + lambda/2 (tr(S - I))^2,
//   P = 2 mu (F - R) + lambda tr(S - I) R,
//   dP/dF = 2 mu (I x I - dR/dF) + lambda R x R + lambda tr(S - I) dR/dF.
// With lambda = 0 this is ARAP (as-rigid-as-possible). Defined for inverted
// elements because R stays a rotation and the reflection lives in S.
#pragma once

#include <hyperelastic/materials/material.h>
#include <hyperelastic/materials/polar_decomposition.h>

namespace hyperelastic
{
  template <int dim>
  class Corotational : public LameBasedMaterial<dim, Corotational>
  {
  public:
    using LameBasedMaterial<dim, Corotational>::LameBasedMaterial;

    std::string
    name() const override
    {
      return "corotational";
    }

    /// One paragraph for the scene documentation (material_registry.h).
    static const char *
    documentation()
    {
      return "psi = mu |F - R|^2 + lambda/2 (tr(S - I))^2 with the "
             "rotation-variant polar decomposition F = R S (ARAP when lambda = "
             "0). Finite for inverted elements (the reflection lives in S). "
             "Constants: the shared elastic constants.";
    }

    double
    energy_density(const Tensor<2, dim> &F) const override
    {
      const PolarDecomposition<dim> polar = polar_decomposition(F);
      const Tensor<2, dim>          F_R   = F - polar.R;
      const double                  tr    = trace(polar.S) - dim;
      return this->lame.mu * scalar_product(F_R, F_R) +
             0.5 * this->lame.lambda * tr * tr;
    }

    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override
    {
      const PolarDecomposition<dim> polar = polar_decomposition(F);
      return stress(F, polar.R, trace(polar.S) - dim);
    }

    StressTangent<dim>
    stress_tangent(const Tensor<2, dim> &F) const override
    {
      Tensor<2, dim>     P;
      StressTangent<dim> A;
      stress_and_tangent(F, P, A);
      return A;
    }

    void
    stress_and_tangent(const Tensor<2, dim> &F,
                       Tensor<2, dim>       &P,
                       StressTangent<dim>   &A) const override
    {
      const RotationVariantSVD<dim> svd = rotation_variant_svd(F);
      const Tensor<2, dim>          R   = svd.U * transpose(svd.V);
      double                        tr  = -double(dim);
      for (unsigned int i = 0; i < dim; ++i)
        tr += svd.sigma[i];
      P = stress(F, R, tr);

      const Tensor<4, dim> dR     = rotation_derivative(svd);
      const double         mu     = this->lame.mu;
      const double         lambda = this->lame.lambda;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int J = 0; J < dim; ++J)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int L = 0; L < dim; ++L)
              A[i][J][k][L] =
                2. * mu * ((i == k && J == L ? 1. : 0.) - dR[i][J][k][L]) +
                lambda * R[i][J] * R[k][L] + lambda * tr * dR[i][J][k][L];
    }

    bool
    defined_for_inverted_elements() const override
    {
      return true;
    }

  private:
    Tensor<2, dim>
    stress(const Tensor<2, dim> &F,
           const Tensor<2, dim> &R,
           const double          trace_S_minus_I) const
    {
      return 2. * this->lame.mu * (F - R) +
             this->lame.lambda * trace_S_minus_I * R;
    }
  };
} // namespace hyperelastic
