// Rigid rotation of obstacles (Contact III, issue 43: 'Rotation axis',
// 'Rotation angle').
//   fd DIM      a turned plane and a turned flat surface mesh (the same
//               plane): the same energy (1e-12); forces against central
//               differences of the potential and the stiffness against
//               central differences of the forces (1e-6), with friction
//               after the obstacle turned within a step; a body carried
//               rigidly with the turning obstacle keeps its energy and its
//               forces turn with it (friction's slip includes the
//               obstacle's rotation: zero); a plane turning into the body
//               is stopped by the feasible step: every distance keeps at
//               least a tenth of its value at 10 points of the way, the
//               full way crosses.
//   tilting_table DIM  a block (mu = 0.5) on a plane turning about a
//               horizontal axis through the block's centre of mass
//               (backward Euler): held at 20 degrees (tan < mu) it sticks,
//               creeping slower than eps_v; held at 35 degrees it slides
//               down with acceleration g (sin - mu cos) (2 %).
//   rotating_plate 3  a block clamped at its bottom, a plate (mu = 1)
//               pressed onto its top, then turned by 3 degrees about the
//               vertical axis (quasi-static): the top vertices turn with
//               it, off the plate's rotation by less than the slip the
//               smoothing allows (eps per load step of the turn); the
//               plate's contact_moment about its point balances the
//               clamp's reaction_moment about the same point (1e-6).
// Usage: mpirun -np N contact_rotation CASE DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/contact/obstacle_contact.h>

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
#include <string>
#include <vector>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using dealii::Utilities::MPI::max;

namespace
{
  /// The rotation by @p angle about the unit vector @p axis (2D: about
  /// +z if axis[2] > 0, else -z), written out here independently of the
  /// library's.
  template <int dim>
  dealii::Tensor<2, dim>
  rotation(const std::array<double, 3> &axis, const double angle)
  {
    const double           c = std::cos(angle), s = std::sin(angle);
    dealii::Tensor<2, dim> Q;
    if constexpr (dim == 2)
      {
        const double z = axis[2] > 0. ? 1. : -1.;
        Q[0][0]        = c;
        Q[1][1]        = c;
        Q[0][1]        = -z * s;
        Q[1][0]        = z * s;
      }
    else
      {
        // Q v = c v + s (a x v) + (1 - c) a (a . v), column by column.
        for (unsigned int j = 0; j < 3; ++j)
          {
            dealii::Tensor<1, 3> e, a;
            e[j] = 1.;
            for (unsigned int i = 0; i < 3; ++i)
              a[i] = axis[i];
            const dealii::Tensor<1, 3> column =
              c * e + s * dealii::cross_product_3d(a, e) + (1. - c) * a[j] * a;
            for (unsigned int i = 0; i < 3; ++i)
              Q[i][j] = column[i];
          }
      }
    return Q;
  }

  /// The axis of the fd case: oblique in 3D, -z in 2D.
  std::array<double, 3>
  fd_axis(const int dim)
  {
    if (dim == 2)
      return {{0., 0., -1.}};
    const double n = std::sqrt(0.01 + 1. + 0.04);
    return {{0.1 / n, 1. / n, 0.2 / n}};
  }

  /// A flat square surface in its file's plane z = 0 (2D: a line along x),
  /// [-1.03, 2.01] in each in-plane direction, its vertices off the box's
  /// coordinates (rank 0 writes it; returns the path). Collective.
  template <int dim>
  std::string
  flat_surface_file()
  {
    const std::string path = (std::filesystem::current_path() /
                              ("turned_floor_" + std::to_string(dim) + "d.msh"))
                               .string();
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        const std::array<double, 3> at = {{-1.03, 0.47, 2.01}};
        std::ofstream               out(path);
        out << std::setprecision(17)
            << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n";
        if constexpr (dim == 2)
          {
            out << "3\n";
            for (unsigned int i = 0; i < 3; ++i)
              out << i + 1 << " " << at[i] << " 0 0\n";
            out << "$EndNodes\n$Elements\n2\n"
                << "1 1 2 1 1 1 2\n2 1 2 1 1 2 3\n";
          }
        else
          {
            out << "9\n";
            for (unsigned int j = 0; j < 3; ++j)
              for (unsigned int i = 0; i < 3; ++i)
                out << 3 * j + i + 1 << " " << at[i] << " " << at[j] << " 0\n";
            out << "$EndNodes\n$Elements\n8\n";
            unsigned int e = 0;
            for (unsigned int j = 0; j < 2; ++j)
              for (unsigned int i = 0; i < 2; ++i)
                {
                  const unsigned int a = 3 * j + i + 1;
                  out << ++e << " 2 2 1 1 " << a << " " << a + 1 << " " << a + 4
                      << "\n";
                  out << ++e << " 2 2 1 1 " << a << " " << a + 4 << " " << a + 3
                      << "\n";
                }
          }
        out << "$EndElements\n";
      }
    MPI_Barrier(MPI_COMM_WORLD);
    return path;
  }

  /// A plane (or the flat surface of flat_surface_file()) through
  /// (0.5, .., -0.06), facing up before it turns, turned by @p angle about
  /// fd_axis() through that point: tilted by 0.1 about an axis across x,
  /// below the unit box's bottom, 0.01 to 0.11 from it.
  template <int dim>
  ObstacleParameters
  turned(const ObstacleType type,
         const std::string &angle,
         const double       friction,
         const std::string &file = "")
  {
    ObstacleParameters o;
    o.number          = 1;
    o.subsection      = "Contact/Obstacle 1";
    o.type            = type;
    o.point           = std::vector<double>(dim, 0.5);
    o.point[dim - 1]  = -0.06;
    o.normal          = std::vector<double>(dim, 0.);
    o.normal[dim - 1] = 1.;
    o.motion          = std::vector<std::string>(dim, "0");
    o.file            = file;
    o.friction        = friction;
    o.rotation_angle  = angle;
    const auto axis   = fd_axis(dim);
    o.rotation_axis   = dim == 2 ? std::vector<double>{axis[2]}
                                 : std::vector<double>(axis.begin(), axis.end());
    return o;
  }

  /// Each owned vertex dof of @p box: f(dofs of its vertex, its reference
  /// position) once.
  template <int dim, typename F>
  void
  for_each_vertex(const BoxDiscretisation<dim> &box, const F &f)
  {
    std::vector<bool> seen(box.dof_handler.n_dofs(), false);
    for (const auto &cell : box.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            std::array<dealii::types::global_dof_index, dim> dofs;
            for (unsigned int d = 0; d < dim; ++d)
              dofs[d] = cell->vertex_dof_index(v, d);
            if (!box.owned.is_element(dofs[0]) || seen[dofs[0]])
              continue;
            seen[dofs[0]] = true;
            f(dofs, cell->vertex(v));
          }
  }

  template <int dim>
  void
  fd(Checker &checker)
  {
    const MPI_Comm         comm = MPI_COMM_WORLD;
    BoxDiscretisation<dim> box(1., 4, 4, 1, comm);
    const LameParameters   moduli = lame_parameters(1., 1.);
    const std::string      floor  = flat_surface_file<dim>();
    const std::string      tag    = std::to_string(dim) + "D ";

    VectorType u(box.owned, comm), ghosted(box.owned, box.relevant, comm);
    VectorType v(box.owned, comm), w(box.owned, comm);
    fill_random(u, 1e-4, 1);
    fill_random(v, 1., 2);
    const auto at = [&](const VectorType &base, const double s) {
      w = base;
      w.add(s, v);
      ghosted = w;
      return ghosted;
    };
    const auto g_at =
      [&](const ObstacleContact<dim> &c, const VectorType &x, const double t) {
        VectorType g(box.owned, comm);
        c.add_forces(x, t, g);
        g.compress(dealii::VectorOperation::add);
        return g;
      };
    const auto contact_of = [&](const ObstacleParameters &o) {
      ContactParameters parameters;
      parameters.barrier_distance = 0.1;
      parameters.obstacles.push_back(o);
      return std::make_unique<ObstacleContact<dim>>(
        parameters, std::map<std::string, double>(), box.dof_handler, moduli);
    };

    // The turned plane and the same plane as a turned surface mesh.
    {
      const auto plane =
        contact_of(turned<dim>(ObstacleType::plane, "0.1", 0.));
      const auto mesh =
        contact_of(turned<dim>(ObstacleType::mesh, "0.1", 0., floor));
      ghosted = u;
      checker.close(tag + "turned mesh's energy = turned plane's",
                    mesh->energy(ghosted, 0.),
                    plane->energy(ghosted, 0.),
                    plane->energy(ghosted, 0.),
                    1e-12);
    }

    // Forces and stiffness against differences, with friction: the
    // obstacle turns back from 0.1 to 0.08 within the step, the body moved by
    // u - u0 (random) meanwhile.
    for (const ObstacleType type : {ObstacleType::plane, ObstacleType::mesh})
      {
        const std::string name =
          tag + (type == ObstacleType::plane ? "turned plane" : "turned mesh") +
          ", friction: ";
        const auto contact =
          contact_of(turned<dim>(type, "0.1 - 0.02*t", 0.5, floor));
        VectorType u0(box.owned, comm);
        fill_random(u0, 1e-4, 3);
        ghosted = u0;
        contact->begin_step(ghosted, 0.);
        contact->prepare_motion(1.);
        contact->advance(1., 1.);
        const double h     = 1e-7;
        ghosted            = u;
        VectorType   g     = g_at(*contact, ghosted, 1.);
        const double slope = -(g * v);
        const double fd_slope =
          (contact->energy(at(u, h), 1.) - contact->energy(at(u, -h), 1.)) /
          (2. * h);
        checker.close(name +
                        "forces . v against (V(u + h v) - V(u - h v)) / 2h",
                      slope,
                      fd_slope,
                      std::abs(fd_slope),
                      1e-6);
        MatrixType K;
        box.reinit_matrix(K);
        VectorType                        rhs(box.owned, comm);
        dealii::AffineConstraints<double> none;
        none.close();
        ghosted = u;
        contact->add_stiffness(
          ghosted, 1., TangentProjection::none, none, K, rhs);
        K.compress(dealii::VectorOperation::add);
        VectorType Kv(box.owned, comm);
        K.vmult(Kv, v);
        VectorType difference = g_at(*contact, at(u, -h), 1.);
        difference -= g_at(*contact, at(u, h), 1.);
        difference /= 2. * h;
        difference -= Kv;
        checker.at_most(name + "|K v - FD of the forces| / |K v|",
                        difference.l2_norm() / Kv.l2_norm(),
                        1e-6);
      }

    // Carried rigidly: the body turns with the obstacle by 0.2 about its
    // point within a step (begin_step at the angle 0.1, the step ending at
    // 0.3): the distances stay, the barrier's forces turn with the body,
    // and friction's slip is zero (so the forces are the barrier's alone).
    const auto                   axis = fd_axis(dim);
    const dealii::Tensor<2, dim> Q    = rotation<dim>(axis, 0.2);
    dealii::Point<dim>           pivot;
    for (unsigned int d = 0; d < dim; ++d)
      pivot[d] = d + 1 == dim ? -0.06 : 0.5;
    for (const ObstacleType type : {ObstacleType::plane, ObstacleType::mesh})
      {
        const std::string name =
          tag + (type == ObstacleType::plane ? "turned plane" : "turned mesh") +
          ", carried with it: ";
        const auto contact =
          contact_of(turned<dim>(type, "0.1 + 0.2*t", 0.5, floor));
        ghosted = u;
        contact->begin_step(ghosted, 0.);
        const VectorType g0 = g_at(*contact, ghosted, 0.);
        const double     e0 = contact->energy(ghosted, 0.);
        VectorType       carried(box.owned, comm);
        for_each_vertex(box,
                        [&](const auto &dofs, const dealii::Point<dim> &X) {
                          dealii::Tensor<1, dim> x = X - pivot;
                          for (unsigned int d = 0; d < dim; ++d)
                            x[d] += u(dofs[d]);
                          const dealii::Tensor<1, dim> y = Q * x;
                          for (unsigned int d = 0; d < dim; ++d)
                            carried(dofs[d]) = y[d] + pivot[d] - X[d];
                        });
        carried.compress(dealii::VectorOperation::insert);
        contact->prepare_motion(1.);
        contact->advance(1., 1.);
        ghosted             = carried;
        const VectorType g1 = g_at(*contact, ghosted, 1.);
        checker.close(name + "energy after the turn = before",
                      contact->energy(ghosted, 1.),
                      e0,
                      e0,
                      1e-10);
        double error = 0., size = 0.;
        for_each_vertex(box, [&](const auto &dofs, const dealii::Point<dim> &) {
          dealii::Tensor<1, dim> f0, f1;
          for (unsigned int d = 0; d < dim; ++d)
            {
              f0[d] = g0(dofs[d]);
              f1[d] = g1(dofs[d]);
            }
          error = std::max(error, (f1 - Q * f0).norm());
          size  = std::max(size, f0.norm());
        });
        error = max(error, comm);
        size  = max(size, comm);
        checker.above(name + "largest force before the turn", size, 0.);
        checker.at_most(name + "max |f after - Q f before| / max |f before|",
                        error / size,
                        1e-9);
      }

    // The feasible step of a plane (and of the flat mesh) turning into the
    // body, from 0.1 to 0.4 (its far edge rises by about 0.16): the body
    // standing, the obstacle's way is cut; at 10 points of the cut way
    // every distance keeps a tenth of its start; the whole way crosses.
    for (const ObstacleType type : {ObstacleType::plane, ObstacleType::mesh})
      {
        const std::string name =
          tag +
          (type == ObstacleType::plane ? "turning plane" : "turning mesh") +
          ": ";
        const auto contact =
          contact_of(turned<dim>(type, "0.1 + 0.3*t", 0., floor));
        ghosted = u;
        contact->begin_step(ghosted, 0.);
        const double start = contact->measure(ghosted, 0.).min_distance;
        checker.is_true(name + "obstacle on its way (prepare_motion)",
                        contact->prepare_motion(1.));
        const VectorType still(box.owned, comm);
        const double     alpha = contact->largest_feasible_step(u, still, 1.);
        checker.is_true(name + "feasible step of the turn in (0, 1): " +
                          std::to_string(alpha),
                        alpha > 0. && alpha < 1.);
        double closest = 1e300;
        for (unsigned int i = 1; i <= 10; ++i)
          {
            contact->begin_step(ghosted, 0.);
            contact->advance(alpha * i / 10., 1.);
            closest =
              std::min(closest, contact->measure(ghosted, 1.).min_distance);
          }
        checker.at_least(name + "smallest distance on the cut way / a tenth "
                                "of the smallest at its start",
                         closest / (0.1 * start),
                         1.);
        if (type != ObstacleType::plane)
          continue;
        contact->begin_step(ghosted, 0.);
        contact->advance(1., 1.);
        checker.is_true(name + "the whole turn crosses (potential infinite)",
                        !std::isfinite(contact->energy(ghosted, 1.)));
      }
  }

  /// The unit block of contact.cc's friction case (E = 1e4, density 1,
  /// gravity 10, bottom 0.99 d_hat above the table, d_hat = 0.005,
  /// mu = 0.5), on a table turning to @p theta by a smooth ramp over
  /// t in [0, 0.5] and held there, about the horizontal axis through the
  /// block's centre of mass (Rotation axis through the table's point, the
  /// Motion (I - Q) c moving it there): the table's normal turns towards
  /// +x, the block slides to +x. Backward Euler, h = 0.01.
  template <int dim>
  std::string
  tilting_table(const double theta, const double end)
  {
    const bool        three = dim == 3;
    const std::string A =
      "(theta*(t < 0.5 ? (1 - cos(2*pi*t))/2 : 1))"; // ramp over 0.5
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection(
             "Mesh",
             entry("Lower corner", three ? "0, 0, 0.00495" : "0, 0.00495") +
               entry("Upper corner", three ? "1, 1, 1.00495" : "1, 1.00495") +
               entry("Subdivisions", three ? "2, 2, 2" : "4, 4")) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1e4") +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading",
                      entry("Body force", three ? "0; 0; -10" : "0; -10") +
                        entry("Constants", "theta = " + number(theta))) +
           subsection("Output",
                      entry("Write VTU", "false") + entry("Verbose", "false") +
                        entry("Points",
                              three ? "0.5, 0.5, 0.00495" : "0.5, 0.00495")) +
           subsection(
             "Contact",
             entry("Barrier distance", "0.005") +
               subsection(
                 "Obstacle 1",
                 entry("Type", "plane") +
                   entry("Point", three ? "0.5, 0.5, 0" : "0.5, 0") +
                   entry("Normal", three ? "0, 0, 1" : "0, 1") +
                   entry("Rotation axis", three ? "0, 1, 0" : "0, 0, -1") +
                   entry("Rotation angle", A) +
                   entry("Motion",
                         "-0.5*sin(" + A + "); " + (three ? "0; " : "") +
                           "0.5*(1 - cos(" + A + "))") +
                   entry("Friction coefficient", "0.5"))) +
           subsection("Time integration",
                      entry("Scheme", "backward Euler") +
                        entry("Density", "1") + entry("Time step", "0.01") +
                        entry("End time", number(end)));
  }

  template <int dim>
  void
  tilting_table(Checker &checker)
  {
    const std::string tag = std::to_string(dim) + "D tilting table: ";
    const std::string up  = dim == 3 ? "momentum_z" : "momentum_y";
    const double      g = 10., mu = 0.5;
    // The velocity along the table, down the slope (unit mass).
    const auto along = [&](const auto &row, const double theta) {
      return column(row, "momentum_x") * std::cos(theta) -
             column(row, up) * std::sin(theta);
    };
    // Held at 20 degrees (tan = 0.36 < mu): it sticks, creeping slower
    // than eps_v = d_hat per unit time = 0.005 once held (t >= 0.6).
    {
      const double theta   = 20. * M_PI / 180.;
      const auto   problem = run_scene<dim>(tilting_table<dim>(theta, 0.8));
      double       fastest = 0., slip = 0.;
      for (const auto &row : problem->summaries())
        if (row.load_factor > 0.6 + 1e-9)
          {
            fastest = std::max(fastest, std::abs(along(row, theta)));
            // Backward Euler: the step's displacement is h v_{n+1}.
            slip += 0.01 * along(row, theta);
          }
      checker.at_most(tag + "20 degrees (tan < mu): largest |velocity along "
                            "the table| / eps_v for t in [0.6, 0.8]",
                      fastest / 0.005,
                      1.);
      checker.at_most(tag + "20 degrees: |slip over t in [0.6, 0.8]| / "
                            "(eps_v 0.2)",
                      std::abs(slip) / (0.005 * 0.2),
                      1.);
      // Stuck, the block turned with the table: the centre of its bottom,
      // 0.49505 below the axis, is where the table's rotation took it,
      // within the creep eps_v t = 0.004 and the block's elastic
      // compression under its weight (1e-3 of its height).
      const auto  &last    = problem->summaries().back();
      const double ux      = column(last, "point1_ux"),
                   uy      = column(last, dim == 3 ? "point1_uz" : "point1_uy");
      const double rigid_x = -0.49505 * std::sin(theta),
                   rigid_y = 0.49505 * (1. - std::cos(theta));
      checker.at_most(tag + "20 degrees: |bottom centre - the table's "
                            "rotation of it| at t = 0.8 / (eps_v 0.8 + 1e-3)",
                      std::hypot(ux - rigid_x, uy - rigid_y) / 0.005,
                      1.);
      checker.above(tag + "20 degrees: smallest contact_min_distance",
                    smallest(problem->summaries(), "contact_min_distance"),
                    0.);
    }
    // Held at 35 degrees (tan = 0.70 > mu): it slides down with
    // acceleration g (sin - mu cos).
    {
      const double theta   = 35. * M_PI / 180.;
      const auto   problem = run_scene<dim>(tilting_table<dim>(theta, 0.8));
      const auto  &s       = problem->summaries();
      const double a =
        (along(at_time(s, 0.8), theta) - along(at_time(s, 0.6), theta)) / 0.2;
      const double exact = g * (std::sin(theta) - mu * std::cos(theta));
      checker.close(tag +
                      "35 degrees (tan > mu): acceleration along the "
                      "table over t in [0.6, 0.8] against g (sin - mu "
                      "cos) = " +
                      number(exact),
                    a,
                    exact,
                    exact,
                    0.02);
      checker.above(tag + "35 degrees: smallest contact_min_distance",
                    smallest(s, "contact_min_distance"),
                    0.);
    }
  }

  /// The block [-0.5, 0.5]^2 x [0, 0.5] (4 x 4 x 2 boxes), clamped at its
  /// bottom, neo-Hookean E = 1, nu = 0.3; a plate (mu = 1) d_hat / 2 above
  /// its top pressed down by 0.05 over t in [0, 0.5], then turned by
  /// @p phi about the vertical axis through the origin over t in [0.5, 1];
  /// 20 load steps; Output/Points at the top's corners, edge midpoints
  /// and two inner vertices.
  std::string
  rotating_plate(const double phi, const double eps)
  {
    return subsection("Problem", entry("Dimension", "3")) +
           subsection("Mesh",
                      entry("Lower corner", "-0.5, -0.5, 0") +
                        entry("Upper corner", "0.5, 0.5, 0.5") +
                        entry("Subdivisions", "4, 4, 2")) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1") +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading",
                      entry("Number of load steps", "20") +
                        entry("Constants", "phi = " + number(phi))) +
           dirichlet(1, 4, "x, y, z", "0; 0; 0") +
           subsection("Output",
                      entry("Write VTU", "false") + entry("Verbose", "false") +
                        entry("Moment point", "0, 0, 0.451") +
                        entry("Points",
                              "0.5, 0.5, 0.5; -0.5, 0.5, 0.5; -0.5, -0.5, "
                              "0.5; 0.5, -0.5, 0.5; 0.5, 0, 0.5; 0, 0.5, 0.5; "
                              "0.25, 0.25, 0.5; -0.25, 0, 0.5")) +
           subsection("Contact",
                      entry("Barrier distance", "0.002") +
                        entry("Friction smoothing", number(eps)) +
                        subsection("Obstacle 1",
                                   entry("Type", "plane") +
                                     entry("Point", "0, 0, 0.501") +
                                     entry("Normal", "0, 0, -1") +
                                     entry("Motion",
                                           "0; 0; -0.05*(t < 0.5 ? 2*t : 1)") +
                                     entry("Rotation axis", "0, 0, 1") +
                                     entry("Rotation angle",
                                           "phi*(t < 0.5 ? 0 : 2*t - 1)") +
                                     entry("Friction coefficient", "1")));
  }

  void
  rotating_plate(Checker &checker)
  {
    const double phi = 3. * M_PI / 180., eps = 1e-4;
    const auto   problem       = run_scene<3>(rotating_plate(phi, eps));
    const auto  &s             = problem->summaries();
    unsigned int turning_steps = 0;
    for (const auto &row : s)
      turning_steps += row.load_factor > 0.5 + 1e-9 ? 1 : 0;
    const auto &pressed = at_time(s, 0.5), &turned = at_time(s, 1.);
    const std::array<std::array<double, 2>, 8> points = {{{{0.5, 0.5}},
                                                          {{-0.5, 0.5}},
                                                          {{-0.5, -0.5}},
                                                          {{0.5, -0.5}},
                                                          {{0.5, 0.}},
                                                          {{0., 0.5}},
                                                          {{0.25, 0.25}},
                                                          {{-0.25, 0.}}}};
    const double c = std::cos(phi), sn = std::sin(phi);
    double       worst = 0., least_turn = 1e300;
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const std::string p  = "point" + std::to_string(k + 1) + "_u";
        const double      xa = points[k][0] + column(pressed, p + "x"),
                     ya      = points[k][1] + column(pressed, p + "y");
        const double xb      = points[k][0] + column(turned, p + "x"),
                     yb      = points[k][1] + column(turned, p + "y");
        // The plate's rotation of the vertex's place when the turn began.
        const double xe = c * xa - sn * ya, ye = sn * xa + c * ya;
        worst      = std::max(worst, std::hypot(xb - xe, yb - ye));
        least_turn = std::min(least_turn, std::hypot(xe - xa, ye - ya));
      }
    const double bound = turning_steps * eps;
    checker.at_least("rotating plate: load steps of the turn",
                     turning_steps,
                     10);
    checker.at_most("rotating plate: largest |top vertex - plate's rotation "
                    "of it| / (eps x steps of the turn = " +
                      number(bound) + ")",
                    worst / bound,
                    1.);
    checker.at_least("rotating plate: smallest way of a top point in the "
                     "turn / the bound (the turn is seen)",
                     least_turn / bound,
                     5.);
    checker.above("rotating plate: smallest contact_min_distance",
                  smallest(s, "contact_min_distance"),
                  0.);
    // The plate's moment about its point (0, 0, 0.451 once pressed, the
    // Moment point) balances the clamp's: the friction's torque and the
    // normal forces' moments.
    double plate_size = 0., balance = 0.;
    for (const char *a : {"x", "y", "z"})
      {
        const double m = column(turned, std::string("contact_moment_1_") + a);
        plate_size += m * m;
        balance +=
          std::pow(m + column(turned, std::string("reaction_moment_4_") + a),
                   2);
      }
    checker.above("rotating plate: |contact_moment_1_z| (the torque)",
                  std::abs(column(turned, "contact_moment_1_z")),
                  1e-4);
    checker.at_most("rotating plate: |contact_moment_1 + reaction_moment_4| "
                    "/ |contact_moment_1|",
                    std::sqrt(balance / plate_size),
                    1e-6);
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
      if (which == "tilting_table")
        tilting_table<2>(checker);
      else
        fd<2>(checker);
    },
    [&](const std::string &which, Checker &checker) {
      if (which == "tilting_table")
        tilting_table<3>(checker);
      else if (which == "rotating_plate")
        rotating_plate(checker);
      else
        fd<3>(checker);
    });
}
