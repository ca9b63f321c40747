// Rigid rotation (stress-tests.md case 8): one face of a block is turned by
// 90, 180 and 360 degrees in load steps of 22.5 degrees (about the z axis in
// 2D, about the oblique axis (1, 2, 2) / 3 in 3D), the rest of the block is
// free. A hyperelastic model must follow rigidly: at the end the stress
// |P| at every quadrature point stays below 1e-10 mu, every node sits at
// its rotated place to 1e-10 and the stored energy is zero at every step. Linear
// elasticity is not invariant under rotation: it is run too and must show
// stresses of the order of mu (documenting why it is only a reference).
//
// Usage: mpirun -np N rigid_rotation DIM
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/manufactured_motion.h"
#include "support/nodal_error.h"
#include "support/scene_text.h"

#include <cmath>
#include <iostream>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  constexpr double mu = 1.;

  /// u(X, t) = R(t angle) X - X.
  template <int dim>
  class RotationDisplacement : public Function<dim>
  {
  public:
    explicit RotationDisplacement(const double angle)
        : Function<dim>(dim)
        , angle(angle)
    {
    }

    double
    value(const Point<dim> &X, const unsigned int c) const override
    {
      return (rotation_matrix<dim>(this->get_time() * angle) * X - X)[c];
    }

  private:
    const double angle;
  };

  struct Deviation
  {
    double stress = 0.;   ///< max |P| / mu over quadrature points
    double position = 0.; ///< max |u_h - (R X - X)| over nodes
    double energy = 0.;
  };

  template <int dim>
  Deviation
  rotate(const std::string &model, const unsigned int degree, const double degrees)
  {
    const bool   three = dim == 3;
    const double angle = degrees * M_PI / 180.;
    const auto   steps = static_cast<unsigned int>(std::lround(degrees / 22.5));
    const std::string text =
      subsection("Problem",
                 entry("Dimension", std::to_string(dim)) +
                   entry("Finite element degree", std::to_string(degree))) +
      subsection("Mesh",
                 entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                   entry("Upper corner", three ? "2, 1, 1" : "2, 1") +
                   entry("Subdivisions", three ? "4, 2, 2" : "8, 4")) +
      material_section(model,
                       entry("Elastic constants", "Lame") +
                         entry("Shear modulus", "1") +
                         entry("Lame lambda", "1.5"),
                       lame_parameters(1., 1.5)) +
      subsection("Loading",
                 entry("Number of load steps", std::to_string(steps))) +
      // The placeholder is replaced by the rotation below.
      dirichlet(1, 0, three ? "x, y, z" : "x, y", three ? "0; 0; 0" : "0; 0") +
      tight_solver("cg") +
      subsection("Output",
                 entry("Write VTU", "false") + entry("Verbose", "false") +
                   entry("Directory", "rigid_rotation_output"));
    Parameters parameters;
    parameters.read_from_string(text);
    Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
    problem.set_load_editor([&](BoundaryConditions<dim> &bc) {
      bc.dirichlet[0].displacement = std::make_unique<RotationDisplacement<dim>>(angle);
    });
    problem.run();

    // Stress at degree + 1 points per cell (the field is affine per cell for
    // P1; P2 has 3 (2D) or 4 (3D) points), node positions.
    const auto material = create_material<dim>(parameters.material);
    const DoFHandler<dim>   &dof_handler = problem.get_dof_handler();
    const MappingFE<dim>     mapping(FE_SimplexP<dim>(1));
    const QGaussSimplex<dim> quadrature(degree + 1);
    FEValues<dim>            fe_values(mapping, dof_handler.get_fe(), quadrature, update_gradients);
    std::vector<Tensor<2, dim>> gradients(quadrature.size());
    Deviation                   d;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[FEValuesExtractors::Vector(0)].get_function_gradients(problem.solution(),
                                                                          gradients);
          for (const auto &g : gradients)
            {
              const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + g;
              d.stress = std::max(d.stress, material->first_piola_kirchhoff(F).norm() / mu);
            }
        }
    const Tensor<2, dim> R = rotation_matrix<dim>(angle);
    d.position = max_nodal_error(dof_handler, problem.solution(), [&](const Point<dim> &X) {
      return R * X - X;
    });
    d.stress   = Utilities::MPI::max(d.stress, MPI_COMM_WORLD);
    // Every load step, not only the last (at 360 degrees the end is the
    // reference state).
    for (const auto &s : problem.summaries())
      d.energy = std::max(d.energy, std::abs(s.energy));
    return d;
  }

  template <int dim>
  void
  check(Checker &checker, bool)
  {
    for (const std::string &model : nonlinear_models())
      for (const unsigned int degree : {1u, 2u})
        for (const double degrees : {90., 180., 360.})
          {
            const Deviation   d = rotate<dim>(model, degree, degrees);
            const std::string tag = std::to_string(dim) + "D " + model + " P" +
                                    std::to_string(degree) + " " +
                                    std::to_string(int(degrees)) + " deg: ";
            checker.at_most(tag + "max |P| / mu", d.stress, 1e-10);
            checker.at_most(tag + "max node error", d.position, 1e-10);
            checker.at_most(tag + "|energy| / mu", d.energy, 1e-10);
          }
    // Linear elasticity measures strain by the symmetric gradient, which a
    // rotation does not leave zero: 22.5 degrees already stresses it like a
    // strain of 8 % (cos 22.5 - 1); at 90 degrees its solution inverts
    // elements.
    const Deviation d = rotate<dim>("linear elastic", 1, 22.5);
    checker.at_least(std::to_string(dim) +
                       "D linear elastic 22.5 deg: max |P| / mu (not objective)",
                     d.stress,
                     0.1);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_checks_for_dimension(argc, argv, check<2>, check<3>);
}
