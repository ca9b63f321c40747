// The barrier contact of the boundary with itself: gathering the boundary,
// broad phase, pair barriers, assembly and continuous collision detection.
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/numerics/rtree.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/contact/barrier.h>
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
    /// (end-state map c, force weight w; SteppedTerm::set_end_state_map) from
    /// the pair's barrier @p b at x_end: energy w / c, gradient w, Hessian
    /// (@p order 2) w c times those.
    template <std::size_t n>
    void
    to_solved_state(PairBarrier<n>    &b,
                    const double       c,
                    const double       w,
                    const unsigned int order)
    {
      b.energy *= w / c;
      for (double &g : b.gradient)
        g *= w;
      if (order == 2)
        for (auto &row : b.hessian)
          for (double &v : row)
            v *= w * c;
    }

    /// Adds the time since construction to a sum.
    class Stopwatch
    {
    public:
      explicit Stopwatch(double &sum)
          : sum(sum)
      {
      }
      ~Stopwatch()
      {
        sum += timer.wall_time();
      }

    private:
      double &sum;
      Timer   timer;
    };
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
      , max_lagging_updates(parameters.friction_lagging_updates)
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
    std::map<types::global_dof_index, unsigned int> index;
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
            index.emplace(v.dofs[0], vertices.size());
            vertices.push_back(v);
          }
        if (r == rank)
          n_owned = vertices.size() - first_owned;
      }

    // The faces, and their measures shared by their vertices (edges: a
    // third of each adjacent triangle).
    const std::vector<std::vector<types::global_dof_index>> all_faces =
      Utilities::MPI::all_gather(comm, my_faces);
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

    // d_hat and kappa as for the obstacles.
    Point<dim> lower = vertices.empty() ? Point<dim>() : vertices[0].X,
               upper = lower;
    for (const Vertex &v : vertices)
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::min(lower[d], v.X[d]);
          upper[d] = std::max(upper[d], v.X[d]);
        }
    d_hat = parameters.barrier_distance > 0. ? parameters.barrier_distance
                                             : 1e-3 * lower.distance(upper);
    kappa = parameters.barrier_stiffness > 0.
              ? parameters.barrier_stiffness
              : (moduli.lambda + 2. * moduli.mu) / d_hat;
    // Friction's smoothing as for the obstacles.
    eps_setting = parameters.friction_smoothing > 0.
                    ? parameters.friction_smoothing
                    : (dynamic ? d_hat : 0.1 * d_hat);

    // The start: no two primitives within d_hat (their barrier would push
    // them apart before any load).
    std::vector<Point<dim>> X(vertices.size());
    for (unsigned int k = 0; k < vertices.size(); ++k)
      X[k] = vertices[k].X;
    double closest = std::numeric_limits<double>::infinity();
    Pair   worst;
    for (const Pair &pair : candidates(boxes(X, nullptr, d_hat)))
      {
        const Coordinates x = coordinates(pair, X);
        const double      d = std::sqrt(
          squared_distance<dim>(classify_pair<dim>(x, pair.edge_edge), x));
        if (d < closest)
          closest = d, worst = pair;
      }
    const double global_closest = Utilities::MPI::min(closest, comm);
    if (global_closest < d_hat)
      {
        const unsigned int holder =
          Utilities::MPI::min(closest == global_closest
                                ? rank
                                : Utilities::MPI::n_mpi_processes(comm),
                              comm);
        std::string message;
        if (rank == holder)
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
              << " (they would repel each other before any load): set "
                 "'Contact/Barrier distance' below "
              << global_closest << " or refine the mesh there";
            message = s.str();
          }
        throw InputError(Utilities::MPI::broadcast(comm, message, holder));
      }
  }

  template <int dim>
  SelfContact<dim>::~SelfContact() = default;

  template <int dim>
  std::vector<double>
  SelfContact<dim>::exchange(const SendLists           &send,
                             const std::vector<double> &owned_values,
                             const unsigned int         m) const
  {
    Stopwatch           watch(spent.exchange);
    std::vector<double> all(vertices.size() * m,
                            std::numeric_limits<double>::quiet_NaN());
    std::copy(owned_values.begin(),
              owned_values.end(),
              all.begin() + std::size_t(first_owned) * m);
    std::map<unsigned int, std::vector<double>> out;
    for (const auto &[q, list] : send)
      {
        std::vector<double> &data = out[q];
        for (const unsigned int k : list)
          {
            data.push_back(first_owned + k);
            data.insert(data.end(),
                        owned_values.begin() + std::size_t(k) * m,
                        owned_values.begin() + std::size_t(k + 1) * m);
          }
      }
    for (const auto &[q, data] : Utilities::MPI::some_to_some(comm, out))
      {
        spent.received += data.size();
        for (std::size_t i = 0; i < data.size(); i += m + 1)
          std::copy(data.begin() + i + 1,
                    data.begin() + i + 1 + m,
                    all.begin() + std::size_t(data[i]) * m);
      }
    return all;
  }

  template <int dim>
  typename SelfContact<dim>::State
  SelfContact<dim>::state(const VectorType &u,
                          const VectorType *direction,
                          const double      reach) const
  {
    // The owned vertices' positions (end-state map applied), motions and
    // (friction) start positions.
    const bool          with_start = friction > 0. && !owned_start.empty();
    const unsigned int  start_at   = direction ? 2 * dim : dim;
    const unsigned int  m          = start_at + (with_start ? dim : 0);
    std::vector<double> owned(std::size_t(n_owned) * m);
    for (unsigned int k = 0; k < n_owned; ++k)
      {
        const Vertex &v = vertices[first_owned + k];
        Point<dim>    x = v.X;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] += u(v.dofs[d]);
        if (end_factor != 1.)
          x = owned_start[k] + end_factor * (x - owned_start[k]);
        for (unsigned int d = 0; d < dim; ++d)
          {
            owned[k * m + d] = x[d];
            if (direction)
              owned[k * m + dim + d] = end_factor * (*direction)(v.dofs[d]);
            if (with_start)
              owned[k * m + start_at + d] = owned_start[k][d];
          }
      }
    // This rank's region: the box of its vertices (swept along the motion),
    // inflated by the reach and twice the longest boundary edge, so that
    // every primitive within reach of its own arrives whole; doubled while
    // a primitive with an owned vertex is incomplete (stretched edges).
    State  s;
    double margin = reach + 2. * longest_edge;
    for (unsigned int attempt = 0;; ++attempt)
      {
        std::vector<std::array<double, 2 * dim>> box(n_owned);
        std::array<double, 2 * dim>              region;
        for (unsigned int d = 0; d < dim; ++d)
          {
            region[d]       = std::numeric_limits<double>::max();
            region[dim + d] = -std::numeric_limits<double>::max();
          }
        for (unsigned int k = 0; k < n_owned; ++k)
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double a  = owned[k * m + d],
                           b  = a + (direction ? owned[k * m + dim + d] : 0.);
              box[k][d]       = std::min(a, b);
              box[k][dim + d] = std::max(a, b);
              region[d]       = std::min(region[d], box[k][d] - margin);
              region[dim + d] =
                std::max(region[dim + d], box[k][dim + d] + margin);
            }
        {
          Stopwatch  watch(spent.exchange);
          const auto regions = Utilities::MPI::all_gather(comm, region);
          s.send.clear();
          for (unsigned int q = 0; q < regions.size(); ++q)
            if (q != rank)
              for (unsigned int k = 0; k < n_owned; ++k)
                {
                  bool inside = true;
                  for (unsigned int d = 0; d < dim && inside; ++d)
                    inside = box[k][dim + d] >= regions[q][d] &&
                             box[k][d] <= regions[q][dim + d];
                  if (inside)
                    s.send[q].push_back(k);
                }
        }
        const std::vector<double> all = exchange(s.send, owned, m);
        s.x.assign(vertices.size(), Point<dim>());
        s.p.assign(direction ? vertices.size() : 0, Tensor<1, dim>());
        s.x0.assign(with_start ? vertices.size() : 0, Point<dim>());
        for (unsigned int k = 0; k < vertices.size(); ++k)
          for (unsigned int d = 0; d < dim; ++d)
            {
              s.x[k][d] = all[std::size_t(k) * m + d];
              if (direction)
                s.p[k][d] = all[std::size_t(k) * m + dim + d];
              if (with_start)
                s.x0[k][d] = all[std::size_t(k) * m + start_at + d];
            }
        bool       complete = true;
        const auto check    = [&](const auto &list) {
          bool mine = false, whole = true;
          for (const unsigned int v : list)
            {
              mine  = mine || vertices[v].owner == rank;
              whole = whole && !std::isnan(s.x[v][0]);
            }
          complete = complete && (!mine || whole);
        };
        for (const auto &f : faces)
          check(f);
        if (Utilities::MPI::min(complete ? 1 : 0, comm) == 1 || attempt > 20)
          break;
        margin *= 2.;
      }
    return s;
  }

  template <int dim>
  typename SelfContact<dim>::Boxes
  SelfContact<dim>::boxes(const std::vector<Point<dim>>     &x,
                          const std::vector<Tensor<1, dim>> *p,
                          const double                       margin) const
  {
    Stopwatch watch(spent.broad);
    Boxes     b;
    b.vertex.reserve(vertices.size());
    for (unsigned int k = 0; k < vertices.size(); ++k)
      {
        BoundingBox<dim> box(std::make_pair(x[k], x[k]));
        if (p)
          {
            const Point<dim> end = x[k] + (*p)[k];
            box.merge_with(BoundingBox<dim>(std::make_pair(end, end)));
          }
        box.extend(margin);
        b.vertex.push_back(box);
      }
    const auto merged = [&](const auto &indices) {
      BoundingBox<dim> box = b.vertex[indices[0]];
      for (const unsigned int v : indices)
        box.merge_with(b.vertex[v]);
      return box;
    };
    for (const auto &f : faces)
      b.face.push_back(merged(f));
    for (const auto &e : edges)
      b.edge.push_back(merged(e));
    return b;
  }

  template <int dim>
  std::vector<typename SelfContact<dim>::Pair>
  SelfContact<dim>::candidates(const Boxes &b) const
  {
    Stopwatch watch(spent.broad);
    using Entry        = std::pair<BoundingBox<dim>, unsigned int>;
    const auto is_mine = [&](const unsigned int v) {
      return v - first_owned < n_owned;
    };
    const auto any_mine = [&](const auto &list) {
      return std::any_of(list.begin(), list.end(), is_mine);
    };
    const auto shares = [](const auto &list, const unsigned int v) {
      return std::find(list.begin(), list.end(), v) != list.end();
    };
    // The vertices this rank has not received (far from its own) are NaN.
    const auto known = [&](const unsigned int v) {
      return !std::isnan(b.vertex[v].get_boundary_points().first[0]);
    };
    const auto all_known = [&](const auto &list) {
      return std::all_of(list.begin(), list.end(), known);
    };
    std::vector<Pair> result;

    // Vertex-face pairs: the owned vertices against every face, and every
    // vertex owned elsewhere against the faces with an owned vertex.
    {
      std::vector<Entry> entries;
      for (unsigned int f = 0; f < faces.size(); ++f)
        if (all_known(faces[f]))
          entries.emplace_back(b.face[f], f);
      const RTree<Entry> tree = pack_rtree(entries);
      std::vector<Entry> found;
      for (unsigned int v = 0; v < vertices.size(); ++v)
        {
          if (!known(v))
            continue;
          found.clear();
          tree.query(boost::geometry::index::intersects(b.vertex[v]),
                     std::back_inserter(found));
          for (const auto &[box, f] : found)
            {
              const auto &face = faces[f];
              if (shares(face, v) || !(is_mine(v) || any_mine(face)))
                continue;
              Pair pair;
              pair.v[0] = v;
              for (unsigned int d = 0; d < dim; ++d)
                pair.v[d + 1] = face[d];
              pair.weight = vertices[v].area;
              result.push_back(pair);
            }
        }
    }
    // Edge-edge pairs (3D), each once: from the lower edge of two with
    // owned vertices.
    if constexpr (dim == 3)
      {
        std::vector<Entry> entries;
        for (unsigned int e = 0; e < edges.size(); ++e)
          if (all_known(edges[e]))
            entries.emplace_back(b.edge[e], e);
        const RTree<Entry> tree = pack_rtree(entries);
        std::vector<Entry> found;
        for (unsigned int e = 0; e < edges.size(); ++e)
          {
            if (!any_mine(edges[e]) || !all_known(edges[e]))
              continue;
            found.clear();
            tree.query(boost::geometry::index::intersects(b.edge[e]),
                       std::back_inserter(found));
            for (const auto &[box, o] : found)
              {
                if (o == e || shares(edges[o], edges[e][0]) ||
                    shares(edges[o], edges[e][1]) ||
                    (o < e && any_mine(edges[o])))
                  continue;
                Pair pair;
                pair.v = {{edges[e][0], edges[e][1], edges[o][0], edges[o][1]}};
                pair.edge_edge = true;
                pair.weight    = 0.5 * (edge_area[e] + edge_area[o]);
                pair.mollifier = 1e-3 * edge_length2[e] * edge_length2[o];
                result.push_back(pair);
              }
          }
      }
    return result;
  }

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
        const Coordinates          c = coordinates(pair, x);
        const DistanceCase         k = classify_pair<dim>(c, pair.edge_edge);
        PairBarrier<n_coordinates> b = pair_barrier<dim>(
          c, k, d_hat, kappa * pair.weight, pair.mollifier, order);
        closest = std::min(closest, b.distance);
        if (!(b.distance > 0.))
          {
            touching = true;
            continue;
          }
        if (b.distance >= d_hat)
          continue;
        to_solved_state(b, end_factor, force_weight, order);
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
    end_factor      = 1.;
    force_weight    = 1.;
    step_start      = t_start;
    lagging_updates = 0;
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
    for_each_active(s.x, 0, [&](const Pair &pair, const auto &b) {
      const Coordinates  c = coordinates(pair, s.x);
      const DistanceCase k = classify_pair<dim>(c, pair.edge_edge);
      Lagged             l;
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
      l.normal_force = -kappa * pair.weight * mollifier *
                       barrier(b.distance, d_hat).derivative;
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
    const double h   = end_factor * (t - std::min(step_start, t));
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
        to_solved_state(b, end_factor, force_weight, order);
        f(l.pair, b);
      }
  }

  template <int dim>
  bool
  SelfContact<dim>::update_lagged(const VectorType &u, const double)
  {
    if (!(friction > 0.) || lagging_updates >= max_lagging_updates)
      return false;
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
    change  = Utilities::MPI::max(change, comm);
    largest = Utilities::MPI::max(largest, comm);
    if (!(change > 1e-3 * largest))
      return false;
    lagged = std::move(next);
    ++lagging_updates;
    return true;
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
  SelfContact<dim>::summarize(const VectorType &u, StepSummary<dim> &s) const
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
    closest               = Utilities::MPI::min(closest, comm);
    const double n_active = Utilities::MPI::sum(active, comm);
    bool         had_min = false, had_count = false;
    for (SummaryColumn &c : s.more)
      if (c.name == "contact_min_distance")
        c.value = std::min(c.value, closest), had_min = true;
      else if (c.name == "contact_active_pairs")
        c.value += n_active, had_count = true;
    if (!had_min)
      s.more.push_back({"contact_min_distance", closest});
    if (!had_count)
      s.more.push_back({"contact_active_pairs", n_active});
  }

  template class SelfContact<2>;
  template class SelfContact<3>;
} // namespace hyperelastic
