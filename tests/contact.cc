// Contact with rigid obstacles (Contact I, issue 26).
//   fd DIM      the barrier's forces against central differences of its
//               potential, for a plane, a sphere and a faceted sphere
//               (surface mesh) (relative 1e-6), and its load stiffness
//               against central differences of the forces for the plane
//               (1e-6); the projected stiffness of the curved obstacles is
//               positive semi-definite; the feasible step keeps every
//               distance positive and cuts a step that would cross.
//   resting DIM a block under gravity on a plane, rollers on its symmetry
//               planes: the plane's total force equals the weight (1e-8),
//               every distance lies in (0, d_hat); so with the mixed
//               formulation; the same floor as a surface mesh gives the
//               same run (1e-9).
//   drop DIM    a block dropped on a plane with backward Euler: every
//               step's contact_min_distance > 0, the total energy never
//               grows (the scheme dissipates), the block hits the floor and
//               bounces (upward momentum after the impact).
//   compression DIM  a block pressed by a moving plate onto a plane,
//               frictionless: the homogeneous uniaxial force and lateral
//               stretch within the bound the gaps allow (dF/da d_hat), the
//               error falling with d_hat.
//   friction DIM  a block on a rough floor (mu = 0.5), backward Euler:
//               sliding, it decelerates at mu g (2 %); pulled by 0.8 mu N it
//               sticks (creeps slower than eps_v); pulled by 1.2 mu N it
//               accelerates at 0.2 mu g (2 %).
//   hertz 2 MESH  a half disk pressed onto a plane: the contact half-width
//               against Hertz's (5 %); MESH: meshes/half_disk_2d.msh.
//   hertz 3 MESH [TOLERANCE [DEGREE]]  a rigid sphere pressed into a
//               half-space block (quarter model): the force against 4/3 E*
//               sqrt(R) delta^1.5 (relative TOLERANCE, default 5 %) and the
//               contact radius against sqrt(R delta) (5 %), elements of
//               DEGREE (default 1); MESH: meshes/hertz_block_3d.msh (P1:
//               force +3.5 %, radius -1.0 %; benchmarks/contact/hertz_3d.sh
//               runs other gradings of the same .geo).
// Usage: mpirun -np N contact CASE DIM [MESH]
#include <deal.II/base/mpi.h>

#include <hyperelastic/contact/obstacle_contact.h>

#include "support/box_discretisation.h"
#include "support/dimension_main.h"
#include "support/owned_vertices.h"
#include "support/random_vector.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using dealii::Utilities::MPI::sum;

namespace
{
  /// Writes (rank 0) a gmsh file of a surface: @p points and @p elements
  /// (vertex indices from 0; dim of them each: lines in 2D, triangles in
  /// 3D), in the working folder; returns its absolute path. Collective.
  template <int dim>
  std::string
  write_surface(const std::string                                &name,
                const std::vector<dealii::Point<dim>>            &points,
                const std::vector<std::array<unsigned int, dim>> &elements)
  {
    const std::string path = (std::filesystem::current_path() / name).string();
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::ofstream out(path);
        out << std::setprecision(17) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
            << "$Nodes\n"
            << points.size() << "\n";
        for (unsigned int i = 0; i < points.size(); ++i)
          out << i + 1 << " " << points[i][0] << " " << points[i][1] << " "
              << (dim == 3 ? points[i][dim - 1] : 0.) << "\n";
        out << "$EndNodes\n$Elements\n" << elements.size() << "\n";
        for (unsigned int e = 0; e < elements.size(); ++e)
          {
            out << e + 1 << " " << (dim == 2 ? 1 : 2) << " 2 1 1";
            for (const unsigned int v : elements[e])
              out << " " << v + 1;
            out << "\n";
          }
        out << "$EndElements\n";
      }
    MPI_Barrier(MPI_COMM_WORLD);
    return path;
  }

  /// A sphere of radius 0.5 about the origin as a surface mesh: a polygon of
  /// 24 sides (2D) or 12 x 24 latitude-longitude triangles (3D), its
  /// vertices on the sphere.
  template <int dim>
  std::string
  faceted_sphere_file()
  {
    const double                               R = 0.5, pi = M_PI;
    std::vector<dealii::Point<dim>>            points;
    std::vector<std::array<unsigned int, dim>> elements;
    if constexpr (dim == 2)
      {
        for (unsigned int i = 0; i < 24; ++i)
          {
            points.emplace_back(R * std::cos(2 * pi * i / 24),
                                R * std::sin(2 * pi * i / 24));
            elements.push_back({{i, (i + 1) % 24}});
          }
      }
    else
      {
        const unsigned int rings = 12, sectors = 24;
        points.emplace_back(0., 0., R); // north pole: 0
        for (unsigned int r = 1; r < rings; ++r)
          for (unsigned int k = 0; k < sectors; ++k)
            {
              const double theta = pi * r / rings, phi = 2 * pi * k / sectors;
              points.emplace_back(R * std::sin(theta) * std::cos(phi),
                                  R * std::sin(theta) * std::sin(phi),
                                  R * std::cos(theta));
            }
        points.emplace_back(0., 0., -R); // south pole
        const auto ring = [&](const unsigned int r, const unsigned int k) {
          return 1 + (r - 1) * sectors + k % sectors;
        };
        const unsigned int south = points.size() - 1;
        for (unsigned int k = 0; k < sectors; ++k)
          {
            elements.push_back({{0, ring(1, k), ring(1, k + 1)}});
            for (unsigned int r = 1; r + 1 < rings; ++r)
              {
                elements.push_back(
                  {{ring(r, k), ring(r + 1, k), ring(r + 1, k + 1)}});
                elements.push_back(
                  {{ring(r, k), ring(r + 1, k + 1), ring(r, k + 1)}});
              }
            elements.push_back(
              {{ring(rings - 1, k), south, ring(rings - 1, k + 1)}});
          }
      }
    return write_surface<dim>("faceted_sphere_" + std::to_string(dim) + "d.msh",
                              points,
                              elements);
  }

  /// The unit box's bottom face (y = 0 in 2D, z = 0 in 3D) is 'down'.
  template <int dim>
  ObstacleParameters
  obstacle(const ObstacleType type, const unsigned int number)
  {
    ObstacleParameters o;
    o.number     = number;
    o.subsection = "Contact/Obstacle " + std::to_string(number);
    o.type       = type;
    o.point      = std::vector<double>(dim, 0.5);
    o.normal     = std::vector<double>(dim, 0.);
    o.motion     = std::vector<std::string>(dim, "0");
    if (type == ObstacleType::plane)
      {
        // A tilted plane below the bottom: 0.00995 from its x = 0 edge,
        // 0.109 from its x = 1 edge.
        o.point[dim - 1]  = -0.06;
        o.normal[0]       = 0.1;
        o.normal[dim - 1] = 1.;
        const double norm = std::sqrt(1.01);
        for (double &n : o.normal)
          n /= norm;
      }
    else
      {
        // The sphere, or the faceted sphere of faceted_sphere_file() (its
        // file's origin at the sphere's centre).
        o.radius         = 0.5;
        o.point[dim - 1] = -0.503;
        if (type == ObstacleType::mesh)
          o.file = faceted_sphere_file<dim>();
      }
    return o;
  }

  double
  dot(const VectorType &a, const VectorType &b)
  {
    return a * b;
  }

  template <int dim>
  void
  fd(Checker &checker)
  {
    const MPI_Comm         comm = MPI_COMM_WORLD;
    BoxDiscretisation<dim> box(1., 4, 4, 1, comm);
    LameParameters         moduli = lame_parameters(1., 1.);
    for (const ObstacleType type :
         {ObstacleType::plane, ObstacleType::sphere, ObstacleType::mesh})
      {
        const std::string name =
          std::to_string(dim) + "D " +
          (type == ObstacleType::plane    ? "plane"
           : type == ObstacleType::sphere ? "sphere"
                                          : "faceted sphere (mesh)") +
          ": ";
        ContactParameters parameters;
        parameters.barrier_distance = 0.1;
        parameters.obstacles.push_back(obstacle<dim>(type, 1));
        const ObstacleContact<dim> contact(parameters,
                                           {},
                                           box.dof_handler,
                                           moduli);

        VectorType u(box.owned, comm), u_ghosted(box.owned, box.relevant, comm);
        VectorType v(box.owned, comm), w(box.owned, comm);
        fill_random(u, 1e-4, 1);
        fill_random(v, 1., 2);
        const double h  = 1e-7;
        const auto   at = [&](const double s) {
          w = u;
          w.add(s, v);
          u_ghosted = w;
          return u_ghosted;
        };
        // Forces g = -dV/du.
        VectorType g(box.owned, comm);
        u_ghosted = u;
        contact.add_forces(u_ghosted, 0., g);
        g.compress(dealii::VectorOperation::add);
        const double slope = -dot(g, v);
        const double fd_slope =
          (contact.energy(at(h), 0.) - contact.energy(at(-h), 0.)) /
          (2. * h);
        checker.close(name +
                        "forces . v against (V(u + h v) - V(u - h v)) / 2h",
                      slope,
                      fd_slope,
                      std::abs(fd_slope),
                      1e-6);
        checker.above(name + "barrier active (|g . v| > 0)",
                      std::abs(slope),
                      0.);

        // Load stiffness K = d2V/du2.
        MatrixType K;
        box.reinit_matrix(K);
        VectorType                        rhs(box.owned, comm);
        dealii::AffineConstraints<double> none;
        none.close();
        u_ghosted = u;
        contact.add_stiffness(u_ghosted, 0., TangentProjection::none, none, K, rhs);
        K.compress(dealii::VectorOperation::add);
        VectorType Kv(box.owned, comm), g_plus(box.owned, comm),
          g_minus(box.owned, comm);
        K.vmult(Kv, v);
        contact.add_forces(at(h), 0., g_plus);
        contact.add_forces(at(-h), 0., g_minus);
        g_plus.compress(dealii::VectorOperation::add);
        g_minus.compress(dealii::VectorOperation::add);
        // -dg/du v.
        VectorType difference = g_minus;
        difference -= g_plus;
        difference /= 2. * h;
        if (type == ObstacleType::plane)
          {
            VectorType error = Kv;
            error -= difference;
            checker.at_most(name + "|K v - FD of the forces| / |K v|",
                            error.l2_norm() / Kv.l2_norm(),
                            1e-6);
          }
        else
          {
            // Projected: v.K v >= 0 for every v, and along v the projected
            // curvature is at least the exact one (the dropped tangential
            // part is negative).
            double smallest = 1e300;
            for (unsigned int seed = 3; seed < 13; ++seed)
              {
                fill_random(w, 1., seed);
                K.vmult(Kv, w);
                smallest = std::min(smallest, dot(w, Kv) / dot(w, w));
              }
            checker.at_least(name + "projected stiffness: min over 10 random "
                                    "v of v.K v / v.v",
                             smallest,
                             0.);
            K.vmult(Kv, v);
            checker.at_least(name + "v.K v - v.(FD of -dg/du) v >= 0",
                             dot(v, Kv) - dot(v, difference) +
                               1e-6 * std::abs(dot(v, Kv)),
                             0.);
          }

        // The feasible step: along a direction that pushes everything down
        // by 1 the step is cut so that no distance becomes negative.
        VectorType down(box.owned, comm);
        for (const auto i : box.owned)
          if (i % dim == dim - 1)
            down(i) = -1.;
        down.compress(dealii::VectorOperation::insert);
        const double alpha = contact.largest_feasible_step(u, down, 0.);
        checker.is_true(name + "feasible step along -e_vertical in (0, 1): " +
                          std::to_string(alpha),
                        alpha > 0. && alpha < 1.);
        w = u;
        w.add(alpha, down);
        u_ghosted = w;
        checker.is_true(name + "potential finite at the feasible step",
                        std::isfinite(contact.energy(u_ghosted, 0.)));
        if (type != ObstacleType::mesh)
          {
            w = u;
            w.add(alpha / 0.9 * 1.001, down);
            u_ghosted = w;
            checker.is_true(name + "past the crossing the potential is "
                                   "infinite",
                            !std::isfinite(contact.energy(u_ghosted, 0.)));
            continue;
          }
        // A surface has no inside (its distance is unsigned): along the
        // step the potential stays finite, and it grows towards the
        // crossing at alpha / 0.9 (conservative advancement stops where the
        // closest vertex keeps a tenth of its distance).
        bool finite = true;
        for (unsigned int i = 0; i <= 20; ++i)
          finite = finite && std::isfinite(contact.energy(
                               [&]() {
                                 w = u;
                                 w.add(alpha * i / 20., down);
                                 u_ghosted = w;
                                 return u_ghosted;
                               }(),
                               0.));
        checker.is_true(name + "potential finite at 21 points of [0, alpha]",
                        finite);
        w = u;
        w.add(alpha, down);
        u_ghosted             = w;
        const double at_alpha = contact.energy(u_ghosted, 0.);
        w                     = u;
        w.add(0.999 * alpha / 0.9, down);
        u_ghosted = w;
        checker.above(name + "potential near the crossing / at alpha",
                      contact.energy(u_ghosted, 0.) / at_alpha,
                      1.);
      }
  }

  /// A unit block of neo-Hookean material (Young's modulus @p young,
  /// Poisson's ratio 0.3) with its bottom at height @p bottom, in boxes of
  /// @p n per side (2D; n / 2 in 3D), under the gravity @p g per unit
  /// volume, above a floor plane at height @p floor (Contact/Obstacle 1,
  /// barrier distance @p d_hat), without VTU output or Newton table.
  template <int dim>
  std::string
  block_above_floor(const double       bottom,
                    const unsigned int n,
                    const std::string &young,
                    const std::string &g,
                    const std::string &floor,
                    const std::string &d_hat)
  {
    const bool        three = dim == 3;
    const std::string low = number(bottom), high = number(bottom + 1.);
    const std::string m = std::to_string(three ? n / 2 : n);
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection(
             "Mesh",
             entry("Lower corner", three ? "0, 0, " + low : "0, " + low) +
               entry("Upper corner", three ? "1, 1, " + high : "1, " + high) +
               entry("Subdivisions",
                     three ? m + ", " + m + ", " + m : m + ", " + m)) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", young) +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading",
                      entry("Body force", three ? "0; 0; -" + g : "0; -" + g)) +
           subsection("Output",
                      entry("Write VTU", "false") + entry("Verbose", "false")) +
           subsection(
             "Contact",
             entry("Barrier distance", d_hat) +
               subsection("Obstacle 1",
                          entry("Type", "plane") +
                            entry("Point",
                                  three ? "0, 0, " + floor : "0, " + floor) +
                            entry("Normal", three ? "0, 0, 1" : "0, 1")));
  }

  /// The value of CSV column @p name in @p summary (NaN if absent).
  template <int dim>
  void
  resting(Checker &checker)
  {
    const bool        three = dim == 3;
    const std::string scene =
      block_above_floor<dim>(0., 6, "1", "0.1", "-0.005", "0.01") +
      subsection("Loading", entry("Number of load steps", "2")) +
      dirichlet(1, 0, "x", "0") + (three ? dirichlet(2, 2, "y", "0") : "") +
      tight_solver("direct");
    const auto        problem = run_scene<dim>(scene);
    const auto       &last    = problem->summaries().back();
    const std::string tag     = std::to_string(dim) + "D resting block: ";
    const std::string up      = three ? "z" : "y";
    // Weight: 0.1 per unit volume of the unit block.
    checker.close(tag + "contact_force_1_" + up + " = weight 0.1",
                  column(last, "contact_force_1_" + up),
                  0.1,
                  0.1,
                  1e-8);
    checker.at_most(tag + "|contact_force_1_x| / weight",
                    std::abs(column(last, "contact_force_1_x")) / 0.1,
                    1e-8);
    const double d = column(last, "contact_min_distance");
    checker.is_true(tag + "0 < contact_min_distance = " + std::to_string(d) +
                      " < d_hat",
                    d > 0. && d < 0.01);
    checker.above(tag + "contact_active_pairs",
                  column(last, "contact_active_pairs"),
                  0.);

    // The mixed displacement-pressure formulation (decoupled neo-Hookean):
    // the floor carries the weight as well.
    const auto mixed = run_scene<dim>(
      scene + subsection("Problem", entry("Formulation", "mixed")) +
      subsection("Material", entry("Model", "decoupled neo-Hookean")));
    checker.close(tag + "mixed formulation: contact_force_1_" + up +
                    " = weight 0.1",
                  column(mixed->summaries().back(), "contact_force_1_" + up),
                  0.1,
                  0.1,
                  1e-8);

    // The floor as a surface mesh (a square of 2 x 2 elements at the same
    // height, 2 lines in 2D): the same distances, so the same run.
    std::vector<dealii::Point<dim>>            points;
    std::vector<std::array<unsigned int, dim>> elements;
    if constexpr (dim == 2)
      {
        for (const double x : {-1., 0.5, 2.})
          points.emplace_back(x, -0.005);
        elements = {{{0, 1}}, {{1, 2}}};
      }
    else
      {
        for (const double y : {-1., 0.5, 2.})
          for (const double x : {-1., 0.5, 2.})
            points.emplace_back(x, y, -0.005);
        for (unsigned int j = 0; j < 2; ++j)
          for (unsigned int i = 0; i < 2; ++i)
            {
              const unsigned int a = 3 * j + i;
              elements.push_back({{a, a + 1, a + 4}});
              elements.push_back({{a, a + 4, a + 3}});
            }
      }
    const std::string file =
      write_surface<dim>("floor_" + std::to_string(dim) + "d.msh",
                         points,
                         elements);
    const auto meshed = run_scene<dim>(
      scene +
      subsection("Contact",
                 subsection("Obstacle 1",
                            entry("Type", "mesh") + entry("File", file) +
                              entry("Point", three ? "0, 0, 0" : "0, 0"))));
    const auto &m = meshed->summaries().back();
    for (const std::string &name : {"contact_force_1_" + up,
                                   std::string("contact_min_distance"),
                                   std::string("energy")})
      checker.close(tag + "meshed floor: " + name + " as with the plane",
                    column(m, name),
                    column(last, name),
                    std::abs(column(last, name)),
                    1e-9);
  }

  template <int dim>
  void
  drop(Checker &checker)
  {
    const std::string scene =
      block_above_floor<dim>(0.1, 4, "20", "1", "0", "0.005") +
      subsection("Time integration",
                 entry("Time step", "0.05") + entry("End time", "1.5"));
    const auto problem =
      run_scene<dim>(scene + subsection("Time integration",
                                        entry("Scheme", "backward Euler")));
    const std::string up       = dim == 3 ? "z" : "y";
    double            smallest = 1e300, growth = -1e300, most_force = 0.;
    double            previous = 0., upward = 0.;
    bool              hit = false;
    for (const auto &s : problem->summaries())
      {
        const double total = column(s, "total_energy");
        const double force = column(s, "contact_force_1_" + up);
        smallest = std::min(smallest, column(s, "contact_min_distance"));
        if (s.step > 1)
          growth = std::max(growth, total - previous);
        previous   = total;
        most_force = std::max(most_force, force);
        hit        = hit || force > 0.;
        if (hit)
          upward = std::max(upward, column(s, "momentum_" + up));
      }
    const std::string tag = std::to_string(dim) + "D drop: ";
    checker.above(tag + "smallest contact_min_distance over all steps",
                  smallest,
                  0.);
    checker.at_most(tag + "largest growth of the total energy per step",
                    growth,
                    1e-12);
    checker.above(tag + "largest contact force (the block hit the floor)",
                  most_force,
                  0.);
    checker.above(tag + "largest upward momentum after the impact (bounce)",
                  upward,
                  0.);

    // Implicit midpoint, frictionless: the barrier holds at the end state
    // of each step (u_n + 2 (u - u_n)), so no end state crosses the floor.
    // Midpoint keeps the energy of the fall; the barrier's work, taken at
    // the end state, can only dissipate (V convex in the gap).
    const auto midpoint =
      run_scene<dim>(scene + subsection("Time integration",
                                        entry("Scheme", "implicit midpoint")));
    double lowest = 1e300, highest = -1e300, closest = 1e300, impact = 0.;
    for (const auto &s : midpoint->summaries())
      {
        const double total = column(s, "total_energy");
        lowest             = std::min(lowest, total);
        highest            = std::max(highest, total);
        closest = std::min(closest, column(s, "contact_min_distance"));
        impact  = std::max(impact, column(s, "kinetic_energy"));
      }
    const std::string mid = std::to_string(dim) + "D drop, implicit midpoint: ";
    checker.above(mid + "smallest contact_min_distance over all steps",
                  closest,
                  0.);
    checker.at_most(mid + "largest total energy (starts at 0) / kinetic "
                          "energy at impact",
                    highest / impact,
                    1e-6);
    checker.at_least(mid + "smallest total energy / kinetic energy at impact",
                     lowest / impact,
                     -0.25);
  }

  /// The homogeneous uniaxial state of the compressible neo-Hookean model
  /// (psi = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2) at axial stretch
  /// @p a with stress-free sides (plane strain in 2D: one lateral stretch
  /// b, the thickness fixed; 3D: two lateral stretches b): returns b and the
  /// axial first Piola-Kirchhoff stress P = mu (a - 1/a) + lambda ln J / a.
  struct Uniaxial
  {
    double lateral = 1.;
    double stress  = 0.;
  };
  Uniaxial
  uniaxial(const int dim, const LameParameters &m, const double a)
  {
    // Lateral stress mu (b - 1/b) + lambda ln(a b^(dim-1)) / b = 0, by
    // Newton on b (increasing in b).
    Uniaxial u;
    double  &b = u.lateral;
    for (unsigned int it = 0; it < 50; ++it)
      {
        const double lnJ = std::log(a) + (dim - 1) * std::log(b);
        const double f   = m.mu * (b - 1. / b) + m.lambda * lnJ / b;
        const double df =
          m.mu * (1. + 1. / (b * b)) + m.lambda * ((dim - 1) - lnJ) / (b * b);
        b -= f / df;
      }
    const double lnJ = std::log(a) + (dim - 1) * std::log(b);
    u.stress         = m.mu * (a - 1. / a) + m.lambda * lnJ / a;
    return u;
  }

  /// A unit block between a floor plane (Obstacle 1) and a plate above it
  /// (Obstacle 2), both at a distance d_hat / 2, the plate moving down by
  /// @p squash over the load steps; rollers on the x = 0 (and y = 0)
  /// faces; frictionless.
  template <int dim>
  std::string
  block_between_plates(const double d_hat, const double squash)
  {
    const bool        three = dim == 3;
    const std::string gap = number(0.5 * d_hat), top = number(1. + 0.5 * d_hat);
    const std::string down = three ? "0, 0, " : "0, ";
    return unit_block(dim) +
           subsection("Loading", entry("Number of load steps", "5")) +
           dirichlet(1, 0, "x", "0") +
           (three ? dirichlet(2, 2, "y", "0") : "") +
           subsection("Output",
                      entry("Write VTU", "false") + entry("Verbose", "false")) +
           subsection(
             "Contact",
             entry("Barrier distance", number(d_hat)) +
               subsection("Obstacle 1",
                          entry("Type", "plane") +
                            entry("Point", down + "-" + gap) +
                            entry("Normal", three ? "0, 0, 1" : "0, 1")) +
               subsection("Obstacle 2",
                          entry("Type", "plane") + entry("Point", down + top) +
                            entry("Normal", three ? "0, 0, -1" : "0, -1") +
                            entry("Motion",
                                  three ? "0; 0; -" + number(squash) + "*t"
                                        : "0; -" + number(squash) + "*t"))) +
           tight_solver("direct");
  }

  template <int dim>
  void
  compression(Checker &checker)
  {
    const double         squash = 0.2;
    const LameParameters moduli = lame_parameters(1. / 2.6, 0.3 / (1.3 * 0.4));
    const std::string    up     = dim == 3 ? "z" : "y";
    const std::string    tag    = std::to_string(dim) + "D compression: ";
    // The nominal axial stretch 1 - squash misses the two gaps' change,
    // each below d_hat / 2 (they start at d_hat / 2 and stay in (0, d_hat)):
    // the force is within dF/da d_hat of the nominal answer.
    const Uniaxial nominal = uniaxial(dim, moduli, 1. - squash);
    const double   slope   = (uniaxial(dim, moduli, 1. - squash + 1e-6).stress -
                          uniaxial(dim, moduli, 1. - squash - 1e-6).stress) /
                         2e-6;
    std::vector<double> errors;
    for (const double d_hat : {4e-3, 1e-3})
      {
        const auto problem =
          run_scene<dim>(block_between_plates<dim>(d_hat, squash));
        const auto       &last        = problem->summaries().back();
        const std::string at          = "d_hat " + number(d_hat) + ": ";
        const double      floor_force = column(last, "contact_force_1_" + up);
        const double      plate_force = column(last, "contact_force_2_" + up);
        // The plate pushes down (-), the floor up (+), both by the axial
        // force |P| A0 (A0 = 1).
        checker.close(tag + at + "floor force = -plate force",
                      floor_force,
                      -plate_force,
                      std::abs(plate_force),
                      1e-8);
        const double error = std::abs(floor_force - (-nominal.stress));
        checker.at_most(tag + at +
                          "|floor force - homogeneous uniaxial force| / "
                          "(dF/da d_hat)",
                        error / (std::abs(slope) * d_hat),
                        1.);
        const double width = last.deformed_max[0] - last.deformed_min[0];
        checker.at_most(
          tag + at + "|lateral stretch - homogeneous| / (db/da d_hat)",
          std::abs(width - nominal.lateral) /
            (std::abs(uniaxial(dim, moduli, 1. - squash + 1e-6).lateral -
                      uniaxial(dim, moduli, 1. - squash - 1e-6).lateral) /
             2e-6 * d_hat),
          1.);
        const double d = column(last, "contact_min_distance");
        checker.is_true(tag + at + "0 < contact_min_distance = " + number(d) +
                          " < d_hat",
                        d > 0. && d < d_hat);
        errors.push_back(error);
      }
    checker.at_most(tag + "force error ratio d_hat 1e-3 / d_hat 4e-3 "
                          "(converging with d_hat)",
                    errors[1] / errors[0],
                    0.5);
  }

  /// A unit block of stiff neo-Hookean material (E = 1e4, density 1: it
  /// deforms by 1e-3 under its weight) with its bottom 0.99 d_hat above a
  /// floor with friction coefficient 0.5 (near the gap where the barrier
  /// carries the weight: it settles at once),
  /// under gravity 10 and the horizontal body force @p pull, starting with
  /// the horizontal velocity @p v0; backward Euler, h = 0.01.
  template <int dim>
  std::string
  block_on_rough_floor(const double pull, const double v0, const double end)
  {
    const bool three = dim == 3;
    return block_above_floor<dim>(0.00495, 4, "1e4", "10", "0", "0.005") +
           subsection("Loading",
                      entry("Body force",
                            three ? number(pull) + "; 0; -10"
                                  : number(pull) + "; -10")) +
           subsection("Contact",
                      subsection("Obstacle 1",
                                 entry("Friction coefficient", "0.5"))) +
           subsection("Time integration",
                      entry("Scheme", "backward Euler") +
                        entry("Density", "1") + entry("Time step", "0.01") +
                        entry("End time", number(end)) +
                        entry("Initial velocity",
                              three ? number(v0) + "; 0; 0"
                                    : number(v0) + "; 0"));
  }

  template <int dim>
  void
  friction(Checker &checker)
  {
    const std::string tag  = std::to_string(dim) + "D friction: ";
    const double      mu_g = 0.5 * 10.; // unit mass
    // Sliding at v0 = 2: the friction decelerates it at mu g.
    {
      const auto problem =
        run_scene<dim>(block_on_rough_floor<dim>(0., 2., 0.3));
      const auto  &s = problem->summaries();
      const double a = mean_rate(s, "momentum_x", 0.1, 0.3);
      checker.close(tag + "sliding block's deceleration over t in [0.1, 0.3] "
                          "against mu g = 5",
                    -a,
                    mu_g,
                    mu_g,
                    0.02);
      checker.above(tag + "sliding: smallest contact_min_distance",
                    smallest(s, "contact_min_distance"),
                    0.);
    }
    // Pulled by T = 0.8 mu N from rest: it sticks, creeping slower than
    // the smoothing velocity eps_v = d_hat per unit time = 0.005 (the
    // smoothed law gives 0.4 eps_v) once the shear wave of the sudden pull
    // has died out (t >= 0.2).
    {
      const auto problem =
        run_scene<dim>(block_on_rough_floor<dim>(0.8 * mu_g, 0., 0.3));
      double fastest = 0.;
      for (const auto &row : problem->summaries())
        if (row.load_factor > 0.2 - 1e-9)
          fastest = std::max(fastest, std::abs(column(row, "momentum_x")));
      checker.at_most(tag + "pulled by 0.8 mu N: largest |velocity_x| / eps_v "
                            "for t in [0.2, 0.3]",
                      fastest / 0.005,
                      1.);
    }
    // Pulled by T = 1.2 mu N: it slides with acceleration (T - mu N) / m.
    {
      const auto problem =
        run_scene<dim>(block_on_rough_floor<dim>(1.2 * mu_g, 0., 0.3));
      const double a = mean_rate(problem->summaries(), "momentum_x", 0.1, 0.3);
      checker.close(tag + "pulled by 1.2 mu N: acceleration over t in "
                          "[0.1, 0.3] against 0.2 mu g = 1",
                    a,
                    0.2 * mu_g,
                    0.2 * mu_g,
                    0.02);
    }
  }

  /// Hertz in plane strain: the half disk of radius R = 1 of
  /// meshes/half_disk_2d.msh (triangles of 0.004 near its lowest point),
  /// its flat top pushed down by 0.02 onto a rigid plane (d_hat = 1e-4),
  /// neo-Hookean E = 1, nu = 0.3. The contact half-width b from the
  /// computed vertex forces f_a at positions x_a, b = 2 sqrt(sum x_a^2 f_a
  /// / sum f_a) (Hertz's elliptic pressure has the second moment b^2 / 4),
  /// against Hertz's b = sqrt(4 F R / (pi E*)), E* = E / (1 - nu^2), F the
  /// force per unit length.
  void
  hertz(Checker &checker, const std::string &mesh)
  {
    const std::string scene =
      subsection("Problem", entry("Dimension", "2")) +
      subsection("Mesh", entry("Source", "file") + entry("File", mesh)) +
      subsection("Material",
                 entry("Model", "neo-Hookean") + entry("Young's modulus", "1") +
                   entry("Poisson's ratio", "0.3")) +
      subsection("Loading", entry("Number of load steps", "4")) +
      dirichlet(1, 1, "x, y", "0; -0.02*t") +
      subsection("Output",
                 entry("Write VTU", "false") + entry("Verbose", "false")) +
      subsection("Contact",
                 entry("Barrier distance", "1e-4") +
                   subsection("Obstacle 1",
                              entry("Type", "plane") +
                                entry("Point", "0, -0.00005") +
                                entry("Normal", "0, 1")));
    const auto problem = run_scene<2>(scene);
    // The vertex forces at the converged state, from a contact term made
    // from the same scene on the same mesh.
    Parameters parameters;
    parameters.read_from_string(scene);
    parameters.contact.check(2);
    const auto              &dof_handler = problem->get_dof_handler();
    const ObstacleContact<2> contact(parameters.contact,
                                     {},
                                     dof_handler,
                                     lame_parameters(1. / 2.6,
                                                     0.3 / (1.3 * 0.4)));
    const VectorType        &u = problem->solution();
    VectorType f(dof_handler.locally_owned_dofs(), MPI_COMM_WORLD);
    contact.contact_forces(u, 1., f);
    f.compress(dealii::VectorOperation::add);
    double                                    F = 0., moment = 0.;
    testing::for_each_owned_vertex(
      dof_handler, [&](const auto &cell, const unsigned int v) {
        const auto   dof = cell->vertex_dof_index(v, 1);
        const double x   = cell->vertex(v)[0] + u(cell->vertex_dof_index(v, 0));
        F += f(dof);
        moment += x * x * f(dof);
      });
    F                   = sum(F, MPI_COMM_WORLD);
    moment              = sum(moment, MPI_COMM_WORLD);
    const double E_star = 1. / (1. - 0.09);
    const double b      = 2. * std::sqrt(moment / F);
    const double hertz  = std::sqrt(4. * F * 1. / (M_PI * E_star));
    checker.close("Hertz: sum of the vertex forces = contact_force_1_y",
                  F,
                  column(problem->summaries().back(), "contact_force_1_y"),
                  F,
                  1e-10);
    checker.close("Hertz: contact half-width 2 sqrt(second moment of the "
                  "forces) against sqrt(4 F R / (pi E*)), F = " +
                    number(F),
                  b,
                  hertz,
                  hertz,
                  0.05);
  }

  /// Hertz in 3D: a rigid sphere of radius R = 0.1 (Contact/Obstacle 1)
  /// pressed into the quarter block [0, 1]^2 x [-1, 0] of
  /// meshes/hertz_block_3d.msh (tetrahedra of 0.002 within 0.03 of the
  /// origin, growing with slope 0.12 to 0.25), rollers on its symmetry
  /// planes x = 0, y = 0 and its bottom; neo-Hookean E = 1, nu = 0.3. The
  /// sphere starts d_hat / 2 above the top and moves down by @p push; the
  /// indentation delta is the depression of the top at the axis, -u_z at
  /// the origin (the sphere's travel less its start gap and the converged
  /// gap at the axis: the barrier's gap is not counted as indentation).
  /// Against Hertz for a rigid sphere on an elastic half space: the force
  /// F = 4/3 E* sqrt(R) delta^1.5, E* = E / (1 - nu^2), and the contact
  /// radius a = sqrt(R delta), a found from the computed vertex forces f_a
  /// at positions x_a: Hertz's pressure p0 sqrt(1 - r^2 / a^2) has the
  /// second moment <r^2> = 2 a^2 / 5 over its disk, so a = sqrt(5/2 sum r_a^2
  /// f_a / sum f_a) (the quarter's forces have the whole disk's moments).
  void
  hertz_3d(Checker           &checker,
           const std::string &mesh,
           const double       force_tolerance,
           const int          degree)
  {
    const double      R = 0.1, d_hat = 1e-5, push = 0.002 + 0.5 * d_hat;
    const std::string scene =
      subsection("Problem",
                 entry("Dimension", "3") +
                   entry("Finite element degree", std::to_string(degree))) +
      subsection("Mesh", entry("Source", "file") + entry("File", mesh)) +
      subsection("Material",
                 entry("Model", "neo-Hookean") + entry("Young's modulus", "1") +
                   entry("Poisson's ratio", "0.3")) +
      subsection("Loading", entry("Number of load steps", "4")) +
      dirichlet(1, 1, "x", "0") + dirichlet(2, 2, "y", "0") +
      dirichlet(3, 3, "z", "0") +
      subsection("Output",
                 entry("Write VTU", "false") + entry("Verbose", "false")) +
      subsection("Contact",
                 entry("Barrier distance", number(d_hat)) +
                   subsection("Obstacle 1",
                              entry("Type", "sphere") +
                                entry("Point",
                                      "0, 0, " + number(R + 0.5 * d_hat)) +
                                entry("Radius", number(R)) +
                                entry("Motion",
                                      "0; 0; -" + number(push) + "*t")));
    const auto problem = run_scene<3>(scene);
    Parameters parameters;
    parameters.read_from_string(scene);
    parameters.contact.check(3);
    const auto              &dof_handler = problem->get_dof_handler();
    const ObstacleContact<3> contact(parameters.contact,
                                     {},
                                     dof_handler,
                                     lame_parameters(1. / 2.6,
                                                     0.3 / (1.3 * 0.4)));
    const VectorType        &u = problem->solution();
    VectorType f(dof_handler.locally_owned_dofs(), MPI_COMM_WORLD);
    contact.contact_forces(u, 1., f);
    f.compress(dealii::VectorOperation::add);
    // Sums over the owned vertices: the force, its second moment about the
    // axis, the depression at the origin, the vertices in contact (vertex
    // force above 1e-3 of the largest) and the largest radius among them.
    double F = 0., moment = 0., delta = 0., largest = 0.;
    std::vector<std::pair<double, double>> radius_force;
    testing::for_each_owned_vertex(
      dof_handler, [&](const auto &cell, const unsigned int v) {
        const auto dof = cell->vertex_dof_index(v, 2);
        if (cell->vertex(v).norm() < 1e-12)
          delta = -u(dof);
        const double x  = cell->vertex(v)[0] + u(cell->vertex_dof_index(v, 0));
        const double y  = cell->vertex(v)[1] + u(cell->vertex_dof_index(v, 1));
        const double fz = -f(dof); // the sphere pushes down
        F += fz;
        moment += (x * x + y * y) * fz;
        if (fz != 0.)
          radius_force.emplace_back(std::sqrt(x * x + y * y), fz);
        largest = std::max(largest, fz);
      });
    F       = 4. * sum(F, MPI_COMM_WORLD);
    moment  = 4. * sum(moment, MPI_COMM_WORLD);
    delta   = sum(delta, MPI_COMM_WORLD);
    largest = dealii::Utilities::MPI::max(largest, MPI_COMM_WORLD);
    double       edge = 0.;
    unsigned int in_contact = 0;
    for (const auto &[r, fz] : radius_force)
      if (fz > 1e-3 * largest)
        {
          edge = std::max(edge, r);
          ++in_contact;
        }
    edge       = dealii::Utilities::MPI::max(edge, MPI_COMM_WORLD);
    in_contact = sum(in_contact, MPI_COMM_WORLD);

    const double E_star = 1. / (1. - 0.09);
    const double a      = std::sqrt(2.5 * moment / F);
    const double hertz_force =
      4. / 3. * E_star * std::sqrt(R) * std::pow(delta, 1.5);
    const double hertz_radius = std::sqrt(R * delta);
    checker.note("delta = " + number(delta) + " (delta / R = " +
                 number(delta / R) + "), Hertz a = " + number(hertz_radius) +
                 "; " + std::to_string(in_contact) +
                 " vertices of the quarter carry more than 1e-3 of the "
                 "largest vertex force, the farthest at r = " +
                 number(edge) + " (a / r = " + number(hertz_radius / edge) +
                 ")");
    checker.close("Hertz 3D: 4 sum of the vertex forces = -4 contact_force_1_z",
                  F,
                  -4. * column(problem->summaries().back(), "contact_force_1_z"),
                  F,
                  1e-10);
    checker.close("Hertz 3D: force against 4/3 E* sqrt(R) delta^1.5, delta = "
                  "-u_z at the origin",
                  F,
                  hertz_force,
                  hertz_force,
                  force_tolerance);
    checker.close("Hertz 3D: contact radius sqrt(5/2 second moment of the "
                  "vertex forces) against sqrt(R delta)",
                  a,
                  hertz_radius,
                  hertz_radius,
                  0.05);
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
      else if (which == "drop")
        drop<2>(checker);
      else if (which == "compression")
        compression<2>(checker);
      else if (which == "friction")
        friction<2>(checker);
      else if (which == "hertz")
        hertz(checker, argc > 3 ? argv[3] : "half_disk_2d.msh");
      else
        resting<2>(checker);
    },
    [&](const std::string &which, Checker &checker) {
      if (which == "fd")
        fd<3>(checker);
      else if (which == "drop")
        drop<3>(checker);
      else if (which == "compression")
        compression<3>(checker);
      else if (which == "friction")
        friction<3>(checker);
      else if (which == "hertz")
        hertz_3d(checker,
                 argc > 3 ? argv[3] : "hertz_block_3d.msh",
                 argc > 4 ? std::atof(argv[4]) : 0.05,
                 argc > 5 ? std::atoi(argv[5]) : 1);
      else
        resting<3>(checker);
    });
}
