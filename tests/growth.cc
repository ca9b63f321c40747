// Multiplicative growth F = Fe Fg (issue 59, materials/grown.h) at the level
// of the material, for every registered model and every growth kind
// (isotropic with t, fibre, a full tensor varying with x, y, z), 2D and 3D,
// at a point copy:
// - dP/dF against central differences of P (1e-7 of |dP/dF|), and P
//   against central differences of psi (1e-7 of |P|);
// - 3D: the grown body is stress-free and without energy at F = Fg (1e-12
//   of the modulus);
// - 2D: P is the in-plane block of the 3D twin's P at diag(F, 1) (1e-14);
// - fibre growth of Holzapfel-Gasser-Ogden follows its fibre family 1;
// - Fg with det <= 0 at the point is an InputError naming the entry and the
//   place; so is a list of the wrong length.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/materials/grown.h>
#include <hyperelastic/materials/material_registry.h>

#include "support/checker.h"

#include <cmath>
#include <string>

using namespace hyperelastic;
using dealii::Point;

namespace
{
  /// The growth entries of each kind.
  std::vector<std::pair<std::string, GrowthParameters>>
  growth_kinds()
  {
    GrowthParameters isotropic;
    isotropic.kind    = GrowthParameters::Kind::isotropic;
    isotropic.stretch = "1 + 0.2 * t";
    GrowthParameters fibre;
    fibre.kind      = GrowthParameters::Kind::fibre;
    fibre.along     = "1.3";
    fibre.across    = "0.9 + 0.1 * y";
    fibre.direction = "1; 2; 2 * t";
    GrowthParameters tensor;
    tensor.kind   = GrowthParameters::Kind::tensor;
    tensor.tensor = "1.1 + 0.1 * x; 0.1; 0.05; -0.05; 0.95; 0.1 * t; "
                    "0.02; -0.1; 1.2 + z";
    return {{"isotropic", isotropic}, {"fibre", fibre}, {"tensor", tensor}};
  }

  template <int dim>
  Tensor<2, dim>
  deformation()
  {
    const double   values[3][3] = {{1.12, 0.08, -0.05},
                                   {-0.06, 0.93, 0.11},
                                   {0.04, -0.07, 1.05}};
    Tensor<2, dim> F;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        F[i][j] = values[i][j];
    return F;
  }

  /// Worst relative errors of dP/dF against differences of P and of P
  /// against differences of psi, at F.
  template <int dim>
  std::pair<double, double>
  finite_difference_errors(const Material<dim> &m, const Tensor<2, dim> &F)
  {
    const double       h = 1e-6;
    StressTangent<dim> A;
    Tensor<2, dim>     P;
    m.stress_and_tangent(F, P, A);
    double tangent = 0., stress = 0.;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int L = 0; L < dim; ++L)
        {
          Tensor<2, dim> Fp = F, Fm = F;
          Fp[k][L] += h;
          Fm[k][L] -= h;
          const Tensor<2, dim> dP =
            (m.first_piola_kirchhoff(Fp) - m.first_piola_kirchhoff(Fm)) /
            (2. * h);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int J = 0; J < dim; ++J)
              tangent = std::max(tangent, std::abs(dP[i][J] - A[i][J][k][L]));
          const double dpsi =
            (m.energy_density(Fp) - m.energy_density(Fm)) / (2. * h);
          stress = std::max(stress, std::abs(dpsi - P[k][L]));
        }
    return {tangent / A.norm(), stress / P.norm()};
  }

  template <int dim>
  std::unique_ptr<Material<dim>>
  grown_at_point(const std::string &model, const GrowthParameters &growth)
  {
    LameParameters lame;
    lame.mu     = 1.;
    lame.lambda = 2.;
    const Grown<dim> scene_model(
      GrowthConstants{material_model(model).from_small_strain(lame),
                      growth,
                      "Material"});
    scene_model.set_load_factor(0.75);
    Point<dim> X;
    for (unsigned int d = 0; d < dim; ++d)
      X[d] = 0.3 - 0.1 * d;
    return scene_model.at_position(X);
  }

  template <int dim>
  void
  check_model(testing::Checker &check, const std::string &model)
  {
    for (const auto &[kind, growth] : growth_kinds())
      {
        const auto  m     = grown_at_point<dim>(model, growth);
        const auto  F     = deformation<dim>();
        const auto  error = finite_difference_errors(*m, F);
        const auto *grows = dynamic_cast<const GrowingMaterial *>(m.get());
        const std::string what =
          model + ", " + kind + ", " + std::to_string(dim) + "D: ";
        check.at_most(what + "dP/dF against differences of P", error.first, 1e-7);
        check.at_most(what + "P against differences of psi", error.second, 1e-7);
        const Tensor<2, 3> Fg = grows->growth_tensor();
        if constexpr (dim == 3)
          {
            const double mu = m->small_strain_moduli().mu;
            check.at_most(what + "|P(Fg)| (stress-free grown state)",
                          m->first_piola_kirchhoff(Fg).norm() / mu,
                          1e-12);
            check.at_most(what + "|psi(Fg)|",
                          std::abs(m->energy_density(Fg)) / mu,
                          1e-12);
          }
        else
          {
            Tensor<2, 3> F3;
            F3[2][2] = 1.;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                F3[i][j] = F[i][j];
            const Tensor<2, 3> P3 =
              m->three_dimensional_twin()->first_piola_kirchhoff(F3);
            const Tensor<2, dim> P = m->first_piola_kirchhoff(F);
            double               worst = 0.;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                worst = std::max(worst, std::abs(P3[i][j] - P[i][j]));
            check.at_most(what + "P = in-plane block of the 3D twin's P",
                          worst / P.norm(),
                          1e-14);
          }
      }
  }

  /// The InputError message of @p f, empty if it throws none.
  template <typename F>
  std::string
  input_error_of(F &&f)
  {
    try
      {
        f();
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace

int
main()
{
  testing::Checker check;
  check.section("tangent and stress against differences, stress-free at "
                "F = Fg, every model and growth kind");
  for (const MaterialModel &m : material_models())
    {
      check_model<3>(check, m.name);
      check_model<2>(check, m.name);
    }

  check.section("fibre growth follows the model's fibre family 1");
  {
    GrowthParameters fibre;
    fibre.kind   = GrowthParameters::Kind::fibre;
    fibre.along  = "1.4";
    fibre.across = "0.8";
    // 'Growth direction' (x) is not used: the model has its own fibres.
    const auto m = grown_at_point<3>("Holzapfel-Gasser-Ogden", fibre);
    const Tensor<2, 3> Fg =
      dynamic_cast<const GrowingMaterial &>(*m).growth_tensor();
    LameParameters lame;
    lame.mu     = 1.;
    lame.lambda = 2.;
    const auto hgo =
      material_model("Holzapfel-Gasser-Ogden").from_small_strain(lame).create<3>();
    const Tensor<1, 3> f =
      dynamic_cast<const FibreFamilies &>(*hgo).fibre_directions()[0];
    Tensor<2, 3> expected = 0.8 * dealii::unit_symmetric_tensor<3>();
    expected += 0.6 * outer_product(f, f);
    check.at_most("Fg = 0.8 I + 0.6 a a, a the model's fibre",
                  (Fg - expected).norm(),
                  1e-15);
  }

  check.section("inadmissible growth is an input error");
  {
    GrowthParameters inverted;
    inverted.kind   = GrowthParameters::Kind::tensor;
    inverted.tensor = "1; 0; 0; 0; 1; 0; 0; 0; 1 - 2 * t";
    const auto        m = grown_at_point<3>("neo-Hookean", inverted);
    const std::string message = input_error_of(
      [&] { dynamic_cast<const GrowingMaterial &>(*m).growth_tensor(); });
    check.is_true("det Fg = -0.5 at t = 0.75: '" + message + "'",
                  message.find("'Material/Growth tensor'") != std::string::npos &&
                    message.find("det Fg = -0.5") != std::string::npos &&
                    message.find("t = 0.75") != std::string::npos);
    GrowthParameters short_list = inverted;
    short_list.tensor           = "1; 0; 0; 0; 1; 0; 0; 0";
    const std::string list_message =
      input_error_of([&] { GrowthLaw(short_list, "Region 2/Material"); });
    check.is_true("eight expressions: '" + list_message + "'",
                  list_message.find("'Region 2/Material/Growth tensor'") !=
                      std::string::npos &&
                    list_message.find("needs 9 expressions") !=
                      std::string::npos);
  }
  return check.exit_code(0);
}
