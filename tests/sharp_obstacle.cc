// Meshed obstacles with sharp corners and edges (issue 43, Contact III):
// the pairs of contact/mesh_obstacle_pairs.h.
//   fd DIM     the term alone on a unit box: a pyramid (3D; 2D: a wedge)
//              whose tip is within d_hat of the box's bottom face, and (3D)
//              a prism whose horizontal ridge passes under the bottom
//              edges: forces against central differences of the energy
//              (1e-6), the exact stiffness against central differences of
//              the forces (1e-6), the projected one positive
//              semi-definite; the feasible step along -e_vertical cuts the
//              step and leaves the energy finite.
//   pyramid 3  a coarse block (2 x 2 x 1 boxes) pressed by its top face
//              onto a meshed pyramid whose tip lies under a bottom face's
//              interior, far from its vertices: at every converged state
//              no deformed boundary triangle crosses an obstacle triangle
//              (the test's own segment-triangle test), the smallest
//              distance is positive and the obstacle's force balances the
//              top's reaction; with 'Meshed obstacle corners = false' the
//              same scene ends with the tip through the face (so the check
//              can fail).
//   wedge 2    the same in 2D: a block of 2 x 1 boxes on a wedge whose tip
//              lies under a bottom segment's interior.
// Usage: mpirun -np N sharp_obstacle CASE DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/contact/barrier_settings.h>
#include <hyperelastic/contact/mesh_obstacle_pairs.h>
#include <hyperelastic/contact/obstacle_surface.h>
#include <hyperelastic/mesh/mesh_distribution.h>

#include "support/box_discretisation.h"
#include "support/dimension_main.h"
#include "support/random_vector.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <string>
#include <vector>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  using dealii::Point;

  /// A surface as points and elements (dim vertex indices each).
  template <int dim>
  struct Surface
  {
    std::vector<Point<dim>>                    points;
    std::vector<std::array<unsigned int, dim>> elements;
  };

  /// Writes (rank 0) @p s as a gmsh file @p name in the working folder;
  /// returns its absolute path. Collective.
  template <int dim>
  std::string
  write_surface(const std::string &name, const Surface<dim> &s)
  {
    const std::string path = (std::filesystem::current_path() / name).string();
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::ofstream out(path);
        out << std::setprecision(17) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
            << "$Nodes\n"
            << s.points.size() << "\n";
        for (unsigned int i = 0; i < s.points.size(); ++i)
          out << i + 1 << " " << s.points[i][0] << " " << s.points[i][1] << " "
              << (dim == 3 ? s.points[i][dim - 1] : 0.) << "\n";
        out << "$EndNodes\n$Elements\n" << s.elements.size() << "\n";
        for (unsigned int e = 0; e < s.elements.size(); ++e)
          {
            out << e + 1 << " " << (dim == 2 ? 1 : 2) << " 2 1 1";
            for (const unsigned int v : s.elements[e])
              out << " " << v + 1;
            out << "\n";
          }
        out << "$EndElements\n";
      }
    MPI_Barrier(MPI_COMM_WORLD);
    return path;
  }

  /// A closed pyramid (3D) with its tip at @p tip pointing up, its square
  /// base of half-width @p half @p height below; 2D: the wedge of the two
  /// sides and the base.
  template <int dim>
  Surface<dim>
  pyramid(const Point<dim> &tip, const double half, const double height)
  {
    Surface<dim> s;
    s.points.push_back(tip);
    if constexpr (dim == 2)
      {
        s.points.emplace_back(tip[0] - half, tip[1] - height);
        s.points.emplace_back(tip[0] + half, tip[1] - height);
        s.elements = {{{1, 0}}, {{0, 2}}, {{2, 1}}};
      }
    else
      {
        for (const auto &[x, y] : std::vector<std::pair<double, double>>{
               {-1., -1.}, {1., -1.}, {1., 1.}, {-1., 1.}})
          s.points.emplace_back(tip[0] + x * half,
                                tip[1] + y * half,
                                tip[2] - height);
        for (unsigned int k = 0; k < 4; ++k)
          s.elements.push_back({{0, 1 + k, 1 + (k + 1) % 4}});
        s.elements.push_back({{1, 3, 2}});
        s.elements.push_back({{1, 4, 3}});
      }
    return s;
  }

  /// A closed triangular prism of @p length whose horizontal ridge passes
  /// through @p middle, turned by @p angle from the x-axis about the
  /// vertical, its base @p height below the ridge and 2 @p half wide.
  Surface<3>
  prism(const Point<3> &middle,
        const double    length,
        const double    angle,
        const double    half,
        const double    height)
  {
    Surface<3> s;
    const dealii::Tensor<1, 3> along  = Point<3>(std::cos(angle), std::sin(angle), 0.),
                               across = Point<3>(-std::sin(angle), std::cos(angle), 0.),
                               up     = Point<3>(0., 0., 1.);
    for (const double e : {-0.5 * length, 0.5 * length})
      {
        s.points.push_back(middle + e * along);
        s.points.push_back(middle + e * along - half * across - height * up);
        s.points.push_back(middle + e * along + half * across - height * up);
      }
    // Ends (0 1 2), (3 5 4); sides.
    s.elements = {{{0, 1, 2}},
                  {{3, 5, 4}},
                  {{0, 3, 4}},
                  {{0, 4, 1}},
                  {{0, 2, 5}},
                  {{0, 5, 3}},
                  {{1, 4, 5}},
                  {{1, 5, 2}}};
    return s;
  }

  ObstacleParameters
  meshed_obstacle(const std::string &file, const int dim)
  {
    ObstacleParameters o;
    o.number     = 1;
    o.subsection = "Contact/Obstacle 1";
    o.type       = ObstacleType::mesh;
    o.file       = file;
    o.point      = std::vector<double>(dim, 0.);
    o.motion     = std::vector<std::string>(dim, "0");
    return o;
  }

  template <int dim>
  void
  fd_case(Checker &checker, const std::string &name, const Surface<dim> &s)
  {
    const MPI_Comm         comm = MPI_COMM_WORLD;
    BoxDiscretisation<dim> box(1., 2, 2, 1, comm);
    ContactParameters      parameters;
    parameters.barrier_distance = 0.1;
    parameters.obstacles.push_back(meshed_obstacle(
      write_surface<dim>("fd_obstacle_" + std::to_string(dim) + "d.msh", s),
      dim));
    // The surface and settings ObstacleContact would hand over (d_hat is
    // given: the body's diagonal does not enter).
    const ObstacleParameters    &o = parameters.obstacles[0];
    const MeshObstaclePairs<dim> term(
      parameters,
      {},
      box.dof_handler,
      {std::make_shared<const ObstacleSurface<dim>>(o.file,
                                                    o.subsection + "/File")},
      barrier_settings(parameters, 1., lame_parameters(1., 1.), false));
    const std::string tag = std::to_string(dim) + "D " + name + ": ";

    VectorType u(box.owned, comm), u_ghosted(box.owned, box.relevant, comm);
    VectorType v(box.owned, comm), w(box.owned, comm);
    fill_random(u, 1e-3, 1);
    fill_random(v, 1., 2);
    const double h  = 1e-7;
    const auto   at = [&](const double step) -> const VectorType & {
      w = u;
      w.add(step, v);
      u_ghosted = w;
      return u_ghosted;
    };
    u_ghosted = u;
    const ContactMeasures m = term.measure(u_ghosted, 0.);
    checker.above(tag + "active pairs", m.active_pairs, 0.);
    checker.above(tag + "smallest distance", m.min_distance, 0.);

    VectorType g(box.owned, comm);
    term.add_forces(u_ghosted, 0., g);
    g.compress(dealii::VectorOperation::add);
    const double slope = -(g * v);
    const double fd_slope =
      (term.energy(at(h), 0.) - term.energy(at(-h), 0.)) / (2. * h);
    checker.close(tag + "forces . v against (V(u + h v) - V(u - h v)) / 2h",
                  slope,
                  fd_slope,
                  std::abs(fd_slope),
                  1e-6);

    dealii::AffineConstraints<double> none;
    none.close();
    VectorType rhs(box.owned, comm), Kv(box.owned, comm),
      g_plus(box.owned, comm), g_minus(box.owned, comm);
    MatrixType K;
    box.reinit_matrix(K);
    u_ghosted = u;
    term.add_stiffness(u_ghosted, 0., TangentProjection::none, none, K, rhs);
    K.compress(dealii::VectorOperation::add);
    K.vmult(Kv, v);
    term.add_forces(at(h), 0., g_plus);
    term.add_forces(at(-h), 0., g_minus);
    g_plus.compress(dealii::VectorOperation::add);
    g_minus.compress(dealii::VectorOperation::add);
    VectorType difference = g_minus;
    difference -= g_plus;
    difference /= 2. * h;
    VectorType error = Kv;
    error -= difference;
    checker.at_most(tag + "exact stiffness: |K v - FD of the forces| / |K v|",
                    error.l2_norm() / Kv.l2_norm(),
                    1e-6);

    MatrixType P;
    box.reinit_matrix(P);
    u_ghosted = u;
    term.add_stiffness(
      u_ghosted, 0., TangentProjection::every_point, none, P, rhs);
    P.compress(dealii::VectorOperation::add);
    double smallest = 1e300;
    for (unsigned int seed = 3; seed < 13; ++seed)
      {
        fill_random(w, 1., seed);
        P.vmult(Kv, w);
        smallest = std::min(smallest, (w * Kv) / (w * w));
      }
    checker.at_least(tag + "projected stiffness: min over 10 random v of "
                           "v.K v / v.v (+1e-12 |K|)",
                     smallest + 1e-12 * P.frobenius_norm(),
                     0.);

    VectorType down(box.owned, comm);
    for (const auto i : box.owned)
      if (i % dim == dim - 1)
        down(i) = -1.;
    down.compress(dealii::VectorOperation::insert);
    const double alpha = term.largest_feasible_step(u, down, 0.);
    checker.is_true(tag + "feasible step along -e_vertical in (0, 1): " +
                      std::to_string(alpha),
                    alpha > 0. && alpha < 1.);
    w = u;
    w.add(alpha, down);
    u_ghosted = w;
    checker.is_true(tag + "energy finite at the feasible step",
                    std::isfinite(term.energy(u_ghosted, 0.)));
  }

  template <int dim>
  void
  fd(Checker &checker)
  {
    // The box's bottom (y = 0 / z = 0) has vertices at 0, 0.5, 1: the tip
    // lies under the interior of a bottom face, 0.04 below it.
    if constexpr (dim == 2)
      fd_case<2>(checker, "wedge tip", pyramid<2>(Point<2>(0.3, -0.04), 0.2, 0.3));
    else
      {
        fd_case<3>(checker,
                   "pyramid tip",
                   pyramid<3>(Point<3>(0.3, 0.12, -0.04), 0.15, 0.3));
        // A ridge 0.03 below the bottom, across its edges.
        fd_case<3>(checker,
                   "prism ridge",
                   prism(Point<3>(0.45, 0.55, -0.03), 2., 0.3, 0.15, 0.2));
      }
  }

  /// The deformed boundary faces of the owned cells (dim points each).
  template <int dim>
  std::vector<std::array<Point<dim>, dim>>
  deformed_faces(const dealii::DoFHandler<dim> &dof_handler, const VectorType &u)
  {
    std::vector<std::array<Point<dim>, dim>> faces;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() ||
                face->boundary_id() == partition_edge_boundary_id)
              continue;
            std::array<Point<dim>, dim> points;
            for (unsigned int v = 0; v < dim; ++v)
              {
                points[v] = face->vertex(v);
                for (unsigned int d = 0; d < dim; ++d)
                  points[v][d] += u(face->vertex_dof_index(v, d));
              }
            faces.push_back(points);
          }
    return faces;
  }

  double
  orient(const Point<2> &a, const Point<2> &b, const Point<2> &c)
  {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }

  double
  orient(const Point<3> &a, const Point<3> &b, const Point<3> &c, const Point<3> &d)
  {
    return (b - a) * dealii::cross_product_3d(c - a, d - a);
  }

  /// Whether the open segment p q crosses the open triangle a b c
  /// (orientation signs; touching and coplanar cases do not count).
  bool
  crosses(const Point<3> &p,
          const Point<3> &q,
          const std::array<Point<3>, 3> &t)
  {
    const double sp = orient(t[0], t[1], t[2], p), sq = orient(t[0], t[1], t[2], q);
    if (!(sp * sq < 0.))
      return false;
    const double s1 = orient(p, q, t[0], t[1]), s2 = orient(p, q, t[1], t[2]),
                 s3 = orient(p, q, t[2], t[0]);
    return (s1 > 0. && s2 > 0. && s3 > 0.) || (s1 < 0. && s2 < 0. && s3 < 0.);
  }

  /// The number of (body face, obstacle element) pairs that intersect:
  /// 3D, an edge of one through the inside of the other; 2D, two segments
  /// crossing. Summed over the ranks.
  template <int dim>
  unsigned int
  intersections(const std::vector<std::array<Point<dim>, dim>> &body,
                const Surface<dim>                             &obstacle)
  {
    unsigned int n = 0;
    for (const auto &f : body)
      for (const auto &e : obstacle.elements)
        {
          std::array<Point<dim>, dim> o;
          for (unsigned int i = 0; i < dim; ++i)
            o[i] = obstacle.points[e[i]];
          bool hit = false;
          if constexpr (dim == 2)
            hit = orient(f[0], f[1], o[0]) * orient(f[0], f[1], o[1]) < 0. &&
                  orient(o[0], o[1], f[0]) * orient(o[0], o[1], f[1]) < 0.;
          else
            for (unsigned int k = 0; k < 3 && !hit; ++k)
              hit = crosses(f[k], f[(k + 1) % 3], o) ||
                    crosses(o[k], o[(k + 1) % 3], f);
          n += hit ? 1 : 0;
        }
    return dealii::Utilities::MPI::sum(n, MPI_COMM_WORLD);
  }

  /// The block [0, 1] x [0, 0.5] (x [0, 1]) of 2 x 1 (x 2) boxes, pressed
  /// down by 0.12 at its top in 4 steps onto the obstacle in @p file
  /// (d_hat = 0.005), neo-Hookean E = 1, nu = 0.3.
  template <int dim>
  std::string
  block_on_obstacle(const std::string &file, const bool corners)
  {
    const bool three = dim == 3;
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh",
                      entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                        entry("Upper corner", three ? "1, 1, 0.5" : "1, 0.5") +
                        entry("Subdivisions", three ? "2, 2, 1" : "2, 1")) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1") +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading", entry("Number of load steps", "4")) +
           dirichlet(1,
                     2 * dim - 1,
                     three ? "x, y, z" : "x, y",
                     three ? "0; 0; -0.12*t" : "0; -0.12*t") +
           subsection("Output",
                      entry("Write VTU", "false") + entry("Verbose", "false")) +
           subsection(
             "Contact",
             entry("Barrier distance", "0.005") +
               entry("Meshed obstacle corners", corners ? "true" : "false") +
               subsection("Obstacle 1",
                          entry("Type", "mesh") + entry("File", file) +
                            entry("Point", three ? "0, 0, 0" : "0, 0")));
  }

  template <int dim>
  void
  pressed(Checker &checker)
  {
    // The tip 0.02 below the bottom, under a bottom face's interior (its
    // vertices are 0.27 or more away sideways), the base 0.4 below it.
    Point<dim> tip;
    tip[0]       = dim == 3 ? 0.25 : 0.3;
    tip[1]       = dim == 3 ? 0.1 : -0.02;
    tip[dim - 1] = -0.02;
    const Surface<dim> obstacle = pyramid<dim>(tip, 0.1, 0.4);
    const std::string file =
      write_surface<dim>("sharp_" + std::to_string(dim) + "d.msh", obstacle);
    const std::string tag =
      std::to_string(dim) + "D " + (dim == 3 ? "pyramid" : "wedge") + ": ";
    const std::string up = dim == 3 ? "z" : "y";
    for (const bool corners : {true, false})
      {
        Parameters parameters;
        parameters.read_from_string(block_on_obstacle<dim>(file, corners));
        Problem<dim>  problem(parameters, MPI_COMM_WORLD, false);
        unsigned int  steps = 0, crossings = 0, last_crossings = 0;
        double        closest = std::numeric_limits<double>::infinity();
        double        balance = 0., force = 0.;
        problem.set_step_observer([&](const StepSummary<dim> &s) {
          ++steps;
          last_crossings = intersections<dim>(
            deformed_faces<dim>(problem.get_dof_handler(), problem.solution()),
            obstacle);
          crossings += last_crossings;
          closest = std::min(closest, column(s, "contact_min_distance"));
          force   = column(s, "contact_force_1_" + up);
          balance = std::abs(force + column(s, "reaction_" +
                                                   std::to_string(2 * dim - 1) +
                                                   "_" + up));
        });
        problem.run();
        if (corners)
          {
            checker.at_least(tag + "converged load steps", steps, 4);
            checker.is_true(tag + "no body face crosses an obstacle element "
                                  "at any converged step (" +
                              std::to_string(crossings) + " crossings)",
                            crossings == 0);
            checker.above(tag + "smallest contact_min_distance over the steps",
                          closest,
                          0.);
            checker.above(tag + "the obstacle pushes the body up: "
                                "contact_force_1_" + up + " at t = 1",
                          force,
                          0.);
            checker.at_most(tag + "|contact force + top reaction| / contact "
                                  "force at t = 1",
                            balance / force,
                            1e-6);
          }
        else
          checker.above(tag + "without the corner pairs ('Meshed obstacle "
                              "corners = false'): crossings at t = 1",
                        last_crossings,
                        0);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_case_for_dimension(
    argc,
    argv,
    "fd",
    [&](const std::string &which, Checker &checker) {
      if (which == "fd")
        fd<2>(checker);
      else
        pressed<2>(checker);
    },
    [&](const std::string &which, Checker &checker) {
      if (which == "fd")
        fd<3>(checker);
      else
        pressed<3>(checker);
    });
}
