// The barrier contact of the boundary with itself: gathering the boundary,
// broad phase, pair barriers, assembly and continuous collision detection.
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/numerics/rtree.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/contact/barrier.h>
#include <hyperelastic/contact/barrier_settings.h>
#include <hyperelastic/contact/collision_detection.h>
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
    /// Each pair keeps a tenth of its distance along a Newton direction.
    constexpr double keep_fraction = 0.1;
    /// The tangent's sparsity holds the couplings of the pairs within this
    /// many d_hat, so that a few iterates more fit in before it grows.
    constexpr double coupling_reach = 4.;

    /// The potential w V(x_end) / c of a pair in the step's solved state
    /// (the end-state map @p map; SteppedTerm::set_end_state_map) from the
    /// pair's barrier @p b at x_end: energy w / c, gradient w, Hessian
    /// (@p order 2) w c times those.
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
      , lagging(parameters.friction_lagging_updates)
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
    shared_settings = barrier_settings(parameters,
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
  std::vector<types::global_dof_index>
  SelfContact<dim>::gather_vertices(const DoFHandler<dim> &dof_handler)
  {
    // The owned boundary vertices (ghost cells too: an owned vertex may lie
    // only on a neighbour's boundary face) and the boundary faces of the
    // owned cells, as first dofs; the faces where the ghost layer ends are
    // not the body's boundary.
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    std::map<types::global_dof_index, std::vector<double>> mine;
    std::vector<types::global_dof_index>                   my_faces;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() ||
                face->boundary_id() == partition_edge_boundary_id)
              continue;
            for (unsigned int v = 0; v < face->n_vertices(); ++v)
              {
                const types::global_dof_index first =
                  face->vertex_dof_index(v, 0);
                if (cell->is_locally_owned())
                  my_faces.push_back(first);
                if (!owned.is_element(first) || mine.count(first))
                  continue;
                std::vector<double> &data = mine[first];
                for (unsigned int d = 0; d < dim; ++d)
                  data.push_back(face->vertex(v)[d]);
                for (unsigned int d = 0; d < dim; ++d)
                  data.push_back(face->vertex_dof_index(v, d));
              }
          }
      }
    std::vector<double> packed;
    for (const auto &[first, data] : mine)
      packed.insert(packed.end(), data.begin(), data.end());
    const std::vector<std::vector<double>> all_vertices =
      Utilities::MPI::all_gather(comm, packed);
    for (unsigned int r = 0; r < all_vertices.size(); ++r)
      {
        if (r == rank)
          first_owned = vertices.size();
        for (std::size_t i = 0; i < all_vertices[r].size(); i += 2 * dim)
          {
            Vertex v;
            for (unsigned int d = 0; d < dim; ++d)
              {
                v.X[d]    = all_vertices[r][i + d];
                v.dofs[d] = static_cast<types::global_dof_index>(
                  all_vertices[r][i + dim + d]);
              }
            v.owner = r;
            vertices.push_back(v);
          }
        if (r == rank)
          n_owned = vertices.size() - first_owned;
      }
    return my_faces;
  }

  template <int dim>
  void
  SelfContact<dim>::build_faces(
    const std::vector<types::global_dof_index> &my_faces)
  {
    // The faces, and their measures shared by their vertices (edges: a
    // third of each adjacent triangle).
    const std::vector<std::vector<types::global_dof_index>> all_faces =
      Utilities::MPI::all_gather(comm, my_faces);
    std::map<types::global_dof_index, unsigned int> index;
    for (unsigned int k = 0; k < vertices.size(); ++k)
      index.emplace(vertices[k].dofs[0], k);
    std::map<std::array<unsigned int, 2>, unsigned int> edge_index;
    for (const auto &list : all_faces)
      for (std::size_t i = 0; i < list.size(); i += dim)
        {
          std::array<unsigned int, dim> face;
          for (unsigned int d = 0; d < dim; ++d)
            face[d] = index.at(list[i + d]);
          double measure = vertices[face[0]].X.distance(vertices[face[1]].X);
          if constexpr (dim == 3)
            measure =
              0.5 * cross_product_3d(vertices[face[1]].X - vertices[face[0]].X,
                                     vertices[face[2]].X - vertices[face[0]].X)
                      .norm();
          for (const unsigned int v : face)
            vertices[v].area += measure / dim;
          for (unsigned int k = 0; k < dim; ++k)
            longest_edge = std::max(longest_edge,
                                    vertices[face[k]].X.distance(
                                      vertices[face[(k + 1) % dim]].X));
          faces.push_back(face);
          if constexpr (dim == 3)
            for (unsigned int k = 0; k < 3; ++k)
              {
                std::array<unsigned int, 2> e = {
                  {std::min(face[k], face[(k + 1) % 3]),
                   std::max(face[k], face[(k + 1) % 3])}};
                auto it = edge_index.find(e);
                if (it == edge_index.end())
                  {
                    it = edge_index.emplace(e, edges.size()).first;
                    edges.push_back(e);
                    edge_area.push_back(0.);
                    edge_length2.push_back(
                      vertices[e[0]].X.distance_square(vertices[e[1]].X));
                  }
                edge_area[it->second] += measure / 3.;
              }
        }
    std::vector<std::array<double, dim>> points(vertices.size());
    for (unsigned int k = 0; k < vertices.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        points[k][d] = vertices[k].X[d];
    incidence = BoundaryIncidence<dim>(faces, points);
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
          << " near (" << vertices[worst.v[0]].X << ") are "
          << global_closest
          << " apart in the reference configuration, closer than the "
             "barrier distance d_hat = "
          << d_hat
          << " (they would repel each other before any load): ";
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
    bool                     touching = false;
    double                   closest  = d_hat;
    for (const Pair &pair : pairs)
      {
        const Coordinates c = coordinates(pair, x);
        if (pair.weight == 0.)
          {
            // A pair kept for the feasible step only (two edges not both
            // sharp: contact/duplicate_counting.h).
            const double d = std::sqrt(std::max(
              squared_distance<dim>(classify_pair<dim>(c, pair.edge_edge), c),
              0.));
            closest        = std::min(closest, d);
            touching       = touching || !(d > 0.);
            continue;
          }
        PairBarrier<n_coordinates> b =
          pair_barrier<dim>(c,
                            pair_terms<dim>(c, pair.edge_edge, pair.correction),
                            d_hat,
                            kappa * pair.weight,
                            pair.mollifier,
                            order);
        closest = std::min(closest, b.distance);
        if (!(b.distance > 0.))
          {
            touching = true;
            continue;
          }
        if (b.distance >= d_hat)
          continue;
        to_solved_state(b, end_state, order);
        f(pair, b);
      }
    if (min_distance)
      *min_distance = closest;
    return touching;
  }

  template <int dim>
  void
  SelfContact<dim>::add_pair_forces(const VectorType &u,
                                    const double      t,
                                    VectorType       &forces) const
  {
    std::vector<types::global_dof_index> rows;
    std::vector<double>                  values;
    const auto add = [&](const Pair &pair, const auto &b) {
      for (unsigned int i = 0; i < n_points; ++i)
        if (vertices[pair.v[i]].owner == rank)
          for (unsigned int d = 0; d < dim; ++d)
            {
              rows.push_back(vertices[pair.v[i]].dofs[d]);
              values.push_back(-b.gradient[i * dim + d]);
            }
    };
    const State s        = near_state(u);
    const bool  touching = for_each_active(s.x, 1, add);
    for_each_friction(s, t, 1, add);
    // On every rank, even without contact: the first add after an insert
    // makes Trilinos assemble the vector, a collective operation.
    forces.add(rows, values);
    if (Utilities::MPI::max(touching ? 1 : 0, comm) != 0)
      throw ConvergenceFailure(
        "two parts of the boundary touch (self contact)");
  }

  template <int dim>
  ForceSize
  SelfContact<dim>::add_forces(const VectorType &u,
                               const double      t,
                               VectorType       &forces) const
  {
    const auto scope = timed_section(timer, "contact");
    add_pair_forces(u, t, forces);
    return {};
  }

  template <int dim>
  void
  SelfContact<dim>::contact_forces(const VectorType &u,
                                   const double      t,
                                   VectorType       &forces) const
  {
    add_pair_forces(u, t, forces);
  }

  template <int dim>
  void
  SelfContact<dim>::add_stiffness(const VectorType                &u,
                                  const double                     t,
                                  const TangentProjection          projection,
                                  const AffineConstraints<double> &constraints,
                                  MatrixType                      &matrix,
                                  VectorType &rhs) const
  {
    const auto scope = timed_section(timer, "contact");
    // Each pair's Hessian exact, or projected to positive semi-definite
    // for Newton's projected tangent.
    const bool project_pairs = projection == TangentProjection::every_point;
    // The prescribed value of every boundary dof near here (NaN where
    // free), from its owner: a pair's far vertices may be constrained on
    // another rank.
    const State         s = near_state(u);
    std::vector<double> owned(std::size_t(n_owned) * dim);
    for (unsigned int k = 0; k < n_owned; ++k)
      for (unsigned int d = 0; d < dim; ++d)
        {
          const types::global_dof_index dof = vertices[first_owned + k].dofs[d];
          owned[k * dim + d]                = constraints.is_constrained(dof)
                                                ? constraints.get_inhomogeneity(dof)
                                                : std::numeric_limits<double>::quiet_NaN();
        }
    const std::vector<double> prescribed = exchange(s.send, owned, dim);
    std::vector<types::global_dof_index> rhs_rows;
    std::vector<double>                  rhs_values;
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    stiff_rows.clear();
    const auto add = [&](const Pair &pair, const auto &b, const bool project) {
      const SmallMatrix<n_coordinates> K =
        project ? positive_semidefinite_part<n_coordinates>(b.hessian)
                : b.hessian;
      for (unsigned int i = 0; i < n_points; ++i)
        {
          const Vertex &row_vertex = vertices[pair.v[i]];
          if (row_vertex.owner != rank)
            continue;
          for (unsigned int r = 0; r < dim; ++r)
            {
              if (!std::isnan(prescribed[pair.v[i] * dim + r]))
                continue; // a constrained row reads d du_r = d g_r
              stiff_rows.push_back(row_vertex.dofs[r]);
              columns.clear();
              values.clear();
              double moved = 0.;
              for (unsigned int j = 0; j < n_points; ++j)
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    const double k = K[i * dim + r][j * dim + c];
                    const double g = prescribed[pair.v[j] * dim + c];
                    if (std::isnan(g))
                      {
                        columns.push_back(vertices[pair.v[j]].dofs[c]);
                        values.push_back(k);
                      }
                    else
                      moved += k * g;
                  }
              matrix.add(row_vertex.dofs[r],
                         columns.size(),
                         columns.data(),
                         values.data());
              if (moved != 0.)
                {
                  rhs_rows.push_back(row_vertex.dofs[r]);
                  rhs_values.push_back(-moved);
                }
            }
        }
    };
    for_each_active(s.x, 2, [&](const Pair &pair, const auto &b) {
      add(pair, b, project_pairs);
    });
    // Friction's pair Hessians are positive semi-definite already.
    for_each_friction(s, t, 2, [&](const Pair &pair, const auto &b) {
      add(pair, b, false);
    });
    rhs.add(rhs_rows, rhs_values);
  }

  template <int dim>
  double
  SelfContact<dim>::energy(const VectorType &u, const double t) const
  {
    const auto scope = timed_section(timer, "contact");
    double     sum   = 0.;
    const auto add   = [&](const Pair &pair, const auto &b) {
      if (counted_here(pair))
        sum += b.energy;
    };
    const State s        = near_state(u);
    const bool  touching = for_each_active(s.x, 0, add);
    for_each_friction(s, t, 0, add);
    if (touching)
      sum = std::numeric_limits<double>::infinity();
    return Utilities::MPI::sum(sum, comm);
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
          additive_ccd<dim>(c, q, pair.edge_edge, keep_fraction, alpha).t);
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
    const double h   = end_state.c * (t - std::min(step_start, t));
    const double eps = dynamic ? eps_setting * h : eps_setting;
    if (!(eps > 0.))
      return; // no time has passed: no slip
    for (const Lagged &l : lagged)
      {
        Coordinates x, x0;
        bool        known = true;
        for (unsigned int i = 0; i < n_points; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            {
              x[i * dim + d]  = s.x[l.pair.v[i]][d];
              x0[i * dim + d] = s.x0[l.pair.v[i]][d];
              known           = known && !std::isnan(x[i * dim + d]) &&
                      !std::isnan(x0[i * dim + d]);
            }
        // A vertex that slid out of reach within the step: its pair has
        // left the contact.
        if (!known)
          continue;
        PairBarrier<n_coordinates> b = pair_friction<dim>(
          x, x0, l.beta, l.normal, friction * l.normal_force, eps, order);
        to_solved_state(b, end_state, order);
        f(l.pair, b);
      }
  }

  template <int dim>
  LaggedUpdate
  SelfContact<dim>::update_lagged(const VectorType &u,
                                  const double,
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
    std::vector<Lagged> next  = lag(near_state(u));
    // The largest change of a pair's normal force (pairs that appear or
    // disappear change from or to 0).
    std::map<std::array<unsigned int, n_points>, double> before;
    for (const Lagged &l : lagged)
      before[l.pair.v] = l.normal_force;
    double change = 0., largest = 0.;
    for (const Lagged &l : next)
      {
        largest = std::max(largest, l.normal_force);
        auto it = before.find(l.pair.v);
        change  = std::max(change,
                          std::abs(l.normal_force -
                                   (it == before.end() ? 0. : it->second)));
        if (it != before.end())
          before.erase(it);
      }
    for (const auto &[pair, force] : before)
      change = std::max(change, force);
    return lagging.take_if_changed(
      change, largest, {moment, unbalanced_force}, comm, lagged, next);
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
  void
  SelfContact<dim>::add_stiff_dofs(IndexSet &dofs) const
  {
    for (const types::global_dof_index dof : stiff_rows)
      dofs.add_index(dof);
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
    m.min_distance = Utilities::MPI::min(closest, comm);
    m.active_pairs = Utilities::MPI::sum(active, comm);
    return m;
  }

  template class SelfContact<2>;
  template class SelfContact<3>;
} // namespace hyperelastic
