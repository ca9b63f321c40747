// A manufactured finite-strain solution on the unit square (cube), shared by
// the convergence-rate test and the benchmark.
//
// The motion phi(X, t) = R(t theta) (X + t w(X)): a smooth deformation
// w_k(X) = a sin(pi c_k . X + d_k) followed by a rotation by theta = 90
// degrees (about the oblique axis (1, 2, 2) / 3 in 3D). The body force that
// makes it an equilibrium is
//   b_i = -(Div P)_i = -A_iJkL(F) dF_kL/dX_J,
//   F = R (I + t grad w),  dF_kL/dX_J = t R_km d^2 w_m / dX_L dX_J,
// with A = dP/dF of the model itself, so it is exact for every model; the
// displacement phi - X is prescribed on the whole boundary.
#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/materials/material.h>

#include <cmath>

namespace hyperelastic::testing
{
  using dealii::Function;
  using dealii::Point;
  using dealii::Tensor;
  using dealii::Vector;

  /// The rotation by @p angle about the z axis (2D) or about the unit axis
  /// (1, 2, 2) / 3 (3D, Rodrigues' formula).
  template <int dim>
  Tensor<2, dim>
  rotation_matrix(const double angle)
  {
    const double   c = std::cos(angle), s = std::sin(angle);
    Tensor<2, dim> R;
    if constexpr (dim == 2)
      {
        R[0][0] = R[1][1] = c;
        R[0][1]           = -s;
        R[1][0]           = s;
        return R;
      }
    const double n[3] = {1. / 3., 2. / 3., 2. / 3.};
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        R[i][j] = (i == j ? c : 0.) + (1. - c) * n[i] * n[j];
    // + s [n]_x
    R[0][1] -= s * n[2];
    R[1][0] += s * n[2];
    R[0][2] += s * n[1];
    R[2][0] -= s * n[1];
    R[1][2] -= s * n[0];
    R[2][1] += s * n[0];
    return R;
  }

  constexpr double theta = M_PI / 2.;
  // Strains up to about 15 %. With 0.06 (20 %) St. Venant-Kirchhoff, whose
  // stiffness softens in compression, has no nearby stable discrete
  // solution on the P2 meshes and Newton stalls.
  constexpr double amplitude = 0.04;

  /// phi(X, t) = R(t theta) (X + t w(X)) and its first two derivatives.
  template <int dim>
  class Motion
  {
  public:
    Motion()
    {
      const double c[3][3] = {{1., 0.5, 0.25}, {-0.5, 1., 0.5}, {0.25, -0.5, 1.}};
      const double d[3]    = {0.3, 1.1, 0.7};
      for (unsigned int k = 0; k < dim; ++k)
        {
          for (unsigned int j = 0; j < dim; ++j)
            wave[k][j] = M_PI * c[k][j];
          phase[k] = d[k];
        }
    }

    Tensor<2, dim>
    rotation(const double t) const
    {
      return rotation_matrix<dim>(t * theta);
    }

    Tensor<1, dim>
    displacement(const Point<dim> &X, const double t) const
    {
      Tensor<1, dim> y = X;
      for (unsigned int k = 0; k < dim; ++k)
        y[k] += t * amplitude * std::sin(wave[k] * X + phase[k]);
      return rotation(t) * y - X;
    }

    /// F = R (I + t grad w).
    Tensor<2, dim>
    deformation_gradient(const Point<dim> &X, const double t) const
    {
      Tensor<2, dim> G = dealii::unit_symmetric_tensor<dim>();
      for (unsigned int k = 0; k < dim; ++k)
        G[k] += t * amplitude * std::cos(wave[k] * X + phase[k]) * wave[k];
      return rotation(t) * G;
    }

    /// dF_kL / dX_J, stored as [k][L][J].
    Tensor<3, dim>
    gradient_of_F(const Point<dim> &X, const double t) const
    {
      const Tensor<2, dim> R = rotation(t);
      Tensor<3, dim>       dF;
      for (unsigned int m = 0; m < dim; ++m)
        {
          const double s = -t * amplitude * std::sin(wave[m] * X + phase[m]);
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int L = 0; L < dim; ++L)
              for (unsigned int J = 0; J < dim; ++J)
                dF[k][L][J] += R[k][m] * s * wave[m][L] * wave[m][J];
        }
      return dF;
    }

  private:
    Tensor<1, dim> wave[dim];
    double         phase[dim];
  };

  /// The exact displacement phi(X, t) - X (time from set_time()).
  template <int dim>
  class ExactDisplacement : public Function<dim>
  {
  public:
    ExactDisplacement()
        : Function<dim>(dim)
    {
    }

    double
    value(const Point<dim> &X, const unsigned int c) const override
    {
      return motion.displacement(X, this->get_time())[c];
    }

    Tensor<1, dim>
    gradient(const Point<dim> &X, const unsigned int c) const override
    {
      Tensor<1, dim> g = motion.deformation_gradient(X, this->get_time())[c];
      g[c] -= 1.;
      return g;
    }

  private:
    const Motion<dim> motion;
  };

  /// b = -Div P(F(X, t)) for the given model.
  template <int dim>
  class ManufacturedBodyForce : public Function<dim>
  {
  public:
    explicit ManufacturedBodyForce(const Material<dim> &material)
        : Function<dim>(dim)
        , material(material)
    {
    }

    void
    vector_value(const Point<dim> &X, Vector<double> &b) const override
    {
      const double             t  = this->get_time();
      const StressTangent<dim> A  = material.stress_tangent(motion.deformation_gradient(X, t));
      const Tensor<3, dim>     dF = motion.gradient_of_F(X, t);
      for (unsigned int i = 0; i < dim; ++i)
        {
          b[i] = 0.;
          for (unsigned int J = 0; J < dim; ++J)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int L = 0; L < dim; ++L)
                b[i] -= A[i][J][k][L] * dF[k][L][J];
        }
    }

  private:
    const Material<dim> &material;
    const Motion<dim>    motion;
  };

} // namespace hyperelastic::testing
