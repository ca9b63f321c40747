// Base of the models that compute P and dP/dF in one routine,
// evaluate(F, P, A, with_tangent) (first_invariant_model.h, ogden.h): the
// three Material entry points call it, and undefined_at() fills P and A
// with NaN where the model is undefined. decoupled_split() gives such a
// decoupled model's volumetric-isochoric split.
#pragma once

#include <hyperelastic/materials/material.h>
#include <hyperelastic/materials/volumetric_split.h>

#include <memory>

namespace hyperelastic
{
  template <int dim>
  class EvaluatedMaterial : public Material<dim>
  {
  public:
    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override
    {
      Tensor<2, dim>     P;
      StressTangent<dim> A;
      evaluate(F, P, A, false);
      return P;
    }

    StressTangent<dim>
    stress_tangent(const Tensor<2, dim> &F) const override
    {
      Tensor<2, dim>     P;
      StressTangent<dim> A;
      evaluate(F, P, A, true);
      return A;
    }

    void
    stress_and_tangent(const Tensor<2, dim> &F,
                       Tensor<2, dim>       &P,
                       StressTangent<dim>   &A) const override
    {
      evaluate(F, P, A, true);
    }

  protected:
    /// P, and dP/dF if @p with_tangent, at @p F.
    virtual void
    evaluate(const Tensor<2, dim> &F,
             Tensor<2, dim>       &P,
             StressTangent<dim>   &A,
             bool                  with_tangent) const = 0;

    /// P (and A) NaN: the model is undefined at this F.
    static void
    undefined_at(Tensor<2, dim>     &P,
                 StressTangent<dim> &A,
                 const bool          with_tangent)
    {
      P = Material<dim>::not_a_number_tensor();
      if (with_tangent)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int J = 0; J < dim; ++J)
            A[i][J] = Material<dim>::not_a_number_tensor();
    }
  };

  /// The split of a decoupled @p Model whose @p constants carry the bulk
  /// modulus kappa of U = kappa/4 (J^2 - 1 - 2 ln J): the isochoric part is
  /// the same model with kappa = 0.
  template <int dim, typename Model, typename Constants>
  std::unique_ptr<VolumetricSplit<dim>>
  decoupled_split(const Constants &constants)
  {
    Constants isochoric = constants;
    isochoric.kappa     = 0.;
    return std::make_unique<VolumetricSplit<dim>>(
      VolumetricSplit<dim>{std::make_unique<Model>(isochoric),
                           LogVolumetricEnergy(constants.kappa)});
  }
} // namespace hyperelastic
