// The moments of the CSV summary (issue 57, item 5): reaction_moment_<id>_*
// about 'Output/Moment point' and contact_moment_<k>_* about an obstacle's
// point.
//   twist 3 DEGREE  the bar [0,4] x [0,1] x [0,1] (neo-Hookean, E = 1,
//               nu = 0.3; P1 8 x 2 x 2 boxes, P2 4 x 1 x 1), clamped at
//               x = 0 (id 0), its end x = 4 (id 1) turned by 90 degrees
//               about the bar's axis, no other load, tight tolerances,
//               the moment point (1, 0.25, 0.75) off the axis: each end's
//               reaction_moment equals the sum over that end's nodes (every
//               dof support point: P2's edge midpoints too) of
//               (X + u - p) x f, computed here from the converged nodal
//               forces with deal.II's support points (1e-10 of |M|), and
//               the two ends' moments are equal and opposite (1e-10).
//   turned_disk 2 MESH  the disk of radius 2 with a hole of radius 0.25 at
//               its centre (meshes/disk_with_hole_2d.msh), held by the hole
//               (id 1), which moves up by 0.02 in the first half of the
//               load, pressing the disk's top onto a straight plate (a
//               meshed obstacle, mu = 0.5) whose Point is the disk's centre
//               (0, 0.02) by then; in the second half the plate turns by
//               0.02 rad about that centre, its friction turning the disk.
//               The plate's contact_moment_1_z about the centre equals
//               minus reaction_moment_1_z about the centre ('Output/Moment
//               point' = 0, 0.02) to 1e-9 of its size, and so do the forces
//               (contact_force_1 = -reaction_1); the moment is not trivial:
//               at least a tenth of mu times the plate's force times the
//               radius 2.
//   wedge 2 MESH  the same disk moved up by 0.01 onto the tip of a fixed
//               frictionless wedge at x = 0.3 (its Point the origin, the
//               moment point too): only the wedge's corner pair
//               (MeshObstaclePairs) touches; the same balance, and the
//               moment is that of the total force at the tip (1e-9).
// Usage: mpirun -np N moments CASE DIM [DEGREE | MESH]
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>

#include "support/dimension_main.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <string>
#include <vector>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  const char *const axes[3] = {"x", "y", "z"};

  /// The moment about @p p of the nodal forces of @p problem's converged
  /// state on boundary @p id: the sum over the owned dofs on that boundary
  /// of (X + u - p) x f e_c, X the dof's support point (deal.II's
  /// map_dofs_to_support_points), u the displacement at the node (the dofs
  /// of the other components at the same support point), f the dof's
  /// entry of f_int - f_ext. Collective.
  template <int dim>
  dealii::Tensor<1, 3>
  nodal_moment(const Problem<dim>       &problem,
               const unsigned int        id,
               const dealii::Point<dim> &p)
  {
    const auto                  &dof_handler = problem.get_dof_handler();
    const VectorType            &u           = problem.solution();
    const VectorType            &f           = problem.residual_forces();
    const dealii::MappingFE<dim> mapping(dealii::FE_SimplexP<dim>(1));
    std::map<dealii::types::global_dof_index, dealii::Point<dim>> support;
    dealii::DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);
    // The dofs of each component, and each node's dofs by support point.
    std::array<dealii::IndexSet, dim> of_component;
    for (unsigned int c = 0; c < dim; ++c)
      {
        dealii::ComponentMask mask(dim, false);
        mask.set(c, true);
        of_component[c] = dealii::DoFTools::extract_dofs(dof_handler, mask);
      }
    const auto key = [](const dealii::Point<dim> &X) {
      std::array<double, dim> k;
      for (unsigned int d = 0; d < dim; ++d)
        k[d] = X[d];
      return k;
    };
    std::map<std::array<double, dim>,
             std::array<dealii::types::global_dof_index, dim>>
      node;
    for (const auto &[dof, X] : support)
      for (unsigned int c = 0; c < dim; ++c)
        if (of_component[c].is_element(dof))
          node[key(X)][c] = dof;
    const dealii::IndexSet on_boundary =
      dealii::DoFTools::extract_boundary_dofs(
        dof_handler,
        dealii::ComponentMask(),
        {static_cast<dealii::types::boundary_id>(id)});
    dealii::Tensor<1, 3> moment;
    for (const auto dof : dof_handler.locally_owned_dofs())
      {
        if (!on_boundary.is_element(dof))
          continue;
        const dealii::Point<dim> &X    = support.at(dof);
        const auto               &dofs = node.at(key(X));
        dealii::Tensor<1, 3>      arm, force;
        for (unsigned int d = 0; d < dim; ++d)
          {
            arm[d] = X[d] + u(dofs[d]) - p[d];
            if (dofs[d] == dof)
              force[d] = f(dof);
          }
        moment += dealii::cross_product_3d(arm, force);
      }
    return dealii::Utilities::MPI::sum(moment, MPI_COMM_WORLD);
  }

  /// The reported moment of column family @p prefix (reaction_moment_1_,
  /// contact_moment_1_, ...) of @p s as a 3D vector (2D: z only).
  template <int dim>
  dealii::Tensor<1, 3>
  moment_columns(const StepSummary<dim> &s, const std::string &prefix)
  {
    dealii::Tensor<1, 3> m;
    for (unsigned int d = (dim == 3 ? 0 : 2); d < 3; ++d)
      m[d] = column(s, prefix + axes[d]);
    return m;
  }

  void
  twist(Checker &checker, const unsigned int degree)
  {
    const std::string tag = "twisted bar P" + std::to_string(degree) + ": ";
    const std::string scene =
      subsection("Problem",
                 entry("Dimension", "3") +
                   entry("Finite element degree", std::to_string(degree))) +
      subsection("Mesh",
                 entry("Upper corner", "4, 1, 1") +
                   entry("Subdivisions", degree == 1 ? "8, 2, 2" : "4, 1, 1")) +
      subsection("Material",
                 entry("Model", "neo-Hookean") + entry("Young's modulus", "1") +
                   entry("Poisson's ratio", "0.3")) +
      subsection("Loading", entry("Number of load steps", "4")) +
      dirichlet(1, 0, "x, y, z", "0; 0; 0") + twisted_end("0", "pi/2*t") +
      tight_solver("direct") +
      subsection("Output",
                 entry("Write VTU", "false") + entry("Verbose", "false") +
                   entry("Moment point", "1, 0.25, 0.75"));
    Parameters parameters;
    parameters.read_from_string(scene);
    Problem<3>             problem(parameters, MPI_COMM_WORLD, false);
    const dealii::Point<3> p(1., 0.25, 0.75);
    // The nodal sums at the last step's converged state.
    std::array<dealii::Tensor<1, 3>, 2> summed;
    problem.set_step_observer([&](const StepSummary<3> &s) {
      if (std::abs(s.load_factor - 1.) < 1e-12)
        for (unsigned int id = 0; id < 2; ++id)
          summed[id] = nodal_moment(problem, id, p);
    });
    problem.run();
    const auto &last = problem.summaries().back();
    checker.close(tag + "completed to t", last.load_factor, 1., 1., 1e-12);
    const dealii::Tensor<1, 3> clamped =
                                 moment_columns(last, "reaction_moment_0_"),
                               turned =
                                 moment_columns(last, "reaction_moment_1_");
    const double size = turned.norm();
    checker.above(tag + "|reaction_moment_1| (the torque)", size, 1e-3);
    checker.at_most(tag + "|reaction_moment_1 - nodal sum of (X + u - p) x f| "
                          "/ |reaction_moment_1|",
                    (turned - summed[1]).norm() / size,
                    1e-10);
    checker.at_most(tag + "|reaction_moment_0 - nodal sum of (X + u - p) x f| "
                          "/ |reaction_moment_1|",
                    (clamped - summed[0]).norm() / size,
                    1e-10);
    checker.at_most(tag + "|reaction_moment_0 + reaction_moment_1| / "
                          "|reaction_moment_1| (equilibrium)",
                    (clamped + turned).norm() / size,
                    1e-10);
    checker.note(tag + "reaction_moment_1 = (" + number(turned[0]) + ", " +
                 number(turned[1]) + ", " + number(turned[2]) + ")");
  }

  /// The polyline through @p points as a gmsh file @p name (with the
  /// number of ranks: runs on 1 and 2 ranks may overlap) in the working
  /// folder (rank 0 writes it; returns the path). Collective.
  std::string
  polyline_file(const std::string                        &name,
                const std::vector<std::array<double, 2>> &points)
  {
    const std::string path =
      (std::filesystem::current_path() /
       (name + "_np" +
        std::to_string(
          dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)) +
        ".msh"))
        .string();
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::ofstream out(path);
        out << std::setprecision(17)
            << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
            << points.size() << "\n";
        for (unsigned int i = 0; i < points.size(); ++i)
          out << i + 1 << " " << points[i][0] << " " << points[i][1] << " 0\n";
        out << "$EndNodes\n$Elements\n" << points.size() - 1 << "\n";
        for (unsigned int i = 1; i < points.size(); ++i)
          out << i << " 1 2 1 1 " << i << " " << i + 1 << "\n";
        out << "$EndElements\n";
      }
    MPI_Barrier(MPI_COMM_WORLD);
    return path;
  }

  /// The disk of the 2D cases (@p mesh), neo-Hookean (E = 1, nu = 0.3),
  /// its hole (id 1) moved by @p hole (x; y expressions), 'Output/Moment
  /// point' @p point, tight tolerances, and @p contact as the Contact
  /// section's body.
  std::string
  disk_scene(const std::string &mesh,
             const std::string &steps,
             const std::string &hole,
             const std::string &point,
             const std::string &contact)
  {
    return subsection("Problem", entry("Dimension", "2")) +
           subsection("Mesh", entry("Source", "file") + entry("File", mesh)) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1") +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading", entry("Number of load steps", steps)) +
           dirichlet(1, 1, "x, y", hole) + tight_solver("direct") +
           subsection("Output",
                      entry("Write VTU", "false") + entry("Verbose", "false") +
                        entry("Moment point", point)) +
           subsection("Contact", contact);
  }

  /// The balance of obstacle 1 and the support (id 1) at the last step of
  /// @p problem: forces and moments about the centre (1e-9 of their size).
  /// Returns |contact_force_1|.
  double
  check_balance(Checker           &checker,
                const Problem<2>  &problem,
                const std::string &tag)
  {
    const auto &last = problem.summaries().back();
    checker.close(tag + "completed to t", last.load_factor, 1., 1., 1e-12);
    double force = 0.;
    for (unsigned int d = 0; d < 2; ++d)
      force +=
        std::pow(column(last, std::string("contact_force_1_") + axes[d]), 2);
    force = std::sqrt(force);
    for (unsigned int d = 0; d < 2; ++d)
      checker.close(tag + "contact_force_1_" + axes[d] + " = -reaction_1_" +
                      axes[d],
                    column(last, std::string("contact_force_1_") + axes[d]),
                    -column(last, std::string("reaction_1_") + axes[d]),
                    force,
                    1e-9);
    const double plate   = column(last, "contact_moment_1_z");
    const double support = column(last, "reaction_moment_1_z");
    checker.close(tag + "contact_moment_1_z = -reaction_moment_1_z",
                  plate,
                  -support,
                  std::abs(plate),
                  1e-9);
    checker.note(tag + "contact_moment_1_z = " + number(plate) +
                 ", reaction_moment_1_z = " + number(support) +
                 ", |contact_force_1| = " + number(force));
    return force;
  }

  void
  turned_disk(Checker &checker, const std::string &mesh)
  {
    const std::string tag   = "disk turned by a plate: ";
    const double      d_hat = 1e-3, mu = 0.5, lift = 0.02;
    // The plate at y = 2 + d_hat / 2 in the scene, its file's coordinates
    // relative to its Point, the disk's centre once lifted.
    const double      top    = 2. + 0.5 * d_hat - lift;
    const std::string centre = "0, " + number(lift);
    const std::string contact =
      entry("Barrier distance", number(d_hat)) +
      entry("Meshed obstacle corners", "false") +
      subsection("Obstacle 1",
                 entry("Type", "mesh") +
                   entry("File",
                         polyline_file("turning_plate_2d",
                                       {{{{-3., top}}, {{3., top}}}})) +
                   entry("Point", centre) + entry("Rotation axis", "0, 0, 1") +
                   entry("Rotation angle", "t < 0.5 ? 0 : 0.02*(2*t - 1)") +
                   entry("Friction coefficient", number(mu)));
    const auto problem =
      run_scene<2>(disk_scene(mesh,
                              "10",
                              "0; " + number(lift) + "*(t < 0.5 ? 2*t : 1)",
                              centre,
                              contact));
    const double force = check_balance(checker, *problem, tag);
    checker.at_least(tag + "|contact_moment_1_z| / (mu |contact_force_1| 2) "
                           "(the friction turns the disk)",
                     std::abs(column(problem->summaries().back(),
                                     "contact_moment_1_z")) /
                       (mu * force * 2.),
                     0.1);
  }

  /// The disk pushed up by 0.01 onto the tip of a fixed frictionless wedge
  /// (its Point the origin) at x = 0.3, between two of the disk's
  /// boundary vertices: only the wedge's corner pair (MeshObstaclePairs)
  /// touches, its force on the face's two vertices.
  void
  wedge(Checker &checker, const std::string &mesh)
  {
    const std::string tag   = "disk pushed onto a wedge's tip: ";
    const double      d_hat = 1e-3;
    // The chord between the boundary vertices at 90 and 78.75 degrees.
    const double a = 78.75 * M_PI / 180., x = 0.3;
    const double y =
      2. + (2. * std::sin(a) - 2.) * x / (2. * std::cos(a)) + 0.5 * d_hat;
    const std::string contact =
      entry("Barrier distance", number(d_hat)) +
      subsection("Obstacle 1",
                 entry("Type", "mesh") +
                   entry("File",
                         polyline_file("wedge_2d",
                                       {{{{x - 0.5, y + 0.5}},
                                         {{x, y}},
                                         {{x + 0.5, y + 0.5}}}})) +
                   entry("Point", "0, 0"));
    const auto problem =
      run_scene<2>(disk_scene(mesh, "5", "0; 0.01*t", "0, 0", contact));
    const auto  &last  = problem->summaries().back();
    const double force = check_balance(checker, *problem, tag);
    checker.above(tag + "|contact_force_1|", force, 1e-4);
    checker.close(tag + "contact_active_pairs (the tip's pair only)",
                  column(last, "contact_active_pairs"),
                  1.,
                  1.,
                  1e-12);
    // The pair's energy depends on its distance only: the moment of its
    // forces on the body's vertices is that of the total force at the tip
    // (minus the moment on the wedge), (x, y) x F.
    const double moment = column(last, "contact_moment_1_z");
    checker.close(tag + "contact_moment_1_z = (x_tip, y_tip) x contact_force_1",
                  moment,
                  x * column(last, "contact_force_1_y") -
                    y * column(last, "contact_force_1_x"),
                  std::abs(moment),
                  1e-9);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_case_for_dimension(
    argc,
    argv,
    "twist",
    [&](const std::string &which, Checker &checker) {
      const std::string mesh = argc > 3 ? argv[3] : "disk_with_hole_2d.msh";
      if (which == "turned_disk")
        turned_disk(checker, mesh);
      else if (which == "wedge")
        wedge(checker, mesh);
      else
        throw InputError("moments: in 2D the cases are turned_disk, wedge");
    },
    [&](const std::string &which, Checker &checker) {
      if (which != "twist")
        throw InputError("moments: in 3D the case is twist");
      twist(checker, argc > 3 ? std::atoi(argv[3]) : 1);
    });
}
