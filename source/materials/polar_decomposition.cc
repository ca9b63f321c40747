// Rotation-variant SVD from the eigen-decomposition of C = F^T F, completed so
// that U and V are proper rotations, and the derivative of R = U V^T.
#include <deal.II/base/symmetric_tensor.h>

#include <hyperelastic/materials/polar_decomposition.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    Tensor<1, 2>
    perpendicular(const Tensor<1, 2> &u)
    {
      Tensor<1, 2> p;
      p[0] = -u[1];
      p[1] = u[0];
      return p;
    }

    /// A unit vector orthogonal to the unit vector u.
    Tensor<1, 3>
    any_perpendicular(const Tensor<1, 3> &u)
    {
      Tensor<1, 3>       e;
      const unsigned int smallest = static_cast<unsigned int>(
        std::min_element(&u[0],
                         &u[0] + 3,
                         [](double a, double b) {
                           return std::abs(a) < std::abs(b);
                         }) -
        &u[0]);
      e[smallest]    = 1.;
      Tensor<1, 3> p = e - (e * u) * u;
      return p / p.norm();
    }

    template <int dim>
    void
    set_column(Tensor<2, dim> &M, const unsigned int c, const Tensor<1, dim> &v)
    {
      for (unsigned int i = 0; i < dim; ++i)
        M[i][c] = v[i];
    }

    template <int dim>
    Tensor<1, dim>
    column(const Tensor<2, dim> &M, const unsigned int c)
    {
      Tensor<1, dim> v;
      for (unsigned int i = 0; i < dim; ++i)
        v[i] = M[i][c];
      return v;
    }

    // Completes U from its first column(s) so that det U = +1.
    void
    complete_left_vectors(const Tensor<2, 2> &F, RotationVariantSVD<2> &svd)
    {
      const Tensor<1, 2> u1 = column(svd.U, 0);
      const Tensor<1, 2> u2 = perpendicular(u1);
      set_column(svd.U, 1, u2);
      svd.sigma[1] = u2 * (F * column(svd.V, 1));
    }

    void
    complete_left_vectors(const Tensor<2, 3> &F, RotationVariantSVD<3> &svd)
    {
      const Tensor<1, 3> u1  = column(svd.U, 0);
      Tensor<1, 3>       Fv2 = F * column(svd.V, 1);
      Tensor<1, 3>       u2  = Fv2 - (Fv2 * u1) * u1;
      const double       n2  = u2.norm();
      u2 =
        (n2 > 1e-300 * (1. + svd.sigma[0])) ? u2 / n2 : any_perpendicular(u1);
      const Tensor<1, 3> u3 = cross_product_3d(u1, u2);
      set_column(svd.U, 1, u2);
      set_column(svd.U, 2, u3);
      svd.sigma[1] = u2 * Fv2;
      svd.sigma[2] = u3 * (F * column(svd.V, 2));
    }
  } // namespace

  template <int dim>
  RotationVariantSVD<dim>
  rotation_variant_svd(const Tensor<2, dim> &F)
  {
    RotationVariantSVD<dim>       svd;
    const SymmetricTensor<2, dim> C = symmetrize(transpose(F) * F);
    const auto eig = eigenvectors(C, SymmetricTensorEigenvectorMethod::jacobi);

    for (unsigned int c = 0; c < dim; ++c)
      {
        set_column(svd.V, c, eig[c].second);
        svd.sigma[c] = std::sqrt(std::max(eig[c].first, 0.));
      }
    if (determinant(svd.V) < 0.)
      set_column(svd.V, dim - 1, -column(svd.V, dim - 1));

    if (!(svd.sigma[0] > 0.))
      {
        // F = 0: any rotation will do.
        svd.U = unit_symmetric_tensor<dim>();
        svd.V = unit_symmetric_tensor<dim>();
        return svd;
      }
    set_column(svd.U, 0, F * column(svd.V, 0) / svd.sigma[0]);
    complete_left_vectors(F, svd);
    return svd;
  }

  template <int dim>
  PolarDecomposition<dim>
  polar_decomposition(const Tensor<2, dim> &F)
  {
    const RotationVariantSVD<dim> svd = rotation_variant_svd(F);
    PolarDecomposition<dim>       polar;
    polar.R = svd.U * transpose(svd.V);
    Tensor<2, dim> sigma_VT;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int J = 0; J < dim; ++J)
        sigma_VT[a][J] = svd.sigma[a] * svd.V[J][a];
    polar.S = svd.V * sigma_VT;
    return polar;
  }

  // With M = U^T dF V, R^T-rotated increments are dR = U W V^T where W is skew,
  // W_ab = (M_ab - M_ba) / (sigma_a + sigma_b). For dF = e_k e_L^T,
  // M_ab = U_ka V_Lb, which gives the closed form below.
  template <int dim>
  Tensor<4, dim>
  rotation_derivative(const RotationVariantSVD<dim> &svd)
  {
    const Tensor<2, dim> &U = svd.U;
    const Tensor<2, dim> &V = svd.V;
    Tensor<4, dim>        dR;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        {
          if (a == b)
            continue;
          double denominator = svd.sigma[a] + svd.sigma[b];
          // sigma_a + sigma_b = 0 only for a flat, inverted element: the
          // derivative is unbounded there, keep it finite.
          if (std::abs(denominator) < 1e-12)
            denominator = (denominator < 0. ? -1e-12 : 1e-12);
          const double w = 1. / denominator;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int J = 0; J < dim; ++J)
              {
                const double UV = U[i][a] * V[J][b] * w;
                for (unsigned int k = 0; k < dim; ++k)
                  for (unsigned int L = 0; L < dim; ++L)
                    dR[i][J][k][L] +=
                      UV * (U[k][a] * V[L][b] - U[k][b] * V[L][a]);
              }
        }
    return dR;
  }

  template struct RotationVariantSVD<2>;
  template struct RotationVariantSVD<3>;
  template RotationVariantSVD<2>
  rotation_variant_svd(const Tensor<2, 2> &);
  template RotationVariantSVD<3>
  rotation_variant_svd(const Tensor<2, 3> &);
  template PolarDecomposition<2>
  polar_decomposition(const Tensor<2, 2> &);
  template PolarDecomposition<3>
  polar_decomposition(const Tensor<2, 3> &);
  template Tensor<4, 2>
  rotation_derivative(const RotationVariantSVD<2> &);
  template Tensor<4, 3>
  rotation_derivative(const RotationVariantSVD<3> &);
} // namespace hyperelastic
