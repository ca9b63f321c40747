// Contact of the body's boundary with itself and between the bodies of one
// mesh ('Contact/Self contact'), through the IPC barrier of the obstacles:
//   V(u) = kappa sum over pairs k of w_k m_k(x) b(d_k(x), d_hat),
// the pairs being every boundary vertex with every boundary segment (2D) or
// triangle (3D) it is not a vertex of, and in 3D every two boundary edges
// without a common vertex; d_k their distance (contact/primitive_distance.h),
// m_k the edge-edge mollifier (1 for the others), w_k the vertex's share of
// the boundary measure (edge-edge: the edge's third of its faces' areas).
// Each pair also carries the corrections of contact/duplicate_counting.h,
// so that a vertex over a shared boundary vertex or edge is not counted
// twice: over a flat boundary the barrier is b(gap) wherever the vertex is.
// Exact gradients and Hessians (automatic differentiation); each pair's
// Hessian is projected to positive semi-definite when Newton asks for a
// projected tangent (EnergyTerm::add_stiffness's projection: after the
// exact one gave no descent direction), exact otherwise, so that Newton
// keeps its quadratic convergence where it can.
//
// Broad phase: R-trees (boost, packed) over the deformed boundary's faces
// and edges, built anew for every evaluation; the candidates are the pairs
// whose boxes, inflated by d_hat, overlap. Feasible step: additive CCD
// (contact/collision_detection.h) on every pair whose swept boxes overlap,
// each keeping a tenth of its distance, so no iterate lets the boundary
// pass through itself.
//
// MPI: every rank holds the whole boundary's connectivity (set up once:
// integers and reference coordinates) and, for every evaluation, the
// positions of its own boundary vertices plus those of the other ranks'
// vertices that lie within reach of its own (each rank publishes the box of
// its vertices; the owners send what falls in another rank's inflated box,
// point to point). A rank evaluates the pairs with a vertex it owns and
// writes its owned rows only; a pair's energy is counted by the owner of its
// lowest vertex. The tangent's sparsity grows with the pairs
// (CouplingTerm::needs_new_couplings). The answer does not depend on the number
// of ranks.
//
// Friction ('Contact/Self contact friction coefficient' mu): the smoothed,
// lagged Coulomb friction of the obstacles, per pair
// (contact/pair_friction.h): at the step's start and at each converged
// state of its lagging updates, every active pair's normal force
// lambda = -kappa w m b'(d), unit normal and closest-point coefficients are
// recorded; the step's slip of the closest points in that tangent plane
// gives the dissipation potential mu lambda f0(|s|) added to the energy.
// Each rank lags the pairs with a vertex it owns; the start positions of the
// vertices travel with the current ones.
//
// P2: the vertices only (flat faces between them), as for the obstacles.
#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>

#include <hyperelastic/assembly/energy_term.h>
#include <hyperelastic/assembly/term_capabilities.h>
#include <hyperelastic/base/timed_section.h>
#include <hyperelastic/contact/barrier_settings.h>
#include <hyperelastic/contact/barrier_stiffness.h>
#include <hyperelastic/contact/contact_measures.h>
#include <hyperelastic/contact/contact_parameters.h>
#include <hyperelastic/contact/duplicate_counting.h>
#include <hyperelastic/contact/end_state_map.h>
#include <hyperelastic/contact/friction_lagging.h>
#include <hyperelastic/contact/pair_assembly.h>
#include <hyperelastic/contact/pair_friction.h>
#include <hyperelastic/contact/primitive_distance.h>
#include <hyperelastic/materials/material.h>

#include <array>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class SelfContact : public EnergyTerm<dim>,
                      public SteppedTerm<dim>,
                      public AdmissibleSetTerm<dim>,
                      public CouplingTerm<dim>,
                      public StiffTerm<dim>
  {
    friend class PairSums<dim, dim + 1>;

  public:
    /// Gathers the boundary (collective), sets d_hat and kappa as the
    /// obstacles do (the automatic d_hat at most half the smallest gap
    /// between non-adjacent boundary features in the reference
    /// configuration) and checks the start: boundary primitives closer than
    /// d_hat in the reference configuration are an InputError naming the
    /// place. With @p dynamic, friction's smoothing is a slip velocity.
    SelfContact(const ContactParameters       &parameters,
                const dealii::DoFHandler<dim> &dof_handler,
                const LameParameters          &moduli,
                bool                           dynamic = false);
    ~SelfContact() override;

    std::string
    name() const override
    {
      return "Contact (self)";
    }

    TermKind
    kind() const override
    {
      return TermKind::conservative;
    }

    /// Throws ConvergenceFailure on every rank if two primitives touch.
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

    /// kappa sum w m b (plus friction's potential); +infinity if two
    /// primitives touch.
    double
    energy(const VectorType &u, const double t) const override
    {
      return Sums::energy(*this, u, t);
    }

    /// The largest step along @p direction that keeps every pair at a
    /// tenth of its distance (additive CCD).
    double
    largest_feasible_step(const VectorType &u,
                          const VectorType &direction,
                          double            t) const override;

    void
    begin_step(const VectorType &u, double t_start) override;
    void
    set_end_state_map(double c, double weight) override
    {
      end_state = {c, weight};
    }

    /// Friction: lags the normal forces, normals and closest points of the
    /// active pairs at @p u; updated if the friction force they change is
    /// more than FrictionLagging's tolerance (at most 'Friction lagging
    /// updates' times a step).
    LaggedUpdate
    update_lagged(const VectorType &u,
                  double            t,
                  LagMoment         moment,
                  double            unbalanced_force) override;

    bool
    needs_new_couplings(const VectorType &u, double t) override;
    void
    add_couplings(dealii::DynamicSparsityPattern &pattern) const override;

    void
    add_stiff_dofs(dealii::IndexSet &dofs) const override
    {
      for (const dealii::types::global_dof_index dof : stiff_rows)
        dofs.add_index(dof);
    }

    /// The smallest distance of the self pairs (capped at d_hat) and the
    /// number of active ones at @p u (ghosted). Collective.
    ContactMeasures
    measure(const VectorType &u) const;

    /// Adds the nodal contact forces of the self pairs at @p u and time
    /// @p t (barrier and friction; owned entries). Collective.
    void
    contact_forces(const VectorType &u, double t, VectorType &forces) const
    {
      add_forces(u, t, forces);
    }

    double
    barrier_distance() const
    {
      return d_hat;
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

    /// d_hat, kappa, eps and where d_hat comes from (the obstacles take
    /// the same).
    const BarrierSettings &
    settings() const
    {
      return shared_settings;
    }

    /// Boundary vertices, faces (segments in 2D) and edges (3D), global.
    std::array<unsigned int, 3>
    boundary_size() const
    {
      return {{static_cast<unsigned int>(vertices.size()),
               static_cast<unsigned int>(faces.size()),
               static_cast<unsigned int>(edges.size())}};
    }

    /// Accumulated wall time of the parts (this rank): the positions'
    /// exchange, the broad phase (trees and queries), the narrow phase
    /// (distances, barrier and derivatives, assembly) and CCD; and the
    /// number of evaluations.
    struct Cost
    {
      double       exchange = 0., broad = 0., narrow = 0., ccd = 0.;
      unsigned int evaluations = 0, sparsity_rebuilds = 0;
      /// The values (doubles) this rank received from the others.
      double received = 0.;
    };
    const Cost &
    cost() const
    {
      return spent;
    }

    /// Times the term's work in the section "contact" of @p timer.
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

    struct Vertex
    {
      dealii::Point<dim>                               X;
      std::array<dealii::types::global_dof_index, dim> dofs;
      double                                           area  = 0.;
      unsigned int                                     owner = 0;
    };

    /// A candidate pair: point-segment [p, a, b] (2D), point-triangle
    /// [p, t0, t1, t2] or edge-edge [a0, a1, b0, b1] (3D).
    struct Pair
    {
      std::array<unsigned int, n_points> v{};
      bool                               edge_edge = false;
      double                             weight    = 0.; ///< w
      double mollifier = 0.; ///< eps_x (edge-edge), 0 otherwise
      /// The corrections that remove double counting
      /// (contact/duplicate_counting.h).
      PairCorrection correction{};
    };

    /// The closest pair of the reference configuration among the
    /// candidates within a reach: its distance over all ranks (+infinity
    /// if none), this rank's closest distance and pair.
    struct Closest
    {
      double distance = std::numeric_limits<double>::infinity();
      double here     = std::numeric_limits<double>::infinity();
      Pair   pair;
    };

    /// The set-up's steps: every rank's boundary vertices (numbered rank
    /// by rank; returns this rank's boundary faces as first dofs), the
    /// faces and edges with their measures (collective), the closest
    /// non-adjacent primitives of the reference configuration within
    /// @p reach (collective), and the check that none start within d_hat
    /// (an InputError naming the place; collective).
    std::vector<dealii::types::global_dof_index>
    gather_vertices(const dealii::DoFHandler<dim> &dof_handler);
    void
    build_faces(const std::vector<dealii::types::global_dof_index> &my_faces);
    Closest
    closest_pair(double reach) const;
    void
    check_start(const Closest &closest) const;

    /// The boxes of every vertex, face and edge, around the positions @p x
    /// (and x + @p p if given: the swept boxes) inflated by @p margin.
    struct Boxes
    {
      std::vector<dealii::BoundingBox<dim>> vertex, face, edge;
    };
    Boxes
    boxes(const std::vector<dealii::Point<dim>>     &x,
          const std::vector<dealii::Tensor<1, dim>> *p,
          double                                     margin) const;

    /// Every pair whose boxes overlap and that has a vertex this rank owns,
    /// once.
    std::vector<Pair>
    candidates(const Boxes &b) const;

    /// Which of its owned boundary vertices (offsets from first_owned) this
    /// rank sends to which other rank.
    using SendLists = std::map<unsigned int, std::vector<unsigned int>>;

    /// The boundary vertices this rank knows in a state: its own and those
    /// the other ranks sent (NaN for the others).
    struct State
    {
      std::vector<dealii::Point<dim>> x; ///< positions (end-state map applied)
      std::vector<dealii::Tensor<1, dim>>
        p; ///< motions (end-state map applied)
      /// The positions at the step's start (friction only).
      std::vector<dealii::Point<dim>> x0;
      SendLists                       send;
    };

    /// The state @p u (and the motion @p direction, if given): each rank
    /// sends its owned vertices that lie (or move) within the region of
    /// another rank, the box of that rank's vertices inflated by @p reach
    /// plus twice the longest boundary edge (more where a stretched
    /// primitive of its own arrived incomplete). Collective.
    State
    state(const VectorType &u, const VectorType *direction, double reach) const;

    /// The state @p u within d_hat (positions, and start positions with
    /// friction). Collective.
    State
    near_state(const VectorType &u) const
    {
      return state(u, nullptr, d_hat);
    }

    /// @p m values per vertex, @p owned_values of the owned vertices, sent
    /// as @p send says: the values of all vertices known here (NaN for the
    /// others). Collective.
    std::vector<double>
    exchange(const SendLists           &send,
             const std::vector<double> &owned_values,
             unsigned int               m) const;

    Coordinates
    coordinates(const Pair                            &pair,
                const std::vector<dealii::Point<dim>> &x) const;

    /// Calls @p f(pair, barrier) for every candidate pair closer than d_hat
    /// at @p x (derivatives up to @p order); returns whether a pair
    /// touches (distance <= 0). Also gives the smallest distance (capped
    /// at d_hat) in @p min_distance if not null.
    template <typename F>
    bool
    for_each_active(const std::vector<dealii::Point<dim>> &x,
                    unsigned int                           order,
                    const F                               &f,
                    double *min_distance = nullptr) const;

    /// Whether this rank counts the pair (owns its lowest vertex).
    bool
    counted_here(const Pair &pair) const
    {
      unsigned int lowest = pair.v[0];
      for (const unsigned int v : pair.v)
        lowest = std::min(lowest, v);
      return vertices[lowest].owner == rank;
    }

    /// What add_forces throws with when two primitives touch.
    static std::string
    touching_message(double)
    {
      return "two parts of the boundary touch (self contact)";
    }

    /// A pair's lagged friction: closest-point coefficients, unit normal
    /// and normal force lambda.
    struct Lagged
    {
      Pair                         pair;
      std::array<double, n_points> beta;
      std::array<double, dim>      normal;
      double                       normal_force = 0.;
    };

    /// The lagged friction of every active pair at @p s (with a vertex
    /// owned here).
    std::vector<Lagged>
    lag(const State &s) const;

    /// Calls @p f(pair, energy) with the friction energy of every lagged
    /// pair at @p s and time @p t (derivatives up to @p order), scaled for
    /// the end-state map as the barrier is.
    template <typename F>
    void
    for_each_friction(const State &s,
                      double       t,
                      unsigned int order,
                      const F     &f) const;

    /// Friction's smoothing eps at time @p t of the step.
    double
    friction_smoothing(double t) const;

    /// The positions @p x and step-start positions @p x0 of @p pair's
    /// vertices in @p s; false if one is not known here (it slid out of
    /// reach within the step).
    bool
    slip_coordinates(const Pair  &pair,
                     const State &s,
                     Coordinates &x,
                     Coordinates &x0) const;

    /// The stencil of @p pair: its vertices' dofs, written by their owner;
    /// with @p prescribed (per vertex and component, NaN where free), the
    /// constrained ones held.
    Stencil
    stencil(const Pair                &pair,
            const std::vector<double> *prescribed = nullptr) const;

    /// Hands each pair at @p u and time @p t to the request (PairSums::Visit);
    /// returns whether a pair touches here.
    bool
    visit(const VectorType             &u,
          double                        t,
          const typename Sums::Request &request) const;

    const MPI_Comm                             comm;
    const unsigned int                         rank;
    std::vector<Vertex>                        vertices;
    std::vector<std::array<unsigned int, dim>> faces;
    /// 3D: the boundary edges, their weights (a third of each adjacent
    /// face's area) and squared rest lengths.
    std::vector<std::array<unsigned int, 2>> edges;
    std::vector<double>                      edge_area, edge_length2;
    /// The faces at each boundary vertex and edge (the pairs' corrections).
    BoundaryIncidence<dim> incidence;
    /// The owned boundary vertices: [first_owned, first_owned + n_owned)
    /// (the vertices are numbered rank by rank).
    unsigned int first_owned = 0, n_owned = 0;
    /// The longest boundary edge in the reference configuration.
    double longest_edge = 0.;

    BarrierSettings shared_settings;
    double          d_hat = 0., kappa = 0.;
    /// kappa's start and its re-targets between steps.
    BarrierStiffness stiffness;
    /// The step's end-state map (set_end_state_map).
    EndStateMap end_state;
    /// The owned boundary vertices' positions at the step's start (the
    /// end-state map, friction's slip), and the step's start time.
    std::vector<dealii::Point<dim>> owned_start;
    double                          step_start = 0.;

    /// Friction: mu, the smoothing (a slip length, or with dynamics a slip
    /// velocity), the lagged pairs and the updates made this step.
    double              friction = 0., eps_setting = 0.;
    bool                dynamic = false;
    FrictionLagging     lagging;
    std::vector<Lagged> lagged;
    /// The vertex couplings (owned vertex, other vertex) in the tangent's
    /// sparsity.
    std::set<std::pair<unsigned int, unsigned int>> reserved;

    /// The candidates within d_hat of the last evaluated positions.
    mutable std::vector<dealii::Point<dim>> candidates_at;
    mutable std::vector<Pair>               near_pairs;
    /// The owned, unconstrained rows the last add_stiffness() wrote.
    mutable std::vector<dealii::types::global_dof_index> stiff_rows;
    /// Where PairSums records them.
    std::vector<dealii::types::global_dof_index> *
    written_rows() const
    {
      return &stiff_rows;
    }

    mutable Cost         spent;
    dealii::TimerOutput *timer = nullptr;
  };
} // namespace hyperelastic
