// The barrier contact of the boundary with itself: gathering the boundary,
// broad phase, pair barriers, assembly and continuous collision detection.
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/numerics/rtree.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/contact/barrier.h>
#include <hyperelastic/contact/barrier_settings.h>
#include <hyperelastic/contact/collision_detection.h>
#include <hyperelastic/contact/pair_assembly.h>
#include <hyperelastic/contact/self_contact.h>
#include <hyperelastic/mesh/mesh_distribution.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// The tangent's sparsity holds the couplings of the pairs within this
    /// many d_hat, so that a few iterates more fit in before it grows.
    constexpr double coupling_reach = 4.;

  } // namespace

  template <int dim>
  SelfContact<dim>::SelfContact(const ContactParameters &parameters,
                                const DoFHandler<dim>   &dof_handler,
                                const LameParameters    &moduli,
                                const bool               dynamic)
      : comm(dof_handler.get_communicator())
      , rank(Utilities::MPI::this_mpi_process(comm))
      , friction(parameters.self_contact_friction)
      , dynamic(dynamic)
      , lagging(parameters.friction_lagging_updates,
                parameters.friction_force_trigger)
  {
    build_faces(gather_vertices(dof_handler));
    // d_hat and kappa as for the obstacles, the automatic d_hat at most
    // half the smallest reference gap (within twice the diagonal's rule:
    // larger gaps leave that rule).
    Point<dim> lower = vertices.empty() ? Point<dim>() : vertices[0].X,
               upper = lower;
    for (const Vertex &v : vertices)
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::min(lower[d], v.X[d]);
          upper[d] = std::max(upper[d], v.X[d]);
        }
    const double  diagonal = lower.distance(upper);
    const Closest closest =
      closest_pair(parameters.barrier_distance > 0.
                     ? parameters.barrier_distance
                     : 2. * diagonal_barrier_distance(diagonal));
    std::vector<double> areas;
    for (const Vertex &v : vertices)
      areas.push_back(v.area);
    shared_settings =
      barrier_settings(parameters,
                       diagonal,
                       moduli,
                       dynamic,
                       mean_element_size(areas, dim, false, comm),
                       closest.distance);
    d_hat       = shared_settings.d_hat;
    kappa       = shared_settings.kappa;
    eps_setting = shared_settings.eps;
    stiffness   = BarrierStiffness(kappa, shared_settings.adaptive_kappa);

    check_start(closest);
  }

  template <int dim>
  typename SelfContact<dim>::Closest
  SelfContact<dim>::closest_pair(const double reach) const
  {
    std::vector<Point<dim>> X(vertices.size());
    for (unsigned int k = 0; k < vertices.size(); ++k)
      X[k] = vertices[k].X;
    Closest c;
    for (const Pair &pair : candidates(boxes(X, nullptr, reach)))
      {
        const Coordinates x = coordinates(pair, X);
        const double      d = std::sqrt(
          squared_distance<dim>(classify_pair<dim>(x, pair.edge_edge), x));
        if (d < c.here)
          c.here = d, c.pair = pair;
      }
    c.distance = Utilities::MPI::min(c.here, comm);
    return c;
  }

  template <int dim>
  void
  SelfContact<dim>::check_start(const Closest &closest) const
  {
    // The start: no two primitives within d_hat (their barrier would push
    // them apart before any load).
    const double global_closest = closest.distance;
    const Pair  &worst          = closest.pair;
    // The closest pair's place, from the first rank that holds it.
    std::string problem;
    if (global_closest < d_hat && closest.here == global_closest)
      {
        std::ostringstream s;
        s << "'Contact/Self contact': boundary "
          << (dim == 2          ? "vertex and segment"
              : worst.edge_edge ? "edges"
                                : "vertex and triangle")
          << " near (" << vertices[worst.v[0]].X << ") are " << global_closest
          << " apart in the reference configuration, closer than the "
             "barrier distance d_hat = "
          << d_hat << " (they would repel each other before any load): ";
        if (global_closest > 0.)
          s << "set 'Contact/Barrier distance' below " << global_closest
            << " or refine the mesh there";
        else
          s << "they touch; no barrier distance separates them (separate "
               "them in the mesh)";
        problem = s.str();
      }
    throw_input_error_of_first_rank(problem, comm);
  }

  template <int dim>
  SelfContact<dim>::~SelfContact() = default;

  template <int dim>
  typename SelfContact<dim>::Coordinates
  SelfContact<dim>::coordinates(const Pair                    &pair,
                                const std::vector<Point<dim>> &x) const
  {
    Coordinates c;
    for (unsigned int i = 0; i < n_points; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        c[i * dim + d] = x[pair.v[i]][d];
    return c;
  }

  template <int dim>
  template <typename F>
  bool
  SelfContact<dim>::for_each_active(const std::vector<Point<dim>> &x,
                                    const unsigned int             order,
                                    const F                       &f,
                                    double *min_distance) const
  {
    ++spent.evaluations;
    // The forces, stiffness and energy of one state share its candidates.
    // (Bitwise: the vertices not received here are NaN.)
    if (x.size() != candidates_at.size() ||
        std::memcmp(x.data(), candidates_at.data(), x.size() * sizeof(x[0])) !=
          0)
      {
        near_pairs    = candidates(boxes(x, nullptr, d_hat));
        candidates_at = x;
      }
    const std::vector<Pair> &pairs = near_pairs;
    Stopwatch                watch(spent.narrow);
    PairScan                 scan(d_hat);
    for (const Pair &pair : pairs)
      {
        const Coordinates c = coordinates(pair, x);
        if (pair.weight == 0.)
          {
            // A pair kept for the feasible step only (two edges not both
            // sharp: contact/duplicate_counting.h).
            scan.active(std::sqrt(std::max(
              squared_distance<dim>(classify_pair<dim>(c, pair.edge_edge), c),
              0.)));
            continue;
          }
        PairBarrier<n_coordinates> b =
          pair_barrier<dim>(c,
                            pair_terms<dim>(c, pair.edge_edge, pair.correction),
                            d_hat,
                            kappa * pair.weight,
                            pair.mollifier,
                            order);
        if (!scan.active(b.distance))
          continue;
        to_solved_state(b, end_state, order);
        f(pair, b);
      }
    if (min_distance)
      *min_distance = scan.closest;
    return scan.touching;
  }

  template <int dim>
  typename SelfContact<dim>::Stencil
  SelfContact<dim>::stencil(const Pair                &pair,
                            const std::vector<double> *prescribed) const
  {
    Stencil s;
    for (unsigned int i = 0; i < n_points; ++i)
      {
        const Vertex &v = vertices[pair.v[i]];
        s.set_vertex(i, v.dofs, v.owner == rank);
        if (prescribed)
          for (unsigned int d = 0; d < dim; ++d)
            s.held[i * dim + d] = (*prescribed)[pair.v[i] * dim + d];
      }
    return s;
  }

  template <int dim>
  bool
  SelfContact<dim>::visit(const VectorType             &u,
                          const double                  t,
                          const typename Sums::Request &request) const
  {
    const State s = near_state(u);
    // With constraints, the prescribed value of every boundary dof near here
    // (NaN where free), from its owner: a pair's far vertices may be
    // constrained on another rank.
    std::vector<double> prescribed;
    if (request.constraints)
      {
        std::vector<double> owned(std::size_t(n_owned) * dim);
        for (unsigned int k = 0; k < n_owned; ++k)
          for (unsigned int d = 0; d < dim; ++d)
            {
              const types::global_dof_index dof =
                vertices[first_owned + k].dofs[d];
              owned[k * dim + d] = prescribed_value(*request.constraints, dof);
            }
        prescribed = exchange(s.send, owned, dim);
      }
    const std::vector<double> *held =
      request.constraints ? &prescribed : nullptr;
    const bool touching =
      for_each_active(s.x, request.order, [&](const Pair &pair, const auto &b) {
        request.take(stencil(pair, held), b, counted_here(pair), true);
      });
    // Friction's pair Hessians are positive semi-definite already.
    for_each_friction(
      s, t, request.order, [&](const Pair &pair, const auto &b) {
        request.take(stencil(pair, held), b, counted_here(pair), false);
      });
    return touching;
  }

  template <int dim>
  double
  SelfContact<dim>::largest_feasible_step(const VectorType &u,
                                          const VectorType &direction,
                                          const double) const
  {
    const auto                         scope = timed_section(timer, "contact");
    const State                        s     = state(u, &direction, d_hat);
    const std::vector<Point<dim>>     &x     = s.x;
    const std::vector<Tensor<1, dim>> &p     = s.p;
    const std::vector<Pair>            pairs = candidates(boxes(x, &p, d_hat));
    Stopwatch                          watch(spent.ccd);
    double                             alpha = 1.;
    for (const Pair &pair : pairs)
      {
        const Coordinates c = coordinates(pair, x);
        Coordinates       q;
        for (unsigned int i = 0; i < n_points; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            q[i * dim + d] = p[pair.v[i]][d];
        alpha = std::min(
          alpha,
          additive_ccd<dim>(c, q, pair.edge_edge, ccd_keep_fraction, alpha)
            .t);
      }
    return Utilities::MPI::min(alpha, comm);
  }

  template <int dim>
  void
  SelfContact<dim>::begin_step(const VectorType &u, const double t_start)
  {
    end_state  = EndStateMap();
    step_start = t_start;
    lagging.begin_step();
    // kappa at a sound operating point for the step to come, from the
    // converged state's smallest distance (BarrierStiffness).
    if (stiffness.adaptive() &&
        stiffness.retarget(measure(u).min_distance / d_hat))
      kappa = stiffness.value();
    owned_start.resize(n_owned);
    for (unsigned int k = 0; k < n_owned; ++k)
      {
        const Vertex &v = vertices[first_owned + k];
        owned_start[k]  = v.X;
        for (unsigned int d = 0; d < dim; ++d)
          owned_start[k][d] += u(v.dofs[d]);
      }
    if (friction > 0.)
      lagged = lag(near_state(u));
  }

  template <int dim>
  std::vector<typename SelfContact<dim>::Lagged>
  SelfContact<dim>::lag(const State &s) const
  {
    std::vector<Lagged> result;
    for_each_active(s.x, 0, [&](const Pair &pair, const auto &) {
      const Coordinates c = coordinates(pair, s.x);
      const PairTerms   terms =
        pair_terms<dim>(c, pair.edge_edge, pair.correction);
      const DistanceCase &k = terms.cases[0];
      Lagged              l;
      l.pair = pair;
      l.beta = closest_point_coefficients<dim>(k, c);
      // n: the closest points' difference sum_i beta_i x_i, normalized.
      l.normal.fill(0.);
      for (unsigned int i = 0; i < n_points; ++i)
        for (unsigned int d = 0; d < dim; ++d)
          l.normal[d] += l.beta[i] * c[i * dim + d];
      double length = 0.;
      for (const double v : l.normal)
        length += v * v;
      length = std::sqrt(length);
      if (!(length > 0.))
        return;
      for (double &v : l.normal)
        v /= length;
      // lambda = -kappa w m b'(d) (the mollifier's value, not its slope).
      double mollifier = 1.;
      if constexpr (dim == 3)
        if (pair.mollifier > 0.)
          {
            const double cs = edge_cross_square(c);
            if (cs < pair.mollifier)
              mollifier = (2. - cs / pair.mollifier) * cs / pair.mollifier;
          }
      // b'(d) of the pair's terms together (the corrections'
      // closest points move with the main one's over a flat boundary).
      l.normal_force = -kappa * pair.weight * mollifier *
                       pair_barrier_slope<dim>(c, terms, d_hat);
      result.push_back(l);
    });
    return result;
  }

  template <int dim>
  template <typename F>
  void
  SelfContact<dim>::for_each_friction(const State       &s,
                                      const double       t,
                                      const unsigned int order,
                                      const F           &f) const
  {
    if (!(friction > 0.) || lagged.empty())
      return;
    Stopwatch    watch(spent.narrow);
    const double eps = friction_smoothing(t);
    if (!(eps > 0.))
      return; // no time has passed: no slip
    for (const Lagged &l : lagged)
      {
        Coordinates x, x0;
        // A vertex that slid out of reach within the step: its pair has
        // left the contact.
        if (!slip_coordinates(l.pair, s, x, x0))
          continue;
        PairBarrier<n_coordinates> b = pair_friction<dim>(
          x, x0, l.beta, l.normal, friction * l.normal_force, eps, order);
        to_solved_state(b, end_state, order);
        f(l.pair, b);
      }
  }

  template <int dim>
  double
  SelfContact<dim>::friction_smoothing(const double t) const
  {
    const double h = end_state.c * (t - std::min(step_start, t));
    return dynamic ? eps_setting * h : eps_setting;
  }

  template <int dim>
  bool
  SelfContact<dim>::slip_coordinates(const Pair  &pair,
                                     const State &s,
                                     Coordinates &x,
                                     Coordinates &x0) const
  {
    for (unsigned int i = 0; i < n_points; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        {
          x[i * dim + d]  = s.x[pair.v[i]][d];
          x0[i * dim + d] = s.x0[pair.v[i]][d];
          if (std::isnan(x[i * dim + d]) || std::isnan(x0[i * dim + d]))
            return false;
        }
    return true;
  }

  template <int dim>
  LaggedUpdate
  SelfContact<dim>::update_lagged(const VectorType &u,
                                  const double      t,
                                  const LagMoment moment,
                                  const double    unbalanced_force)
  {
    // Not at the dynamics guess: its pairs are not the answer's (taken
    // there, the block sliding on a block of tests/self_contact.cc
    // decelerated at 5.24 against mu g = 5).
    if (!(friction > 0.) || !lagging.may_update() ||
        moment == LagMoment::predicted)
      return LaggedUpdate::unchanged;
    const auto          scope = timed_section(timer, "contact");
    const State         s     = near_state(u);
    std::vector<Lagged> next  = lag(s);
    const double        eps   = friction_smoothing(t);
    // Each pair's change of normal force (pairs that appear or disappear
    // change from or to 0) and of its friction force on its vertices,
    // counted on the rank that owns its first vertex. The friction forces'
    // changes are summed in squares pair by pair, not assembled per vertex
    // as the obstacles' are: pairs that share a vertex (a hand-over from a
    // point-edge to a point-point pair) do not cancel, and the trigger is
    // the stricter for it.
    std::map<std::array<unsigned int, n_points>, double> before;
    for (const Lagged &l : lagged)
      before[l.pair.v] = l.normal_force;
    FrictionLagging::Change change;
    const auto              add = [&](const Lagged &l, const double from) {
      const unsigned int first = l.pair.v[0];
      if (first < first_owned || first >= first_owned + n_owned)
        return;
      const double to = l.normal_force;
      change.add_normal_force(from, to);
      Coordinates x, x0;
      if (!lagging.needs_friction_change() || !(eps > 0.) ||
          !slip_coordinates(l.pair, s, x, x0))
        return;
      const PairBarrier<n_coordinates> b = pair_friction<dim>(
        x, x0, l.beta, l.normal, friction * (to - from), eps, 1);
      for (const double g : b.gradient)
        change.friction_squared += g * g;
    };
    for (const Lagged &l : next)
      {
        auto it = before.find(l.pair.v);
        add(l, it == before.end() ? 0. : it->second);
        if (it != before.end())
          before.erase(it);
      }
    for (const Lagged &l : lagged)
      if (before.count(l.pair.v) > 0)
        {
          Lagged gone       = l;
          gone.normal_force = 0.;
          add(gone, l.normal_force);
        }
    return lagging.take_if_changed(
      change, {moment, unbalanced_force}, comm, lagged, next);
  }

  template <int dim>
  bool
  SelfContact<dim>::needs_new_couplings(const VectorType &u, const double)
  {
    const auto                    scope = timed_section(timer, "contact");
    const std::vector<Point<dim>> x =
      state(u, nullptr, coupling_reach * d_hat).x;
    bool       grew  = false;
    const auto check = [&](const Pair &pair) {
      for (const unsigned int a : pair.v)
        if (vertices[a].owner == rank)
          for (const unsigned int b : pair.v)
            grew = grew || (a != b && !reserved.count({a, b}));
    };
    for_each_active(x, 0, [&](const Pair &pair, const auto &) { check(pair); });
    // Friction's lagged pairs write their couplings too.
    for (const Lagged &l : lagged)
      if (friction > 0.)
        check(l.pair);
    if (Utilities::MPI::max(grew ? 1 : 0, comm) == 0)
      return false;
    // Reserve the couplings of every pair within coupling_reach d_hat.
    const auto reserve = [&](const Pair &pair) {
      for (const unsigned int a : pair.v)
        if (vertices[a].owner == rank)
          for (const unsigned int b : pair.v)
            if (a != b)
              reserved.insert({a, b});
    };
    for (const Pair &pair :
         candidates(boxes(x, nullptr, coupling_reach * d_hat)))
      reserve(pair);
    for (const Lagged &l : lagged)
      if (friction > 0.)
        reserve(l.pair);
    ++spent.sparsity_rebuilds;
    return true;
  }

  template <int dim>
  void
  SelfContact<dim>::add_couplings(DynamicSparsityPattern &pattern) const
  {
    for (const auto &[a, b] : reserved)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          pattern.add(vertices[a].dofs[i], vertices[b].dofs[j]);
  }

  template <int dim>
  ContactMeasures
  SelfContact<dim>::measure(const VectorType &u) const
  {
    double       closest = d_hat;
    unsigned int active  = 0;
    for_each_active(
      near_state(u).x,
      0,
      [&](const Pair &pair, const auto &) {
        active += counted_here(pair) ? 1 : 0;
      },
      &closest);
    ContactMeasures m;
    m.set_pairs(closest, active, comm);
    return m;
  }

  template class SelfContact<2>;
  template class SelfContact<3>;
} // namespace hyperelastic
