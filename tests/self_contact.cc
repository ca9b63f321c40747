// Self-contact and contact between bodies of one mesh (issue 27), whole
// scenes:
//   two_blocks DIM MESH  two separate blocks in one gmsh file, the lower one
//       clamped at its bottom, the upper one pressed onto it by its top face,
//       frictionless: the contact forces on the two bodies are equal and
//       opposite (1e-8 of their size) and equal the load applied through
//       the top face (its support reaction, 1e-8), the boundary is free of
//       intersections at every converged step and contact_min_distance > 0;
//   bent_bar MESH        a C-shaped bar (2D) bent by pulling the outer arcs
//       next to its ends towards each other until the end faces press on
//       each other: completes, every converged state free of intersections
//       with the self pairs' smallest distance > 0, and the ends do touch
//       (self pairs active, end gap below d_hat);
//   hollow_ball DIM MESH a hollow disk (2D) or ball (3D) squashed by a plate
//       until its inner surfaces meet: the same checks.
// The intersection check is the test's own: every two deformed boundary
// segments (2D) or triangles (3D) without a common vertex, candidates from
// an R-tree of their boxes, tested exactly with orientation signs.
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/rtree.h>

#include <hyperelastic/contact/self_contact.h>
#include <hyperelastic/mesh/mesh_distribution.h>

#include "support/checker.h"
#include "support/scene_run.h"
#include "support/scene_text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using namespace hyperelastic;
  using namespace hyperelastic::testing;

  /// The deformed boundary faces of the whole mesh on every rank: dim
  /// points per face, and the faces' vertex first dofs (to tell neighbours).
  template <int dim>
  struct DeformedBoundary
  {
    std::vector<Point<dim>>              points;
    std::vector<types::global_dof_index> ids;
    unsigned int
    n_faces() const
    {
      return ids.size() / dim;
    }
  };

  template <int dim>
  DeformedBoundary<dim>
  deformed_boundary(const DoFHandler<dim> &dof_handler, const VectorType &u)
  {
    std::vector<double> mine;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() ||
                face->boundary_id() == partition_edge_boundary_id)
              continue;
            for (unsigned int v = 0; v < face->n_vertices(); ++v)
              {
                mine.push_back(face->vertex_dof_index(v, 0));
                for (unsigned int d = 0; d < dim; ++d)
                  mine.push_back(face->vertex(v)[d] +
                                 u(face->vertex_dof_index(v, d)));
              }
          }
    DeformedBoundary<dim> b;
    for (const auto &list : Utilities::MPI::all_gather(MPI_COMM_WORLD, mine))
      for (std::size_t i = 0; i < list.size(); i += dim + 1)
        {
          b.ids.push_back(static_cast<types::global_dof_index>(list[i]));
          Point<dim> p;
          for (unsigned int d = 0; d < dim; ++d)
            p[d] = list[i + 1 + d];
          b.points.push_back(p);
        }
    return b;
  }

  double
  orient2d(const Point<2> &a, const Point<2> &b, const Point<2> &c)
  {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }

  double
  orient3d(const Point<3> &a,
           const Point<3> &b,
           const Point<3> &c,
           const Point<3> &d)
  {
    return (b - a) * cross_product_3d(c - a, d - a);
  }

  /// Whether segment p q passes through the inside of triangle a b c (3D;
  /// touching and coplanar configurations do not count: the distances > 0
  /// are checked separately).
  bool
  segment_crosses_triangle(const Point<3> &p,
                           const Point<3> &q,
                           const Point<3> &a,
                           const Point<3> &b,
                           const Point<3> &c)
  {
    const double sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
    if (!(sp * sq < 0.))
      return false;
    const double s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c),
                 s3 = orient3d(p, q, c, a);
    return (s1 > 0. && s2 > 0. && s3 > 0.) || (s1 < 0. && s2 < 0. && s3 < 0.);
  }

  /// The number of pairs of boundary faces without a common vertex that
  /// cross (segments: each through the other's line inside both;
  /// triangles: an edge of one through the inside of the other).
  template <int dim>
  unsigned int
  count_intersections(const DeformedBoundary<dim> &b)
  {
    using Entry = std::pair<BoundingBox<dim>, unsigned int>;
    std::vector<Entry> boxes;
    for (unsigned int f = 0; f < b.n_faces(); ++f)
      boxes.emplace_back(BoundingBox<dim>(std::vector<Point<dim>>(
                           b.points.begin() + f * dim,
                           b.points.begin() + (f + 1) * dim)),
                         f);
    const auto         tree = pack_rtree(boxes);
    unsigned int       n    = 0;
    std::vector<Entry> found;
    for (unsigned int f = 0; f < b.n_faces(); ++f)
      {
        found.clear();
        tree.query(boost::geometry::index::intersects(boxes[f].first),
                   std::back_inserter(found));
        for (const auto &[box, g] : found)
          {
            if (g <= f)
              continue;
            bool neighbours = false;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                neighbours =
                  neighbours || b.ids[f * dim + i] == b.ids[g * dim + j];
            if (neighbours)
              continue;
            const Point<dim> *P = &b.points[f * dim], *Q = &b.points[g * dim];
            if constexpr (dim == 2)
              {
                const double a = orient2d(P[0], P[1], Q[0]),
                             c = orient2d(P[0], P[1], Q[1]),
                             d = orient2d(Q[0], Q[1], P[0]),
                             e = orient2d(Q[0], Q[1], P[1]);
                n += (a * c < 0. && d * e < 0.) ? 1 : 0;
              }
            else
              {
                bool hit = false;
                for (unsigned int k = 0; k < 3 && !hit; ++k)
                  hit = segment_crosses_triangle(
                          P[k], P[(k + 1) % 3], Q[0], Q[1], Q[2]) ||
                        segment_crosses_triangle(
                          Q[k], Q[(k + 1) % 3], P[0], P[1], P[2]);
                n += hit ? 1 : 0;
              }
          }
      }
    return n;
  }

  template <int dim>
  double
  column(const StepSummary<dim> &s, const std::string &name)
  {
    for (const auto &c : s.more)
      if (c.name == name)
        return c.value;
    return std::numeric_limits<double>::quiet_NaN();
  }

  /// Runs @p scene, checking every converged state: no intersection, the
  /// CSV's contact_min_distance > 0, and the self pairs' own smallest
  /// distance > 0. Returns the problem.
  template <int dim>
  std::unique_ptr<Problem<dim>>
  run_checked(Checker           &checker,
              const std::string &name,
              const std::string &scene)
  {
    Parameters parameters;
    parameters.read_from_string(scene);
    auto problem =
      std::make_unique<Problem<dim>>(parameters, MPI_COMM_WORLD, false);
    unsigned int intersections = 0, steps = 0;
    double       smallest      = std::numeric_limits<double>::infinity();
    double       self_smallest = smallest;
    std::unique_ptr<SelfContact<dim>> self;
    problem->set_step_observer([&](const StepSummary<dim> &s) {
      if (!self)
        self = std::make_unique<SelfContact<dim>>(parameters.contact,
                                                  problem->get_dof_handler(),
                                                  LameParameters());
      ++steps;
      intersections += count_intersections(
        deformed_boundary(problem->get_dof_handler(), problem->solution()));
      smallest = std::min(smallest, column(s, "contact_min_distance"));
      StepSummary<dim> own;
      self->summarize(problem->solution(), own);
      self_smallest =
        std::min(self_smallest, column(own, "contact_min_distance"));
    });
    problem->run();
    checker.at_least(name + ": converged load steps",
                     steps,
                     parameters.loading.n_load_steps);
    checker.is_true(name +
                      ": no boundary intersection at any converged step (" +
                      std::to_string(intersections) + " found)",
                    intersections == 0);
    checker.above(name + ": smallest contact_min_distance over the steps",
                  smallest,
                  0.);
    checker.above(name + ": smallest self-pair distance over the steps",
                  self_smallest,
                  0.);
    return problem;
  }

  /// The scene's common sections; @p tight: Newton to round-off (the force
  /// balance checks), otherwise its default tolerances with up to 40
  /// iterations (the folds of the bent and squashed scenes).
  std::string
  common(const int          dim,
         const std::string &mesh,
         const unsigned int steps,
         const bool         tight = false)
  {
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh", entry("Source", "file") + entry("File", mesh)) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1") +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading",
                      entry("Number of load steps", std::to_string(steps))) +
           subsection("Output", entry("Write VTU", "false")) +
           (tight
              ? subsection("Newton",
                           entry("Max iterations", "40") +
                             entry("Absolute residual tolerance", "1e-13") +
                             entry("Relative residual tolerance", "1e-11")) +
                  subsection("Linear solver",
                             entry("Relative tolerance", "1e-10"))
              : subsection("Newton", entry("Max iterations", "40")));
  }

  template <int dim>
  void
  two_blocks(Checker &checker, const std::string &mesh)
  {
    const std::string down       = dim == 2 ? "0; -0.06*t" : "0; 0; -0.06*t";
    const std::string zero       = dim == 2 ? "0; 0" : "0; 0; 0";
    const std::string components = dim == 2 ? "x, y" : "x, y, z";
    const std::string scene =
      common(dim, mesh, 4, true) +
      subsection("Dirichlet 1",
                 entry("Boundary id", "1") + entry("Components", components) +
                   entry("Displacement", zero)) +
      subsection("Dirichlet 2",
                 entry("Boundary id", "2") + entry("Components", components) +
                   entry("Displacement", down)) +
      subsection("Contact",
                 entry("Barrier distance", "0.005") +
                   entry("Self contact", "true"));
    const std::string name = std::to_string(dim) + "D two blocks";
    Parameters        parameters;
    parameters.read_from_string(scene);
    const auto problem = run_checked<dim>(checker, name, scene);

    // The contact forces on each body at the last state: the upper block's
    // vertices lie above 0.51 (reference).
    const DoFHandler<dim> &dh = problem->get_dof_handler();
    // The scene's term (E = 1, nu = 0.3: the same automatic kappa).
    const SelfContact<dim> self(parameters.contact,
                                dh,
                                LameParameters::from_young_poisson(1., 0.3));
    VectorType             forces(dh.locally_owned_dofs(), MPI_COMM_WORLD);
    self.contact_forces(problem->solution(), forces);
    forces.compress(VectorOperation::add);
    Tensor<1, dim>                    lower, upper;
    std::set<types::global_dof_index> seen;
    for (const auto &cell : dh.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const types::global_dof_index first = cell->vertex_dof_index(v, 0);
            if (!dh.locally_owned_dofs().is_element(first) ||
                !seen.insert(first).second)
              continue;
            Tensor<1, dim> f;
            for (unsigned int d = 0; d < dim; ++d)
              f[d] = forces(cell->vertex_dof_index(v, d));
            (cell->vertex(v)[dim - 1] > 0.51 ? upper : lower) += f;
          }
    lower = Utilities::MPI::sum(lower, MPI_COMM_WORLD);
    upper = Utilities::MPI::sum(upper, MPI_COMM_WORLD);
    Tensor<1, dim> reaction;
    for (const auto &[id, r] : problem->summaries().back().reactions)
      if (id == 2)
        reaction = r;
    checker.above(name + ": contact force on the upper block, vertical",
                  upper[dim - 1],
                  1e-3);
    checker.at_most(name + ": |F_lower + F_upper| / |F_upper|",
                    (lower + upper).norm() / upper.norm(),
                    1e-8);
    checker.at_most(name + ": |F_upper + support reaction on its top| / "
                           "|F_upper|",
                    (upper + reaction).norm() / upper.norm(),
                    1e-8);
    // The intersection check can fail: without self contact the upper
    // block's bottom passes into the lower block.
    std::string without = scene;
    without.replace(without.find("Self contact = true"),
                    std::string("Self contact = true").size(),
                    "Self contact = false");
    Parameters through;
    through.read_from_string(without);
    Problem<dim> passing(through, MPI_COMM_WORLD, false);
    unsigned int crossings = 0;
    passing.set_step_observer([&](const StepSummary<dim> &) {
      crossings += count_intersections(
        deformed_boundary(passing.get_dof_handler(), passing.solution()));
    });
    passing.run();
    checker.above(name + " without self contact: intersections found by the "
                         "test's check",
                  crossings,
                  0.);
    checker.note(name + ": vertical contact force " +
                 std::to_string(upper[dim - 1]) + ", " +
                 std::to_string(column(problem->summaries().back(),
                                       "contact_active_pairs")) +
                 " active pairs");
  }

  /// The plates' Contact entries: @p n obstacles (planes) given as text.
  std::string
  plate(const unsigned int k,
        const std::string &point,
        const std::string &normal,
        const std::string &motion)
  {
    return subsection("Obstacle " + std::to_string(k),
                      entry("Type", "plane") + entry("Point", point) +
                        entry("Normal", normal) + entry("Motion", motion));
  }

  void
  bent_bar(Checker &checker, const std::string &mesh)
  {
    // The C's slot (0.1 wide at the top) closes as its outer arcs next to
    // the ends (ids 2, 3) are pulled towards each other by 0.06 each.
    const std::string scene =
      common(2, mesh, 10) +
      subsection("Dirichlet 1",
                 entry("Boundary id", "1") + entry("Components", "x, y") +
                   entry("Displacement", "0; 0")) +
      subsection("Dirichlet 2",
                 entry("Boundary id", "2") + entry("Components", "x, y") +
                   entry("Displacement", "-0.06*t; 0")) +
      subsection("Dirichlet 3",
                 entry("Boundary id", "3") + entry("Components", "x, y") +
                   entry("Displacement", "0.06*t; 0")) +
      subsection("Contact",
                 entry("Barrier distance", "0.004") +
                   entry("Self contact", "true"));
    Parameters parameters;
    parameters.read_from_string(scene);
    const auto     problem = run_checked<2>(checker, "bent bar", scene);
    SelfContact<2> self(parameters.contact,
                        problem->get_dof_handler(),
                        LameParameters());
    StepSummary<2> own;
    self.summarize(problem->solution(), own);
    checker.above("bent bar: self pairs active at the end (the ends touch)",
                  column(own, "contact_active_pairs"),
                  0.);
    checker.below("bent bar: the end faces' gap / d_hat",
                  column(own, "contact_min_distance") / 0.004,
                  1.);
  }

  template <int dim>
  void
  hollow_ball(Checker &checker, const std::string &mesh)
  {
    // The plate above the top (r = 1) comes down by 1.45: the walls (0.3
    // thick) are squashed onto each other, the inner surface (r = 0.7)
    // meets itself.
    const std::string scene =
      common(dim, mesh, dim == 2 ? 16 : 16) +
      subsection("Dirichlet 1",
                 entry("Boundary id", "1") +
                   entry("Components", dim == 2 ? "x, y" : "x, y, z") +
                   entry("Displacement", dim == 2 ? "0; 0" : "0; 0; 0")) +
      subsection("Contact",
                 entry("Barrier distance", "0.004") +
                   entry("Self contact", "true") +
                   (dim == 2
                      ? plate(1, "0, 1.002", "0, -1", "0; -1.45*t")
                      : plate(1, "0, 0, 1.002", "0, 0, -1", "0; 0; -1.45*t")));
    Parameters parameters;
    parameters.read_from_string(scene);
    const std::string name    = std::to_string(dim) + "D hollow ball";
    const auto        problem = run_checked<dim>(checker, name, scene);
    SelfContact<dim>  self(parameters.contact,
                          problem->get_dof_handler(),
                          LameParameters());
    StepSummary<dim>  own;
    self.summarize(problem->solution(), own);
    checker.above(name + ": self pairs active at the end (inner surfaces meet)",
                  column(own, "contact_active_pairs"),
                  0.);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Checker checker(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  const std::string which  = argc > 1 ? argv[1] : "";
  const int         status = run_and_report(
    [&]() {
      if (which == "two_blocks" && argc > 3)
        {
          if (std::atoi(argv[2]) == 2)
            two_blocks<2>(checker, argv[3]);
          else
            two_blocks<3>(checker, argv[3]);
        }
      else if (which == "bent_bar" && argc > 2)
        bent_bar(checker, argv[2]);
      else if (which == "hollow_ball" && argc > 3)
        {
          if (std::atoi(argv[2]) == 2)
            hollow_ball<2>(checker, argv[3]);
          else
            hollow_ball<3>(checker, argv[3]);
        }
      else
        throw InputError("usage: self_contact two_blocks DIM MESH | bent_bar "
                                 "MESH | hollow_ball DIM MESH");
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
