// Small-strain linear elasticity written as a function of F, the reference the
// nonlinear models reduce to at F = I:
//   eps = sym(F - I),  psi = mu eps:eps + lambda/2 (tr eps)^2,
//   P = 2 mu eps + lambda tr(eps) I.
// Not rotation invariant: a rigid rotation produces spurious stress.
#pragma once

#include <hyperelastic/materials/material.h>

namespace hyperelastic
{
  template <int dim>
  class LinearElastic : public LameBasedMaterial<dim, LinearElastic>
  {
  public:
    using LameBasedMaterial<dim, LinearElastic>::LameBasedMaterial;

    std::string
    name() const override
    {
      return "linear elastic";
    }

    /// One paragraph for the scene documentation (material_registry.h).
    static const char *
    documentation()
    {
      return "Small-strain linear elasticity, psi = mu eps:eps + lambda/2 (tr "
             "eps)^2 with eps = sym(F - I): P is linear in F, so one linear "
             "solve is the whole answer. Not rotation invariant: a rigid "
             "rotation produces stress. Constants: the shared elastic "
             "constants.";
    }

    double
    energy_density(const Tensor<2, dim> &F) const override
    {
      const Tensor<2, dim> eps = small_strain(F);
      const double         tr  = trace(eps);
      return this->lame.mu * scalar_product(eps, eps) +
             0.5 * this->lame.lambda * tr * tr;
    }

    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override
    {
      const Tensor<2, dim> eps = small_strain(F);
      Tensor<2, dim>       P   = 2. * this->lame.mu * eps;
      const double         tr  = trace(eps);
      for (unsigned int i = 0; i < dim; ++i)
        P[i][i] += this->lame.lambda * tr;
      return P;
    }

    StressTangent<dim>
    stress_tangent(const Tensor<2, dim> &) const override
    {
      return linear_elastic_tangent<dim>(this->lame);
    }

    bool
    defined_for_inverted_elements() const override
    {
      return true;
    }

    bool
    is_linear() const override
    {
      return true;
    }

  private:
    static Tensor<2, dim>
    small_strain(const Tensor<2, dim> &F)
    {
      Tensor<2, dim> eps = 0.5 * (F + transpose(F));
      for (unsigned int i = 0; i < dim; ++i)
        eps[i][i] -= 1.;
      return eps;
    }
  };
} // namespace hyperelastic
