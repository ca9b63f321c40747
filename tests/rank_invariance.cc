// Rank invariance: the same scene solved on all ranks of MPI_COMM_WORLD
// (METIS partitions) and on rank 0 alone must give the same energies,
// reactions, deformed bounding boxes and point displacements to 1e-10
// relative. Scenes: the homogeneous bar (exact answer) and a
// non-homogeneous clamped bar that is twisted, pulled, loaded by a body
// force and by a traction, in 2D and 3D, P1 and (twisted) P2, and (twisted)
// with the mixed formulation for every mixed element (decoupled neo-Hookean,
// nu = 0.4999, direct solver; the pressure range is compared too), and
// (twisted, P1) in implicit dynamics with each scheme (kinetic energy and
// linear and angular momentum compared too) and with stiffness warping
// (Newmark), whose vertex rows reach into the ghost layer.
//
// Usage: mpirun -np N rank_invariance
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/scene_text.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  constexpr double tolerance = 1e-10;

  std::string
  scene(const int          dim,
        const bool         twisted,
        const unsigned int degree,
        const std::string &base_name,
        const std::string &mixed_element = "",
        const std::string &scheme        = "",
        const std::string &model         = "")
  {
    const bool  three = dim == 3;
    const bool  mixed = !mixed_element.empty();
    std::string text =
      small_bar(dim, degree) +
      (mixed ? subsection("Problem",
                          entry("Formulation", "mixed") +
                            entry("Mixed element", mixed_element)) :
               std::string()) +
      subsection("Material",
                 entry("Model",
                       !model.empty() ? model :
                       mixed          ? "decoupled neo-Hookean" :
                       three ? "neo-Hookean" :
                               "corotational") +
                   entry("Young's modulus", "1") +
                   entry("Poisson's ratio", mixed ? "0.4999" : "0.3"));
    if (twisted)
      {
        text += subsection("Loading",
                           entry("Number of load steps", "3") +
                             entry("Constants", "a = 1.0") +
                             entry("Body force",
                                   three ? "0; 0; -0.05*t" : "0; -0.05*t"));
        text += dirichlet(1,
                          0,
                          three ? "x, y, z" : "x, y",
                          three ? "0; 0; 0" : "0; 0");
        text +=
          dirichlet(2,
                    1,
                    three ? "x, y, z" : "x, y",
                    three
                      ? "0.3*t; (cos(a*t) - 1)*(y - 0.5) - sin(a*t)*(z - 0.5);"
                        " sin(a*t)*(y - 0.5) + (cos(a*t) - 1)*(z - 0.5)"
                      : "0.2*t; 0.3*t");
        text +=
          subsection("Traction 1",
                     entry("Boundary id", "3") +
                       entry("Traction", three ? "0; 0.02*t; 0" : "0.02*t; 0"));
      }
    else
      {
        text += subsection("Loading", entry("Number of load steps", "2"));
        text += dirichlet(1, 0, "x", "0") + dirichlet(2, 2, "y", "0") +
                dirichlet(3, 1, "x", "1.5*t");
        if (three)
          text += dirichlet(4, 4, "z", "0");
      }
    if (!scheme.empty())
      text += subsection("Time integration",
                         entry("Scheme", scheme) + entry("Time step", "0.25") +
                           entry("End time", "1") +
                           entry("Initial velocity",
                                 three ? "0; 0.1*x; 0.05*x" : "0; 0.1*x"));
    return text + tight_solver(mixed ? "direct" : "cg") +
           subsection("Output",
                      entry("Directory", "rank_invariance_output") +
                        entry("Base name", base_name) +
                        entry("Write VTU", "false") +
                        entry("Verbose", "false"));
  }

  /// Named numbers a run produces: per load step the energy, the reactions
  /// and the deformed bounding box, then the displacement at a few vertices.
  struct Numbers
  {
    std::vector<std::string> names;
    std::vector<double>      values;
    void
    add(const std::string &name, const double value)
    {
      names.push_back(name);
      values.push_back(value);
    }
  };

  template <int dim>
  Numbers
  solve(const std::string &text, const MPI_Comm comm)
  {
    Parameters parameters;
    parameters.read_from_string(text);
    Problem<dim> problem(parameters, comm, false);
    problem.run();

    Numbers numbers;
    for (const auto &s : problem.summaries())
      {
        const std::string step = "step " + std::to_string(s.step) + ": ";
        numbers.add(step + "energy", s.energy);
        for (const auto &[id, force] : s.reactions)
          for (unsigned int d = 0; d < dim; ++d)
            numbers.add(step + "reaction " + std::to_string(id) + " " +
                          std::string(1, "xyz"[d]),
                        force[d]);
        for (unsigned int d = 0; d < dim; ++d)
          {
            numbers.add(step + "deformed min " + std::string(1, "xyz"[d]),
                        s.deformed_min[d]);
            numbers.add(step + "deformed max " + std::string(1, "xyz"[d]),
                        s.deformed_max[d]);
          }
        if (s.has_pressure)
          {
            numbers.add(step + "pressure min", s.pressure_min);
            numbers.add(step + "pressure max", s.pressure_max);
          }
        if (s.dynamic)
          {
            numbers.add(step + "kinetic energy", s.kinetic_energy);
            for (unsigned int d = 0; d < 3; ++d)
              {
                numbers.add(step + "momentum " + std::string(1, "xyz"[d]),
                            s.linear_momentum[d]);
                numbers.add(step + "angular momentum " +
                              std::string(1, "xyz"[d]),
                            s.angular_momentum[d]);
              }
          }
      }

    // Displacements at a few vertices, wherever they are owned.
    std::vector<Point<dim>> points(3);
    points[0][0] = 1.5;
    points[1][0] = 3.;
    points[2][0] = 3.;
    for (unsigned int d = 1; d < dim; ++d)
      {
        points[0][d] = 0.5;
        points[2][d] = 1.;
      }
    const auto &dof_handler = problem.get_dof_handler();
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        Tensor<1, dim> u;
        double         found = 0.;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              if (cell->vertex(v).distance(points[p]) < 1e-12 && found == 0.)
                {
                  for (unsigned int d = 0; d < dim; ++d)
                    u[d] = problem.solution()(cell->vertex_dof_index(v, d));
                  found = 1.;
                }
        // A vertex may be owned by several ranks' cells: take one copy.
        const double n_found = Utilities::MPI::sum(found, comm);
        const double owner =
          Utilities::MPI::max(found > 0.
                                ? double(Utilities::MPI::this_mpi_process(comm))
                                : -1.,
                              comm);
        AssertThrow(n_found > 0., ExcMessage("test vertex not in the mesh"));
        if (double(Utilities::MPI::this_mpi_process(comm)) != owner)
          u = 0.;
        u = Utilities::MPI::sum(u, comm);
        for (unsigned int d = 0; d < dim; ++d)
          numbers.add("u" + std::string(1, "xyz"[d]) + " at vertex " +
                        std::to_string(p),
                      u[d]);
      }
    return numbers;
  }

  /// Returns {numbers compared, numbers that differ}.
  template <int dim>
  void
  compare(Checker           &checker,
          const bool         twisted,
          const unsigned int degree,
          const std::string &mixed_element = "",
          const std::string &scheme        = "",
          const std::string &model         = "")
  {
    std::string tag = std::to_string(dim) + "d_" +
                      (twisted ? "twisted" : "bar") + "_P" +
                      std::to_string(degree);
    if (!scheme.empty())
      {
        tag += "_" + scheme + (model.empty() ? "" : "_" + model);
        for (char &c : tag)
          if (c == ' ')
            c = '_';
      }
    if (!mixed_element.empty())
      {
        tag = std::to_string(dim) + "d_twisted_mixed_" + mixed_element;
        for (char &c : tag)
          if (c == '/' || c == ' ')
            c = '_';
      }
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const Numbers parallel =
      solve<dim>(scene(dim,
                       twisted,
                       degree,
                       tag + "_np" + std::to_string(n_ranks),
                       mixed_element,
                       scheme,
                       model),
                 MPI_COMM_WORLD);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        const Numbers serial =
          solve<dim>(scene(dim,
                           twisted,
                           degree,
                           tag + "_np1",
                           mixed_element,
                           scheme,
                           model),
                     MPI_COMM_SELF);
        // Relative to the largest number of the same kind, so that values
        // that are zero by symmetry are judged against the problem's scale.
        double scale = 0.;
        for (const double v : serial.values)
          scale = std::max(scale, std::abs(v));
        checker.section(tag + ": " + std::to_string(n_ranks) +
                        " ranks against 1");
        AssertThrow(serial.values.size() == parallel.values.size(),
                    ExcMessage(
                      "the runs produced different numbers of values"));
        for (unsigned int i = 0; i < serial.values.size(); ++i)
          checker.close(serial.names[i],
                        parallel.values[i],
                        serial.values[i],
                        std::max(std::abs(serial.values[i]), 1e-3 * scale),
                        tolerance);
      }
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // The comparison runs on rank 0 (which also solves serially); the counts
  // are summed over the ranks so that every rank exits alike.
  Checker   checker(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  const int status = run_and_report(
    [&]() {
      // P1 homogeneous and twisted bars, and the twisted bars with P2.
      for (const auto &[twisted, degree] : {std::make_pair(false, 1u),
                                            std::make_pair(true, 1u),
                                            std::make_pair(true, 2u)})
        {
          compare<2>(checker, twisted, degree);
          compare<3>(checker, twisted, degree);
        }
      for (const std::string element :
           {"P1-bubble/P1", "P1/P1 stabilized", "P2/P1"})
        {
          compare<2>(checker, true, 1, element);
          compare<3>(checker, true, 1, element);
        }
      for (const std::string scheme :
           {"backward Euler", "Newmark", "implicit midpoint"})
        {
          compare<2>(checker, true, 1, "", scheme);
          compare<3>(checker, true, 1, "", scheme);
        }
      // Stiffness warping's vertex rows reach into the ghost layer.
      compare<2>(checker, true, 1, "", "Newmark", "stiffness warping");
      compare<3>(checker, true, 1, "", "Newmark", "stiffness warping");
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status, MPI_COMM_WORLD);
}
