// One benchmark run: a 3D P1 scene at a given resolution, solved with the
// application's own solver; prints one CSV row (header with --header) with
// the size, the wall time of each phase, the iteration counts, the peak
// memory, the time of one sparse matrix-vector product with the assembled
// tangent, and the error.
//
// Usage: mpirun -np R hyperelastic_benchmark SCENE N [--header]
//   SCENE bar    homogeneous uniaxial stretch of a 4 x 1 x 1 bar to 1.5 times
//                its length on symmetry rollers; error: largest nodal
//                displacement error against the exact solution, relative
//   SCENE twist  the bar clamped at x = 0, its end turned by 90 degrees about
//                its axis, under gravity; error: computed by run.py from the
//                stored energy against the finest run
//   N            cells across the bar's width (4N x N x N boxes, 6 tets each)
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <hyperelastic/error_handling.h>
#include <hyperelastic/problem.h>

#include "../tests/analytic_bar.h"
#include "../tests/scene_text.h"

#include <sys/resource.h>

#include <iomanip>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  constexpr double stretch = 1.5; // bar scene: final length / initial

  std::string
  scene_text(const std::string &scene, const unsigned int n)
  {
    if (scene == "bar")
      return bar_3d(n) +
             subsection("Loading", entry("Number of load steps", "2")) +
             dirichlet(1, 0, "x", "0") + dirichlet(2, 2, "y", "0") +
             dirichlet(3, 4, "z", "0") +
             dirichlet(4, 1, "x", std::to_string(4. * (stretch - 1.)) + "*t");
    if (scene == "twist")
      return bar_3d(n) + twist_loading();
    throw InputError("unknown benchmark scene '" + scene + "' (bar, twist)");
  }

  /// Largest nodal error against the exact homogeneous stretch, relative to
  /// the largest exact displacement.
  double
  bar_error(const Problem<3> &problem)
  {
    const double mu = 1. / 2.6, lambda = 0.3 / (1.3 * 0.4);
    const double l2 = uniaxial("neo-Hookean", 3, stretch, mu, lambda).l2;
    const Tensor<1, 3> strain({stretch - 1., l2 - 1., l2 - 1.});
    const auto        &u     = problem.solution();
    double             error = 0.;
    for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c < 3; ++c)
            error = std::max(error,
                             std::abs(u[cell->vertex_dof_index(v, c)] -
                                      strain[c] * cell->vertex(v)[c]));
    return Utilities::MPI::max(error, MPI_COMM_WORLD) / (4. * (stretch - 1.));
  }

  /// Seconds of one product y = K x with the assembled tangent (the best
  /// of several repetitions, slowest rank).
  double
  spmv_seconds(const MatrixType &K)
  {
    VectorType x(K.locally_owned_domain_indices(), MPI_COMM_WORLD);
    VectorType y(K.locally_owned_range_indices(), MPI_COMM_WORLD);
    x = 1.;
    double best = 1e300;
    for (unsigned int repeat = 0; repeat < 5; ++repeat)
      {
        MPI_Barrier(MPI_COMM_WORLD);
        Timer              timer;
        const unsigned int n = 10;
        for (unsigned int k = 0; k < n; ++k)
          K.vmult(y, x);
        timer.stop();
        best = std::min(best,
                        Utilities::MPI::max(timer.wall_time(), MPI_COMM_WORLD) /
                          n);
      }
    return best;
  }

  double
  peak_memory_bytes()
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return Utilities::MPI::sum(1024. * usage.ru_maxrss, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const char *header =
    "scene,ranks,n,cells,dofs,load_steps,newton_iterations,krylov_iterations,"
    "krylov_per_newton,amg_setups,t_setup,t_tangent_assembly,t_residual,t_line_search,"
    "t_preconditioner,t_krylov,t_output,t_total,t_spmv,"
    "assembly_per_newton_in_spmv,peak_memory_bytes,memory_per_dof_bytes,"
    "energy,error";
  if (argc > 1 && std::string(argv[1]) == "--header")
    {
      if (root)
        std::cout << header << std::endl;
      return 0;
    }
  return run_and_report(
    [&]() {
      if (argc < 3)
        throw InputError("usage: hyperelastic_benchmark bar|twist N");
      const std::string  scene = argv[1];
      const unsigned int n     = std::stoul(argv[2]);
      Parameters         parameters;
      parameters.read_from_string(scene_text(scene, n));
      parameters.output.directory = "output_benchmark";
      parameters.output.verbose   = false;

      Timer      total;
      Problem<3> problem(parameters, MPI_COMM_WORLD, false);
      problem.run();
      total.stop();

      std::map<std::string, double> times = problem.wall_times();
      const auto                    time  = [&](const std::string &phase) {
        return Utilities::MPI::max(times.count(phase) ? times[phase] : 0.,
                                   MPI_COMM_WORLD);
      };
      unsigned int newton = 0, krylov = 0;
      for (const auto &s : problem.summaries())
        {
          newton += s.newton_iterations;
          krylov += s.linear_iterations;
        }
      // Every collective call happens here, on all ranks, before rank 0
      // prints.
      const double t_spmv  = spmv_seconds(problem.tangent_matrix());
      const double memory  = peak_memory_bytes();
      const auto   n_dofs  = problem.get_dof_handler().n_dofs();
      const double error   = scene == "bar" ? bar_error(problem) : 0.;
      const double t_total = Utilities::MPI::max(total.wall_time(),
                                                 MPI_COMM_WORLD);
      const char *phases[] = {"mesh and setup",
                              "assembly",
                              "residual",
                              "line search",
                              "preconditioner setup",
                              "linear solve",
                              "output"};
      std::map<std::string, double> t;
      for (const char *phase : phases)
        t[phase] = time(phase);
      const unsigned int n_cells =
        problem.get_dof_handler().get_triangulation().n_global_active_cells();
      if (root)
        std::cout << std::setprecision(6) << scene << ","
                  << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << ","
                  << n << "," << n_cells << "," << n_dofs << ","
                  << problem.summaries().size() << "," << newton << ","
                  << krylov << "," << double(krylov) / std::max(newton, 1u)
                  << "," << problem.n_preconditioner_setups() << "," << t["mesh and setup"] << "," << t["assembly"] << ","
                  << t["residual"] << "," << t["line search"] << ","
                  << t["preconditioner setup"] << "," << t["linear solve"]
                  << "," << t["output"] << "," << t_total << "," << t_spmv
                  << ","
                  << (t["assembly"] + t["residual"]) / std::max(newton, 1u) /
                       t_spmv
                  << "," << memory << "," << memory / n_dofs << ","
                  << std::setprecision(12)
                  << problem.summaries().back().energy << ","
                  << std::setprecision(6) << error << std::endl;
    },
    MPI_COMM_WORLD);
}
