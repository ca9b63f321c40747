// Contact of the body's boundary vertices with rigid obstacles (planes,
// spheres and surface meshes, moving rigidly as expressions of t: a
// displacement m(t) and a rotation Q(t) by an angle about a fixed axis
// through the obstacle's point p, an obstacle point X of the entries'
// placement being at p + m(t) + Q(t) (X - p)) through the IPC barrier and
// lagged, smoothed Coulomb friction:
//   V(u, t) = sum over boundary vertices a and obstacles k of
//             kappa A_a b(d_k(x_a, t), d_hat)
//           + mu_k lambda_ak f0(|s_ak|, eps),
// A_a the vertex's share of the boundary's area (2D: length), x_a = X_a +
// u_a, lambda_ak the pair's normal force and P_ak the projection on its
// tangent plane, both lagged (taken at the step's start, then at its
// converged state for 'Friction lagging updates' more solves), s_ak =
// P_ak (x_a - x_a(step start) - w_ak) the slip of the step, w_ak the
// displacement since the step began of the obstacle's material point that
// was at x_a(step start) (a vertex stuck to a turning plate turns with
// it), f0 the smoothed |s| (f0' = f1, f1 = 1 beyond eps).
// One load term: forces g = -dV/du, load stiffness d2V/du2 (each pair's
// dim x dim block positive semi-definite: the barrier's projected, the
// friction's by construction), potential V.
//
// Feasibility: the largest feasible step keeps every distance above a tenth
// of its value along a Newton direction (closed form for planes and
// spheres, a turning plane's through a bound on the distance's rate of
// change; conservative advancement for meshes), so no iterate crosses an
// obstacle. A moving obstacle does not
// jump to its place at t when a step begins: it stays where it was, and
// each Newton iteration carries it (like a prescribed displacement) as far
// along its way as the feasible step allows, together with the body
// (MovingAdmissibleSetTerm::prepare_motion/advance); the step converges
// only once it has arrived.
//
// Distances: plane d = n . (x - p(t)), n the unit normal towards the body;
// sphere d = |x - c(t)| - R (the body outside; turning about its centre,
// only its friction feels the rotation); mesh: the distance to the rigid
// surface (contact/obstacle_surface.h), evaluated in the surface's own
// coordinates Q^T (x - p - m) (the gradient and Hessian turned back),
// found through its R-tree, its feasible step by conservative advancement.
// Within a step an obstacle's way is taken as linear in m and in the angle
// between the obstacle times (exact for motions linear in t). Every rank
// handles the boundary vertices whose dofs it owns (P2: the vertices only, not
// the mid-edge nodes); the answer does not depend on the number of ranks.
#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>

#include <hyperelastic/assembly/energy_term.h>
#include <hyperelastic/assembly/term_capabilities.h>
#include <hyperelastic/base/timed_section.h>
#include <hyperelastic/contact/barrier_settings.h>
#include <hyperelastic/contact/barrier_stiffness.h>
#include <hyperelastic/contact/contact_measures.h>
#include <hyperelastic/contact/contact_parameters.h>
#include <hyperelastic/contact/friction_lagging.h>
#include <hyperelastic/contact/obstacle_clock.h>
#include <hyperelastic/contact/obstacle_surface.h>
#include <hyperelastic/contact/pair_assembly.h>
#include <hyperelastic/materials/material.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class ObstacleContact : public EnergyTerm<dim>,
                          public SteppedTerm<dim>,
                          public MovingAdmissibleSetTerm<dim>,
                          public StiffTerm<dim>
  {
    friend class PairSums<dim, 2>;

  public:
    /// Finds the owned boundary vertices, sets d_hat and kappa (automatic
    /// where the scene gives 0) and checks the start: a vertex on the wrong
    /// side of an obstacle at t = 0 is an InputError naming the obstacle and
    /// the vertex. Collective.
    /// With @p dynamic, friction's slip is the step's (velocity times h)
    /// and its smoothing eps_v h. With @p shared (self contact's, which
    /// may make the automatic d_hat smaller), d_hat, kappa and eps are
    /// those.
    ObstacleContact(const ContactParameters             &parameters,
                    const std::map<std::string, double> &constants,
                    const dealii::DoFHandler<dim>       &dof_handler,
                    const LameParameters                &moduli,
                    bool                                 dynamic = false,
                    const BarrierSettings               *shared  = nullptr);
    ~ObstacleContact() override;

    std::string
    name() const override
    {
      return "Contact (obstacles)";
    }

    TermKind
    kind() const override
    {
      return TermKind::conservative;
    }

    /// Throws ConvergenceFailure on every rank if a vertex is on the wrong
    /// side of an obstacle (an obstacle moved into the body over the step).
    ForceSize
    add_forces(const VectorType &u,
               const double      t,
               VectorType       &forces) const override
    {
      return Sums::forces(*this, u, t, forces);
    }

    void
    add_stiffness(const VectorType                        &u,
                  const double                             t,
                  const TangentProjection                  projection,
                  const dealii::AffineConstraints<double> &constraints,
                  MatrixType                              &matrix,
                  VectorType                              &rhs) const override
    {
      Sums::stiffness(*this, u, t, projection, constraints, matrix, rhs);
    }

    /// kappa sum b(d); +infinity if a distance is not positive.
    double
    energy(const VectorType &u, const double t) const override
    {
      return Sums::energy(*this, u, t);
    }

    void
    add_stiff_dofs(dealii::IndexSet &dofs) const override
    {
      for (const dealii::types::global_dof_index dof : stiff_rows)
        dofs.add_index(dof);
    }

    /// Along @p direction with the obstacles moving jointly from where
    /// they are to their place at @p t.
    double
    largest_feasible_step(const VectorType &u,
                          const VectorType &direction,
                          double            t) const override;

    void
    begin_step(const VectorType &u, double t_start) override;
    void
    set_end_state_map(double c, double weight) override
    {
      clock.end_state = {c, weight};
    }
    bool
    prepare_motion(const double t) override
    {
      return clock.prepare_motion(t, [&](const double from, const double to) {
        const std::vector<Placed> now = placed(from), end = placed(to);
        for (unsigned int k = 0; k < obstacles.size(); ++k)
          if (now[k].point != end[k].point || now[k].angle != end[k].angle)
            return true;
        return false;
      });
    }
    void
    advance(const double alpha, const double t) override
    {
      clock.advance(alpha, t);
    }
    LaggedUpdate
    update_lagged(const VectorType &u,
                  double            t,
                  LagMoment         moment,
                  double            unbalanced_force) override;
    /// Friction's normal forces grow (or fall) within the step at the rate
    /// they had between @p u_before at @p t_before and the step's start,
    /// where both are positive, until the first update replaces them.
    void
    extrapolate_lagged(const VectorType &u_before, double t_before) override;
    /// Friction: a sliding pair (slip beyond eps at @p u) whose slip the
    /// trial @p trial carries back by more than eps (across the whole
    /// stick zone) is moved back to zero slip along its old direction (not
    /// a vertex with a constrained dof). Its exact tangent has no
    /// curvature along the slip, so where its force must fall back into
    /// the stick zone (normal forces that grew under it) Newton's step
    /// jumps across that zone onto the opposite slide, whose energy the
    /// line search refuses: every vertex's step was then shortened for
    /// that one pair's sake.
    void
    project_trial(
      const VectorType                        &u,
      VectorType                              &trial,
      double                                   t,
      const dealii::AffineConstraints<double> &constraints) const override;

    /// The force each obstacle exerts on the body (columns
    /// contact_force_<k>_<axis>) and its moment about the obstacle's point
    /// (contact_moment_<k>_<axis>), the smallest distance and the active
    /// pairs at @p u (ghosted). Collective.
    ContactMeasures
    measure(const VectorType &u, double t) const;

    /// The nodal contact forces on the body at @p u (owned entries;
    /// barrier and friction). Collective.
    void
    contact_forces(const VectorType &u, double t, VectorType &forces) const
    {
      add_forces(u, t, forces);
    }

    double
    barrier_distance() const
    {
      return d_hat_value;
    }

    /// d_hat, kappa, eps and where d_hat comes from.
    const BarrierSettings &
    settings() const
    {
      return shared_settings;
    }

    /// The surfaces of the meshed obstacles, one entry per obstacle of the
    /// scene (null for the other types), read once from their files.
    const std::vector<std::shared_ptr<const ObstacleSurface<dim>>> &
    obstacle_surfaces() const
    {
      return surfaces;
    }

    double
    barrier_stiffness() const
    {
      return kappa;
    }

    /// kappa's start and its re-targets between steps (BarrierStiffness).
    const BarrierStiffness &
    stiffness_control() const
    {
      return stiffness;
    }

    /// eps of the friction of a step of length @p h (dynamics: eps_v h).
    double
    friction_smoothing(double h) const
    {
      return dynamic ? eps_setting * h : eps_setting;
    }

    /// Whether any obstacle has friction.
    bool
    has_friction() const;

    /// Times the term's work (forces, stiffness, potential, feasible step)
    /// in the section "contact" of @p timer, which must outlive the term.
    void
    set_timer(dealii::TimerOutput &timer)
    {
      this->timer = &timer;
    }

  private:
    /// The owned, unconstrained rows the last add_stiffness() wrote.
    mutable std::vector<dealii::types::global_dof_index> stiff_rows;
    /// Where PairSums records them.
    std::vector<dealii::types::global_dof_index> *
    written_rows() const
    {
      return &stiff_rows;
    }

    /// One boundary vertex: its reference position and its dofs.
    struct Vertex
    {
      dealii::Point<dim>                               X;
      std::array<dealii::types::global_dof_index, dim> dofs;
      /// Its share of the boundary's measure (area in 3D, length in 2D):
      /// the weight of its barrier, so that a uniform contact pressure
      /// gives equal distances.
      double area = 0.;
    };

    /// The boundary vertices whose dofs this rank owns, with their area
    /// weights; returns the squared diagonal of the body's bounding box
    /// (collective).
    double
    gather_vertices(const dealii::DoFHandler<dim> &dof_handler);

    /// The start must be feasible: a vertex on the wrong side of an
    /// obstacle at t = 0 is an InputError naming both (collective).
    void
    check_start() const;

    /// An obstacle where it stands at one time.
    struct Placed
    {
      ObstacleType type = ObstacleType::plane;
      /// plane: on it; sphere: centre; mesh: the origin of the file's
      /// coordinates
      dealii::Point<dim>          point;
      const ObstacleSurface<dim> *surface = nullptr; ///< mesh
      /// plane: the unit normal (turned with the obstacle)
      dealii::Tensor<1, dim> normal;
      double                 radius   = 0.;
      double                 friction = 0.;
      /// Whether it has a rotation axis; its axis, angle and rotation Q
      /// from the entries' placement (the identity if it does not turn).
      bool                   turns = false;
      dealii::Tensor<1, 3>   axis;
      double                 angle = 0.;
      dealii::Tensor<2, dim> rotation;
      /// Friction's reference: the displacement of its point since the
      /// step began, and for a turning obstacle that point at the step's
      /// start and the rotation since then.
      dealii::Tensor<1, dim> shift;
      dealii::Point<dim>     start_point;
      dealii::Tensor<2, dim> turn;
    };

    /// The displacement, from placement @p from to placement @p to of the
    /// same obstacle, of its material point at @p x in @p from.
    static dealii::Tensor<1, dim>
    carried(const Placed &from, const Placed &to, const dealii::Point<dim> &x);

    /// The obstacles at obstacle time @p time.
    std::vector<Placed>
    placed(double time) const;

    /// Distance of @p x to @p o, its gradient and Hessian (a meshed
    /// obstacle: up to @p reach, beyond it @p reach and zero derivatives).
    static double
    distance(const Placed             &o,
             const dealii::Point<dim> &x,
             double                    reach,
             dealii::Tensor<1, dim>   *gradient = nullptr,
             dealii::Tensor<2, dim>   *hessian  = nullptr);

    /// Friction's lagged quantities of a vertex-obstacle pair.
    struct Lagged
    {
      double normal_force = 0.; ///< lambda
      /// d lambda / dt, extrapolated from the last two converged states
      /// (zero once updated within the step).
      double                          rate = 0.;
      dealii::SymmetricTensor<2, dim> tangent_projection;

      /// lambda at @p elapsed time after the step's start (not negative).
      double
      normal_force_after(const double elapsed) const
      {
        return std::max(0., normal_force + rate * elapsed);
      }
    };

    /// A pair's share of V, its force on the body and its stiffness.
    struct PairState
    {
      double                          distance = 0.;
      bool                            active   = false; ///< d < d_hat
      double                          energy   = 0.;
      dealii::Tensor<1, dim>          force;
      dealii::SymmetricTensor<2, dim> stiffness;
    };

    using Stencil = PairStencil<dim, 2>;
    using Sums    = PairSums<dim, 2>;

    /// Hands each pair at @p u and time @p t to the request (PairSums::Visit);
    /// returns whether a pair touches here.
    bool
    visit(const VectorType             &u,
          double                        t,
          const typename Sums::Request &request) const;
    /// A pair as PairSums takes it: vertex @p a (its constrained dofs held
    /// where @p constraints is given) and the obstacle's point under it,
    /// moving by @p motion.
    Stencil
    stencil(unsigned int                             a,
            const dealii::AffineConstraints<double> *constraints = nullptr,
            const dealii::Tensor<1, dim>            &motion      = {}) const;

    /// What add_forces throws with when a pair touches at time @p t.
    static std::string
    touching_message(double t);

    /// The pair's barrier over the vertex and the obstacle's point, its
    /// derivatives up to @p order.
    static PairBarrier<2 * dim>
    as_barrier(const PairState &p, unsigned int order);

    /// The slip of vertex @p a at @p x relative to obstacle @p o since the
    /// step's start, in the tangent plane of @p l.
    dealii::Tensor<1, dim>
    slip(unsigned int              a,
         const dealii::Point<dim> &x,
         const Placed             &o,
         const Lagged             &l) const;

    /// Vertex @p a at @p x against obstacle @p k placed at @p o; the
    /// stiffness only if @p with_stiffness. Friction's eps: @p eps; the
    /// time since the step's start: @p since_start (extrapolated lambda).
    PairState
    pair(unsigned int              a,
         unsigned int              k,
         const dealii::Point<dim> &x,
         const Placed             &o,
         double                    eps,
         double                    since_start,
         bool                      with_stiffness) const;

    /// Calls @p f(a, k, pair) for every vertex a and obstacle k (pairs
    /// beyond d_hat without friction included, inactive); returns whether
    /// a distance was not positive.
    template <typename F>
    bool
    for_each_pair(const VectorType &u,
                  double            t,
                  bool              with_stiffness,
                  const F          &f) const;

    /// Friction's lambda and tangent projection of every pair at @p u.
    std::vector<Lagged>
    lagged_at(const VectorType &u, double time) const;

    /// Where vertex @p a is at the end of the step whose solved state is
    /// @p u (X + u, or its image under the end-state map).
    dealii::Point<dim>
    position(unsigned int a, const VectorType &u) const;

    const std::vector<ObstacleParameters> obstacles;
    /// The surfaces of the meshed obstacles (null for the others).
    std::vector<std::shared_ptr<const ObstacleSurface<dim>>> surfaces;
    std::vector<std::unique_ptr<dealii::Function<dim>>>      motions;
    /// The rotation angles (null for obstacles that do not turn).
    std::vector<std::unique_ptr<dealii::Function<dim>>> angles;
    const MPI_Comm                                      comm;
    const bool                                          dynamic;
    std::vector<Vertex>                                 vertices;
    BarrierSettings                                     shared_settings;
    double                                              d_hat_value = 0.;
    double                                              kappa       = 0.;
    /// kappa's start and its re-targets between steps.
    BarrierStiffness stiffness;
    /// eps (quasi-static) or eps_v (dynamics).
    double eps_setting = 0.;
    /// Friction's lagging updates ('Friction lagging updates' a step).
    FrictionLagging lagging;

    /// The step's start, where the obstacles stand within it and its
    /// end-state map; the vertices' positions at the start and the lagged
    /// friction [a * n_obstacles + k].
    ObstacleClock                   clock;
    std::vector<dealii::Point<dim>> start_positions;
    std::vector<Lagged>             lagged;
    dealii::TimerOutput            *timer = nullptr;
  };
} // namespace hyperelastic
