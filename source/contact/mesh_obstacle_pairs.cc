// The corner-face and edge-edge pairs between meshed obstacles and the
// body's boundary: the obstacles' sharp features, the body's boundary as
// this rank sees it, broad phase, pair barriers, assembly and CCD.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/rtree.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/contact/barrier_settings.h>
#include <hyperelastic/contact/collision_detection.h>
#include <hyperelastic/contact/mesh_obstacle_pairs.h>
#include <hyperelastic/contact/obstacle_surface.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/mesh/mesh_distribution.h>

#include <algorithm>
#include <iterator>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// Each pair keeps a tenth of its distance along a Newton direction.
    constexpr double keep_fraction = 0.1;

    template <int dim>
    double
    element_measure(const Point<dim> &a, const Point<dim> &b, const Point<dim> *c)
    {
      if constexpr (dim == 3)
        return 0.5 * cross_product_3d(b - a, *c - a).norm();
      (void)c;
      return a.distance(b);
    }
  } // namespace

  template <int dim>
  bool
  MeshObstaclePairs<dim>::wanted(const ContactParameters &parameters)
  {
    if (!parameters.meshed_obstacle_corners)
      return false;
    return std::any_of(parameters.obstacles.begin(),
                       parameters.obstacles.end(),
                       [](const ObstacleParameters &o) {
                         return o.type == ObstacleType::mesh;
                       });
  }

  template <int dim>
  MeshObstaclePairs<dim>::MeshObstaclePairs(
    const ContactParameters                                        &parameters,
    const std::map<std::string, double>                            &constants,
    const DoFHandler<dim>                                          &dof_handler,
    const std::vector<std::shared_ptr<const ObstacleSurface<dim>>> &surfaces,
    const BarrierSettings                                          &settings)
      : comm(dof_handler.get_communicator())
      , my_subdomain(dof_handler.get_triangulation().locally_owned_subdomain())
      , d_hat(settings.d_hat)
      , kappa(settings.kappa)
      , stiffness(settings.kappa, settings.adaptive_kappa)
  {
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    ghost_buffer.reinit(dof_handler.locally_owned_dofs(), relevant, comm);
    for (const ObstacleParameters &o : parameters.obstacles)
      if (o.type == ObstacleType::mesh)
        motions.push_back(parse_vector_function<dim>(o.motion,
                                                     constants,
                                                     o.subsection + "/Motion"));
    find_features(parameters, surfaces);
    gather_body(dof_handler);
    check_start();
  }

  template <int dim>
  MeshObstaclePairs<dim>::~MeshObstaclePairs() = default;

  template <int dim>
  void
  MeshObstaclePairs<dim>::find_features(
    const ContactParameters                                        &parameters,
    const std::vector<std::shared_ptr<const ObstacleSurface<dim>>> &surfaces)
  {
    AssertDimension(surfaces.size(), parameters.obstacles.size());
    for (unsigned int k = 0; k < parameters.obstacles.size(); ++k)
      {
        const ObstacleParameters &o = parameters.obstacles[k];
        if (o.type != ObstacleType::mesh)
          continue;
        Assert(surfaces[k] != nullptr, ExcInternalError());
        const ObstacleSurface<dim> &surface = *surfaces[k];
        const unsigned int m = numbers.size();
        numbers.push_back(o.number);
        sections.push_back(o.subsection);
        // The points where they are at t = 0: the file's coordinates
        // shifted by Point and by the motion at t = 0.
        Tensor<1, dim> shift;
        motions[m]->set_time(0.);
        for (unsigned int d = 0; d < dim; ++d)
          shift[d] = o.point[d] + motions[m]->value(Point<dim>(), d);
        anchors.push_back(Point<dim>() + shift);
        const unsigned int first = obstacle_points.size();
        for (const Point<dim> &p : surface.points())
          {
            obstacle_points.push_back(p + shift);
            point_obstacle.push_back(m);
          }
        const auto &elements = surface.element_vertices();
        const auto  Y        = [&](const unsigned int i) -> const Point<dim> & {
          return obstacle_points[first + i];
        };
        // Every vertex's share of the area; in 3D the edges with their
        // triangles' opposite vertices and their share of the area.
        std::vector<double>                               area(surface.points().size());
        std::map<std::array<unsigned int, 2>, std::vector<unsigned int>> opposite;
        std::map<std::array<unsigned int, 2>, double>     edge_area;
        std::vector<std::vector<unsigned int>>            neighbours(area.size());
        for (const auto &e : elements)
          {
            const double measure =
              element_measure<dim>(Y(e[0]), Y(e[1]), dim == 3 ? &Y(e[dim - 1]) : nullptr);
            for (const unsigned int v : e)
              area[v] += measure / dim;
            if constexpr (dim == 2)
              {
                neighbours[e[0]].push_back(e[1]);
                neighbours[e[1]].push_back(e[0]);
              }
            else
              for (unsigned int k = 0; k < 3; ++k)
                {
                  const std::array<unsigned int, 2> edge = {
                    {std::min(e[k], e[(k + 1) % 3]), std::max(e[k], e[(k + 1) % 3])}};
                  opposite[edge].push_back(e[(k + 2) % 3]);
                  edge_area[edge] += measure / 3.;
                }
          }
        // Sharp: an obstacle vertex whose two segments (2D) are not one
        // straight line, an edge whose two triangles (3D) are not one flat
        // piece (boundary and non-manifold edges are sharp), and the
        // vertices of sharp edges.
        std::vector<bool> sharp(area.size(), false);
        if constexpr (dim == 2)
          for (unsigned int v = 0; v < area.size(); ++v)
            {
              if (neighbours[v].empty())
                continue;
              sharp[v] = true;
              if (neighbours[v].size() == 2)
                {
                  const Tensor<1, 2> a = Y(neighbours[v][0]) - Y(v),
                                     b = Y(neighbours[v][1]) - Y(v);
                  const double cross = a[0] * b[1] - a[1] * b[0];
                  sharp[v] = !(std::abs(cross) <= 1e-10 * a.norm() * b.norm() &&
                               a * b < 0.);
                }
            }
        else
          for (const auto &[edge, others] : opposite)
            {
              bool flat = false;
              if (others.size() == 2)
                {
                  const Point<3>    &a = Y(edge[0]), &b = Y(edge[1]);
                  const Tensor<1, 3> n1 = cross_product_3d(b - a, Y(others[0]) - a),
                                     n2 = cross_product_3d(b - a, Y(others[1]) - a);
                  // One plane, the opposite vertices on either side.
                  flat = cross_product_3d(n1, n2).norm() <=
                           1e-10 * n1.norm() * n2.norm() &&
                         n1 * n2 < 0.;
                }
              if (flat)
                continue;
              Feature ridge;
              ridge.v        = {{first + edge[0], first + edge[1]}};
              ridge.obstacle = m;
              ridge.area     = edge_area[edge];
              ridge.length2  = Y(edge[0]).distance_square(Y(edge[1]));
              ridges.push_back(ridge);
              sharp[edge[0]] = sharp[edge[1]] = true;
            }
        for (unsigned int v = 0; v < area.size(); ++v)
          if (sharp[v])
            {
              Feature corner;
              corner.v        = {{first + v, first + v}};
              corner.obstacle = m;
              corner.area     = area[v];
              corners.push_back(corner);
            }
      }
  }

  template <int dim>
  void
  MeshObstaclePairs<dim>::gather_body(const DoFHandler<dim> &dof_handler)
  {
    // The boundary faces of the owned and ghost cells (the faces where the
    // ghost layer ends are not the body's boundary) that this rank counts
    // (an owned cell's) or that have an owned vertex.
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    std::map<types::global_dof_index, unsigned int> index;
    // 3D: each edge's faces' areas and the lowest subdomain among them.
    std::map<std::array<unsigned int, 2>, std::pair<double, unsigned int>>
      edge_data;
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
            bool any_owned = false;
            for (unsigned int v = 0; v < face->n_vertices(); ++v)
              any_owned = any_owned || owned.is_element(face->vertex_dof_index(v, 0));
            BodyPrimitive<dim> primitive;
            primitive.counted = cell->is_locally_owned();
            for (unsigned int v = 0; v < face->n_vertices(); ++v)
              {
                const types::global_dof_index first = face->vertex_dof_index(v, 0);
                auto it = index.find(first);
                if (it == index.end())
                  {
                    BodyVertex vertex;
                    vertex.X = face->vertex(v);
                    for (unsigned int d = 0; d < dim; ++d)
                      vertex.dofs[d] = face->vertex_dof_index(v, d);
                    vertex.owned = owned.is_element(first);
                    it = index.emplace(first, vertices.size()).first;
                    vertices.push_back(vertex);
                  }
                primitive.v[v] = it->second;
              }
            const auto &p = primitive.v;
            primitive.area =
              element_measure<dim>(vertices[p[0]].X,
                                   vertices[p[1]].X,
                                   dim == 3 ? &vertices[p[dim - 1]].X : nullptr);
            if constexpr (dim == 3)
              for (unsigned int k = 0; k < 3; ++k)
                {
                  const std::array<unsigned int, 2> e = {
                    {std::min(p[k], p[(k + 1) % 3]), std::max(p[k], p[(k + 1) % 3])}};
                  auto it = edge_data.emplace(
                    e, std::make_pair(0., dealii::numbers::invalid_unsigned_int)).first;
                  it->second.first += primitive.area / 3.;
                  it->second.second =
                    std::min(it->second.second,
                             static_cast<unsigned int>(cell->subdomain_id()));
                }
            if (primitive.counted || any_owned)
              faces.push_back(primitive);
          }
      }
    if constexpr (dim == 3)
      for (const auto &[e, data] : edge_data)
        {
          BodyPrimitive<2> edge;
          edge.v       = e;
          edge.counted = data.second == my_subdomain;
          edge.area    = data.first;
          edge.length2 = vertices[e[0]].X.distance_square(vertices[e[1]].X);
          if (edge.counted || vertices[e[0]].owned || vertices[e[1]].owned)
            edges.push_back(edge);
        }
  }

  template <int dim>
  typename MeshObstaclePairs<dim>::Placement
  MeshObstaclePairs<dim>::placement(const unsigned int m,
                                    const double       time) const
  {
    const auto motion = [&](const double s) {
      motions[m]->set_time(s);
      Tensor<1, dim> w;
      for (unsigned int d = 0; d < dim; ++d)
        w[d] = motions[m]->value(Point<dim>(), d);
      return w;
    };
    Placement p;
    p.shift = motion(time) - motion(0.);
    return p;
  }

  template <int dim>
  std::vector<Point<dim>>
  MeshObstaclePairs<dim>::obstacle_at(const double time) const
  {
    std::vector<Placement> where;
    for (unsigned int m = 0; m < motions.size(); ++m)
      where.push_back(placement(m, time));
    std::vector<Point<dim>> y(obstacle_points.size());
    for (unsigned int i = 0; i < y.size(); ++i)
      y[i] = where[point_obstacle[i]](obstacle_points[i]);
    return y;
  }

  template <int dim>
  const VectorType &
  MeshObstaclePairs<dim>::ghosted(const VectorType &v) const
  {
    if (v.has_ghost_elements())
      return v;
    ghost_buffer = v;
    return ghost_buffer;
  }

  template <int dim>
  std::vector<Point<dim>>
  MeshObstaclePairs<dim>::body_at(const VectorType &u_in) const
  {
    const VectorType       &u = ghosted(u_in);
    std::vector<Point<dim>> x(vertices.size());
    for (unsigned int i = 0; i < vertices.size(); ++i)
      {
        x[i] = vertices[i].X;
        for (unsigned int d = 0; d < dim; ++d)
          x[i][d] += u(vertices[i].dofs[d]);
        if (clock.end_state.c != 1.)
          x[i] = clock.end_state.end_position(start_positions[i], x[i]);
      }
    return x;
  }

  template <int dim>
  std::array<int, MeshObstaclePairs<dim>::n_points>
  MeshObstaclePairs<dim>::body_points(const Pair &pair) const
  {
    std::array<int, n_points> b;
    b.fill(-1);
    if (pair.edge_edge)
      {
        b[0] = edges[pair.body].v[0];
        b[1] = edges[pair.body].v[1];
      }
    else
      for (unsigned int i = 0; i < dim; ++i)
        b[i + 1] = faces[pair.body].v[i];
    return b;
  }

  template <int dim>
  std::array<int, MeshObstaclePairs<dim>::n_points>
  MeshObstaclePairs<dim>::obstacle_points_of(const Pair &pair) const
  {
    std::array<int, n_points> o;
    o.fill(-1);
    if (pair.edge_edge)
      {
        o[2] = ridges[pair.feature].v[0];
        o[3] = ridges[pair.feature].v[1];
      }
    else
      o[0] = corners[pair.feature].v[0];
    return o;
  }

  template <int dim>
  typename MeshObstaclePairs<dim>::Coordinates
  MeshObstaclePairs<dim>::coordinates(const Pair                    &pair,
                                      const std::vector<Point<dim>> &x,
                                      const std::vector<Point<dim>> &y) const
  {
    const auto  b = body_points(pair), o = obstacle_points_of(pair);
    Coordinates c;
    for (unsigned int i = 0; i < n_points; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        c[i * dim + d] = b[i] >= 0 ? x[b[i]][d] : y[o[i]][d];
    return c;
  }

  template <int dim>
  std::vector<typename MeshObstaclePairs<dim>::Pair>
  MeshObstaclePairs<dim>::candidates(const std::vector<Point<dim>>     &x,
                                     const std::vector<Point<dim>>     &y,
                                     const std::vector<Tensor<1, dim>> *p,
                                     const std::vector<Tensor<1, dim>> *q,
                                     const double margin,
                                     const bool   counted_only) const
  {
    const auto box_of = [](const auto                        &indices,
                           const std::vector<Point<dim>>     &z,
                           const std::vector<Tensor<1, dim>> *motion,
                           const double                       extend) {
      BoundingBox<dim> box(std::make_pair(z[indices[0]], z[indices[0]]));
      for (const unsigned int i : indices)
        {
          box.merge_with(BoundingBox<dim>(std::make_pair(z[i], z[i])));
          if (motion)
            {
              const Point<dim> end = z[i] + (*motion)[i];
              box.merge_with(BoundingBox<dim>(std::make_pair(end, end)));
            }
        }
      box.extend(extend);
      return box;
    };
    const auto takes = [&](const auto &primitive) {
      if (counted_only)
        return primitive.counted;
      return std::any_of(primitive.v.begin(),
                         primitive.v.end(),
                         [&](const unsigned int v) { return vertices[v].owned; }) ||
             primitive.counted;
    };
    using Entry = std::pair<BoundingBox<dim>, unsigned int>;
    std::vector<Pair>  result;
    std::vector<Entry> found;
    const auto         search = [&](const std::vector<Feature> &features,
                            const unsigned int          n,
                            const auto                 &bodies,
                            const bool                  edge_edge) {
      if (features.empty() || bodies.empty())
        return;
      std::vector<Entry> entries;
      for (unsigned int f = 0; f < features.size(); ++f)
        entries.emplace_back(
          box_of(std::vector<unsigned int>(features[f].v.begin(),
                                           features[f].v.begin() + n),
                 y,
                 q,
                 0.),
          f);
      const RTree<Entry> tree = pack_rtree(entries);
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          if (!takes(bodies[b]))
            continue;
          found.clear();
          tree.query(boost::geometry::index::intersects(
                       box_of(bodies[b].v, x, p, margin)),
                     std::back_inserter(found));
          for (const auto &[box, f] : found)
            result.push_back({edge_edge, b, f});
        }
    };
    search(corners, 1, faces, false);
    if constexpr (dim == 3)
      search(ridges, 2, edges, true);
    return result;
  }

  template <int dim>
  template <typename F>
  bool
  MeshObstaclePairs<dim>::for_each_active(const VectorType  &u,
                                          const double       t,
                                          const unsigned int order,
                                          const F           &f,
                                          double *min_distance) const
  {
    const std::vector<Point<dim>> x = body_at(u);
    const std::vector<Point<dim>> y = obstacle_at(clock.obstacle_time(t));
    bool                          touching = false;
    double                        closest  = d_hat;
    for (const Pair &pair : candidates(x, y, nullptr, nullptr, d_hat, false))
      {
        const Coordinates  c = coordinates(pair, x, y);
        const DistanceCase k = classify_pair<dim>(c, pair.edge_edge);
        double weight = 0., mollifier = 0.;
        if (!pair.edge_edge)
          weight = corners[pair.feature].area;
        else
          {
            weight = 0.5 * (edges[pair.body].area + ridges[pair.feature].area);
            mollifier =
              1e-3 * edges[pair.body].length2 * ridges[pair.feature].length2;
          }
        PairBarrier<n_coordinates> b =
          pair_barrier<dim>(c, k, d_hat, kappa * weight, mollifier, order);
        closest = std::min(closest, b.distance);
        if (!(b.distance > 0.))
          {
            touching = true;
            continue;
          }
        if (b.distance >= d_hat)
          continue;
        b.energy *= clock.end_state.energy_factor();
        for (double &g : b.gradient)
          g *= clock.end_state.gradient_factor();
        if (order == 2)
          for (auto &row : b.hessian)
            for (double &v : row)
              v *= clock.end_state.hessian_factor();
        f(pair, b);
      }
    if (min_distance)
      *min_distance = closest;
    return touching;
  }

  template <int dim>
  void
  MeshObstaclePairs<dim>::check_start() const
  {
    // No sharp feature of an obstacle on or through the body's boundary at
    // t = 0 (distance 0 to a face or edge).
    const std::vector<Point<dim>> y = obstacle_at(0.);
    std::vector<Point<dim>>       X(vertices.size());
    for (unsigned int i = 0; i < vertices.size(); ++i)
      X[i] = vertices[i].X;
    std::string problem;
    for (const Pair &pair : candidates(X, y, nullptr, nullptr, 0., true))
      {
        const Coordinates c = coordinates(pair, X, y);
        const double      d = std::sqrt(std::max(
          squared_distance<dim>(classify_pair<dim>(c, pair.edge_edge), c), 0.));
        if (d > 0.)
          continue;
        const unsigned int m =
          pair.edge_edge ? ridges[pair.feature].obstacle :
                           corners[pair.feature].obstacle;
        std::ostringstream s;
        s << "the obstacle of '" << sections[m] << "' starts on the body's "
          << "boundary: its " << (pair.edge_edge ? "edge" : "vertex")
          << " at (" << y[obstacle_points_of(pair)[pair.edge_edge ? 2 : 0]]
          << ") touches a boundary " << (pair.edge_edge ? "edge" : "face")
          << " of the body at t = 0";
        problem = s.str();
        break;
      }
    throw_input_error_of_first_rank(problem, comm);
  }

  template <int dim>
  void
  MeshObstaclePairs<dim>::contact_forces(const VectorType &u,
                                         const double      t,
                                         VectorType       &forces) const
  {
    std::vector<types::global_dof_index> rows;
    std::vector<double>                  values;
    const bool                           touching =
      for_each_active(u, t, 1, [&](const Pair &pair, const auto &b) {
        const auto body = body_points(pair);
        for (unsigned int i = 0; i < n_points; ++i)
          if (body[i] >= 0 && vertices[body[i]].owned)
            for (unsigned int d = 0; d < dim; ++d)
              {
                rows.push_back(vertices[body[i]].dofs[d]);
                values.push_back(-b.gradient[i * dim + d]);
              }
      });
    // On every rank: the first add after an insert is collective.
    forces.add(rows, values);
    if (Utilities::MPI::max(touching ? 1 : 0, comm) != 0)
      throw ConvergenceFailure(
        "a corner or edge of a meshed obstacle touches the body's boundary "
        "at t = " +
        std::to_string(t));
  }

  template <int dim>
  ForceSize
  MeshObstaclePairs<dim>::add_forces(const VectorType &u,
                                     const double      t,
                                     VectorType       &forces) const
  {
    const auto scope = timed_section(timer, "contact");
    contact_forces(u, t, forces);
    return {};
  }

  template <int dim>
  void
  MeshObstaclePairs<dim>::add_stiffness(
    const VectorType                &u,
    const double                     t,
    const TangentProjection          projection,
    const AffineConstraints<double> &constraints,
    MatrixType                      &matrix,
    VectorType                      &rhs) const
  {
    const auto scope = timed_section(timer, "contact");
    // The rest of the obstacles' way within the step, per obstacle point:
    // the linearization carries it as a prescribed motion of the pairs'
    // obstacle points (end-state coordinates, hence / c).
    std::vector<Tensor<1, dim>> rest(obstacle_points.size());
    if (clock.on_the_way(t))
      {
        const std::vector<Point<dim>> now = obstacle_at(clock.reached),
                                      end = obstacle_at(clock.end_time(t));
        for (unsigned int i = 0; i < rest.size(); ++i)
          rest[i] = (end[i] - now[i]) / clock.end_state.c;
      }
    const bool project = projection == TangentProjection::every_point;
    std::vector<types::global_dof_index> rhs_rows, columns;
    std::vector<double>                  rhs_values, values;
    rhs.add(rhs_rows, rhs_values); // the switch to adding, on every rank
    for_each_active(u, t, 2, [&](const Pair &pair, const auto &b) {
      const auto body = body_points(pair), obstacle = obstacle_points_of(pair);
      // The body's block, projected to positive semi-definite where asked
      // (the obstacle's coordinates are no unknowns).
      SmallMatrix<n_coordinates> K = b.hessian;
      for (unsigned int i = 0; i < n_points; ++i)
        for (unsigned int j = 0; j < n_points; ++j)
          if (body[i] < 0 || body[j] < 0)
            for (unsigned int r = 0; r < dim; ++r)
              for (unsigned int c = 0; c < dim; ++c)
                K[i * dim + r][j * dim + c] = 0.;
      if (project)
        K = positive_semidefinite_part<n_coordinates>(K);
      for (unsigned int i = 0; i < n_points; ++i)
        {
          if (body[i] < 0 || !vertices[body[i]].owned)
            continue;
          for (unsigned int r = 0; r < dim; ++r)
            {
              const types::global_dof_index row = vertices[body[i]].dofs[r];
              if (constraints.is_constrained(row))
                continue;
              columns.clear();
              values.clear();
              double moved = 0.;
              for (unsigned int j = 0; j < n_points; ++j)
                for (unsigned int c = 0; c < dim; ++c)
                  if (body[j] >= 0)
                    {
                      columns.push_back(vertices[body[j]].dofs[c]);
                      values.push_back(K[i * dim + r][j * dim + c]);
                    }
                  else
                    moved += b.hessian[i * dim + r][j * dim + c] *
                             rest[obstacle[j]][c];
              moved += condense_row(constraints, columns, values);
              matrix.add(row, columns.size(), columns.data(), values.data());
              if (moved != 0.)
                {
                  rhs_rows.push_back(row);
                  rhs_values.push_back(-moved);
                }
            }
        }
    });
    rhs.add(rhs_rows, rhs_values);
  }

  template <int dim>
  double
  MeshObstaclePairs<dim>::energy(const VectorType &u, const double t) const
  {
    const auto scope    = timed_section(timer, "contact");
    double     sum      = 0.;
    const bool touching = for_each_active(u, t, 0, [&](const Pair &pair,
                                                       const auto &b) {
      if (counted(pair))
        sum += b.energy;
    });
    if (touching)
      sum = std::numeric_limits<double>::infinity();
    return Utilities::MPI::sum(sum, comm);
  }

  template <int dim>
  double
  MeshObstaclePairs<dim>::largest_feasible_step(const VectorType &u,
                                                const VectorType &direction_in,
                                                const double      t) const
  {
    const auto                    scope = timed_section(timer, "contact");
    const std::vector<Point<dim>> x     = body_at(u);
    // The body's motion (end state) and the obstacles' from where they
    // stand to their place at t.
    const VectorType           &direction = ghosted(direction_in);
    std::vector<Tensor<1, dim>> p(vertices.size());
    for (unsigned int i = 0; i < vertices.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        p[i][d] = clock.end_state.c * direction(vertices[i].dofs[d]);
    const std::vector<Point<dim>> y = obstacle_at(clock.obstacle_time(t));
    std::vector<Tensor<1, dim>>   q(y.size());
    if (clock.on_the_way(t))
      {
        const std::vector<Point<dim>> end = obstacle_at(clock.end_time(t));
        for (unsigned int i = 0; i < y.size(); ++i)
          q[i] = end[i] - y[i];
      }
    double alpha = 1.;
    for (const Pair &pair : candidates(x, y, &p, &q, d_hat, true))
      {
        const Coordinates c = coordinates(pair, x, y);
        const auto body = body_points(pair), obstacle = obstacle_points_of(pair);
        Coordinates motion;
        for (unsigned int i = 0; i < n_points; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            motion[i * dim + d] =
              body[i] >= 0 ? p[body[i]][d] : q[obstacle[i]][d];
        alpha = std::min(alpha,
                         additive_ccd<dim>(
                           c, motion, pair.edge_edge, keep_fraction, alpha)
                           .t);
      }
    return Utilities::MPI::min(alpha, comm);
  }

  template <int dim>
  void
  MeshObstaclePairs<dim>::begin_step(const VectorType &u, const double t_start)
  {
    clock.begin_step(t_start);
    start_positions = body_at(u);
    // kappa at a sound operating point for the step to come, from the
    // converged state's smallest distance (BarrierStiffness).
    if (stiffness.adaptive() &&
        stiffness.retarget(measure(u, t_start).min_distance / d_hat))
      kappa = stiffness.value();
  }

  template <int dim>
  bool
  MeshObstaclePairs<dim>::prepare_motion(const double t)
  {
    const double t_end = clock.end_time(t);
    if (!(clock.reached < t_end))
      return false;
    for (unsigned int m = 0; m < motions.size(); ++m)
      if (placement(m, clock.reached).shift != placement(m, t_end).shift)
        return true;
    clock.reached = t_end;
    return false;
  }

  template <int dim>
  void
  MeshObstaclePairs<dim>::advance(const double alpha, const double t)
  {
    clock.advance(alpha, t);
  }

  template <int dim>
  ContactMeasures
  MeshObstaclePairs<dim>::measure(const VectorType &u, const double t) const
  {
    std::vector<Tensor<1, dim>> force(numbers.size());
    std::vector<Tensor<1, 3>>   moment(numbers.size());
    unsigned int                active  = 0;
    double                      closest = d_hat;
    // Moments about each obstacle's point where it stands, the forces on
    // the body at its deformed vertices (the pair's energy depends on
    // distances only: minus the moment of its forces on the obstacle's
    // vertices).
    const std::vector<Point<dim>> x = body_at(u);
    std::vector<Point<dim>>       centre;
    for (unsigned int k = 0; k < numbers.size(); ++k)
      centre.push_back(placement(k, clock.obstacle_time(t))(anchors[k]));
    for_each_active(
      u,
      t,
      1,
      [&](const Pair &pair, const auto &b) {
        active += counted(pair) ? 1 : 0;
        const unsigned int m = pair.edge_edge ? ridges[pair.feature].obstacle :
                                                corners[pair.feature].obstacle;
        const auto body = body_points(pair);
        for (unsigned int i = 0; i < n_points; ++i)
          if (body[i] >= 0 && vertices[body[i]].owned)
            {
              Tensor<1, dim> f;
              for (unsigned int d = 0; d < dim; ++d)
                f[d] = -b.gradient[i * dim + d];
              force[m] += f;
              moment[m] += moment_of<dim>(x[body[i]] - centre[m], f);
            }
      },
      &closest);
    ContactMeasures measures;
    for (unsigned int k = 0; k < numbers.size(); ++k)
      measures.add_obstacle<dim>(numbers[k],
                                 Utilities::MPI::sum(force[k], comm),
                                 Utilities::MPI::sum(moment[k], comm));
    measures.min_distance = Utilities::MPI::min(closest, comm);
    measures.active_pairs = Utilities::MPI::sum(active, comm);
    return measures;
  }

  template class MeshObstaclePairs<2>;
  template class MeshObstaclePairs<3>;
} // namespace hyperelastic
