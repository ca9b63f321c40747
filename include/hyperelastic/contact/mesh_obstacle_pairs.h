// The pairs that keep a meshed obstacle (Contact/Obstacle k/Type = mesh) and
// the body apart besides ObstacleContact's body vertices against the
// obstacle's surface: the obstacle's vertices against the body's boundary
// faces (2D: segments, 3D: triangles) and, in 3D, the obstacle's edges
// against the body's boundary edges. With them no obstacle corner or edge
// passes through a body face, however coarse the body:
//   V(u, t) = kappa sum over pairs k of w_k m_k(x) b(d_k(x, y(t)), d_hat),
// x the body's vertices, y(t) the obstacle's (rigid, no unknowns), d_k the
// pair's distance and m_k the edge-edge mollifier
// (contact/primitive_distance.h), w_k the obstacle vertex's share of the
// obstacle's area (vertex-face; 2D: length) or the mean of the two edges'
// shares of their faces' areas (edge-edge), as self contact weighs its
// pairs. Frictionless.
//
// Only the obstacle's sharp features take part: an edge whose two
// triangles lie in one plane (a vertex whose neighbourhood is flat) cannot
// be the first point of a crossing, which the body's vertices against the
// obstacle's faces and the other pairs catch, so a flat part of an obstacle
// (a meshed floor) adds nothing to ObstacleContact's barrier.
//
// Forces, stiffness (each pair's Hessian in the body's coordinates, exact
// or projected to positive semi-definite when Newton asks for a projected
// tangent) and energy; the feasible step is additive CCD
// (contact/collision_detection.h) of every pair with the body moving along
// the Newton direction and the obstacle along the rest of its way within
// the step (the obstacle time is kept as ObstacleContact keeps it, by the
// same prepare_motion/advance calls; the linearization carries the rest of
// the obstacle's motion, as a prescribed motion of the pairs' obstacle
// points).
//
// MPI: the obstacle is known on every rank; a rank holds the boundary faces
// of its own and its ghost cells that have a vertex it owns or a cell it
// owns (ghosted positions, no exchange), writes its owned rows only, and
// counts a pair's energy (and feasible step) if it owns the face's cell
// (edge: the cell of lowest subdomain among the edge's faces). No pair
// couples dofs outside one cell, so the mesh's sparsity holds the stiffness.
#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
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
#include <hyperelastic/contact/obstacle_clock.h>
#include <hyperelastic/contact/obstacle_surface.h>
#include <hyperelastic/contact/pair_assembly.h>
#include <hyperelastic/contact/primitive_distance.h>
#include <hyperelastic/materials/material.h>

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
  class MeshObstaclePairs : public EnergyTerm<dim>,
                            public SteppedTerm<dim>,
                            public MovingAdmissibleSetTerm<dim>
  {
    friend class PairSums<dim, dim + 1>;

  public:
    /// Whether the scene has a meshed obstacle whose features need the
    /// pairs ('Contact/Meshed obstacle corners').
    static bool
    wanted(const ContactParameters &parameters);

    /// Finds the sharp vertices and edges of the meshed obstacles of
    /// @p parameters (their surfaces in @p surfaces, one entry per
    /// obstacle, null for the others: those ObstacleContact read) and the
    /// body's boundary faces and edges this rank needs; d_hat and kappa
    /// are @p settings, the ones ObstacleContact uses (with self contact,
    /// the reference gaps' d_hat). A corner or edge of an obstacle through
    /// a body face at t = 0 is an InputError naming the obstacle.
    /// Collective.
    MeshObstaclePairs(
      const ContactParameters             &parameters,
      const std::map<std::string, double> &constants,
      const dealii::DoFHandler<dim>       &dof_handler,
      const std::vector<std::shared_ptr<const ObstacleSurface<dim>>> &surfaces,
      const BarrierSettings                                          &settings);
    ~MeshObstaclePairs() override;

    std::string
    name() const override
    {
      return "Contact (obstacle corners and edges)";
    }

    TermKind
    kind() const override
    {
      return TermKind::conservative;
    }

    /// Throws ConvergenceFailure on every rank if a pair touches.
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

    /// kappa sum w m b; +infinity if a pair touches.
    double
    energy(const VectorType &u, const double t) const override
    {
      return Sums::energy(*this, u, t);
    }

    /// The largest step along @p direction, the obstacles moving jointly
    /// to their place at @p t, that keeps every pair at a tenth of its
    /// distance (additive CCD).
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
    /// Frictionless: nothing lagged.
    LaggedUpdate
    update_lagged(const VectorType &, double, LagMoment, double) override
    {
      return LaggedUpdate::unchanged;
    }
    bool
    prepare_motion(const double t) override
    {
      return clock.prepare_motion(t, [&](const double from, const double to) {
        for (unsigned int m = 0; m < motions.size(); ++m)
          if (placement(m, from).shift != placement(m, to).shift)
            return true;
        return false;
      });
    }
    void
    advance(const double alpha, const double t) override
    {
      clock.advance(alpha, t);
    }

    /// The force of each meshed obstacle's pairs on the body (columns
    /// contact_force_<k>_<axis>, to be added to ObstacleContact's) and its
    /// moment about the obstacle's point (contact_moment_<k>_<axis>), the
    /// smallest pair distance (capped at d_hat) and the active pairs at
    /// @p u (ghosted). Collective.
    ContactMeasures
    measure(const VectorType &u, double t) const;

    /// Adds the pairs' nodal forces on the body at @p u (ghosted; owned
    /// entries). Collective.
    void
    contact_forces(const VectorType &u, double t, VectorType &forces) const
    {
      add_forces(u, t, forces);
    }

    /// kappa's start and its re-targets between steps (BarrierStiffness).
    const BarrierStiffness &
    stiffness_control() const
    {
      return stiffness;
    }

    /// The sharp obstacle vertices and edges (all meshed obstacles).
    std::array<unsigned int, 2>
    n_features() const
    {
      return {{static_cast<unsigned int>(corners.size()),
               static_cast<unsigned int>(ridges.size())}};
    }

    void
    set_timer(dealii::TimerOutput &timer)
    {
      this->timer = &timer;
    }

  private:
    static constexpr unsigned int n_points      = dim + 1;
    static constexpr std::size_t  n_coordinates = n_points * dim;
    using Coordinates = std::array<double, n_coordinates>;
    using Stencil     = PairStencil<dim, n_points>;
    using Sums        = PairSums<dim, n_points>;

    /// A body boundary vertex this rank sees.
    struct BodyVertex
    {
      dealii::Point<dim>                               X;
      std::array<dealii::types::global_dof_index, dim> dofs;
      bool                                             owned = false;
    };

    /// A body boundary face (dim vertices) or edge (3D, 2 vertices), and
    /// whether this rank counts its pairs.
    template <unsigned int n>
    struct BodyPrimitive
    {
      std::array<unsigned int, n> v;
      bool                        counted = false;
      double                      area    = 0.; ///< edges: their weight
      double                      length2 = 0.; ///< edges: squared length
    };

    /// A sharp obstacle vertex (v[0]) or edge, indices into
    /// obstacle_points, with its weight and (edges) squared length.
    struct Feature
    {
      std::array<unsigned int, 2> v{};
      unsigned int                obstacle = 0; ///< index into meshed
      double                      area     = 0.;
      double                      length2  = 0.;
    };

    /// A pair: corner against face, [y, f0, (f1,) f_dim-1], or (3D) body
    /// edge against ridge, [e0, e1, y0, y1].
    struct Pair
    {
      bool         edge_edge = false;
      unsigned int body      = 0; ///< face or edge
      unsigned int feature   = 0; ///< corner or ridge
    };

    /// The rigid placement of a meshed obstacle at one time: where the
    /// obstacle's point that is at X at t = 0 is then. Today a
    /// translation; a rotation enters here (and in placement()) only.
    struct Placement
    {
      dealii::Tensor<1, dim> shift;
      dealii::Point<dim>
      operator()(const dealii::Point<dim> &X) const
      {
        return X + shift;
      }
    };

    /// The placement of meshed obstacle @p m at obstacle time @p time.
    Placement
    placement(unsigned int m, double time) const;

    /// Every obstacle point placed at obstacle time @p time.
    std::vector<dealii::Point<dim>>
    obstacle_at(double time) const;

    void
    gather_body(const dealii::DoFHandler<dim> &dof_handler);
    void
    find_features(
      const ContactParameters &parameters,
      const std::vector<std::shared_ptr<const ObstacleSurface<dim>>> &surfaces);
    void
    check_start() const;

    /// The body vertices' positions at @p u (ghosted), end-state map
    /// applied.
    std::vector<dealii::Point<dim>>
    body_at(const VectorType &u) const;

    /// The pairs whose boxes (around @p x and @p y, swept by @p p and
    /// @p q if given) come within @p margin; @p counted_only: the pairs
    /// this rank counts, otherwise those with an owned body vertex.
    std::vector<Pair>
    candidates(const std::vector<dealii::Point<dim>>     &x,
               const std::vector<dealii::Point<dim>>     &y,
               const std::vector<dealii::Tensor<1, dim>> *p,
               const std::vector<dealii::Tensor<1, dim>> *q,
               double                                     margin,
               bool                                       counted_only) const;

    /// The pair's points: body vertex index (or -1) and obstacle point
    /// index (or -1) for each of its n_points.
    std::array<int, n_points>
    body_points(const Pair &pair) const;
    std::array<int, n_points>
    obstacle_points_of(const Pair &pair) const;

    Coordinates
    coordinates(const Pair                            &pair,
                const std::vector<dealii::Point<dim>> &x,
                const std::vector<dealii::Point<dim>> &y) const;

    /// The stencil of @p pair: its body vertices' dofs (constrained ones
    /// held where @p constraints is given), written where owned, and its
    /// obstacle points moving by @p rest (per obstacle point; none: 0).
    Stencil
    stencil(const Pair                                &pair,
            const dealii::AffineConstraints<double>   *constraints = nullptr,
            const std::vector<dealii::Tensor<1, dim>> *rest = nullptr) const;

    /// Hands each pair at @p u and time @p t to the request (PairSums::Visit);
    /// returns whether a pair touches here.
    bool
    visit(const VectorType             &u,
          double                        t,
          const typename Sums::Request &request) const;

    /// What add_forces throws with when a pair touches at time @p t.
    static std::string
    touching_message(double t);

    bool
    counted(const Pair &pair) const
    {
      return pair.edge_edge ? edges[pair.body].counted
                            : faces[pair.body].counted;
    }

    /// Calls @p f(pair, barrier) for every pair with an owned body vertex
    /// or counted here that is closer than d_hat at @p u and time @p t
    /// (derivatives up to @p order, in the solved state); returns whether a
    /// pair touches; the smallest distance (capped at d_hat) in
    /// @p min_distance if not null.
    template <typename F>
    bool
    for_each_active(const VectorType &u,
                    double            t,
                    unsigned int      order,
                    const F          &f,
                    double           *min_distance = nullptr) const;

    /// The ghosted copy of an owned vector (collective).
    const VectorType &
    ghosted(const VectorType &v) const;

    const MPI_Comm   comm;
    dealii::IndexSet relevant;
    unsigned int     my_subdomain = 0;
    double           d_hat = 0., kappa = 0.;
    /// kappa's start and its re-targets between steps.
    BarrierStiffness stiffness;

    /// The meshed obstacles: their section number k and motion, and where
    /// their Point is at t = 0 (Point moved by the motion at t = 0: the
    /// reference of their moments).
    std::vector<unsigned int>                           numbers;
    std::vector<dealii::Point<dim>>                     anchors;
    std::vector<std::string>                            sections;
    std::vector<std::unique_ptr<dealii::Function<dim>>> motions;
    /// Every meshed obstacle's vertices where they are at t = 0, and which
    /// obstacle each belongs to.
    std::vector<dealii::Point<dim>> obstacle_points;
    std::vector<unsigned int>       point_obstacle;
    std::vector<Feature>            corners, ridges;

    std::vector<BodyVertex>         vertices;
    std::vector<BodyPrimitive<dim>> faces;
    std::vector<BodyPrimitive<2>>   edges;

    /// The step's start, where the obstacles stand within it and its
    /// end-state map (as ObstacleContact's).
    ObstacleClock                   clock;
    std::vector<dealii::Point<dim>> start_positions;
    mutable VectorType              ghost_buffer;
    dealii::TimerOutput            *timer = nullptr;

    /// Its stiffness's rows are not recorded (no StiffTerm).
    static std::vector<dealii::types::global_dof_index> *
    written_rows()
    {
      return nullptr;
    }
  };
} // namespace hyperelastic
