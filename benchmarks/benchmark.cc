// One benchmark run: a 3D P1 scene at a given resolution, solved with the
// application's own solver; prints one CSV row (header with --header) with
// the size, the wall time of each phase, the iteration counts, the peak
// memory, the time of one sparse matrix-vector product with the assembled
// tangent, and the error.
//
// Usage: mpirun -np R hyperelastic_benchmark SCENE N [DEGREE] [--header]
//   SCENE bar    homogeneous uniaxial stretch of a 4 x 1 x 1 bar to 1.5 times
//                its length on symmetry rollers; error: largest nodal
//                displacement error against the exact solution, relative
//   SCENE twist  the bar clamped at x = 0, its end turned by 90 degrees about
//                its axis, under gravity; error: computed by run.py from the
//                stored energy against the finest run
//   SCENE twist_file  the twist on the gmsh bar of
//                benchmarks/mesh_input/bar_big.geo with L = 4 and h = 1/N,
//                read from the file twist_bar_N.msh in the working directory
//                (run.py generates it; another file: "Mesh/File=PATH"),
//                so that reading the file is part of the run; error: run.py
//                compares the energy with the twist series' extrapolation
//   SCENE manufactured  the unit cube in the manufactured finite-strain
//                motion of tests/manufactured_motion.h (90-degree rotation of
//                a smoothly deformed cube, body force -Div P), neo-Hookean;
//                error: L2 error of the displacement relative to its L2
//                norm (error_h1: the same in the H1 seminorm)
//   SCENE ball   a rigid ball pressed into a soft slab (contact, issue 26):
//                t_contact is the contact term's share of the phases
//   N            cells across the bar's width (4N x N x N boxes, 6 tets each;
//                manufactured: N x N x N boxes; twist_file: 1/h)
//   DEGREE       1 (default) or 2
//   then any number of SECTION/ENTRY=VALUE, appended to the scene (e.g.
//   "Linear solver/AMG smoothed aggregation=false")
//
// With --stages first (mpirun -np R hyperelastic_benchmark --stages SCENE N
// ...) only the set-up runs (Problem::setup(), no load step) and the row
// holds the wall time of each set-up stage (slowest rank; header with
// --stages --header): read, order, check, build, partition, wait, describe,
// distribute (the mesh), dofs, system (sparsity, matrix), null_space,
// operator, rest, and t_setup (the slowest rank's sum); peak memory as above.
//
// With --p2-preconditioner first (DEGREE 2; header with --p2-preconditioner
// --header) the scene runs as usual, then its last tangent A is solved for
// b = A x (x known, smooth in the unknown's index) to 1e-8 relative with CG
// and each preconditioner: ML AMG on A itself (the application's solver)
// and the two-level P2 -> P1 scheme (TwoLevelPreconditioner) with Chebyshev
// degree 1, 2, 3; one row each: set-up and solve time, CG iterations, error.
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>
#include <hyperelastic/solvers/linear_solver.h>
#include <hyperelastic/solvers/rigid_body_modes.h>
#include <hyperelastic/solvers/two_level_preconditioner.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/numerics/vector_tools.h>

#include "support/analytic_bar.h"
#include "support/manufactured_motion.h"
#include "support/scene_text.h"

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

  /// The rows of --p2-preconditioner for the last tangent of @p problem.
  void
  compare_p2_preconditioners(const Problem<3>             &problem,
                             const LinearSolverParameters &solver_parameters,
                             const std::string            &prefix)
  {
    const MatrixType &A    = problem.tangent_matrix();
    const MPI_Comm    comm = A.get_mpi_communicator();
    VectorType exact(A.locally_owned_domain_indices(), comm);
    for (const auto i : A.locally_owned_domain_indices())
      exact(i) = std::sin(0.37 * i) + 0.5;
    exact.compress(VectorOperation::insert);
    VectorType b(exact), x(exact);
    A.vmult(b, exact);
    const auto report = [&](const std::string &name,
                            const double       setup,
                            const unsigned int iterations,
                            const double       solve,
                            const types::global_dof_index coarse_dofs) {
      VectorType error(x);
      error -= exact;
      const double relative = error.l2_norm() / exact.l2_norm();
      const double t_setup  = Utilities::MPI::max(setup, comm);
      const double t_solve  = Utilities::MPI::max(solve, comm);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        std::cout << prefix << "," << coarse_dofs << "," << name << ","
                  << t_setup << "," << iterations << "," << t_solve << ","
                  << t_setup + t_solve << "," << relative << std::endl;
    };
    const double tolerance = 1e-8;
    {
      LinearSolver solver(solver_parameters);
      solver.set_near_null_space(
        rigid_body_modes(MappingFE<3>(FE_SimplexP<3>(1)),
                         problem.get_dof_handler()),
        n_rigid_body_modes<3>,
        3);
      Timer setup;
      solver.prepare(A);
      setup.stop();
      x = 0.;
      Timer              solve;
      const unsigned int its = solver.solve(A, x, b, tolerance);
      solve.stop();
      report("ML on P2", setup.wall_time(), its, solve.wall_time(), 0);
    }
    for (const unsigned int degree : {1u, 2u, 3u})
      {
        Timer                       setup;
        TwoLevelPreconditioner<3>   two_level(problem.get_dof_handler(),
                                            degree);
        two_level.initialize(A);
        setup.stop();
        x = 0.;
        SolverControl control(2000, tolerance * b.l2_norm());
        Timer         solve;
        SolverCG<VectorType>(control).solve(A, x, b, two_level);
        solve.stop();
        report("two-level Chebyshev " + std::to_string(degree),
               setup.wall_time(),
               control.last_step(),
               solve.wall_time(),
               two_level.n_coarse_dofs());
      }
  }

  std::string
  scene_text(const std::string &scene, const unsigned int n, const unsigned int degree)
  {
    const std::string element =
      subsection("Problem", entry("Finite element degree", std::to_string(degree)));
    if (scene == "manufactured")
      {
        const std::string N = std::to_string(n);
        std::string       text =
          subsection("Problem",
                     entry("Dimension", "3") +
                       entry("Finite element degree", std::to_string(degree))) +
          subsection("Mesh",
                     entry("Lower corner", "0, 0, 0") + entry("Upper corner", "1, 1, 1") +
                       entry("Subdivisions", N + ", " + N + ", " + N)) +
          subsection("Material",
                     entry("Model", "neo-Hookean") + entry("Elastic constants", "Lame") +
                       entry("Shear modulus", "1") + entry("Lame lambda", "1.5")) +
          subsection("Loading", entry("Number of load steps", "4")) +
          subsection("Output", entry("Write VTU", "false"));
        // Placeholders, replaced by the exact displacement.
        for (unsigned int id = 0; id < 6; ++id)
          text += dirichlet(id + 1, id, "x, y, z", "0; 0; 0");
        return text;
      }
    if (degree != 1)
      return scene_text(scene, n, 1) + element;
    if (scene == "bar")
      return bar_3d(n) +
             subsection("Loading", entry("Number of load steps", "2")) +
             dirichlet(1, 0, "x", "0") + dirichlet(2, 2, "y", "0") +
             dirichlet(3, 4, "z", "0") +
             dirichlet(4, 1, "x", std::to_string(4. * (stretch - 1.)) + "*t");
    if (scene == "twist")
      return bar_3d(n) + twist_loading();
    // The gmsh bar's physical surfaces: 1 at x = 0, 2 at x = 4.
    if (scene == "twist_file")
      return bar_3d(n) + twist_loading() +
             subsection("Mesh",
                        entry("Source", "file") +
                          entry("File", "twist_bar_" + std::to_string(n) + ".msh")) +
             subsection("Dirichlet 1", entry("Boundary id", "1")) +
             subsection("Dirichlet 2", entry("Boundary id", "2"));
    // A rigid ball of radius 0.5 pressed 0.1 deep into the slab
    // [0, 2] x [0, 2] x [0, 0.5] (4n x 4n x n boxes) glued at its bottom;
    // frictionless, d_hat = 0.005, 5 load steps.
    if (scene == "ball")
      {
        const std::string m = std::to_string(4 * n), k = std::to_string(n);
        return subsection("Problem", entry("Dimension", "3")) +
               subsection("Mesh",
                          entry("Lower corner", "0, 0, 0") +
                            entry("Upper corner", "2, 2, 0.5") +
                            entry("Subdivisions", m + ", " + m + ", " + k)) +
               subsection("Material",
                          entry("Model", "neo-Hookean") +
                            entry("Young's modulus", "1") +
                            entry("Poisson's ratio", "0.3")) +
               subsection("Loading", entry("Number of load steps", "5")) +
               dirichlet(1, 4, "x, y, z", "0; 0; 0") +
               subsection("Output", entry("Write VTU", "false")) +
               subsection(
                 "Contact",
                 entry("Barrier distance", "0.005") +
                   subsection("Obstacle 1",
                              entry("Type", "sphere") +
                                entry("Point", "1, 1, 1.002") +
                                entry("Radius", "0.5") +
                                entry("Motion", "0; 0; -0.102*t")));
      }
    throw InputError("unknown benchmark scene '" + scene +
                     "' (bar, twist, twist_file, manufactured, ball)");
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

  /// Errors of the displacement in L2 and in the H1 seminorm, relative to
  /// the norms of the exact displacement.
  std::pair<double, double>
  manufactured_errors(const Problem<3> &problem)
  {
    const auto               &dof_handler = problem.get_dof_handler();
    const MappingFE<3>        mapping(FE_SimplexP<3>(1));
    const QGaussSimplex<3>    quadrature(dof_handler.get_fe().degree + 2);
    ExactDisplacement<3>      exact;
    exact.set_time(1.);
    VectorType zero(problem.solution());
    zero = 0.;
    Vector<double> cellwise(dof_handler.get_triangulation().n_active_cells());
    const auto     norm = [&](const VectorType &u, const VectorTools::NormType type) {
      VectorTools::integrate_difference(mapping, dof_handler, u, exact, cellwise, quadrature, type);
      return VectorTools::compute_global_error(dof_handler.get_triangulation(), cellwise, type);
    };
    return {norm(problem.solution(), VectorTools::L2_norm) / norm(zero, VectorTools::L2_norm),
            norm(problem.solution(), VectorTools::H1_seminorm) /
              norm(zero, VectorTools::H1_seminorm)};
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
  // --stages: the set-up alone, one column per stage.
  const bool stages_only = argc > 1 && std::string(argv[1]) == "--stages";
  const bool p2_preconditioner =
    argc > 1 && std::string(argv[1]) == "--p2-preconditioner";
  if (stages_only || p2_preconditioner)
    {
      --argc;
      ++argv;
    }
  const char *stages_header =
    "scene,ranks,n,cells,dofs,read,order,check,build,partition,wait,"
    "describe,distribute,dofs_setup,system,null_space,operator,rest,"
    "t_setup,peak_memory_bytes";
  const char *header =
    "scene,ranks,n,cells,dofs,load_steps,newton_iterations,krylov_iterations,"
    "krylov_per_newton,amg_setups,t_setup,t_tangent_assembly,t_residual,t_line_search,"
    "t_preconditioner,t_krylov,t_output,t_total,t_spmv,"
    "assembly_per_newton_in_spmv,peak_memory_bytes,memory_per_dof_bytes,"
    "energy,error,degree,error_h1,t_contact";
  const char *p2_header = "scene,ranks,n,dofs,coarse_dofs,preconditioner,"
                          "t_setup,cg_iterations,t_solve,t_total,error";
  if (argc > 1 && std::string(argv[1]) == "--header")
    {
      if (root)
        std::cout << (stages_only         ? stages_header
                      : p2_preconditioner ? p2_header
                                          : header)
                  << std::endl;
      return 0;
    }
  return run_and_report(
    [&]() {
      if (argc < 3)
        throw InputError("usage: hyperelastic_benchmark bar|twist|twist_file|manufactured|ball N [DEGREE [SECTION/ENTRY=VALUE ...]]");
      const std::string  scene  = argv[1];
      const unsigned int n      = std::stoul(argv[2]);
      const unsigned int degree = argc > 3 ? std::stoul(argv[3]) : 1;
      std::string text = scene_text(scene, n, degree);
      for (int k = 4; k < argc; ++k)
        {
          const std::string setting = argv[k];
          const auto        slash = setting.find('/'), equal = setting.find('=');
          if (slash == std::string::npos || equal == std::string::npos ||
              equal < slash)
            throw InputError("extra setting '" + setting +
                             "' is not SECTION/ENTRY=VALUE");
          text += "subsection " + setting.substr(0, slash) + "\n  set " +
                  setting.substr(slash + 1, equal - slash - 1) + " = " +
                  setting.substr(equal + 1) + "\nend\n";
        }
      Parameters parameters;
      parameters.read_from_string(text);
      parameters.output.directory = "output_benchmark";
      parameters.output.verbose   = false;

      Timer      total;
      Problem<3> problem(parameters, MPI_COMM_WORLD, false);
      const auto material = create_material<3>(parameters.material);
      if (scene == "manufactured")
        problem.set_load_editor([&](BoundaryConditions<3> &bc) {
          for (auto &d : bc.dirichlet)
            d.displacement = std::make_unique<ExactDisplacement<3>>();
          bc.body_force = std::make_unique<ManufacturedBodyForce<3>>(*material);
        });
      if (stages_only)
        {
          problem.setup();
          const unsigned int n_cells = problem.get_dof_handler()
                                         .get_triangulation()
                                         .n_global_active_cells();
          const auto   n_dofs = problem.get_dof_handler().n_dofs();
          double       sum    = 0.;
          std::ostringstream row;
          row << std::setprecision(6) << scene << ","
              << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << "," << n
              << "," << n_cells << "," << n_dofs;
          for (const auto &[name, seconds] : problem.setup_stage_times())
            {
              const double slowest =
                Utilities::MPI::max(seconds, MPI_COMM_WORLD);
              sum += seconds;
              row << "," << slowest;
            }
          // The whole set-up: the slowest rank's sum (a rank waiting for
          // the reader counts its wait, not the reader's stages).
          const double total_setup = Utilities::MPI::max(sum, MPI_COMM_WORLD);
          const double memory      = peak_memory_bytes();
          if (root)
            std::cout << row.str() << "," << total_setup << "," << memory
                      << std::endl;
          return;
        }
      problem.run();
      total.stop();
      if (p2_preconditioner)
        {
          std::ostringstream prefix;
          prefix << std::setprecision(6) << scene << ","
                 << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << ","
                 << n << "," << problem.get_dof_handler().n_dofs();
          compare_p2_preconditioners(problem,
                                     parameters.linear_solver,
                                     prefix.str());
          return;
        }

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
      const auto errors = scene == "manufactured" ? manufactured_errors(problem) :
                                                    std::make_pair(0., 0.);
      const double error = scene == "bar" ? bar_error(problem) : errors.first;
      const double t_total = Utilities::MPI::max(total.wall_time(),
                                                 MPI_COMM_WORLD);
      const char *phases[] = {"mesh and setup",
                              "Dirichlet values",
                              "assembly",
                              "residual",
                              "line search",
                              "preconditioner setup",
                              "linear solve",
                              "output",
                              "contact"};
      std::map<std::string, double> t;
      for (const char *phase : phases)
        t[phase] = time(phase);
      // The tangent phase includes the prescribed values of each step.
      t["assembly"] += t["Dirichlet values"];
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
                  << std::setprecision(6) << error << "," << degree << ","
                  << errors.second << "," << t["contact"] << std::endl;
    },
    MPI_COMM_WORLD);
}
