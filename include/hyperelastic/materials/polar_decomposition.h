// Rotation-variant polar decomposition F = R S and the derivative of R.
// "Rotation variant" means R is always a proper rotation (det R = +1): when
// det F < 0 the reflection is placed in S (its smallest singular value is
// negated), never in R, so that energies built on R stay smooth through
// inversion.
#pragma once

#include <deal.II/base/tensor.h>

namespace hyperelastic
{
  using dealii::Tensor;

  /// F = U diag(sigma) V^T with U and V proper rotations; sigma[dim-1] carries
  /// the sign of det F.
  template <int dim>
  struct RotationVariantSVD
  {
    Tensor<2, dim> U;
    Tensor<2, dim> V;
    Tensor<1, dim> sigma;
  };

  template <int dim>
  RotationVariantSVD<dim>
  rotation_variant_svd(const Tensor<2, dim> &F);

  template <int dim>
  struct PolarDecomposition
  {
    Tensor<2, dim> R; ///< proper rotation
    Tensor<2, dim> S; ///< symmetric, F = R S
  };

  template <int dim>
  PolarDecomposition<dim>
  polar_decomposition(const Tensor<2, dim> &F);

  /// dR/dF as dR[i][J][k][L] = d R_iJ / d F_kL, from the SVD of F.
  template <int dim>
  Tensor<4, dim>
  rotation_derivative(const RotationVariantSVD<dim> &svd);
} // namespace hyperelastic
