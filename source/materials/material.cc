// Lame parameter conversions and the factory that maps scene names to models.
#include <deal.II/base/exceptions.h>

#include <hyperelastic/materials/corotational.h>
#include <hyperelastic/materials/decoupled_neo_hookean.h>
#include <hyperelastic/materials/linear_elastic.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/materials/neo_hookean.h>
#include <hyperelastic/materials/st_venant_kirchhoff.h>
#include <hyperelastic/materials/stable_neo_hookean.h>

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

  std::string
  material_model_names()
  {
    return "linear elastic|St. Venant-Kirchhoff|corotational|neo-Hookean|"
           "stable neo-Hookean|decoupled neo-Hookean";
  }

  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const std::string &name, const LameParameters &lame)
  {
    if (name == "linear elastic")
      return std::make_unique<LinearElastic<dim>>(lame);
    if (name == "St. Venant-Kirchhoff")
      return std::make_unique<StVenantKirchhoff<dim>>(lame);
    if (name == "corotational")
      return std::make_unique<Corotational<dim>>(lame);
    if (name == "neo-Hookean")
      return std::make_unique<NeoHookean<dim>>(lame);
    if (name == "stable neo-Hookean")
      return std::make_unique<StableNeoHookean<dim>>(lame);
    if (name == "decoupled neo-Hookean")
      return std::make_unique<DecoupledNeoHookean<dim>>(lame);
    AssertThrow(false,
                dealii::ExcMessage(
                  "Unknown material model '" + name +
                  "'; known models: " + material_model_names()));
    return nullptr;
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

  template std::unique_ptr<Material<2>>
  create_material<2>(const std::string &, const LameParameters &);
  template std::unique_ptr<Material<3>>
  create_material<3>(const std::string &, const LameParameters &);
  template StressTangent<2>
  linear_elastic_tangent<2>(const LameParameters &);
  template StressTangent<3>
  linear_elastic_tangent<3>(const LameParameters &);
} // namespace hyperelastic
