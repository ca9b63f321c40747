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
//       until its inner surfaces meet: the same checks;
//   concentric_shells MESH  two concentric hemispherical shells (a
//       quarter), 0.02 apart, with parallel facing edges on the symmetry
//       planes, the outer dented onto the inner (2 ranks): the reference
//       check passes (it refused them, issue 43), the press completes free
//       of intersections with contact_min_distance > 0 and the shells
//       touch (self pairs active, gap below d_hat);
//   automatic_barrier MESH  two blocks of one mesh 4e-4 apart, far below
//       1e-3 of the diagonal, 'Barrier distance' automatic: d_hat is half
//       the gap (1e-9), named so, and pressing them together completes
//       free of intersections;
//   friction DIM MESH    a unit block on a long block (one mesh, the lower
//       one clamped), 'Self contact friction coefficient' = 0.5, gravity
//       10, backward Euler: sliding at 2 it decelerates at mu g (2 %);
//       pulled by 0.8 mu N it sticks (creeps slower than eps_v once the
//       pull's shear wave has died out, t in [0.3, 0.5]); pulled by
//       1.2 mu N it accelerates at 0.2 mu g (2 %) (as the obstacle test of
//       tests/contact.cc).
// The intersection check is the test's own: every two deformed boundary
// segments (2D) or triangles (3D) without a common vertex, candidates from
// an R-tree of their boxes, tested exactly with orientation signs.
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/rtree.h>

#include <hyperelastic/contact/self_contact.h>
#include <hyperelastic/mesh/mesh_distribution.h>

#include "support/checker.h"
#include "support/owned_vertices.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

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
      self_smallest = std::min(self_smallest,
                               self->measure(problem->solution()).min_distance);
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
    self.contact_forces(problem->solution(), 1., forces);
    forces.compress(VectorOperation::add);
    Tensor<1, dim>                    lower, upper;
    testing::for_each_owned_vertex(
      dh, [&](const auto &cell, const unsigned int v) {
        Tensor<1, dim> f;
        for (unsigned int d = 0; d < dim; ++d)
          f[d] = forces(cell->vertex_dof_index(v, d));
        (cell->vertex(v)[dim - 1] > 0.51 ? upper : lower) += f;
      });
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

  /// A unit block (E = 1e4, density 1) resting on a long one (clamped at
  /// its bottom), one mesh (meshes/block_on_block_DIMd.msh), friction mu =
  /// 0.5 between them, gravity 10 and the horizontal body force @p pull on
  /// the upper block, which starts with the horizontal velocity @p v0;
  /// backward Euler, h = 0.01, to t = @p end.
  template <int dim>
  std::string
  block_on_block(const std::string &mesh,
                 const double       pull,
                 const double       v0,
                 const double       end = 0.3)
  {
    const std::string upper = std::string(dim == 2 ? "y" : "z") + " > 0.502";
    const std::string rest  = dim == 2 ? "" : "; 0";
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh", entry("Source", "file") + entry("File", mesh)) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1e4") +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading",
                      entry("Body force",
                            upper + " ? " + number(pull) + " : 0" + rest +
                              "; -10")) +
           subsection("Output", entry("Write VTU", "false")) +
           subsection("Dirichlet 1",
                      entry("Boundary id", "1") +
                        entry("Components", dim == 2 ? "x, y" : "x, y, z") +
                        entry("Displacement", dim == 2 ? "0; 0" : "0; 0; 0")) +
           subsection("Contact",
                      entry("Barrier distance", "0.005") +
                        entry("Self contact", "true") +
                        entry("Self contact friction coefficient", "0.5")) +
           subsection("Time integration",
                      entry("Scheme", "backward Euler") +
                        entry("Density", "1") + entry("Time step", "0.01") +
                        entry("End time", number(end)) +
                        entry("Initial velocity",
                              upper + " ? " + number(v0) + " : 0" + rest +
                                "; 0"));
  }

  template <int dim>
  void
  friction(Checker &checker, const std::string &mesh)
  {
    const std::string tag  = std::to_string(dim) + "D block on a block: ";
    const double      mu_g = 0.5 * 10.; // unit mass
    // Sliding at v0 = 2: friction decelerates it at mu g.
    {
      const auto  problem = run_scene<dim>(block_on_block<dim>(mesh, 0., 2.));
      const auto &s       = problem->summaries();
      checker.close(tag + "sliding block's deceleration over t in [0.1, 0.3] "
                          "against mu g = 5",
                    -mean_rate(s, "momentum_x", 0.1, 0.3),
                    mu_g,
                    mu_g,
                    0.02);
      checker.above(tag + "sliding: smallest contact_min_distance",
                    smallest(s, "contact_min_distance"),
                    0.);
    }
    // Pulled by 0.8 mu N from rest: it sticks, creeping slower than the
    // smoothing velocity eps_v = d_hat per unit time once the pull's shear
    // wave has died out (t >= 0.3; the smoothed law's creep is
    // (1 - sqrt(0.2)) eps_v = 0.55 eps_v).
    {
      const auto problem =
        run_scene<dim>(block_on_block<dim>(mesh, 0.8 * mu_g, 0., 0.5));
      double fastest = 0.;
      for (const auto &row : problem->summaries())
        if (row.load_factor > 0.3 - 1e-9)
          {
            // (NaN if the column were missing: the check fails.)
            const double v = std::abs(column(row, "momentum_x"));
            fastest        = std::isnan(v) ? v : std::max(fastest, v);
          }
      checker.at_most(tag + "pulled by 0.8 mu N: largest |momentum_x| / eps_v "
                            "for t in [0.3, 0.5]",
                      fastest / 0.005,
                      1.);
    }
    // Pulled by 1.2 mu N: it slides with acceleration (T - mu N) / m.
    {
      const auto problem =
        run_scene<dim>(block_on_block<dim>(mesh, 1.2 * mu_g, 0.));
      checker.close(tag + "pulled by 1.2 mu N: acceleration over t in "
                          "[0.1, 0.3] against 0.2 mu g = 1",
                    mean_rate(problem->summaries(), "momentum_x", 0.1, 0.3),
                    0.2 * mu_g,
                    0.2 * mu_g,
                    0.02);
    }
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
    const ContactMeasures own = self.measure(problem->solution());
    checker.above("bent bar: self pairs active at the end (the ends touch)",
                  own.active_pairs,
                  0.);
    checker.below("bent bar: the end faces' gap / d_hat",
                  own.min_distance / 0.004,
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
    checker.above(name + ": self pairs active at the end (inner surfaces meet)",
                  self.measure(problem->solution()).active_pairs,
                  0.);
  }

  /// Two concentric hemispherical shells (a quarter; meshes/
  /// concentric_shells_3d.msh), 0.02 apart, their arcs divided alike so
  /// that facing edges on the symmetry planes and the rim are parallel
  /// (issue 43: they were taken as 0 apart and the mesh refused). The inner
  /// shell's inner face clamped, the outer shell's outer face dented
  /// towards the centre around the pole (0.03 (z - 0.85) / 0.27 above
  /// z = 0.85, held elsewhere), rollers on the symmetry planes, automatic
  /// d_hat, 3 steps.
  void
  concentric_shells(Checker &checker, const std::string &mesh)
  {
    const std::string dent =
      "-0.03*t*max(0, z - 0.85)/0.27/sqrt(x*x + y*y + z*z)";
    const std::string scene =
      common(3, mesh, 3) +
      subsection("Linear solver", entry("Type", "direct")) +
      subsection("Dirichlet 1",
                 entry("Boundary id", "1") + entry("Components", "x, y, z") +
                   entry("Displacement", "0; 0; 0")) +
      subsection("Dirichlet 2",
                 entry("Boundary id", "2") + entry("Components", "x, y, z") +
                   entry("Displacement",
                         "x*" + dent + "; y*" + dent + "; z*" + dent)) +
      subsection("Dirichlet 3",
                 entry("Boundary id", "3") + entry("Components", "x") +
                   entry("Displacement", "0")) +
      subsection("Dirichlet 4",
                 entry("Boundary id", "4") + entry("Components", "y") +
                   entry("Displacement", "0")) +
      subsection("Contact", entry("Self contact", "true"));
    Parameters parameters;
    parameters.read_from_string(scene);
    const auto problem = run_checked<3>(checker, "concentric shells", scene);
    const SelfContact<3> self(parameters.contact,
                              problem->get_dof_handler(),
                              LameParameters());
    const ContactMeasures end = self.measure(problem->solution());
    checker.above("concentric shells: self pairs active at the end (the "
                  "shells press on each other)",
                  end.active_pairs,
                  0.);
    checker.below("concentric shells: smallest self-pair distance at the "
                  "end / d_hat",
                  end.min_distance / self.barrier_distance(),
                  1.);
    checker.note("concentric shells: d_hat = " +
                 std::to_string(self.barrier_distance()) + ", " +
                 std::to_string(end.active_pairs) +
                 " active pairs at the end, smallest distance " +
                 std::to_string(end.min_distance));
  }

  /// Two blocks of one mesh 4e-4 apart (meshes/close_blocks_2d.msh), far
  /// below 1e-3 of the diagonal, 'Barrier distance' left automatic: d_hat
  /// is half the gap (the diagonal's rule would refuse the mesh), and the
  /// upper block pressed down by 1e-3 completes.
  void
  automatic_barrier(Checker &checker, const std::string &mesh)
  {
    const double      gap = 4e-4;
    const std::string scene =
      common(2, mesh, 3) +
      subsection("Dirichlet 1",
                 entry("Boundary id", "1") + entry("Components", "x, y") +
                   entry("Displacement", "0; 0")) +
      subsection("Dirichlet 2",
                 entry("Boundary id", "2") + entry("Components", "x, y") +
                   entry("Displacement", "0; -0.001*t")) +
      subsection("Contact", entry("Self contact", "true"));
    Parameters parameters;
    parameters.read_from_string(scene);
    const auto problem = run_checked<2>(checker, "close blocks", scene);
    const SelfContact<2>   self(parameters.contact,
                              problem->get_dof_handler(),
                              LameParameters());
    const BarrierSettings &b = self.settings();
    checker.is_true("close blocks: d_hat from the reference gap",
                    b.origin == BarrierSettings::Origin::reference_gap);
    checker.close("close blocks: the smallest reference gap", b.reference_gap, gap, gap, 1e-9);
    checker.close("close blocks: d_hat = half the gap", b.d_hat, 0.5 * gap, gap, 1e-9);
    checker.below("close blocks: d_hat / (1e-3 diagonal)",
                  b.d_hat / (1e-3 * std::sqrt(1. + (1. + gap) * (1. + gap))),
                  1.);
    checker.note("close blocks: header text '" + barrier_distance_text(b) +
                 "'");
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
      else if (which == "friction" && argc > 3)
        {
          if (std::atoi(argv[2]) == 2)
            friction<2>(checker, argv[3]);
          else
            friction<3>(checker, argv[3]);
        }
      else if (which == "automatic_barrier" && argc > 2)
        automatic_barrier(checker, argv[2]);
      else if (which == "concentric_shells" && argc > 2)
        concentric_shells(checker, argv[2]);
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
                                 "MESH | hollow_ball DIM MESH | friction DIM MESH "
                                 "| concentric_shells MESH | automatic_barrier MESH");
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
