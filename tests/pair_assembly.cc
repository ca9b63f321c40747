// The one pair assembly of the contact terms (issue 67, item 1;
// contact/pair_assembly.h), on one rank against hand-computed values: a
// pair of a body vertex (dofs 0, 1) and a rigid obstacle's point moving by
// w = (0.1, -0.2), its barrier's Hessian [[S, -S], [-S, S]] with
// S = [[2, 1], [1, 3]] and gradient (1, 2, -1, -2), and a second pair of
// two body vertices (dofs 0, 1 and 2, 3) with the indefinite Hessian
// diag(1, -1, 0, 0):
// - forces: minus the gradient on the body's rows only;
// - stiffness: S on the vertex's rows, S w on the right-hand side (the
//   obstacle drags the vertex); with dof 1 held at 0.5, its row left alone
//   and its column moved (rhs_0 = S w_0 - S_01 0.5); the indefinite pair
//   projected to diag(1, 0) where asked, exact where not, never where the
//   pair says it may not be;
// - energy: the counted pairs' sum; infinite once a pair touches.
// Usage: pair_assembly
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <hyperelastic/contact/pair_assembly.h>

#include "support/checker.h"

#include <cmath>
#include <limits>
#include <string>

using namespace hyperelastic;

namespace
{
  using Sums2    = PairSums<2, 2>;
  using Stencil2 = PairStencil<2, 2>;

  /// The vertex-obstacle pair: dofs {0, 1}, the obstacle moving by w.
  Stencil2
  obstacle_pair(const dealii::AffineConstraints<double> *constraints)
  {
    Stencil2 s;
    s.set_vertex(0, {{0, 1}}, true, constraints);
    dealii::Tensor<1, 2> w;
    w[0] = 0.1;
    w[1] = -0.2;
    s.set_obstacle_point(1, w);
    return s;
  }

  Sums2::Barrier
  obstacle_barrier()
  {
    const double   S[2][2] = {{2., 1.}, {1., 3.}};
    Sums2::Barrier b;
    b.distance = 0.5;
    b.energy   = 0.25;
    b.gradient = {{1., 2., -1., -2.}};
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        {
          b.hessian[i][j] = b.hessian[2 + i][2 + j] = S[i][j];
          b.hessian[i][2 + j] = b.hessian[2 + i][j] = -S[i][j];
        }
    return b;
  }

  /// The indefinite pair of two body vertices {0, 1} and {2, 3}.
  Stencil2
  body_pair()
  {
    Stencil2 s;
    s.set_vertex(0, {{0, 1}}, true);
    s.set_vertex(1, {{2, 3}}, true);
    return s;
  }

  Sums2::Barrier
  indefinite_barrier()
  {
    Sums2::Barrier b;
    b.distance      = 0.5;
    b.energy        = 1.;
    b.hessian[0][0] = 1.;
    b.hessian[1][1] = -1.;
    return b;
  }

  /// A fake contact term: the pairs it hands over, as PairSums takes a
  /// term's visit.
  struct Term
  {
    bool     touching = false, projectable = true, indefinite = false;
    MPI_Comm comm                                              = MPI_COMM_SELF;
    dealii::TimerOutput                                 *timer = nullptr;
    mutable std::vector<dealii::types::global_dof_index> rows;

    bool
    visit(const VectorType &, double, const Sums2::Request &request) const
    {
      if (indefinite)
        request.take(body_pair(), indefinite_barrier(), true, projectable);
      else
        {
          request.take(obstacle_pair(request.constraints),
                       obstacle_barrier(),
                       true,
                       false);
          // A second pair that this rank does not count.
          request.take(obstacle_pair(request.constraints),
                       obstacle_barrier(),
                       false,
                       false);
        }
      return touching;
    }
    static std::string
    touching_message(double)
    {
      return "touching";
    }
    std::vector<dealii::types::global_dof_index> *
    written_rows() const
    {
      return &rows;
    }
  };

  /// The 4 x 4 matrix (full pattern) and the right-hand side after the
  /// stiffness sum of @p term with @p constraints.
  void
  stiffness(const Term                              &term,
            const dealii::AffineConstraints<double> &constraints,
            const TangentProjection                  projection,
            MatrixType                              &A,
            VectorType                              &rhs)
  {
    const dealii::IndexSet         all = dealii::complete_index_set(4);
    dealii::DynamicSparsityPattern pattern(4, 4);
    for (unsigned int i = 0; i < 4; ++i)
      for (unsigned int j = 0; j < 4; ++j)
        pattern.add(i, j);
    A.reinit(all, all, pattern, MPI_COMM_SELF);
    rhs.reinit(all, MPI_COMM_SELF);
    VectorType u(all, MPI_COMM_SELF);
    Sums2::stiffness(term, u, 0., projection, constraints, A, rhs);
    A.compress(dealii::VectorOperation::add);
    rhs.compress(dealii::VectorOperation::add);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker(true);
  const dealii::IndexSet                   all = dealii::complete_index_set(4);
  const dealii::AffineConstraints<double>  none;
  Term                                     term;

  checker.section("forces: minus the gradient on the body's rows");
  VectorType f(all, MPI_COMM_SELF), u(all, MPI_COMM_SELF);
  Sums2::forces(term, u, 0., f);
  f.compress(dealii::VectorOperation::add);
  checker.close("f_0 (two pairs)", f(0), -2., 1., 1e-15);
  checker.close("f_1 (two pairs)", f(1), -4., 1., 1e-15);
  checker.close("f_2 (no body vertex there)", f(2), 0., 1., 1e-15);

  checker.section("stiffness: S on the vertex's rows, the obstacle's drag");
  MatrixType A;
  VectorType rhs;
  stiffness(term, none, TangentProjection::none, A, rhs);
  checker.close("A_00 = 2 S_00", A.el(0, 0), 4., 1., 1e-15);
  checker.close("A_01 = 2 S_01", A.el(0, 1), 2., 1., 1e-15);
  checker.close("A_11 = 2 S_11", A.el(1, 1), 6., 1., 1e-15);
  checker.close("A_22 (no row)", A.el(2, 2), 0., 1., 1e-15);
  checker.close("rhs_0 = 2 (S w)_0 = 0", rhs(0), 0., 1., 1e-15);
  checker.close("rhs_1 = 2 (S w)_1 = -1", rhs(1), -1., 1., 1e-15);
  checker.close(
    "rows written (2 pairs x 2 rows)", term.rows.size(), 4., 1., 1e-15);

  checker.section("a constrained dof: its row alone, its column moved");
  dealii::AffineConstraints<double> held;
  held.add_line(1);
  held.set_inhomogeneity(1, 0.5);
  held.close();
  stiffness(term, held, TangentProjection::none, A, rhs);
  checker.close("A_00", A.el(0, 0), 4., 1., 1e-15);
  checker.close("A_01 (column moved)", A.el(0, 1), 0., 1., 1e-15);
  checker.close("A_11 (row left alone)", A.el(1, 1), 0., 1., 1e-15);
  // Per pair: rhs_0 = -((-S w)_0 + S_01 0.5) = 0 - 0.5.
  checker.close("rhs_0 = 2 ((S w)_0 - S_01 0.5) = -1", rhs(0), -1., 1., 1e-15);
  checker.close("rhs_1 (row left alone)", rhs(1), 0., 1., 1e-15);
  checker.close("rows written (the free one of each pair)",
                term.rows.size(),
                2.,
                1.,
                1e-15);

  checker.section("projection of an indefinite pair");
  term.indefinite = true;
  stiffness(term, none, TangentProjection::every_point, A, rhs);
  checker.close("projected: A_00", A.el(0, 0), 1., 1., 1e-14);
  checker.close("projected: A_11", A.el(1, 1), 0., 1., 1e-14);
  stiffness(term, none, TangentProjection::none, A, rhs);
  checker.close("exact: A_11", A.el(1, 1), -1., 1., 1e-15);
  term.projectable = false;
  stiffness(term, none, TangentProjection::every_point, A, rhs);
  checker.close("not projectable: A_11", A.el(1, 1), -1., 1., 1e-15);

  checker.section("energy: the counted pairs; infinite once one touches");
  term.indefinite = false;
  checker.close(
    "energy (one of two counted)", Sums2::energy(term, u, 0.), 0.25, 1., 1e-15);
  term.touching = true;
  checker.is_true("energy infinite when touching",
                  std::isinf(Sums2::energy(term, u, 0.)));
  bool thrown = false;
  try
    {
      Sums2::forces(term, u, 0., f);
    }
  catch (const std::exception &e)
    {
      thrown = std::string(e.what()).find("touching") != std::string::npos;
    }
  checker.is_true("forces throw the term's message when touching", thrown);
  return checker.exit_code();
}
