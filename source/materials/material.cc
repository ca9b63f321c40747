// Lame parameter conversions and the small-strain elasticity tensor. (The
// models a scene can name are in material_registry.cc.)
#include <hyperelastic/materials/material.h>

namespace hyperelastic
{
  LameParameters
  LameParameters::from_young_poisson(const double E, const double nu)
  {
    LameParameters p;
    p.mu     = E / (2. * (1. + nu));
    p.lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
    return p;
  }

  double
  LameParameters::young_modulus() const
  {
    return mu * (3. * lambda + 2. * mu) / (lambda + mu);
  }

  double
  LameParameters::poisson_ratio() const
  {
    return lambda / (2. * (lambda + mu));
  }

  template <int dim>
  StressTangent<dim>
  linear_elastic_tangent(const LameParameters &lame)
  {
    StressTangent<dim> A;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        {
          A[i][j][i][j] += lame.mu;
          A[i][j][j][i] += lame.mu;
          A[i][i][j][j] += lame.lambda;
        }
    return A;
  }

  template StressTangent<2>
  linear_elastic_tangent<2>(const LameParameters &);
  template StressTangent<3>
  linear_elastic_tangent<3>(const LameParameters &);
} // namespace hyperelastic
