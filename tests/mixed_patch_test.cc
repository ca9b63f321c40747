// Patch test of the mixed displacement-pressure formulation (issue 14) on
// the unstructured gmsh meshes meshes/bar_2d.msh (triangles) and
// meshes/bar_3d.msh (tetrahedra), every mixed element, decoupled neo-Hookean
// and Mooney-Rivlin, on the ranks of MPI_COMM_WORLD.
//
// The motion x = F X + c is affine with a non-symmetric F (stretch, shear
// and rotation together):
//   - exactly incompressible (bulk modulus 'inf'): det F = 1, any constant
//     pressure p0 is admissible; the end x = 3 carries the dead traction
//     P N = (P_iso(F) + p0 F^-T) e1, every other face the displacement;
//   - nu = 0.4999: det F = 1.06, p = U'(J) = kappa/2 (J - 1/J); every face
//     carries the displacement (a traction P(F) e1 of about 100 mu on the
//     end, applied in proportion to the load factor, would not be near
//     equilibrium with the intermediate displacements).
// The homogeneous state solves the discrete problem on any mesh (the MINI
// bubble is zero, the stabilisation p - Pi0 p vanishes), so every
// displacement node must equal F X + c - X to 1e-10 and every pressure
// unknown the exact pressure to 1e-8 (relative).
//
// Usage: mpirun -np N mixed_patch_test DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/materials/material_registry.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/nodal_error.h"
#include "support/scene_text.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  constexpr double mu = 1., nu = 0.4999, p0 = 0.35;
  const double     lambda = 2. * mu * nu / (1. - 2. * nu);

  // A non-symmetric deformation gradient (before its volume is set) and
  // the rigid translation.
  constexpr double G[3][3] = {{1.12, 0.21, -0.06},
                              {-0.09, 0.94, 0.17},
                              {0.05, 0.26, 1.03}};
  constexpr double c[3]    = {0.01, -0.02, 0.03};

  /// G scaled to det F = @p J.
  template <int dim>
  Tensor<2, dim>
  deformation_gradient(const double J)
  {
    Tensor<2, dim> F;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        F[i][j] = G[i][j];
    return std::pow(J / determinant(F), 1. / dim) * F;
  }

  template <int dim>
  std::string
  scene(const std::string    &element,
        const std::string    &model,
        const bool            incompressible,
        const Tensor<2, dim> &F,
        const Tensor<1, dim> &traction)
  {
    const double lame_lambda =
      incompressible ? std::numeric_limits<double>::infinity() : lambda;
    const std::string elastic =
      incompressible ? entry("Elastic constants", "shear and bulk modulus") +
                         entry("Shear modulus", number(mu)) +
                         entry("Bulk modulus", "inf") :
                       entry("Elastic constants", "Lame") +
                         entry("Shear modulus", number(mu)) +
                         entry("Lame lambda", number(lambda));
    // u = t (F X + c - X), applied in two load steps; the end traction
    // grows with t too (exact at t = 1 only: the first step is a path).
    std::string displacement, end_traction;
    for (unsigned int i = 0; i < dim; ++i)
      {
        displacement += std::string(i > 0 ? "; " : "") + "t*(" + number(c[i]);
        for (unsigned int j = 0; j < dim; ++j)
          displacement += " + " + number(F[i][j] - (i == j ? 1. : 0.)) +
                          "*" + std::string(1, "xyz"[j]);
        displacement += ")";
        end_traction +=
          std::string(i > 0 ? "; " : "") + "t*" + number(traction[i]);
      }
    std::string text =
      subsection("Problem",
                 entry("Dimension", std::to_string(dim)) +
                   entry("Formulation", "mixed") +
                   entry("Mixed element", element)) +
      subsection("Mesh",
                 entry("Source", "file") +
                   entry("File",
                         std::string(SOURCE_DIR) + "/meshes/bar_" +
                           std::to_string(dim) + "d.msh")) +
      material_section(model, elastic, lame_parameters(mu, lame_lambda)) +
      subsection("Loading", entry("Number of load steps", "2")) +
      (incompressible ? subsection("Traction 1",
                                   entry("Boundary id", "2") +
                                     entry("Traction", end_traction)) :
                        std::string()) +
      subsection("Newton",
                 entry("Max iterations", "25") +
                   entry("Relative residual tolerance", "1e-13") +
                   entry("Update tolerance", "1e-12")) +
      subsection("Linear solver", entry("Type", "direct")) +
      subsection("Output",
                 entry("Directory", "mixed_patch_test_output") +
                   entry("Write VTU", "false") + entry("Verbose", "false"));
    // Boundary ids of the bar meshes: 1 x = 0, 2 x = 3 (loaded if
    // incompressible), 3, 4 the y faces, 5, 6 the z faces.
    int slot = 1;
    for (unsigned int id = 1; id <= 2 * dim; ++id)
      if (id != 2 || !incompressible)
        text += dirichlet(slot++,
                          id,
                          dim == 3 ? "x, y, z" : "x, y",
                          displacement);
    return text;
  }

  template <int dim>
  void
  check(Checker &checker, bool)
  {
    const double kappa = lambda + 2. / 3. * mu;
    for (const std::string element :
         {"P1-bubble/P1", "P1/P1 stabilized", "P2/P1"})
      for (const std::string model : {"decoupled neo-Hookean", "Mooney-Rivlin"})
        for (const bool incompressible : {true, false})
          {
            const double         J = incompressible ? 1. : 1.06;
            const Tensor<2, dim> F = deformation_gradient<dim>(J);
            // The model at nu = 0.4999; its isochoric part is the same at
            // any bulk modulus.
            const auto material = material_model(model)
                                    .from_small_strain(lame_parameters(mu, lambda))
                                    .template create<dim>();
            const Tensor<2, dim> P =
              incompressible ?
                material->volumetric_split()->isochoric->first_piola_kirchhoff(F) +
                  p0 * transpose(invert(F)) :
                material->first_piola_kirchhoff(F);
            const double p_exact =
              incompressible ? p0 : 0.5 * kappa * (J - 1. / J);
            Tensor<1, dim> e1;
            e1[0] = 1.;

            Parameters parameters;
            parameters.read_from_string(
              scene<dim>(element, model, incompressible, F, P * e1));
            Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
            problem.run();

            const std::string tag =
              std::to_string(dim) + "D " + element + " " + model +
              (incompressible ? " incompressible" : " nu 0.4999") + ": ";
            const double u_error = max_nodal_error(
              problem.get_dof_handler(),
              problem.solution(),
              [&](const Point<dim> &X) {
                Tensor<1, dim> u = F * X - X;
                for (unsigned int i = 0; i < dim; ++i)
                  u[i] += c[i];
                return u;
              });
            checker.at_most(tag + "max nodal displacement error", u_error, 1e-10);
            checker.at_most(tag + "max |p - p exact| / |p exact|",
                            max_pressure_error(problem.get_dof_handler(),
                                               problem.solution(),
                                               p_exact) /
                              std::abs(p_exact),
                            1e-8);
          }
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_checks_for_dimension(argc, argv, check<2>, check<3>);
}
