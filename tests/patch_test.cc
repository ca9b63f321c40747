// Patch test on irregular meshes (stress-tests.md case 6): the unstructured
// gmsh meshes meshes/bar_2d.msh (triangles) and meshes/bar_3d.msh
// (tetrahedra) get a linear displacement u = A X + c on their whole
// boundary, with a finite, non-symmetric A (stretch, shear and rotation,
// J = det(I + A) away from 1). The homogeneous state F = I + A solves every
// model, so the inside must reproduce u at every node to 1e-10 (P1 and P2,
// every model).
//
// Usage: mpirun -np N patch_test DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/nodal_error.h"
#include "support/scene_text.h"

#include <iostream>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  // u = A X + c, rows of A and c.
  constexpr double A[3][3] = {{0.25, 0.1, -0.05}, {-0.15, -0.1, 0.2}, {0.05, 0.3, 0.15}};
  constexpr double c[3]    = {0.01, -0.02, 0.03};

  template <int dim>
  std::string
  scene(const std::string &model, const unsigned int degree)
  {
    std::string expressions;
    for (unsigned int i = 0; i < dim; ++i)
      {
        // Applied in two load steps: u = t (A X + c).
        expressions += std::string(i > 0 ? "; " : "") + "t*(" + std::to_string(c[i]);
        for (unsigned int j = 0; j < dim; ++j)
          expressions += " + " + std::to_string(A[i][j]) + "*" + std::string(1, "xyz"[j]);
        expressions += ")";
      }
    std::string text =
      subsection("Problem",
                 entry("Dimension", std::to_string(dim)) +
                   entry("Finite element degree", std::to_string(degree))) +
      subsection("Mesh",
                 entry("Source", "file") +
                   entry("File",
                         std::string(SOURCE_DIR) + "/meshes/bar_" +
                           std::to_string(dim) + "d.msh")) +
      material_section(model,
                       entry("Young's modulus", "1") +
                         entry("Poisson's ratio", "0.3"),
                       LameParameters::from_young_poisson(1., 0.3)) +
      subsection("Loading", entry("Number of load steps", "2")) +
      tight_solver("cg") +
      subsection("Output",
                 entry("Directory", "patch_test_output") +
                   entry("Write VTU", "false") + entry("Verbose", "false"));
    for (unsigned int id = 1; id <= 2 * dim; ++id)
      text += dirichlet(id, id, dim == 3 ? "x, y, z" : "x, y", expressions);
    return text;
  }

  template <int dim>
  void
  check(Checker &checker, bool)
  {
    for (const std::string &model : all_models())
      for (const unsigned int degree : {1u, 2u})
        {
          Parameters parameters;
          parameters.read_from_string(scene<dim>(model, degree));
          Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
          problem.run();
          const double error =
            max_nodal_error(problem.get_dof_handler(), problem.solution(), [](const Point<dim> &X) {
              Tensor<1, dim> u;
              for (unsigned int i = 0; i < dim; ++i)
                {
                  u[i] = c[i];
                  for (unsigned int j = 0; j < dim; ++j)
                    u[i] += A[i][j] * X[j];
                }
              return u;
            });
          checker.at_most(std::to_string(dim) + "D " + model + " P" + std::to_string(degree) +
                            ": max nodal error",
                          error,
                          1e-10);
        }
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_checks_for_dimension(argc, argv, check<2>, check<3>);
}
