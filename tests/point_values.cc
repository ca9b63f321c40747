// 'Output/Points': the displacement at given points against an exact field.
// A box (2D and 3D, P1) whose whole boundary follows the affine displacement
// u = t (A X + b) deforms homogeneously (constant F is an equilibrium for
// every hyperelastic model), and P1 reproduces the field exactly, so the
// reported values must match u at a mesh vertex, on an edge, on a face (3D)
// and inside a cell to 1e-12, at every load step and on any number of
// ranks. A point outside the mesh, or with the wrong number of coordinates,
// must be an input error naming 'Output/Points' on every rank, before the
// first load step.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/scene_text.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  // u = t (A X + b): a general affine map with det(I + A) > 0.
  constexpr double A[3][3] = {{0.20, 0.10, -0.05},
                              {-0.05, 0.15, 0.08},
                              {0.04, -0.06, 0.10}};
  constexpr double b[3]    = {0.01, -0.02, 0.03};

  std::string
  exact_expressions(const int dim)
  {
    const char        *names[3] = {"x", "y", "z"};
    std::ostringstream text;
    for (int i = 0; i < dim; ++i)
      {
        text << (i > 0 ? "; " : "") << "t*(" << b[i];
        for (int j = 0; j < dim; ++j)
          text << " + " << A[i][j] << "*" << names[j];
        text << ")";
      }
    return text.str();
  }

  template <int dim>
  Tensor<1, dim>
  exact(const std::vector<double> &X, const double t)
  {
    Tensor<1, dim> u;
    for (int i = 0; i < dim; ++i)
      {
        u[i] = b[i];
        for (int j = 0; j < dim; ++j)
          u[i] += A[i][j] * X[j];
        u[i] *= t;
      }
    return u;
  }

  /// The box [0,2] x [0,1] (x [0,1]) with cells of size 0.5, its whole
  /// boundary (ids 0 ... 2 dim - 1) moved with the exact field.
  std::string
  scene(const int dim, const std::string &points, const std::string &name)
  {
    std::string text =
      subsection("Problem", entry("Dimension", std::to_string(dim))) +
      subsection("Mesh",
                 entry("Source", "box") +
                   entry("Lower corner", dim == 3 ? "0, 0, 0" : "0, 0") +
                   entry("Upper corner", dim == 3 ? "2, 1, 1" : "2, 1") +
                   entry("Subdivisions", dim == 3 ? "4, 2, 2" : "4, 2")) +
      subsection("Material",
                 entry("Model", "neo-Hookean") + entry("Young's modulus", "1") +
                   entry("Poisson's ratio", "0.3")) +
      subsection("Loading", entry("Number of load steps", "2"));
    const std::string components = dim == 3 ? "x, y, z" : "x, y";
    for (int id = 0; id < 2 * dim; ++id)
      text += dirichlet(id + 1, id, components, exact_expressions(dim));
    text += tight_solver("direct");
    text +=
      subsection("Output",
                 entry("Directory", "point_values_output") +
                   entry("Base name", name) + entry("Write VTU", "false") +
                   entry("Verbose", "false") + entry("Points", points));
    return text;
  }

  template <int dim>
  void
  check_exact(Checker &checker, const unsigned int n_ranks)
  {
    // A vertex, a point on a cell edge, a point on a face (3D: the plane
    // x = 1 is made of tetrahedron faces), points inside cells, a boundary
    // point and a corner.
    std::vector<std::pair<std::string, std::vector<double>>> points;
    if (dim == 2)
      points = {{"vertex", {1., 0.5}},
                {"edge", {0.25, 0.5}},
                {"inside", {0.3, 0.1}},
                {"inside", {1.62, 0.77}},
                {"boundary edge", {2., 0.7}},
                {"corner", {2., 1.}}};
    else
      points = {{"vertex", {1., 0.5, 0.5}},
                {"edge", {0.25, 0.5, 0.5}},
                {"face", {1., 0.3, 0.1}},
                {"inside", {0.3, 0.1, 0.2}},
                {"inside", {1.62, 0.77, 0.41}},
                {"boundary face", {2., 0.7, 0.2}},
                {"corner", {2., 1., 1.}}};
    std::ostringstream text;
    text << std::setprecision(17);
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        text << (k > 0 ? "; " : "");
        for (int d = 0; d < dim; ++d)
          text << (d > 0 ? ", " : "") << points[k].second[d];
      }
    const std::string name =
      "exact_" + std::to_string(dim) + "d_np" + std::to_string(n_ranks);

    Parameters parameters;
    parameters.read_from_string(scene(dim, text.str(), name), ".", name);
    Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
    problem.run();

    checker.is_true(std::to_string(dim) + "D: two load steps",
                    problem.summaries().size() == 2);
    for (const auto &s : problem.summaries())
      {
        checker.is_true("one value per point",
                        s.point_displacements.size() == points.size());
        for (unsigned int k = 0;
             k < std::min(points.size(), s.point_displacements.size());
             ++k)
          {
            const Tensor<1, dim> error =
              s.point_displacements[k] -
              exact<dim>(points[k].second, s.load_factor);
            std::ostringstream what;
            what << std::to_string(dim) << "D t = " << s.load_factor << ' '
                 << points[k].first << " (point " << k + 1
                 << "): |u - u_exact|";
            checker.at_most(what.str(), error.norm(), 1e-12);
          }
      }

    // The CSV has the columns point<k>_u<axis> at the end of the row.
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::ifstream csv("point_values_output/" + name + ".csv");
        std::string   header;
        std::getline(csv, header);
        const std::string last = "point" + std::to_string(points.size()) +
                                 "_u" + std::string(1, "xyz"[dim - 1]);
        checker.is_true("CSV header ends with " + last,
                        header.size() >= last.size() &&
                          header.compare(header.size() - last.size(),
                                         last.size(),
                                         last) == 0 &&
                          header.find(",point1_ux,point1_uy") !=
                            std::string::npos);
      }
  }

  /// Expects InputError containing every string of @p expected on every
  /// rank, thrown before any load step.
  template <int dim>
  void
  check_error(Checker                        &checker,
              const std::string              &what,
              const std::string              &points,
              const std::vector<std::string> &expected)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    bool           ok   = false;
    std::string    message;
    try
      {
        Parameters parameters;
        parameters.read_from_string(scene(dim, points, "error"), ".", "error");
        Problem<dim> problem(parameters, comm, false);
        try
          {
            problem.run();
          }
        catch (const InputError &e)
          {
            message = e.what();
            ok      = problem.summaries().empty();
          }
      }
    catch (const InputError &e) // from the parser
      {
        message = e.what();
        ok      = true;
      }
    for (const auto &s : expected)
      ok = ok && message.find(s) != std::string::npos;
    // Every rank must have thrown (and returned: no hang).
    const bool all = Utilities::MPI::min(ok ? 1 : 0, comm) == 1;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << "  " << what << ": " << message << std::endl;
    checker.is_true(what + ": InputError on every rank", all);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int n_ranks            = Utilities::MPI::n_mpi_processes(comm);
  Checker            checker(Utilities::MPI::this_mpi_process(comm) == 0);

  const int status = run_and_report(
    [&]() {
      check_exact<2>(checker, n_ranks);
      check_exact<3>(checker, n_ranks);
      check_error<2>(checker,
                     "2D point outside",
                     "1, 0.5; 3, 0.5",
                     {"Output/Points", "(3, 0.5)", "point 2", "no cell"});
      check_error<3>(checker,
                     "3D point outside",
                     "1, 0.5, 1.5",
                     {"Output/Points", "(1, 0.5, 1.5)", "no cell"});
      check_error<2>(checker,
                     "3 coordinates in 2D",
                     "1, 0.5, 0",
                     {"Output/Points", "(1, 0.5, 0)", "3 coordinates"});
      check_error<2>(checker,
                     "not a number",
                     "1, 0.5; 1, a",
                     {"Output/Points", "'1, a'"});
    },
    comm);
  return checker.exit_code(status);
}
