// The quadrature-point kernel every assembler and post-processor shares: the
// deformation gradient from a displacement gradient, and a model's stress and
// tangent at F with the finiteness check (before anything is written:
// Trilinos would carry NaN into the solver) and the optional projection of
// the tangent to positive semi-definite (projected Newton).
#pragma once

#include <deal.II/base/tensor.h>

#include <hyperelastic/assembly/assembly_tools.h>
#include <hyperelastic/base/tangent_projection_mode.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/materials/tangent_projection.h>

namespace hyperelastic
{
  /// F = I + grad u.
  template <int dim>
  inline dealii::Tensor<2, dim>
  deformation_gradient_of(const dealii::Tensor<2, dim> &grad_u)
  {
    dealii::Tensor<2, dim> F = grad_u;
    for (unsigned int d = 0; d < dim; ++d)
      F[d][d] += 1.;
    return F;
  }

  /// P and dP/dF of @p material at @p F, dP/dF projected to positive
  /// semi-definite as @p projection says (at every point, or where
  /// det F <= 0). Returns false if an entry is not finite (then nothing is
  /// projected); the model's own exceptions propagate.
  template <int dim>
  inline bool
  stress_and_tangent_at(const Material<dim>          &material,
                        const dealii::Tensor<2, dim> &F,
                        const TangentProjection       projection,
                        dealii::Tensor<2, dim>       &P,
                        StressTangent<dim>           &A)
  {
    material.stress_and_tangent(F, P, A);
    if (!stress_and_tangent_finite(P, A))
      return false;
    if (projection == TangentProjection::every_point ||
        (projection == TangentProjection::inverted_points &&
         dealii::determinant(F) <= 0.))
      project_to_positive_semidefinite(A);
    return true;
  }
} // namespace hyperelastic
