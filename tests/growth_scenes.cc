// Growth in whole scenes (issue 59), on the ranks of MPI_COMM_WORLD (the
// same bounds on 1 and 2 ranks), for every registered model:
// - free isotropic growth of a unit cube (rollers on three faces), g =
//   1 + 0.2 t: every vertex at g X (1e-12) and no reaction (1e-12);
// - confined growth (rollers on all six faces, F = I, Fe = I / g): the
//   reaction per reference area on x = 1 is g^2 P_e(I / g)_xx of the
//   model's own stress (1e-10); for neo-Hookean also the closed form
//   g^2 [mu (1/g - g) - 3 lambda g ln g] and for the decoupled models
//   kappa/2 (g^-3 - g^3); in 2D (plane strain, Fg = g I in 3D) the same;
// - fibre growth of a bar along its axis ('Growth direction' x, g = 1.25):
//   free, it lengthens by g (every vertex at (g X, Y, Z), 1e-12); with both
//   ends held axially, the axial reaction is the nominal stress of the
//   model in uniaxial compression to 1 / g with free lateral faces
//   (calibration's homogeneous test, its own Newton solve; 1e-10).
#include <deal.II/base/mpi.h>

#include <hyperelastic/calibration/homogeneous_test.h>
#include <hyperelastic/materials/material_registry.h>

#include "support/checker.h"
#include "support/owned_vertices.h"
#include "support/scene_run.h"
#include "support/scene_text.h"

#include <cmath>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  const LameParameters lame = lame_parameters(1., 2.);

  /// A box scene of @p model with @p growth entries and @p supports.
  std::string
  box_scene(const int          dim,
            const std::string &model,
            const std::string &upper,
            const std::string &subdivisions,
            const std::string &growth,
            const std::string &supports)
  {
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh",
                      entry("Lower corner", dim == 3 ? "0, 0, 0" : "0, 0") +
                        entry("Upper corner", upper) +
                        entry("Subdivisions", subdivisions)) +
           material_section(model,
                            entry("Elastic constants", "Lame") +
                              entry("Shear modulus", "1") +
                              entry("Lame lambda", "2"),
                            lame) +
           subsection("Material", growth) +
           subsection("Loading", entry("Number of load steps", "2")) +
           tight_solver("direct") + supports +
           subsection("Output", entry("Write VTU", "false"));
  }

  /// Rollers on the faces with ids @p ids (0, 1: x = min, max; 2, 3: y;
  /// 4, 5: z), each holding its normal component.
  std::string
  rollers(const std::vector<int> &ids)
  {
    const char *axis[3] = {"x", "y", "z"};
    std::string text;
    int         slot = 1;
    for (const int id : ids)
      text += dirichlet(slot++, id, axis[id / 2], "0");
    return text;
  }

  /// The largest |u - (stretch(X) - X)| over the owned vertices, over all
  /// ranks.
  template <int dim, typename Expected>
  double
  worst_displacement(const Problem<dim> &problem, Expected &&expected)
  {
    const auto &dofs  = problem.get_dof_handler();
    const auto &u     = problem.solution();
    double      worst = 0.;
    for_each_owned_vertex(dofs, [&](const auto &cell, const unsigned int v) {
      const dealii::Point<dim> X = cell->vertex(v);
      const auto               x = expected(X);
      for (unsigned int d = 0; d < dim; ++d)
        worst =
          std::max(worst,
                   std::abs(u(cell->vertex_dof_index(v, d)) - (x[d] - X[d])));
    });
    return dealii::Utilities::MPI::max(worst, MPI_COMM_WORLD);
  }

  /// The reaction on boundary @p id at the last step.
  template <int dim>
  dealii::Tensor<1, dim>
  reaction(const Problem<dim> &problem, const unsigned int id)
  {
    for (const auto &[boundary, force] : problem.summaries().back().reactions)
      if (boundary == id)
        return force;
    return dealii::Tensor<1, dim>();
  }

  dealii::Tensor<2, 3>
  scaled_identity(const double s)
  {
    dealii::Tensor<2, 3> T;
    for (unsigned int d = 0; d < 3; ++d)
      T[d][d] = s;
    return T;
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  Checker           check(dealii::Utilities::MPI::this_mpi_process(comm) == 0);
  const double      g = 1.2;
  const std::string isotropic =
    entry("Growth", "isotropic") + entry("Growth stretch", "1 + 0.2 * t");

  for (const MaterialModel &m : material_models())
    {
      const auto model3 = m.from_small_strain(lame).create<3>();
      check.section(m.name);
      {
        const auto free = run_scene<3>(box_scene(
          3, m.name, "1, 1, 1", "2, 2, 2", isotropic, rollers({0, 2, 4})));
        check.at_most("free isotropic growth: |x - g X|",
                      worst_displacement(*free,
                                         [&](const dealii::Point<3> &X) {
                                           return g * X;
                                         }),
                      1e-12);
        double largest = 0.;
        for (const unsigned int id : {0u, 2u, 4u})
          largest = std::max(largest, reaction(*free, id).norm());
        check.at_most("free isotropic growth: |reactions|", largest, 1e-12);
      }
      {
        const auto confined =
          run_scene<3>(box_scene(3,
                                 m.name,
                                 "1, 1, 1",
                                 "2, 2, 2",
                                 isotropic,
                                 rollers({0, 1, 2, 3, 4, 5})));
        const double expected =
          g * g * model3->first_piola_kirchhoff(scaled_identity(1. / g))[0][0];
        check.close("confined growth: reaction_1_x = g^2 P_e(I/g)_xx",
                    reaction(*confined, 1)[0],
                    expected,
                    std::abs(expected),
                    1e-10);
        if (m.has_volumetric_split)
          {
            // Decoupled: the isochoric stress vanishes at I / g, U'(J) J
            // F^-T with J = g^-3 gives kappa/2 (g^-3 - g^3).
            const LameParameters rest  = model3->small_strain_moduli();
            const double         kappa = rest.lambda + 2. * rest.mu / 3.;
            const double closed = 0.5 * kappa * (std::pow(g, -3) - g * g * g);
            check.close("confined growth: kappa/2 (g^-3 - g^3)",
                        reaction(*confined, 1)[0],
                        closed,
                        std::abs(closed),
                        1e-10);
          }
        if (m.name == "neo-Hookean")
          {
            const double closed =
              g * g * (1. / g - g - 3. * 2. * g * std::log(g));
            check.close("confined growth: g^2 [mu (1/g - g) - 3 lambda g ln "
                        "g]",
                        reaction(*confined, 1)[0],
                        closed,
                        std::abs(closed),
                        1e-10);
            const auto plane = run_scene<2>(box_scene(
              2, m.name, "1, 1", "3, 3", isotropic, rollers({0, 1, 2, 3})));
            check.close("confined growth in plane strain (Fg = g I in 3D)",
                        reaction(*plane, 1)[0],
                        closed,
                        std::abs(closed),
                        1e-10);
          }
      }
      {
        const std::string fibre = entry("Growth", "fibre") +
                                  entry("Growth direction", "1; 0; 0") +
                                  entry("Growth along fibre", "1 + 0.25 * t") +
                                  entry("Growth across fibre", "1");
        const double gf   = 1.25;
        const auto   free = run_scene<3>(box_scene(
          3, m.name, "3, 1, 1", "3, 1, 1", fibre, rollers({0, 2, 4})));
        check.at_most("free fibre growth: |x - (g X, Y, Z)|",
                      worst_displacement(*free,
                                         [&](const dealii::Point<3> &X) {
                                           return dealii::Point<3>(gf * X[0],
                                                                   X[1],
                                                                   X[2]);
                                         }),
                      1e-12);
        if (!calibration::isotropic_about_x(*model3))
          continue;
        const auto             held = run_scene<3>(box_scene(
          3, m.name, "3, 1, 1", "3, 1, 1", fibre, rollers({0, 1, 2, 4})));
        calibration::TestState compression;
        compression.type      = calibration::TestType::uniaxial;
        compression.stretch_1 = 1. / gf;
        const double expected = calibration::homogeneous_response(*model3,
                                                                  nullptr,
                                                                  compression,
                                                                  false)
                                  .value;
        check.close("held fibre growth: axial reaction = uniaxial nominal "
                    "stress at 1/g",
                    reaction(*held, 1)[0],
                    expected,
                    std::abs(expected),
                    1e-10);
      }
    }
  return check.exit_code(0, comm);
}
