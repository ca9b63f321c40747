// Homogeneous uniaxial tension and compression of the rubber models whose
// isochoric energy depends on Ib = J^(-2/3) I1 alone (issue 29: Yeoh, Gent,
// Arruda-Boyce; materials/first_invariant_model.h). The bar [0,3] x [0,1]
// (x [0,1]) on symmetry rollers (x = 0, y = 0, z = 0) has its end x = 3
// moved to the stretch l1 (1.6 and 0.6) in 4 load steps; the lateral faces
// are free, so the state is homogeneous. The lateral stretch (deformed
// y-extent) and the end reaction (P11 times the unit end area) are checked
// against the model's own one-dimensional equilibrium, solved here by
// bisection from W'(Ib) written out independently of the material classes
// (1e-10).
//   rubber_models DIM MODEL            displacement formulation
//   rubber_models DIM MODEL mixed      Bulk modulus = inf, mixed formulation
//                                      (P1-bubble/P1): J = 1 exactly, l2 =
//                                      l1^(-1/2) (3D) or 1/l1 (2D), P11 =
//                                      2 W'(Ib) (l1^2 - l2^2) / l1.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>

#include "support/analytic_bar.h"
#include "support/checker.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace
{
  using namespace dealii;
  using namespace hyperelastic;
  using namespace hyperelastic::testing;

  /// A model's constants as scene entries and its W'(Ib) (NaN where the
  /// chains lock), written out from the formulas of the issue.
  struct RubberModel
  {
    std::string                   entries;
    std::function<double(double)> W1;
  };

  RubberModel
  rubber_model(const std::string &name, const std::string &kappa)
  {
    if (name == "Yeoh")
      {
        const double c10 = 0.5, c20 = -0.05, c30 = 0.01;
        return {entry("C10", "0.5") + entry("C20", "-0.05") +
                  entry("C30", "0.01") + entry("Bulk modulus", kappa),
                [=](const double Ib) {
                  const double x = Ib - 3.;
                  return c10 + 2. * c20 * x + 3. * c30 * x * x;
                }};
      }
    if (name == "Gent")
      {
        const double mu = 1., jm = 5.;
        return {entry("Shear modulus", "1") + entry("Jm", "5") +
                  entry("Bulk modulus", kappa),
                [=](const double Ib) {
                  const double room = 1. - (Ib - 3.) / jm;
                  return room > 0. ? 0.5 * mu / room
                                   : std::numeric_limits<double>::quiet_NaN();
                }};
      }
    if (name == "Arruda-Boyce")
      {
        const double mu = 1., lm = 2.5;
        const double c[5] = {
          0.5, 0.05, 11. / 1050., 19. / 7000., 519. / 673750.};
        return {entry("Shear modulus", "1") + entry("Locking stretch", "2.5") +
                  entry("Bulk modulus", kappa),
                [=](const double Ib) {
                  double W1 = 0.;
                  for (int i = 1; i <= 5; ++i)
                    W1 += mu * c[i - 1] * i * std::pow(lm, 2. - 2. * i) *
                          std::pow(Ib, i - 1.);
                  return W1;
                }};
      }
    throw InputError("unknown model '" + name + "'");
  }

  template <int dim>
  void
  uniaxial(Checker &checker, const std::string &model, const bool mixed)
  {
    const bool        three = dim == 3;
    const RubberModel law   = rubber_model(model, mixed ? "inf" : "5");
    const double kappa = mixed ? std::numeric_limits<double>::infinity() : 5.;
    for (const double l1 : {1.6, 0.6})
      {
        const std::string tag = std::to_string(dim) + "D " + model +
                                (mixed ? " (mixed, incompressible)" : "") +
                                ", l1 = " + std::to_string(l1) + ": ";
        const std::string scene =
          subsection("Problem",
                     entry("Dimension", std::to_string(dim)) +
                       entry("Formulation", mixed ? "mixed" : "displacement")) +
          subsection("Mesh",
                     entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                       entry("Upper corner", three ? "3, 1, 1" : "3, 1") +
                       entry("Subdivisions", three ? "3, 1, 1" : "6, 2")) +
          subsection("Material",
                     entry("Model", model) + subsection(model, law.entries)) +
          subsection("Loading", entry("Number of load steps", "4")) +
          tight_solver("direct") + dirichlet(1, 0, "x", "0") +
          dirichlet(2, 2, "y", "0") + (three ? dirichlet(3, 4, "z", "0") : "") +
          dirichlet(4, 1, "x", std::to_string(3. * (l1 - 1.)) + "*t") +
          subsection("Output", entry("Write VTU", "false"));
        const auto          problem = run_scene<dim>(scene);
        const auto         &last    = problem->summaries().back();
        const UniaxialState exact =
          uniaxial_first_invariant(dim, l1, law.W1, kappa);
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
      dim == 2 ? uniaxial<2>(checker, model, mixed)
               : uniaxial<3>(checker, model, mixed);
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
