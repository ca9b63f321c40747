// Homogeneous uniaxial tension and compression of the rubber models of issue
// 29: those whose isochoric energy depends on Ib = J^(-2/3) I1 alone (Yeoh,
// Gent, Arruda-Boyce; materials/first_invariant_model.h) and Ogden (on the
// isochoric principal stretches; materials/ogden.h). The bar [0,3] x [0,1]
// (x [0,1]) on symmetry rollers (x = 0, y = 0, z = 0) has its end x = 3
// moved to the stretch l1 (1.6 and 0.6) in 4 load steps; the lateral faces
// are free, so the state is homogeneous. The lateral stretch (deformed
// y-extent) and the end reaction (P11 times the unit end area) are checked
// against the model's own one-dimensional equilibrium, solved here by
// bisection from W'(Ib) or Ogden's principal stresses written out
// independently of the material classes (1e-10).
//   rubber_models DIM MODEL            displacement formulation
//   rubber_models DIM equal_stretches  Ogden's dP/dF and P where principal
//                                      stretches coincide, against central
//                                      differences (1e-7), and at F = I
//   rubber_models DIM MODEL mixed      Bulk modulus = inf, mixed formulation
//                                      (P1-bubble/P1): J = 1 exactly, l2 =
//                                      l1^(-1/2) (3D) or 1/l1 (2D), P11 =
//                                      2 W'(Ib) (l1^2 - l2^2) / l1.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/materials/ogden.h>

#include "support/analytic_bar.h"
#include "support/checker.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace
{
  using namespace dealii;
  using namespace hyperelastic;
  using namespace hyperelastic::testing;

  /// A model's constants as scene entries and its exact uniaxial state
  /// (dim, l1, kappa), written out from the formulas of the issue.
  struct RubberModel
  {
    std::string                                       entries;
    std::function<UniaxialState(int, double, double)> exact;
  };

  /// From W'(Ib) (NaN where the chains lock).
  std::function<UniaxialState(int, double, double)>
  first_invariant(const std::function<double(double)> &W1)
  {
    return [W1](const int dim, const double l1, const double kappa) {
      return uniaxial_first_invariant(dim, l1, W1, kappa);
    };
  }

  /// Ogden: l_a P_aa = sum_p mu_p (lb_a^alpha_p - 1/3 sum_b lb_b^alpha_p)
  /// + kappa/2 (J^2 - 1), lb_b = J^(-1/3) l_b, P22 = 0 by bisection;
  /// incompressible: P11 = sum_p mu_p (l1^alpha_p - l2^alpha_p) / l1.
  UniaxialState
  uniaxial_ogden(const int                    dim,
                 const double                 l1,
                 const std::array<double, 3> &mu,
                 const std::array<double, 3> &alpha,
                 const double                 kappa)
  {
    const auto l3 = [&](const double l2) { return dim == 3 ? l2 : 1.; };
    if (std::isinf(kappa))
      {
        const double l2  = dim == 3 ? 1. / std::sqrt(l1) : 1. / l1;
        double       P11 = 0.;
        for (int p = 0; p < 3; ++p)
          P11 += mu[p] * (std::pow(l1, alpha[p]) - std::pow(l2, alpha[p]));
        return {l2, P11 / l1};
      }
    const auto stretch_term = [&](const double l2, const double la) {
      const double J = l1 * l2 * l3(l2), c = std::cbrt(J);
      double       sum = 0.5 * kappa * (J * J - 1.);
      for (int p = 0; p < 3; ++p)
        sum +=
          mu[p] * (std::pow(la / c, alpha[p]) -
                   (std::pow(l1 / c, alpha[p]) + std::pow(l2 / c, alpha[p]) +
                    std::pow(l3(l2) / c, alpha[p])) /
                     3.);
      return sum;
    };
    const double l2 =
      bisect([&](const double l2) { return stretch_term(l2, l2); }, 1e-3, 10.);
    return {l2, stretch_term(l2, l1) / l1};
  }

  RubberModel
  rubber_model(const std::string &name, const std::string &kappa)
  {
    if (name == "Yeoh")
      {
        const double c10 = 0.5, c20 = -0.05, c30 = 0.01;
        return {entry("C10", "0.5") + entry("C20", "-0.05") +
                  entry("C30", "0.01") + entry("Bulk modulus", kappa),
                first_invariant([=](const double Ib) {
                  const double x = Ib - 3.;
                  return c10 + 2. * c20 * x + 3. * c30 * x * x;
                })};
      }
    if (name == "Gent")
      {
        const double mu = 1., jm = 5.;
        return {entry("Shear modulus", "1") + entry("Jm", "5") +
                  entry("Bulk modulus", kappa),
                first_invariant([=](const double Ib) {
                  const double room = 1. - (Ib - 3.) / jm;
                  return room > 0. ? 0.5 * mu / room
                                   : std::numeric_limits<double>::quiet_NaN();
                })};
      }
    if (name == "Arruda-Boyce")
      {
        const double mu = 1., lm = 2.5;
        const double c[5] = {
          0.5, 0.05, 11. / 1050., 19. / 7000., 519. / 673750.};
        return {entry("Shear modulus", "1") + entry("Locking stretch", "2.5") +
                  entry("Bulk modulus", kappa),
                first_invariant([=](const double Ib) {
                  double W1 = 0.;
                  for (int i = 1; i <= 5; ++i)
                    W1 += mu * c[i - 1] * i * std::pow(lm, 2. - 2. * i) *
                          std::pow(Ib, i - 1.);
                  return W1;
                })};
      }
    if (name == "Ogden")
      {
        // Ogden's three-term fit of Treloar's data (MPa).
        const std::array<double, 3> mu    = {{0.63, 0.0012, -0.01}};
        const std::array<double, 3> alpha = {{1.3, 5., -2.}};
        return {entry("mu1", "0.63") + entry("alpha1", "1.3") +
                  entry("mu2", "0.0012") + entry("alpha2", "5") +
                  entry("mu3", "-0.01") + entry("alpha3", "-2") +
                  entry("Bulk modulus", kappa),
                [=](const int dim, const double l1, const double kappa) {
                  return uniaxial_ogden(dim, l1, mu, alpha, kappa);
                }};
      }
    throw InputError("unknown model '" + name + "'");
  }

  template <int dim>
  void
  uniaxial(Checker &checker, const std::string &model, const bool mixed)
  {
    const RubberModel law   = rubber_model(model, mixed ? "inf" : "5");
    const double kappa = mixed ? std::numeric_limits<double>::infinity() : 5.;
    for (const double l1 : {1.6, 0.6})
      {
        const std::string tag = std::to_string(dim) + "D " + model +
                                (mixed ? " (mixed, incompressible)" : "") +
                                ", l1 = " + std::to_string(l1) + ": ";
        const std::string scene =
          rollered_bar_stretch(dim, model, law.entries, l1, mixed);
        const auto          problem = run_scene<dim>(scene);
        const auto         &last    = problem->summaries().back();
        const UniaxialState exact   = law.exact(dim, l1, kappa);
        checker.is_true(tag + "reaches t = 1", last.load_factor == 1.);
        checker.close(tag + "lateral stretch",
                      column(last, "deformed_max_y"),
                      exact.l2,
                      1.,
                      1e-10);
        checker.close(tag + "end reaction = P11",
                      column(last, "reaction_1_x"),
                      exact.P11,
                      std::abs(exact.P11),
                      1e-10);
      }
  }

  /// Ogden's tangent where principal stretches coincide (the eigenvectors
  /// of C are not unique there): dP/dF against central differences of P,
  /// P against central differences of psi (1e-7 of the largest entry), and
  /// F = I against the small-strain tensor (1e-12).
  template <int dim>
  void
  equal_stretches(Checker &checker)
  {
    OgdenConstants constants;
    constants.mu    = {{0.63, 0.0012, -0.01}};
    constants.alpha = {{1.3, 5., -2.}};
    constants.kappa = 5.;
    const Ogden<dim> model(constants);
    // A rotation about (1, 2, 3) by 0.7 (its 2D block in 2D).
    Tensor<2, 3> R;
    {
      const double angle = 0.7;
      Tensor<1, 3> a({1., 2., 3.});
      a /= a.norm();
      const double c = std::cos(angle), s = std::sin(angle);
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          R[i][j] = (i == j ? c : 0.) + (1. - c) * a[i] * a[j];
      R[0][1] -= s * a[2], R[1][0] += s * a[2];
      R[0][2] += s * a[1], R[2][0] -= s * a[1];
      R[1][2] -= s * a[0], R[2][1] += s * a[0];
    }
    const auto diagonal = [&](const std::array<double, 3> &l,
                              const bool                   rotate) {
      Tensor<2, 3> D;
      for (unsigned int i = 0; i < 3; ++i)
        D[i][i] = l[i];
      const Tensor<2, 3> F3 = rotate ? R * D * transpose(R) : D;
      Tensor<2, dim>     F;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F[i][j] = F3[i][j];
      return F;
    };
    // In 2D the third stretch is 1: l = (1.3, 1.3) and (1, 1.4) make two
    // equal, a rotation only mixes the in-plane pair.
    std::vector<std::pair<std::string, Tensor<2, dim>>> cases;
    if (dim == 3)
      {
        cases = {{"(1.2, 1.2, 0.8)", diagonal({{1.2, 1.2, 0.8}}, false)},
                 {"(1.1, 1.1, 1.1)", diagonal({{1.1, 1.1, 1.1}}, false)},
                 {"R (1.3, 0.9, 0.9) R^T", diagonal({{1.3, 0.9, 0.9}}, true)},
                 {"(1.2, 1.2 + 1e-9, 0.8)",
                  diagonal({{1.2, 1.2 + 1e-9, 0.8}}, false)}};
      }
    else
      {
        Tensor<2, dim> rotated;
        const double   c = std::cos(0.7), s = std::sin(0.7);
        const double   l[2] = {1.3, 1.3};
        rotated[0][0]       = c * c * l[0] + s * s * l[1];
        rotated[1][1]       = s * s * l[0] + c * c * l[1];
        cases = {{"(1.3, 1.3, 1)", diagonal({{1.3, 1.3, 1.}}, false)},
                 {"(1, 1.4, 1)", diagonal({{1., 1.4, 1.}}, false)},
                 {"rotated (1.3, 1.3, 1)", rotated},
                 {"(1.3, 1.3 + 1e-9, 1)",
                  diagonal({{1.3, 1.3 + 1e-9, 1.}}, false)}};
      }
    const double h = 1e-6;
    for (const auto &[label, F] : cases)
      {
        const std::string  tag = std::to_string(dim) + "D Ogden at " + label;
        Tensor<2, dim>     P;
        StressTangent<dim> A;
        model.stress_and_tangent(F, P, A);
        double tangent_error = 0., largest_A = 0., stress_error = 0.,
               largest_P = 0.;
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int L = 0; L < dim; ++L)
            {
              Tensor<2, dim> Fp = F, Fm = F;
              Fp[k][L] += h, Fm[k][L] -= h;
              const Tensor<2, dim> dP = (model.first_piola_kirchhoff(Fp) -
                                         model.first_piola_kirchhoff(Fm)) /
                                        (2. * h);
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int J = 0; J < dim; ++J)
                  {
                    tangent_error =
                      std::max(tangent_error,
                               std::abs(A[i][J][k][L] - dP[i][J]));
                    largest_A = std::max(largest_A, std::abs(A[i][J][k][L]));
                  }
              const double dpsi =
                (model.energy_density(Fp) - model.energy_density(Fm)) /
                (2. * h);
              stress_error = std::max(stress_error, std::abs(P[k][L] - dpsi));
              largest_P    = std::max(largest_P, std::abs(P[k][L]));
            }
        checker.at_most(tag + ": |dP/dF - central differences of P| / "
                              "largest",
                        tangent_error / largest_A,
                        1e-7);
        checker.at_most(tag + ": |P - central differences of psi| / largest",
                        stress_error / largest_P,
                        1e-7);
      }
    // Rest state: stress free, the small-strain tensor of mu = 1/2 sum
    // mu_p alpha_p, lambda = kappa - 2 mu / 3.
    const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
    LameParameters       lame;
    lame.mu     = 0.5 * (0.63 * 1.3 + 0.0012 * 5. + 0.01 * 2.);
    lame.lambda = 5. - 2. / 3. * lame.mu;
    const StressTangent<dim> rest  = model.stress_tangent(I);
    const StressTangent<dim> small = linear_elastic_tangent<dim>(lame);
    checker.at_most(std::to_string(dim) + "D Ogden at F = I: |P|",
                    model.first_piola_kirchhoff(I).norm(),
                    1e-14);
    checker.at_most(std::to_string(dim) +
                      "D Ogden at F = I: |dP/dF - small-strain tensor| / |.|",
                    (rest - small).norm() / small.norm(),
                    1e-12);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Checker   checker(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  const int dim            = argc > 1 ? std::atoi(argv[1]) : 2;
  const std::string model  = argc > 2 ? argv[2] : "";
  const bool        mixed  = argc > 3 && std::string(argv[3]) == "mixed";
  const int         status = run_and_report(
    [&]() {
      if (model == "equal_stretches")
        dim == 2 ? equal_stretches<2>(checker) : equal_stretches<3>(checker);
      else
        dim == 2 ? uniaxial<2>(checker, model, mixed)
                         : uniaxial<3>(checker, model, mixed);
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
