// Fitting through a scene (issue 58, item 5): a 2D block indented by a flat
// punch (a prescribed displacement on part of its top), neo-Hookean with
// shear and bulk modulus. The punch force of the exact constants at load
// factors off the nominal step grid (0.3, 0.55, 0.8, 1: 'Load stepping/Stop
// at load factors' lands on them) is the data; the fit starts 50 % away
// (1.5 mu, kappa / 2) and must recover both to 1e-5, with the Jacobian of
// the adjoint, which matches central differences of whole runs (1e-5).
// With more than one rank the same fit on rank 0 alone gives the same
// constants (1e-10).
#include <deal.II/base/mpi.h>

#include <hyperelastic/calibration/fit_parameters.h>
#include <hyperelastic/inverse/scene_fit.h>

#include "support/checker.h"
#include "support/scene_run.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

using namespace hyperelastic;

namespace
{
  std::string
  scene(const double       mu,
        const double       kappa,
        const std::string &stops,
        const unsigned int degree = 1,
        const std::string &extra  = "")
  {
    std::ostringstream out;
    out << std::setprecision(17) << "subsection Problem\n  set Dimension = 2\n"
        << "  set Finite element degree = " << degree << "\nend\n"
        << "subsection Mesh\n  set Source = box\n  set Lower corner = 0, 0\n"
        << "  set Upper corner = 2, 1\n  set Subdivisions = 8, 4\nend\n"
        << "subsection Material\n  set Model = neo-Hookean\n"
        << "  set Elastic constants = shear and bulk modulus\n"
        << "  set Shear modulus = " << mu << "\n  set Bulk modulus = " << kappa
        << "\nend\n"
        << "subsection Loading\n  set Number of load steps = 4\nend\n"
        << "subsection Load stepping\n  set Stop at load factors = " << stops
        << "\nend\n"
        << "subsection Dirichlet 1\n  set Boundary id = 2\n"
        << "  set Components = x, y\n  set Displacement = 0; 0\nend\n"
        << "subsection Dirichlet 2\n"
        << "  set Boundary region = y > 1 - 1e-6 && x < 0.75\n"
        << "  set Components = x, y\n  set Displacement = 0; -0.25 * t\nend\n"
        << "subsection Output\n  set Write VTU = false\n"
        << "  set Base name = scene_fit_data\nend\n"
        << extra;
    return out.str();
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const unsigned int rank  = dealii::Utilities::MPI::this_mpi_process(comm);
  const unsigned int ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
  testing::Checker   check(rank == 0);
  const double       mu = 1., kappa = 5.;
  const std::vector<double> stops = {0.3, 0.55, 0.8, 1.};

  // The data: the punch force (boundary region id 4) at the stops.
  const auto truth = testing::run_scene<2>(scene(mu, kappa, "0.3, 0.55, 0.8"));
  const std::string   tag         = "np" + std::to_string(ranks);
  const std::string   data        = "scene_fit_data_" + tag + ".csv";
  const std::string   start_scene = "scene_fit_start_" + tag + ".prm";
  std::vector<double> forces;
  for (const double t : stops)
    for (const auto &row : truth->summaries())
      if (row.load_factor == t)
        for (const auto &[id, force] : row.reactions)
          if (id == 4)
            forces.push_back(force[1]);
  check.is_true("the data's run landed on 0.3, 0.55, 0.8 and 1 exactly",
                forces.size() == stops.size());
  // Each step on a stop carries the stop's index (the fit reads its data
  // points by it); the end, not in the list, and the steps between carry
  // none.
  unsigned int indexed = 0;
  for (const auto &row : truth->summaries())
    if (row.stop)
      indexed += *row.stop < 3 && row.load_factor == stops[*row.stop];
    else
      check.is_true("no stop index at t = " + std::to_string(row.load_factor),
                    row.load_factor != 0.3 && row.load_factor != 0.55 &&
                      row.load_factor != 0.8);
  check.is_true("the steps at 0.3, 0.55 and 0.8 indexed 0, 1 and 2",
                indexed == 3);
  if (rank == 0)
    {
      std::ofstream csv(data);
      csv << "# punch force of mu = 1, kappa = 5\nload_factor,reaction_4_y\n"
          << std::setprecision(17);
      for (unsigned int k = 0; k < forces.size(); ++k)
        csv << stops[k] << "," << forces[k] << "\n";
      std::ofstream start(start_scene);
      start << scene(1.5 * mu, 0.5 * kappa, "");
    }
  MPI_Barrier(comm);

  calibration::FitParameters fit;
  fit.scene          = start_scene;
  fit.scene_column   = "reaction_4_y";
  fit.scene_reaction = calibration::reaction_column(fit.scene_column);
  check.is_true("reaction_4_y is the y force of boundary id 4",
                fit.scene_reaction && fit.scene_reaction->boundary_id == 4 &&
                  fit.scene_reaction->component == 1);
  check.is_true("reaction_moment_4_z and reaction_4_w are no reactions",
                !calibration::reaction_column("reaction_moment_4_z") &&
                  !calibration::reaction_column("reaction_4_w") &&
                  !calibration::reaction_column("reaction__y"));
  fit.free_constants = {"Shear modulus", "Bulk modulus"};
  fit.starts         = 1;
  fit.directory      = "output";
  fit.base_name      = "scene_fit_" + tag;
  fit.data.push_back(calibration::read_scene_data(data, fit.scene_column));
  fit.data.back().index = 1;
  // The adjoint's Jacobian at the start against central differences of
  // whole runs (relative to the largest entry of each column, 1e-5): P1,
  // P2, and P1 with a follower pressure on the top right of the punch (an
  // open surface with both ends free: the tangent is not symmetric, the
  // adjoint solves with its transpose); the mixed formulation with each
  // element: the decoupled neo-Hookean model (its Lame pair chained to mu
  // and kappa), and Mooney-Rivlin's C1 and Bulk modulus with Taylor-Hood.
  const std::string follower =
    "subsection Pressure 1\n  set Boundary region = y > 1 - 1e-6 && x > 1\n"
    "  set Pressure = 0.5 * t\nend\n";
  const auto mixed = [](const std::string &element) {
    return "subsection Problem\n  set Formulation = mixed\n"
           "  set Mixed element = " +
           element +
           "\nend\nsubsection Material\n"
           "  set Model = decoupled neo-Hookean\nend\n";
  };
  const std::string mooney_rivlin =
    "subsection Material\n  set Model = Mooney-Rivlin\n"
    "  subsection Mooney-Rivlin\n    set C1 = 0.6\n    set C2 = 0.15\n"
    "    set Bulk modulus = 3\n  end\nend\n";
  struct Case
  {
    std::string              name, text;
    std::vector<std::string> free;
  };
  const std::vector<std::string> lame_free = {"Shear modulus", "Bulk modulus"};
  const std::vector<Case>        cases     = {
               {"P1", scene(1.5 * mu, 0.5 * kappa, "", 1), lame_free},
               {"P2", scene(1.5 * mu, 0.5 * kappa, "", 2), lame_free},
               {"P1, follower pressure",
                scene(1.5 * mu, 0.5 * kappa, "", 1, follower),
                lame_free},
               {"mixed MINI",
                scene(1.5 * mu, 0.5 * kappa, "", 1, mixed("P1-bubble/P1")),
                lame_free},
               {"mixed P1/P1 stabilized",
                scene(1.5 * mu, 0.5 * kappa, "", 1, mixed("P1/P1 stabilized")),
                lame_free},
               {"mixed P2/P1, Mooney-Rivlin, follower pressure",
                scene(
       1.5 * mu, 0.5 * kappa, "", 1, mixed("P2/P1") + mooney_rivlin + follower),
                {"C1", "Bulk modulus"}}};
  for (const Case &c : cases)
    {
      if (rank == 0)
        {
          std::ofstream start(start_scene);
          start << c.text;
        }
      MPI_Barrier(comm);
      fit.free_constants         = c.free;
      const auto         J       = scene_jacobians(fit, comm);
      const std::string &element = c.name;
      check.is_true(element + ": the adjoint applies (a reaction, no contact)",
                    J[0].size() == stops.size());
      for (unsigned int k = 0; k < 2 && J[0].size() == stops.size(); ++k)
        {
          double worst = 0., scale = 0.;
          for (unsigned int i = 0; i < stops.size(); ++i)
            {
              worst = std::max(worst, std::abs(J[0][i][k] - J[1][i][k]));
              scale = std::max(scale, std::abs(J[1][i][k]));
            }
          check.at_most(element + ": adjoint d(force)/d" + c.free[k] +
                          " against central differences of runs",
                        worst / scale,
                        1e-5);
        }
    }
  fit.free_constants = lame_free;
  if (rank == 0)
    {
      std::ofstream start(start_scene);
      start << scene(1.5 * mu, 0.5 * kappa, "");
    }
  MPI_Barrier(comm);

  const auto result = fit_through_scene(fit, "scene_fit.cc", comm);
  check.close("mu from a start 50 % away", result.values[0], mu, mu, 1e-5);
  check.close(
    "kappa from a start 50 % away", result.values[1], kappa, kappa, 1e-5);

  if (ranks > 1)
    {
      // The same fit on rank 0 alone.
      MPI_Comm alone;
      MPI_Comm_split(comm, rank == 0 ? 0 : MPI_UNDEFINED, 0, &alone);
      std::vector<double> single(2, 0.);
      if (rank == 0)
        {
          fit.base_name = "scene_fit_" + tag + "_alone";
          single        = fit_through_scene(fit, "scene_fit.cc", alone).values;
          MPI_Comm_free(&alone);
        }
      MPI_Bcast(single.data(), 2, MPI_DOUBLE, 0, comm);
      check.close("mu on " + std::to_string(ranks) + " ranks and on 1",
                  result.values[0],
                  single[0],
                  mu,
                  1e-10);
      check.close("kappa on " + std::to_string(ranks) + " ranks and on 1",
                  result.values[1],
                  single[1],
                  kappa,
                  1e-10);
    }
  return check.exit_code(0, comm);
}
