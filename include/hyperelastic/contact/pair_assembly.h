// The sums over a list of contact pairs that every contact term shares,
// written once: a term enumerates its pairs, finds their distances and
// friction, and hands each pair's energy, gradient and Hessian (over the
// coordinates of its points) to PairSums with the pair's stencil, which
// says where each coordinate goes:
// - a vertex of the body: its dofs, and whether this rank writes its rows
//   (the rank that owns it);
// - a constrained dof: held at its prescribed value (its column moves to
//   the right-hand side, its row is left alone: it reads d du_r = d g_r);
// - a point of a rigid obstacle: no unknown; its motion over the rest of
//   the step (in the solved state's coordinates) moves to the right-hand
//   side through the pair's exact Hessian, so the obstacle drags what it
//   touches.
// PairSums visits a term's pairs once per sum (the term's Visit), projects
// a pair's Hessian (its block of the body's coordinates) to positive
// semi-definite where asked, scatters the forces and stiffness to the rows
// this rank writes, and ends each sum with its collective: the forces'
// first add after an insert (Trilinos assembles the vector), the
// right-hand side's, and the energy's sum over ranks. No virtual call and
// no term-specific branch: the three contact terms (obstacles, meshed
// obstacles' corners and edges, self contact) differ only in their pairs
// and stencils.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>

#include <hyperelastic/assembly/energy_term.h>
#include <hyperelastic/base/linear_algebra.h>
#include <hyperelastic/base/tangent_projection_mode.h>
#include <hyperelastic/base/timed_section.h>
#include <hyperelastic/contact/end_state_map.h>
#include <hyperelastic/contact/primitive_distance.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// Where the coordinates of a pair of @p n_points points go.
  template <int dim, unsigned int n_points>
  struct PairStencil
  {
    static constexpr std::size_t n = std::size_t(n_points) * dim;

    /// Each coordinate's dof; dealii::numbers::invalid_dof_index for the
    /// points of a rigid obstacle.
    std::array<dealii::types::global_dof_index, n> dofs;
    /// NaN for an unknown; a constrained dof's prescribed value; an
    /// obstacle point's motion over the rest of the step.
    std::array<double, n> held;
    /// Whether this rank writes the point's rows.
    std::array<bool, n_points> writes{};

    PairStencil()
    {
      dofs.fill(dealii::numbers::invalid_dof_index);
      held.fill(std::numeric_limits<double>::quiet_NaN());
    }

    /// Point @p i is the body's vertex with @p vertex_dofs, written here
    /// where @p written; with @p constraints, each constrained dof is held
    /// at its prescribed value.
    void
    set_vertex(
      unsigned int                                            i,
      const std::array<dealii::types::global_dof_index, dim> &vertex_dofs,
      bool                                                    written,
      const dealii::AffineConstraints<double> *constraints = nullptr);

    /// Point @p i is an obstacle's, moving by @p motion over the rest of
    /// the step.
    void
    set_obstacle_point(unsigned int i, const dealii::Tensor<1, dim> &motion);
  };

  /// The potential weight V(x_end) / c of a pair in the step's solved state
  /// (@p map, SteppedTerm::set_end_state_map) from the pair's barrier @p b
  /// at x_end: energy, gradient and Hessian (@p order 2) scaled.
  template <std::size_t n>
  void
  to_solved_state(PairBarrier<n>    &b,
                  const EndStateMap &map,
                  const unsigned int order)
  {
    b.energy *= map.energy_factor();
    for (double &g : b.gradient)
      g *= map.gradient_factor();
    if (order == 2)
      for (auto &row : b.hessian)
        for (double &v : row)
          v *= map.hessian_factor();
  }

  /// The smallest distance over a list of pairs (at most d_hat) and
  /// whether one touches, as a term's enumeration meets them.
  struct PairScan
  {
    explicit PairScan(const double d_hat)
        : d_hat(d_hat)
        , closest(d_hat)
    {
    }

    /// Records a pair at distance @p d; whether its barrier is active
    /// (0 < d < d_hat).
    bool
    active(const double d)
    {
      closest  = std::min(closest, d);
      touching = touching || !(d > 0.);
      return d > 0. && d < d_hat;
    }

    double d_hat, closest;
    bool   touching = false;
  };

  /// The energy, force and stiffness sums over the pairs of a contact term
  /// of pairs of @p n_points points.
  template <int dim, unsigned int n_points>
  class PairSums
  {
  public:
    using Stencil                  = PairStencil<dim, n_points>;
    static constexpr std::size_t n = Stencil::n;
    using Barrier                  = PairBarrier<n>;

    /// What a term hands over for each pair: its stencil, its barrier in
    /// the solved state (derivatives up to the visit's order), whether this
    /// rank counts its energy, whether its Hessian may be projected.
    using Take = std::function<
      void(const Stencil &, const Barrier &, bool counted, bool projectable)>;

    /// What a term's visit of its pairs at one state is asked for:
    /// derivatives up to @p order (0: energy, 1: gradient, 2: Hessian),
    /// with order 2 the @p constraints that hold dofs, and @p take for each
    /// pair.
    struct Request
    {
      unsigned int                             order;
      const dealii::AffineConstraints<double> *constraints;
      Take                                     take;
    };

    /// A term's visit of its pairs; returns whether a pair touches here.
    using Visit = std::function<bool(const Request &)>;

    /// A contact term's EnergyTerm sums at @p u and time @p t, timed in
    /// its timer's section "contact". The term (PairSums its friend) has
    /// visit(u, t, request) (a Visit), its communicator comm, its timer,
    /// touching_message(t) (what a touching pair throws with) and
    /// written_rows() (where the rows its stiffness writes go, or null).
    template <typename Term>
    static double
    energy(const Term &term, const VectorType &u, const double t)
    {
      const auto scope = timed_section(term.timer, "contact");
      return sum_energy(visit_of(term, u, t), term.comm);
    }

    template <typename Term>
    static ForceSize
    forces(const Term &term, const VectorType &u, const double t, VectorType &f)
    {
      const auto scope = timed_section(term.timer, "contact");
      sum_forces(visit_of(term, u, t), f, term.comm, term.touching_message(t));
      return {};
    }

    template <typename Term>
    static void
    stiffness(const Term                              &term,
              const VectorType                        &u,
              const double                             t,
              const TangentProjection                  projection,
              const dealii::AffineConstraints<double> &constraints,
              MatrixType                              &matrix,
              VectorType                              &rhs)
    {
      const auto scope = timed_section(term.timer, "contact");
      sum_stiffness(visit_of(term, u, t),
                    constraints,
                    projection == TangentProjection::every_point,
                    matrix,
                    rhs,
                    term.written_rows());
    }

  private:
    template <typename Term>
    static Visit
    visit_of(const Term &term, const VectorType &u, const double t)
    {
      return [&term, &u, t](const Request &request) {
        return term.visit(u, t, request);
      };
    }

    /// The energy over all ranks; infinite if a pair touches on any rank.
    /// Collective.
    static double
    sum_energy(const Visit &visit, MPI_Comm comm);

    /// Adds the pairs' nodal forces (minus their gradients) on the rows this
    /// rank writes to @p forces; throws ConvergenceFailure with @p touching
    /// on every rank if a pair touches on any. Collective.
    static void
    sum_forces(const Visit       &visit,
               VectorType        &forces,
               MPI_Comm           comm,
               const std::string &touching);

    /// Adds the pairs' Hessians to @p matrix on the rows this rank writes
    /// that are not held (the body's block, projected to positive
    /// semi-definite where @p project and the pair allows), and their held
    /// columns to @p rhs; the rows written in @p written if not null.
    /// Collective (the right-hand side's add).
    static void
    sum_stiffness(const Visit                                  &visit,
                  const dealii::AffineConstraints<double>      &constraints,
                  bool                                          project,
                  MatrixType                                   &matrix,
                  VectorType                                   &rhs,
                  std::vector<dealii::types::global_dof_index> *written);
  };
} // namespace hyperelastic
