// Holzapfel-Gasser-Ogden with dispersion (issue 29;
// materials/holzapfel_gasser_ogden.h).
//   fibre_models DIM material   the model itself, two families at
//       (+-30 degrees, out of plane in 3D), k1 = 2, k2 = 0.8, kd = 0 and
//       0.2, on random F with J in [0.4, 2.5] away from the switches
//       I4 = 1: P against central differences of psi and dP/dF against
//       central differences of P (1e-6 of the largest entry); objectivity
//       psi(QF) = psi(F), P(QF) = Q P(F) (1e-12); the rest state (P = 0,
//       dP/dF the matrix's small-strain tensor); a compressed fibre
//       (I4 <= 1) adds nothing (the matrix alone, k1 = 0, to round-off);
//       plane strain = the 3D twin at diag(F, 1); directions that depend
//       on x, y, z evaluated and normalised at a point.
//   fibre_models DIM CASE [mixed]  homogeneous uniaxial stretch of the bar
//       [0,3] x [0,1] (x [0,1]) on symmetry rollers, end x = 3 moved to
//       l1 in 4 load steps: the lateral stretches (deformed y- and
//       z-extent) and the end reaction P11 against the one-dimensional
//       equilibrium written out here (1e-10):
//         along     fibres along x, kd = 0.2, l1 = 1.3 and 0.8 (off in
//                   compression); 3D: l2 = l3 by symmetry;
//         across    fibres along y, l1 = 1.3: I4 = l2^2 < 1, the matrix
//                   alone (decoupled neo-Hookean);
//         families  two families at +-30 degrees in the x-y plane, kd =
//                   0.1, l1 = 1.3: F stays diagonal by symmetry, l2 != l3
//                   in 3D (nested bisection);
//         position  'along' with the direction given as "x; 0; 0", which
//                   depends on x and is e_x after normalisation: the
//                   per-quadrature-point path gives the same numbers;
//       mixed: Bulk modulus = inf (P1-bubble/P1), J = 1, along only.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/materials/holzapfel_gasser_ogden.h>

#include "support/analytic_bar.h"
#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>

namespace
{
  using namespace dealii;
  using namespace hyperelastic;
  using namespace hyperelastic::testing;

  constexpr double mu = 1., kappa = 5.;

  HolzapfelGasserOgdenConstants
  constants(const double       k1,
            const double       k2,
            const double       kd,
            const std::string &direction_1,
            const std::string &direction_2,
            const double       bulk = kappa)
  {
    HolzapfelGasserOgdenConstants c;
    c.mu                = mu;
    c.k1                = k1;
    c.k2                = k2;
    c.kd                = kd;
    c.kappa             = bulk;
    c.direction_text[0] = direction_1;
    c.direction_text[1] = direction_2;
    c.parse_directions("Material/Holzapfel-Gasser-Ogden");
    return c;
  }

  /// The largest |entry| of a tensor.
  template <int rank, int dim>
  double
  largest(const Tensor<rank, dim> &T)
  {
    double m = 0.;
    for (unsigned int i = 0; i < T.n_independent_components; ++i)
      m = std::max(m, std::abs(T[T.unrolled_to_component_indices(i)]));
    return m;
  }

  template <int dim>
  void
  material(Checker &checker)
  {
    const std::string tag = std::to_string(dim) + "D HGO: ";
    // Unit directions at +-30 degrees (3D: tilted out of plane).
    const std::string d1 =
      dim == 2 ? "cos(pi/6); sin(pi/6); 0" : "cos(pi/6); sin(pi/6); 0.4";
    const std::string d2 =
      dim == 2 ? "cos(pi/6); -sin(pi/6); 0" : "cos(pi/6); -sin(pi/6); -0.2";
    std::mt19937                           random(29);
    std::uniform_real_distribution<double> entry(-0.45, 0.45);
    for (const double kd : {0., 0.2})
      {
        const auto                      c = constants(2., 0.8, kd, d1, d2);
        const HolzapfelGasserOgden<dim> model(c);
        const auto                      a = c.directions.at(Point<3>(), dim);
        const std::string row     = tag + "kd = " + std::to_string(kd) + ", ";
        double       stress_error = 0., tangent_error = 0., objectivity = 0.;
        int          samples = 0, active = 0;
        const double h = 1e-6;
        while (samples < 200)
          {
            Tensor<2, dim> F;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                F[i][j] = (i == j ? 1. : 0.) + entry(random);
            const double J = determinant(F);
            if (J < 0.4 || J > 2.5)
              continue;
            // Away from the switches (finite differences would cross them).
            bool near_switch = false;
            int  on          = 0;
            for (const auto &a3 : a)
              {
                Tensor<1, dim> ad;
                for (unsigned int d = 0; d < dim; ++d)
                  ad[d] = a3[d];
                const double I4 = (F * ad) * (F * ad);
                near_switch     = near_switch || std::abs(I4 - 1.) < 1e-3;
                on += I4 > 1.;
              }
            if (near_switch)
              continue;
            ++samples;
            active += on > 0;
            Tensor<2, dim>     P;
            StressTangent<dim> A;
            model.stress_and_tangent(F, P, A);
            const double scale_P = largest(P), scale_A = largest(A);
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int L = 0; L < dim; ++L)
                {
                  Tensor<2, dim> Fp = F, Fm = F;
                  Fp[k][L] += h, Fm[k][L] -= h;
                  const double dpsi =
                    (model.energy_density(Fp) - model.energy_density(Fm)) /
                    (2. * h);
                  stress_error =
                    std::max(stress_error, std::abs(P[k][L] - dpsi) / scale_P);
                  const Tensor<2, dim> dP = (model.first_piola_kirchhoff(Fp) -
                                             model.first_piola_kirchhoff(Fm)) /
                                            (2. * h);
                  for (unsigned int i = 0; i < dim; ++i)
                    for (unsigned int J_ = 0; J_ < dim; ++J_)
                      tangent_error =
                        std::max(tangent_error,
                                 std::abs(A[i][J_][k][L] - dP[i][J_]) /
                                   scale_A);
                }
            // A rotation Q: psi(QF) = psi(F), P(QF) = Q P(F).
            Tensor<2, dim> Q;
            const double   angle = 0.3 + samples * 0.01;
            Q[0][0] = Q[1][1] = std::cos(angle);
            Q[0][1]           = -std::sin(angle);
            Q[1][0]           = std::sin(angle);
            if (dim == 3)
              Q[dim - 1][dim - 1] = 1.;
            objectivity = std::max(
              {objectivity,
               std::abs(model.energy_density(Q * F) - model.energy_density(F)) /
                 std::max(1., std::abs(model.energy_density(F))),
               (model.first_piola_kirchhoff(Q * F) - Q * P).norm() / P.norm()});
          }
        checker.at_least(row + "samples with a stretched family", active, 50);
        checker.at_most(row + "|P - central differences of psi| / largest",
                        stress_error,
                        1e-6);
        checker.at_most(row + "|dP/dF - central differences of P| / largest",
                        tangent_error,
                        1e-6);
        checker.at_most(row + "objectivity", objectivity, 1e-12);

        // Rest state: the matrix's small-strain tensor.
        const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
        LameParameters       lame;
        lame.mu     = mu;
        lame.lambda = kappa - 2. / 3. * mu;
        checker.at_most(row + "|P(I)|",
                        model.first_piola_kirchhoff(I).norm(),
                        1e-14);
        checker.at_most(
          row + "|dP/dF(I) - small-strain tensor| / |.|",
          (model.stress_tangent(I) - linear_elastic_tangent<dim>(lame)).norm() /
            linear_elastic_tangent<dim>(lame).norm(),
          1e-14);
        checker.close(row + "small_strain_moduli().mu",
                      model.small_strain_moduli().mu,
                      mu,
                      1.,
                      1e-15);

        // Both families compressed (F = diag(0.9, 0.95, 1.02)): the matrix.
        Tensor<2, dim> Fc;
        Fc[0][0] = 0.9, Fc[1][1] = 0.95;
        if (dim == 3)
          Fc[2][2] = 1.02;
        const HolzapfelGasserOgden<dim> matrix(constants(0., 0.8, kd, d1, d2));
        checker.at_most(row + "compressed fibres: |P - P_matrix| / |P|",
                        (model.first_piola_kirchhoff(Fc) -
                         matrix.first_piola_kirchhoff(Fc))
                            .norm() /
                          matrix.first_piola_kirchhoff(Fc).norm(),
                        1e-15);
        checker.at_most(row + "compressed fibres: psi - psi_matrix",
                        std::abs(model.energy_density(Fc) -
                                 matrix.energy_density(Fc)),
                        1e-15);

        // Plane strain: the 3D twin at diag(F, 1).
        if constexpr (dim == 2)
          {
            const auto     twin = model.three_dimensional_twin();
            Tensor<2, dim> F;
            F[0][0] = 1.25, F[0][1] = 0.2, F[1][0] = -0.1, F[1][1] = 0.9;
            Tensor<2, 3> F3;
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j < 2; ++j)
                F3[i][j] = F[i][j];
            F3[2][2]               = 1.;
            const Tensor<2, 3> P3  = twin->first_piola_kirchhoff(F3);
            const Tensor<2, 2> P2  = model.first_piola_kirchhoff(F);
            double             gap = 0.;
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j < 2; ++j)
                gap = std::max(gap, std::abs(P3[i][j] - P2[i][j]));
            checker.at_most(row + "plane strain = 3D twin: |P2 - P3| / |P|",
                            gap / P2.norm(),
                            1e-14);
            checker.close(row + "plane strain = 3D twin: psi",
                          model.energy_density(F),
                          twin->energy_density(F3),
                          1.,
                          1e-14);
          }
      }

    // Directions depending on position: evaluated and normalised there.
    const auto c = constants(2., 0.8, 0., "2*cos(x); 2*sin(x); 0", "");
    const HolzapfelGasserOgden<dim> field(c);
    checker.is_true(tag + "expressions of x: depends_on_position()",
                    field.depends_on_position());
    checker.is_true(tag + "constant expressions: !depends_on_position()",
                    !HolzapfelGasserOgden<dim>(constants(2., 0.8, 0., d1, d2))
                       .depends_on_position());
    Point<dim> X;
    X[0]                                  = 0.7;
    const auto                      there = field.at_position(X);
    const HolzapfelGasserOgden<dim> fixed(
      constants(2., 0.8, 0., "cos(0.7); sin(0.7); 0", ""));
    Tensor<2, dim> F = unit_symmetric_tensor<dim>();
    F[0][0] = 1.2, F[0][1] = 0.1;
    checker.at_most(tag + "at_position(x = 0.7) = fixed direction (cos 0.7, "
                          "sin 0.7): |P - P_fixed| / |P|",
                    (there->first_piola_kirchhoff(F) -
                     fixed.first_piola_kirchhoff(F))
                        .norm() /
                      fixed.first_piola_kirchhoff(F).norm(),
                    1e-15);
  }

  /// The uniaxial cases' one-dimensional equilibrium, with the matrix
  /// term of each principal direction
  ///   m(l_b) = mu J^(-2/3) (l_b^2 - I1/3) + kappa/2 (J^2 - 1)
  /// and a family of direction a adding psi_f'(E) (2 kd l_b^2 + 2 (1 - 3
  /// kd) (l_b a_b)^2) to l_b P_bb while I4 > 1; psi_f' = k1 E exp(k2 E^2).
  struct Uniaxial
  {
    double k1, k2, kd;
    /// In-plane components (cos, sin) of each family.
    std::vector<std::array<double, 2>> families;
    double                             bulk;

    /// l_b P_bb for the stretches l (l[2] = 1 in plane strain).
    double
    stress_term(const std::array<double, 3> &l, const unsigned int b) const
    {
      const double J  = l[0] * l[1] * l[2];
      const double I1 = l[0] * l[0] + l[1] * l[1] + l[2] * l[2];
      double       t  = mu * std::pow(J, -2. / 3.) * (l[b] * l[b] - I1 / 3.) +
                 0.5 * bulk * (J * J - 1.);
      for (const auto &a : families)
        {
          const double I4 =
            l[0] * l[0] * a[0] * a[0] + l[1] * l[1] * a[1] * a[1];
          if (!(I4 > 1.))
            continue;
          const double E     = kd * (I1 - 3.) + (1. - 3. * kd) * (I4 - 1.);
          const double first = k1 * E * std::exp(k2 * E * E);
          const double ab    = b < 2 ? a[b] : 0.;
          t += first * (2. * kd * l[b] * l[b] +
                        2. * (1. - 3. * kd) * l[b] * l[b] * ab * ab);
        }
      return t;
    }

    /// The lateral stretches (l2, l3) with l_2 P_22 = l_3 P_33 = 0 (l3 =
    /// 1 in plane strain); P11.
    std::array<double, 3>
    solve(const int dim, const double l1) const
    {
      const auto l3_for = [&](const double l2) {
        if (dim == 2)
          return 1.;
        return bisect(
          [&](const double l3) {
            return stress_term({{l1, l2, l3}}, 2);
          },
          0.2,
          3.);
      };
      const double l2 = bisect(
        [&](const double l2) {
          return stress_term({{l1, l2, l3_for(l2)}}, 1);
        },
        0.2,
        3.);
      const double l3 = l3_for(l2);
      return {{l2, l3, stress_term({{l1, l2, l3}}, 0) / l1}};
    }
  };

  template <int dim>
  void
  uniaxial(Checker &checker, const std::string &name, const bool mixed)
  {
    const bool   three = dim == 3;
    const double bulk = mixed ? std::numeric_limits<double>::infinity() : kappa;
    std::string  d1   = "1; 0; 0", d2;
    Uniaxial     law{1., 2., 0.2, {{{1., 0.}}}, bulk};
    std::vector<double> stretches = {1.3, 0.8};
    if (name == "position")
      d1 = "x; 0; 0";
    else if (name == "across")
      {
        d1           = "0; 1; 0";
        law.families = {{{0., 1.}}};
        stretches    = {1.3};
      }
    else if (name == "families")
      {
        const double c = std::cos(M_PI / 6.), s = std::sin(M_PI / 6.);
        d1           = "cos(pi/6); sin(pi/6); 0";
        d2           = "cos(pi/6); -sin(pi/6); 0";
        law.kd       = 0.1;
        law.families = {{{c, s}}, {{c, -s}}};
        stretches    = {1.3};
      }
    else if (name != "along")
      throw InputError("unknown case '" + name + "'");
    for (const double l1 : stretches)
      {
        const std::string tag = std::to_string(dim) + "D HGO " + name +
                                (mixed ? " (mixed, incompressible)" : "") +
                                ", l1 = " + std::to_string(l1) + ": ";
        const std::string model = "Holzapfel-Gasser-Ogden";
        const std::string scene =
          rollered_bar_stretch(dim,
                               model,
                               entry("Shear modulus", "1") + entry("k1", "1") +
                                 entry("k2", "2") +
                                 entry("Dispersion", std::to_string(law.kd)) +
                                 entry("Fibre direction 1", d1) +
                                 entry("Fibre direction 2", d2) +
                                 entry("Bulk modulus", mixed ? "inf" : "5"),
                               l1,
                               mixed);
        const auto            problem = run_scene<dim>(scene);
        const auto           &last    = problem->summaries().back();
        std::array<double, 3> exact;
        if (mixed)
          {
            // J = 1: l2 = l3 = l1^(-1/2) (3D) or l2 = 1/l1; the pressure
            // cancels l2 P22, leaving l1 P11 = t(l1) - t(l2) with the
            // volumetric part dropped.
            const double l2         = three ? 1. / std::sqrt(l1) : 1. / l1;
            const double l3         = three ? l2 : 1.;
            Uniaxial     deviatoric = law;
            deviatoric.bulk         = 0.;
            exact                   = {{l2,
                                        l3,
                                        (deviatoric.stress_term({{l1, l2, l3}}, 0) -
                       deviatoric.stress_term({{l1, l2, l3}}, 1)) /
                                          l1}};
          }
        else
          exact = law.solve(dim, l1);
        checker.is_true(tag + "reaches t = 1", last.load_factor == 1.);
        checker.close(tag + "lateral stretch l2",
                      column(last, "deformed_max_y"),
                      exact[0],
                      1.,
                      1e-10);
        if (three)
          checker.close(tag + "lateral stretch l3",
                        column(last, "deformed_max_z"),
                        exact[1],
                        1.,
                        1e-10);
        checker.close(tag + "end reaction = P11",
                      column(last, "reaction_1_x"),
                      exact[2],
                      std::abs(exact[2]),
                      1e-10);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_for_dimension(
    argc, argv, 1, [&](const int dim, Checker &checker, bool) {
      const std::string name  = argc > 2 ? argv[2] : "";
      const bool        mixed = argc > 3 && std::string(argv[3]) == "mixed";
      if (name == "material")
        dim == 2 ? material<2>(checker) : material<3>(checker);
      else
        dim == 2 ? uniaxial<2>(checker, name, mixed)
                 : uniaxial<3>(checker, name, mixed);
    });
}
