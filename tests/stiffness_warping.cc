// Stiffness warping (Müller et al. 2002, assembly/warped_assembler.h), on the
// ranks of MPI_COMM_WORLD:
//   rigid         a rigid rotation (1.1 rad about a skew axis) plus a
//                 translation of a box: every vertex rotation equals the
//                 rotation and the forces vanish (1e-12 of the forces of a
//                 10 % stretch); the same rotation superposed on a
//                 deformation rotates every nodal force (objectivity, 1e-12);
//   small_strain  at u = eps w(X) the warped forces approach the linear
//                 elastic K u: relative difference below 1e-3 at eps = 1e-4,
//                 falling at order 1 in eps (quadratic absolute); at rest the
//                 warped tangent is the linear elastic stiffness (1e-13);
//                 bent, it differs from the forces' derivative (central
//                 differences) by less than 0.2 x the bending amplitude
//                 (the dR/dx it leaves out);
//   cantilever    a cantilever swinging under gravity (Newmark): the tip
//                 trajectory of stiffness warping stays within a stated band
//                 of the element-rotation corotational model's (5 % of the
//                 tip's largest deflection; measured 3.5 % in 2D, 0.8 % in
//                 3D); with 'Linearize once per step' one Newton iteration
//                 per step and the tip within 3 % of full Newton (measured
//                 1.1 %, 2.0 %);
//   momentum      a free body translating rigidly keeps its momentum (1e-12)
//                 and moves as u = v t; set spinning and deforming, the
//                 momentum drifts (vertex rotations make sum_i f_i != 0,
//                 the ghost forces Müller and Gross 2004 removed with element
//                 rotations): the drift is printed and held below 2e-3 of
//                 |p| (measured 2.2e-4 in 2D, 4.1e-4 in 3D).
//
// Usage: mpirun -np N stiffness_warping CASE DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/assembly/generic_assembler.h>
#include <hyperelastic/assembly/warped_assembler.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/materials/material_registry.h>
#include <hyperelastic/problem/problem.h>

#include "support/box_discretisation.h"
#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/nodal_error.h"
#include "support/random_vector.h"
#include "support/scene_run.h"
#include "support/scene_text.h"

#include <cmath>
#include <functional>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  /// Sets every owned entry of a P1 vector field to @p value(cell, i,
  /// dofs) for the cell's local dof i (component and vertex from
  /// system_to_component_index); @p dofs are the cell's dof indices.
  template <int dim, typename Value>
  VectorType
  owned_nodal_values(const BoxDiscretisation<dim> &box, Value &&value)
  {
    VectorType                           owned(box.owned, box.comm);
    std::vector<types::global_dof_index> dofs(box.fe.dofs_per_cell);
    for (const auto &cell : box.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (box.owned.is_element(dofs[i]))
              owned(dofs[i]) = value(cell, i, dofs);
        }
    owned.compress(VectorOperation::insert);
    return owned;
  }

  /// u_a = g(X_a) at every vertex (P1), with ghost entries.
  template <int dim>
  VectorType
  nodal_field(const BoxDiscretisation<dim>                            &box,
              const std::function<Tensor<1, dim>(const Point<dim> &)> &g)
  {
    const VectorType owned = owned_nodal_values(
      box, [&](const auto &cell, const unsigned int i, const auto &) {
        const auto [c, v] = box.fe.system_to_component_index(i);
        return g(cell->vertex(v))[c];
      });
    // A copy (not a move) imports the ghost entries.
    VectorType ghosted(box.owned, box.relevant, box.comm);
    ghosted = owned;
    return ghosted;
  }

  /// @p f with every nodal vector multiplied by @p Q.
  template <int dim>
  VectorType
  rotate_nodal(const BoxDiscretisation<dim> &box,
               const VectorType             &f,
               const Tensor<2, dim>         &Q)
  {
    VectorType ghosted(box.owned, box.relevant, box.comm);
    ghosted = f;
    return owned_nodal_values(
      box, [&](const auto &, const unsigned int i, const auto &dofs) {
        const auto [c, v] = box.fe.system_to_component_index(i);
        double value      = 0.;
        for (unsigned int j = 0; j < dofs.size(); ++j)
          if (box.fe.system_to_component_index(j).second == v)
            value += Q[c][box.fe.system_to_component_index(j).first] *
                     ghosted(dofs[j]);
        return value;
      });
  }

  /// Rotation by @p angle about (1, 2, 2)/3 in 3D, in the plane in 2D.
  template <int dim>
  Tensor<2, dim>
  rotation(const double angle)
  {
    Tensor<2, dim> Q;
    const double   c = std::cos(angle), s = std::sin(angle);
    if constexpr (dim == 2)
      {
        Q[0][0] = c;
        Q[0][1] = -s;
        Q[1][0] = s;
        Q[1][1] = c;
      }
    else
      {
        const Tensor<1, 3> n({1. / 3., 2. / 3., 2. / 3.});
        Tensor<2, 3>       N; // the cross-product matrix of n
        N[0][1] = -n[2];
        N[0][2] = n[1];
        N[1][0] = n[2];
        N[1][2] = -n[0];
        N[2][0] = -n[1];
        N[2][1] = n[0];
        Q       = unit_symmetric_tensor<3>() + s * N + (1. - c) * (N * N);
      }
    return Q;
  }

  double
  difference_norm(VectorType a, const VectorType &b)
  {
    a -= b;
    return a.l2_norm();
  }

  template <int dim>
  void
  rigid(Checker &checker)
  {
    const BoxDiscretisation<dim> box(3., 6, 2, 1, MPI_COMM_WORLD);
    const auto                   material =
      create_material<dim>("corotational", lame_parameters(1., 1.5));
    const WarpedAssembler<dim> warped(box.dof_handler, box.mapping, *material);
    const Tensor<2, dim>       Q = rotation<dim>(1.1);
    Tensor<1, dim>             c;
    for (unsigned int d = 0; d < dim; ++d)
      c[d] = 0.3 - 0.25 * d;
    const auto deformation = [](const Point<dim> &X) {
      Tensor<1, dim> s;
      s[0] = 0.1 * X[0] + 0.05 * X[1] * X[1];
      s[1] = -0.03 * X[0] * X[1];
      return s;
    };

    VectorType f(box.owned, box.comm), f_reference(box.owned, box.comm);
    warped.internal_forces(nodal_field<dim>(box, deformation), f_reference);
    const std::string tag = std::to_string(dim) + "D: ";

    const VectorType moved = nodal_field<dim>(box, [&](const Point<dim> &X) {
      return Tensor<1, dim>(Q * X + c - X);
    });
    warped.internal_forces(moved, f);
    checker.at_most(tag + "rigid motion: |f| / |f of a 10 % stretch|",
                    f.l2_norm() / f_reference.l2_norm(),
                    1e-12);
    double worst = 0.;
    for (const auto &R : warped.vertex_rotations(moved))
      worst = std::max(worst, (R - Q).norm());
    checker.at_most(tag + "rigid motion: max over vertices |R_i - Q|",
                    Utilities::MPI::max(worst, box.comm),
                    1e-12);

    // Objectivity: f(Q (X + s) + c - X) = Q f(X + s - X) at every node.
    const VectorType rotated = nodal_field<dim>(box, [&](const Point<dim> &X) {
      return Tensor<1, dim>(Q * (X + deformation(X)) + c - X);
    });
    warped.internal_forces(rotated, f);
    checker.at_most(tag + "rotated deformation: |f - Q f_unrotated| / |f|",
                    difference_norm(f, rotate_nodal(box, f_reference, Q)) /
                      f_reference.l2_norm(),
                    1e-12);
  }

  template <int dim>
  void
  small_strain(Checker &checker)
  {
    const BoxDiscretisation<dim> box(3., 6, 2, 1, MPI_COMM_WORLD);
    const LameParameters         lame = lame_parameters(1., 1.5);
    const auto material = create_material<dim>("corotational", lame);
    const auto linear   = create_material<dim>("linear elastic", lame);
    const WarpedAssembler<dim>  warped(box.dof_handler, box.mapping, *material);
    const GenericAssembler<dim> reference(box.dof_handler,
                                          box.mapping,
                                          *linear);
    const std::string           tag = std::to_string(dim) + "D: ";

    std::vector<double> relative;
    for (const double eps : {1e-3, 1e-4})
      {
        const VectorType u = nodal_field<dim>(box, [&](const Point<dim> &X) {
          Tensor<1, dim> w;
          w[0] = std::sin(X[0]) + 0.5 * X[1];
          w[1] = std::cos(X[0] * X[1]);
          w[dim - 1] += 0.3 * X[0] * X[0];
          return Tensor<1, dim>(eps * w);
        });
        VectorType       f(box.owned, box.comm), Ku(box.owned, box.comm);
        warped.internal_forces(u, f);
        reference.internal_forces(u, Ku);
        relative.push_back(difference_norm(f, Ku) / Ku.l2_norm());
      }
    checker.at_most(tag + "eps = 1e-4: |f_warped - K u| / |K u|",
                    relative[1],
                    1e-3);
    checker.at_least(tag + "order in eps of |f_warped - K u| / |K u| "
                           "(1e-3 -> 1e-4)",
                     std::log10(relative[0] / relative[1]),
                     0.9);

    // At rest the warped tangent is K (no constraints).
    MatrixType K_warped, K_linear;
    box.reinit_matrix(K_warped);
    box.reinit_matrix(K_linear);
    VectorType                rest(box.owned, box.relevant, box.comm);
    VectorType                rhs(box.owned, box.comm);
    AffineConstraints<double> none;
    none.close();
    warped.system(rest, none, TangentProjection::none, K_warped, rhs);
    reference.system(rest, none, TangentProjection::none, K_linear, rhs);
    VectorType v(box.owned, box.comm), a(box.owned, box.comm),
      b(box.owned, box.comm);
    fill_random(v, 1., 7);
    K_warped.vmult(a, v);
    K_linear.vmult(b, v);
    checker.at_most(tag + "at rest: |K_warped v - K v| / |K v|",
                    difference_norm(a, b) / b.l2_norm(),
                    1e-13);

    // Bent (rotation up to about amplitude * 3): the warped tangent leaves
    // out dR/dx, whose effect is of the order of the strain.
    for (const double amplitude : {0.01, 0.1})
      {
        const VectorType u = nodal_field<dim>(box, [&](const Point<dim> &X) {
          Tensor<1, dim> s;
          s[0] = -amplitude * X[0] * X[1];
          s[1] = 0.5 * amplitude * X[0] * X[0];
          return s;
        });
        warped.system(u, none, TangentProjection::none, K_warped, rhs);
        K_warped.vmult(a, v);
        // Central difference of the forces along v.
        const double step = 1e-6;
        VectorType   plus(box.owned, box.relevant, box.comm),
          minus(box.owned, box.relevant, box.comm),
          shifted(box.owned, box.comm);
        shifted = u;
        shifted.add(step, v);
        plus = shifted;
        shifted.add(-2. * step, v);
        minus = shifted;
        VectorType f_plus(box.owned, box.comm), f_minus(box.owned, box.comm);
        warped.internal_forces(plus, f_plus);
        warped.internal_forces(minus, f_minus);
        f_plus -= f_minus;
        f_plus /= 2. * step;
        checker.at_most(tag + "bent, amplitude " +
                          std::string(amplitude < 0.05 ? "0.01" : "0.1") +
                          ": |K_warped v - J_fd v| / |J_fd v| / amplitude",
                        difference_norm(a, f_plus) / f_plus.l2_norm() /
                          amplitude,
                        0.2);
      }
  }

  std::string
  quiet_output(const std::string &points = "")
  {
    return subsection("Output",
                      entry("Directory", "stiffness_warping_output") +
                        entry("Write VTU", "false") +
                        entry("Verbose", "false") + entry("Points", points));
  }

  template <int dim>
  void
  cantilever(Checker &checker)
  {
    const bool three = dim == 3;
    const auto scene = [&](const std::string &model,
                           const std::string &linearize) {
      return subsection("Problem", entry("Dimension", std::to_string(dim))) +
             subsection("Mesh",
                        entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                          entry("Upper corner",
                                three ? "4, 0.5, 0.5" : "4, 0.5") +
                          entry("Subdivisions", three ? "8, 1, 1" : "16, 2")) +
             subsection("Material",
                        entry("Model", model) + entry("Young's modulus", "1") +
                          entry("Poisson's ratio", "0.3")) +
             subsection("Loading",
                        entry("Body force",
                              three ? "0; 0; -0.002" : "0; -0.002")) +
             dirichlet(1,
                       0,
                       three ? "x, y, z" : "x, y",
                       three ? "0; 0; 0" : "0; 0") +
             tight_solver("direct") +
             quiet_output(three ? "4, 0.25, 0.25" : "4, 0.25") +
             subsection("Time integration",
                        entry("Scheme", "Newmark") + entry("Time step", "2") +
                          entry("End time", "60") +
                          entry("Linearize once per step", linearize));
    };
    auto corotational = run_scene<dim>(scene("corotational", "false"));
    auto warped       = run_scene<dim>(scene("stiffness warping", "false"));
    auto once         = run_scene<dim>(scene("stiffness warping", "true"));
    // The formulation entry with the corotational model: the same run as the
    // alias 'Material/Model = stiffness warping'.
    auto formulation = run_scene<dim>(
      scene("corotational", "false") +
      subsection("Problem", entry("Formulation", "stiffness warping")));

    const auto tip = [](const StepSummary<dim> &s) {
      return s.point_displacements[0][dim - 1];
    };
    double       amplitude = 0., band = 0., once_band = 0.;
    unsigned int most = 0;
    const auto  &c = corotational->summaries(), &w = warped->summaries(),
               &o = once->summaries();
    for (unsigned int k = 0; k < c.size(); ++k)
      {
        amplitude = std::max(amplitude, std::abs(tip(c[k])));
        band      = std::max(band, std::abs(tip(w[k]) - tip(c[k])));
        once_band = std::max(once_band, std::abs(tip(o[k]) - tip(w[k])));
        most      = std::max(most, o[k].newton_iterations);
      }
    const std::string tag =
      std::to_string(dim) + "D swinging cantilever, t <= 60: ";
    checker.is_true(tag + "30 steps of each run (" + std::to_string(c.size()) +
                      ", " + std::to_string(w.size()) + ", " +
                      std::to_string(o.size()) + ")",
                    c.size() == w.size() && w.size() == o.size() &&
                      c.size() == 30);
    checker.at_most(tag + "max |tip_warping - tip_corotational| / max |tip|",
                    band / amplitude,
                    5e-2);
    double alias_difference = 0.;
    for (unsigned int k = 0; k < w.size(); ++k)
      alias_difference =
        std::max(alias_difference,
                 std::abs(tip(formulation->summaries()[k]) - tip(w[k])));
    checker.is_true(tag + "Problem/Formulation = stiffness warping: as many "
                          "steps as the alias",
                    formulation->summaries().size() == w.size());
    checker.at_most(tag + "Problem/Formulation = stiffness warping with the "
                          "corotational model: max |tip - tip_alias|",
                    alias_difference,
                    0.);
    checker.is_true(tag + "linearized once: one Newton iteration per step",
                    most == 1);
    checker.at_most(tag + "max |tip_linearized - tip_full| / max |tip|",
                    once_band / amplitude,
                    3e-2);
  }

  template <int dim>
  void
  momentum(Checker &checker)
  {
    const bool three = dim == 3;
    const auto scene = [&](const std::string &velocity) {
      return subsection("Problem", entry("Dimension", std::to_string(dim))) +
             subsection("Mesh",
                        entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                          entry("Upper corner", three ? "1, 1, 1" : "1, 1") +
                          entry("Subdivisions", three ? "2, 2, 2" : "2, 2")) +
             subsection("Material",
                        entry("Model", "stiffness warping") +
                          entry("Young's modulus", "1") +
                          entry("Poisson's ratio", "0.3")) +
             tight_solver("direct") + quiet_output() +
             subsection("Time integration",
                        entry("Scheme", "Newmark") + entry("Time step", "0.2") +
                          entry("End time", "2") +
                          entry("Initial velocity", velocity));
    };
    const std::string tag =
      std::to_string(dim) + "D stiffness warping, free body: ";
    const std::string v0          = three ? "0.1; -0.2; 0.3" : "0.1; -0.2";
    auto              translating = run_scene<dim>(scene(v0));
    Tensor<1, dim>    v;
    v[0] = 0.1;
    v[1] = -0.2;
    if constexpr (dim == 3)
      v[2] = 0.3;
    double     drift = 0.;
    const auto p0    = translating->summaries().front().linear_momentum;
    for (const auto &s : translating->summaries())
      drift = std::max(drift, (s.linear_momentum - p0).norm());
    checker.at_most(tag + "translating: momentum drift / |p|",
                    drift / p0.norm(),
                    1e-12);
    checker.at_most(tag + "translating: max |u - v t| / |v t| at t = 2",
                    max_nodal_error(translating->get_dof_handler(),
                                    translating->solution(),
                                    [&](const Point<dim> &) {
                                      return Tensor<1, dim>(2. * v);
                                    }) /
                      (2. * v.norm()),
                    1e-12);

    auto spinning = run_scene<dim>(scene(
      three ? "0.1 - 0.3*(y - 0.5) + 0.1*(z - 0.5)*y; 0.3*(x - 0.5) - 0.05; "
              "0.02 - 0.1*(x - 0.5)*x"
            : "0.1 - 0.3*(y - 0.5) + 0.05*y*y; 0.3*(x - 0.5) - 0.05"));
    drift         = 0.;
    const auto q0 = spinning->summaries().front().linear_momentum;
    for (const auto &s : spinning->summaries())
      drift = std::max(drift, (s.linear_momentum - q0).norm());
    checker.at_most(tag + "spinning and deforming: momentum drift / |p| "
                          "(not conserved: ghost forces; band)",
                    drift / q0.norm(),
                    2e-3);
  }

  template <int dim>
  void
  run_case(const std::string &which, Checker &checker)
  {
    if (which == "rigid")
      rigid<dim>(checker);
    else if (which == "small_strain")
      small_strain<dim>(checker);
    else if (which == "cantilever")
      cantilever<dim>(checker);
    else if (which == "momentum")
      momentum<dim>(checker);
    else
      throw InputError("unknown case '" + which + "'");
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_case_for_dimension(argc, argv, "rigid", run_case<2>, run_case<3>);
}
