// Projection of a stress tangent dP/dF onto the positive semi-definite cone,
// the building block of a projected Newton method.
//
// dP/dF = d^2 psi / dF dF of a hyperelastic model is the Hessian of the energy
// density, so read as the (dim*dim) x (dim*dim) matrix
//   M[(iJ)][(kL)] = A[i][J][k][L],   (iJ) = i * dim + J,
// it is symmetric. It is indefinite under strong compression (and for some
// models under large shear), and then the element stiffness
//   K = sum over quadrature points of w B^T M B
// may be indefinite too, so a Newton step need not be a descent direction.
// Replacing M by its projection M+ = V max(Lambda, 0) V^T at every quadrature
// point makes every B^T M+ B, and hence K, positive semi-definite. M+ is the
// positive semi-definite matrix nearest to M in the Frobenius norm.
//
// The eigen-decomposition is a cyclic Jacobi method on a fixed-size
// std::array (4 x 4 in 2D, 9 x 9 in 3D): no allocation, and accurate to
// round-off relative to the norm of the matrix for every eigenvalue, which
// is what deciding the sign of eigenvalues near zero needs. Pure functions;
// nothing here knows about meshes, quadrature or MPI.
#pragma once

#include <hyperelastic/materials/material.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace hyperelastic
{
  /// A dense n x n matrix, row by row.
  template <std::size_t n>
  using SmallMatrix = std::array<std::array<double, n>, n>;

  /// dP/dF as the (dim*dim) x (dim*dim) matrix M[(iJ)][(kL)].
  template <int dim>
  using TangentMatrix = SmallMatrix<dim * dim>;

  /// Eigen-decomposition of the symmetric matrix @p matrix (only its upper
  /// triangle is read; the lower one is assumed equal) with the cyclic Jacobi
  /// method: matrix = V diag(eigenvalues) V^T with V orthogonal; column k of
  /// @p eigenvectors (eigenvectors[r][k], r = 0..n-1) belongs to
  /// eigenvalues[k]. The eigenvalues are not sorted. Returns the number of
  /// sweeps done (60 would mean that the bound, not convergence, stopped it).
  template <std::size_t n>
  unsigned int
  jacobi_eigen_decomposition(const SmallMatrix<n>  &matrix,
                             std::array<double, n> &eigenvalues,
                             SmallMatrix<n>        &eigenvectors)
  {
    SmallMatrix<n> a;
    double         norm_squared = 0.;
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c)
        {
          a[r][c] = r <= c ? matrix[r][c] : matrix[c][r];
          norm_squared += a[r][c] * a[r][c];
          eigenvectors[r][c] = r == c ? 1. : 0.;
        }

    // Rotations keep the Frobenius norm. Stop when the off-diagonal part is
    // below half a unit round-off of it: by Weyl's inequality every diagonal
    // entry is then an eigenvalue to within that. Jacobi converges
    // quadratically once the off-diagonal part is small (at most 7 sweeps
    // for 9 x 9 material tangents, 11 for random matrices with triple
    // eigenvalues, measured). The sweep bound is only a safeguard: NaN or
    // infinite entries make the tolerance NaN or infinite and end the loop
    // at once, leaving NaN or infinite eigenvalues.
    const double tolerance_squared =
      0.25 * std::numeric_limits<double>::epsilon() *
      std::numeric_limits<double>::epsilon() * norm_squared;
    const double skip_below =
      1e-2 * std::numeric_limits<double>::epsilon() * std::sqrt(norm_squared);
    constexpr unsigned int max_sweeps = 60;
    unsigned int           sweep      = 0;
    for (;; ++sweep)
      {
        double off_squared = 0.;
        for (std::size_t p = 0; p < n; ++p)
          for (std::size_t q = p + 1; q < n; ++q)
            off_squared += 2. * a[p][q] * a[p][q];
        if (!(off_squared > tolerance_squared) || sweep == max_sweeps)
          break;

        for (std::size_t p = 0; p < n; ++p)
          for (std::size_t q = p + 1; q < n; ++q)
            {
              const double apq = a[p][q];
              // Entries below 1e-2 of the round-off of the matrix are
              // dropped without a rotation. They change no eigenvalue by
              // more than that, but within a cluster of (numerically) equal
              // eigenvalues the exact rotation for them is up to 45 degrees
              // and moves already annihilated coupling back into the
              // visited rows: without this, triple eigenvalues took up to 38
              // sweeps instead of 11.
              if (std::abs(apq) <= skip_below)
                {
                  a[p][q] = 0.;
                  a[q][p] = 0.;
                  continue;
                }
              // The rotation angle phi with t = tan(phi) zeroes a[p][q]; take
              // the root with |phi| <= pi/4 (the smaller t) for stability.
              const double theta = (a[q][q] - a[p][p]) / (2. * apq);
              double       t;
              if (std::abs(theta) > 1e150) // theta^2 would overflow
                t = 0.5 / theta;
              else
                t = (theta >= 0. ? 1. : -1.) /
                    (std::abs(theta) + std::sqrt(theta * theta + 1.));
              const double c = 1. / std::sqrt(t * t + 1.);
              const double s = t * c;

              a[p][p] -= t * apq;
              a[q][q] += t * apq;
              a[p][q] = 0.;
              a[q][p] = 0.;
              for (std::size_t r = 0; r < n; ++r)
                {
                  if (r != p && r != q)
                    {
                      const double arp = a[r][p];
                      const double arq = a[r][q];
                      a[r][p]          = c * arp - s * arq;
                      a[p][r]          = a[r][p];
                      a[r][q]          = s * arp + c * arq;
                      a[q][r]          = a[r][q];
                    }
                  const double vrp   = eigenvectors[r][p];
                  const double vrq   = eigenvectors[r][q];
                  eigenvectors[r][p] = c * vrp - s * vrq;
                  eigenvectors[r][q] = s * vrp + c * vrq;
                }
            }
      }
    for (std::size_t k = 0; k < n; ++k)
      eigenvalues[k] = a[k][k];
    return sweep;
  }

  /// The symmetric part (M + M^T) / 2 of @p A read as the matrix M[(iJ)][(kL)].
  template <int dim>
  TangentMatrix<dim>
  symmetric_tangent_matrix(const StressTangent<dim> &A)
  {
    constexpr std::size_t n = dim * dim;
    TangentMatrix<dim>    M;
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c)
        M[r][c] = 0.5 * (A[r / dim][r % dim][c / dim][c % dim] +
                         A[c / dim][c % dim][r / dim][r % dim]);
    return M;
  }

  /// The inverse of the reading above: A[i][J][k][L] = M[(iJ)][(kL)].
  template <int dim>
  StressTangent<dim>
  tangent_from_matrix(const TangentMatrix<dim> &M)
  {
    constexpr std::size_t n = dim * dim;
    StressTangent<dim>    A;
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c)
        A[r / dim][r % dim][c / dim][c % dim] = M[r][c];
    return A;
  }

  /// Replaces @p A by the positive semi-definite tangent nearest to its
  /// symmetric part (in the Frobenius norm): negative eigenvalues of the
  /// (dim*dim) x (dim*dim) matrix become 0, eigenvectors stay.
  ///
  /// Computed as M - sum over negative eigenvalues of lambda_k v_k v_k^T,
  /// which equals V max(Lambda, 0) V^T but leaves a tangent without negative
  /// eigenvalues exactly at its symmetric part instead of rounding it through
  /// the reassembly. A tangent with NaN entries (neo-Hookean at J <= 0) stays
  /// NaN.
  template <int dim>
  void
  project_to_positive_semidefinite(StressTangent<dim> &A)
  {
    constexpr std::size_t n = dim * dim;
    TangentMatrix<dim>    M = symmetric_tangent_matrix(A);
    std::array<double, n> eigenvalues;
    SmallMatrix<n>        V;
    jacobi_eigen_decomposition<n>(M, eigenvalues, V);
    // Upper triangle only, mirrored, so that the result is exactly symmetric.
    for (std::size_t k = 0; k < n; ++k)
      if (eigenvalues[k] < 0.)
        for (std::size_t r = 0; r < n; ++r)
          for (std::size_t c = r; c < n; ++c)
            {
              M[r][c] -= eigenvalues[k] * V[r][k] * V[c][k];
              M[c][r] = M[r][c];
            }
    A = tangent_from_matrix<dim>(M);
  }

  /// The smallest eigenvalue of the symmetric part of @p A read as the matrix
  /// M[(iJ)][(kL)] (for tests and diagnostics).
  template <int dim>
  double
  smallest_eigenvalue(const StressTangent<dim> &A)
  {
    constexpr std::size_t n = dim * dim;
    std::array<double, n> eigenvalues;
    SmallMatrix<n>        V;
    jacobi_eigen_decomposition<n>(symmetric_tangent_matrix(A), eigenvalues, V);
    return *std::min_element(eigenvalues.begin(), eigenvalues.end());
  }
} // namespace hyperelastic
