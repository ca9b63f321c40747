// Problem/Reference = loaded: the backward-displacement fixed point with
// Aitken relaxation (unloaded_shape.h), and the reference mesh written with
// the gmsh API into a copy of the loaded mesh file.
#include <deal.II/base/mpi.h>

#include <hyperelastic/assembly/assembly_tools.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/inverse/unloaded_shape.h>
#include <hyperelastic/mesh/gmsh_session.h>

#include <array>
#include <chrono>
#include <cmath>
#include <gmsh.h>
#include <iomanip>
#include <map>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// Calls @p visit(cell, v) for every vertex of the locally owned cells
    /// whose displacement dofs this rank owns, once each.
    template <int dim, typename Visit>
    void
    for_each_owned_vertex(const DoFHandler<dim> &dof_handler, Visit &&visit)
    {
      std::vector<bool> seen(dof_handler.get_triangulation().n_vertices(),
                             false);
      const IndexSet   &owned = dof_handler.locally_owned_dofs();
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            if (!seen[cell->vertex_index(v)] &&
                owned.is_element(cell->vertex_dof_index(v, 0)))
              {
                seen[cell->vertex_index(v)] = true;
                visit(cell, v);
              }
    }

    /// The reference positions of the vertices on their displacement dofs
    /// (0 on every other dof), owned entries.
    template <int dim>
    VectorType
    vertex_positions(const DoFHandler<dim> &dof_handler, const MPI_Comm comm)
    {
      VectorType X(dof_handler.locally_owned_dofs(), comm);
      for_each_owned_vertex(dof_handler, [&](const auto &cell, unsigned v) {
        for (unsigned int d = 0; d < dim; ++d)
          X[cell->vertex_dof_index(v, d)] = cell->vertex(v)[d];
      });
      X.compress(VectorOperation::insert);
      return X;
    }

    /// r = x^ - (X + u) on the vertices' displacement dofs (0 elsewhere).
    template <int dim>
    VectorType
    position_misfit(const Problem<dim> &problem,
                    const VectorType   &target,
                    const MPI_Comm      comm)
    {
      const DoFHandler<dim> &dof_handler = problem.get_dof_handler();
      VectorType             r           = vertex_positions(dof_handler, comm);
      r *= -1.;
      r += target;
      const VectorType &u = problem.solution();
      for_each_owned_vertex(dof_handler, [&](const auto &cell, unsigned v) {
        for (unsigned int d = 0; d < dim; ++d)
          r[cell->vertex_dof_index(v, d)] -= u(cell->vertex_dof_index(v, d));
      });
      r.compress(VectorOperation::insert);
      return r;
    }

    /// The largest vertex distance |r_v| (over the ranks).
    template <int dim>
    double
    largest_distance(const DoFHandler<dim> &dof_handler, const VectorType &r)
    {
      double largest = 0.;
      for_each_owned_vertex(dof_handler, [&](const auto &cell, unsigned v) {
        double squared = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          squared += std::pow(r[cell->vertex_dof_index(v, d)], 2);
        largest = std::max(largest, std::sqrt(squared));
      });
      return Utilities::MPI::max(largest, dof_handler.get_communicator());
    }

    double
    seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
        .count();
    }
  } // namespace

  template <int dim>
  UnloadedShape
  find_unloaded_shape(Problem<dim>               &problem,
                      const ProblemParameters    &parameters,
                      dealii::ConditionalOStream &pcout)
  {
    const auto start = std::chrono::steady_clock::now();
    problem.setup();
    const DoFHandler<dim> &dof_handler = problem.get_dof_handler();
    const MPI_Comm         comm        = dof_handler.get_communicator();
    const VectorType       target      = vertex_positions(dof_handler, comm);
    const double           diagonal    = reference_diameter(dof_handler);
    UnloadedShape          shape;
    shape.loaded = target;
    VectorType previous;
    double     omega = 1.;
    for (unsigned int k = 1;; ++k)
      {
        const auto solve_start = std::chrono::steady_clock::now();
        problem.run();
        if (k == 1)
          shape.first_solve_seconds = seconds_since(solve_start);
        shape.iterations          = k;
        const VectorType r        = position_misfit(problem, target, comm);
        const double     distance = largest_distance(dof_handler, r) / diagonal;
        shape.distances.push_back(distance);
        std::ostringstream line;
        line << "Reference = loaded: forward solve " << k
             << ", largest vertex distance to the loaded mesh "
             << std::setprecision(3) << std::scientific << distance
             << " of the diagonal";
        pcout << line.str() << std::endl;
        if (distance <= parameters.reference_tolerance)
          break;
        if (k >= parameters.reference_iterations)
          throw ConvergenceFailure(
            "Problem/Reference = loaded: the forward solution is still " +
            std::to_string(distance) +
            " of the mesh's diagonal from the loaded mesh after " +
            std::to_string(k) +
            " forward solves ('Problem/Reference iterations')");
        if (k > 1)
          {
            // Aitken: w_k = -w_(k-1) r_(k-1).(r_k - r_(k-1)) / |r_k -
            // r_(k-1)|^2.
            VectorType change(r);
            change -= previous;
            const double squared = change * change;
            if (squared > 0.)
              omega = -omega * (previous * change) / squared;
            // Aitken's factor kept in (0, 2]: a reversed or very long
            // step would fold the moved mesh.
            if (!(omega > 0.05))
              omega = 0.05;
            omega = std::min(omega, 2.);
          }
        shape.relaxation.push_back(omega);
        previous = r;
        VectorType step(r);
        step *= omega;
        VectorType ghosted(problem.solution());
        ghosted = step;
        problem.move_reference(ghosted);
      }
    shape.seconds = seconds_since(start);
    return shape;
  }

  template <int dim>
  void
  write_reference_mesh(const Problem<dim> &problem,
                       const VectorType   &loaded,
                       const std::string  &mesh_file,
                       const std::string  &path)
  {
    const DoFHandler<dim> &dof_handler = problem.get_dof_handler();
    const MPI_Comm         comm        = dof_handler.get_communicator();
    // (loaded x, y, z; reference x, y, z) of every owned vertex, on rank 0.
    std::vector<double> pairs;
    for_each_owned_vertex(dof_handler, [&](const auto &cell, unsigned v) {
      std::array<double, 6> pair{};
      for (unsigned int d = 0; d < dim; ++d)
        {
          pair[d]     = loaded[cell->vertex_dof_index(v, d)];
          pair[3 + d] = cell->vertex(v)[d];
        }
      pairs.insert(pairs.end(), pair.begin(), pair.end());
    });
    const std::vector<std::vector<double>> all =
      Utilities::MPI::gather(comm, pairs, 0);
    std::string problem_text;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          // The loaded positions are the mesh file's node coordinates as
          // the scene read them.
          std::map<std::array<double, 3>, std::array<double, 3>> reference;
          for (const auto &rank : all)
            for (std::size_t i = 0; i + 6 <= rank.size(); i += 6)
              reference[{{rank[i], rank[i + 1], rank[i + 2]}}] = {
                {rank[i + 3], rank[i + 4], rank[i + 5]}};
          const GmshSession session;
          gmsh::open(mesh_file);
          std::vector<std::size_t> tags;
          std::vector<double>      coordinates, parametric;
          gmsh::model::mesh::getNodes(tags, coordinates, parametric);
          std::size_t matched = 0;
          for (std::size_t n = 0; n < tags.size(); ++n)
            {
              const std::array<double, 3> x = {{coordinates[3 * n],
                                                coordinates[3 * n + 1],
                                                coordinates[3 * n + 2]}};
              // A node of no cell (a geometry point) stays where it is.
              const auto found = reference.find(x);
              if (found == reference.end())
                continue;
              ++matched;
              const std::array<double, 3> &X = found->second;
              gmsh::model::mesh::setNode(tags[n], {X[0], X[1], X[2]}, {});
            }
          if (matched != reference.size())
            throw std::runtime_error(
              std::to_string(reference.size() - matched) + " of the mesh's " +
              std::to_string(reference.size()) + " vertices are no node of " +
              mesh_file);
          gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
          gmsh::option::setNumber("Mesh.Binary", 0);
          // Every element, also those of no physical group.
          gmsh::option::setNumber("Mesh.SaveAll", 1);
          gmsh::write(path);
        }
      catch (const std::exception &e)
        {
          problem_text =
            "writing the reference mesh " + path + ": " + exception_message(e);
        }
      catch (...)
        {
          problem_text =
            "writing the reference mesh " + path + " failed (the gmsh API)";
        }
    throw_input_error_of_first_rank(problem_text, comm);
  }

  template UnloadedShape
  find_unloaded_shape(Problem<2> &,
                      const ProblemParameters &,
                      dealii::ConditionalOStream &);
  template UnloadedShape
  find_unloaded_shape(Problem<3> &,
                      const ProblemParameters &,
                      dealii::ConditionalOStream &);
  template void
  write_reference_mesh(const Problem<2> &,
                       const VectorType &,
                       const std::string &,
                       const std::string &);
  template void
  write_reference_mesh(const Problem<3> &,
                       const VectorType &,
                       const std::string &,
                       const std::string &);
} // namespace hyperelastic
