// Closed surfaces filled with tetrahedra: the surface's checks (closed,
// orientation, self-intersections through an R-tree of triangle boxes and
// a segment-triangle test), midpoint splitting to the target size, gmsh's
// 3D Delaunay mesher on the surface as discrete entities, element quality,
// and the gmsh 4.1 file of the result.
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/timer.h>
#include <deal.II/numerics/rtree.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/gmsh_session.h>
#include <hyperelastic/mesh/surface_mesher.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gmsh.h>
#include <iomanip>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>

namespace hyperelastic
{
  using dealii::BoundingBox;
  using dealii::Point;
  using dealii::Tensor;

  namespace
  {
    using Triangle = std::array<unsigned int, 3>;

    std::string
    coordinates(const Point<3> &x)
    {
      std::ostringstream text;
      text << std::setprecision(6) << "(" << x[0] << ", " << x[1] << ", "
           << x[2] << ")";
      return text.str();
    }

    std::string
    triangle_text(const SurfaceTriangles &s, const unsigned int t)
    {
      const Triangle &v = s.triangles[t];
      return "triangle " + std::to_string(t + 1) + " " +
             coordinates(s.vertices[v[0]]) + " " +
             coordinates(s.vertices[v[1]]) + " " +
             coordinates(s.vertices[v[2]]);
    }

    /// (b - a) . ((c - a) x (d - a)): six times the signed volume of abcd.
    double
    orient(const Point<3> &a,
           const Point<3> &b,
           const Point<3> &c,
           const Point<3> &d)
    {
      return (b - a) * dealii::cross_product_3d(c - a, d - a);
    }

    /// Sign with a relative tolerance for round-off: 0 means "on".
    int
    sign(const double value, const double scale)
    {
      const double tolerance = 1e-13 * scale;
      return value > tolerance ? 1 : value < -tolerance ? -1 : 0;
    }

    /// 2D: do segments pq and ab (projected, coordinates i, j) meet?
    bool
    segments_meet_2d(const Point<3>    &p,
                     const Point<3>    &q,
                     const Point<3>    &a,
                     const Point<3>    &b,
                     const unsigned int i,
                     const unsigned int j,
                     const double       scale)
    {
      const auto cross =
        [&](const Point<3> &o, const Point<3> &u, const Point<3> &w) {
          return sign((u[i] - o[i]) * (w[j] - o[j]) -
                        (u[j] - o[j]) * (w[i] - o[i]),
                      scale);
        };
      const int d1 = cross(a, b, p), d2 = cross(a, b, q), d3 = cross(p, q, a),
                d4 = cross(p, q, b);
      if (d1 * d2 < 0 && d3 * d4 < 0)
        return true;
      const auto on = [&](const Point<3> &o,
                          const Point<3> &u,
                          const Point<3> &w) { // w on segment ou (collinear)
        return std::min(o[i], u[i]) <= w[i] && w[i] <= std::max(o[i], u[i]) &&
               std::min(o[j], u[j]) <= w[j] && w[j] <= std::max(o[j], u[j]);
      };
      return (d1 == 0 && on(a, b, p)) || (d2 == 0 && on(a, b, q)) ||
             (d3 == 0 && on(p, q, a)) || (d4 == 0 && on(p, q, b));
    }

    /// Does segment pq meet triangle abc (closed sets)?
    bool
    segment_meets_triangle(const Point<3> &p,
                           const Point<3> &q,
                           const Point<3> &a,
                           const Point<3> &b,
                           const Point<3> &c,
                           const double    scale)
    {
      const int sp = sign(orient(a, b, c, p), scale),
                sq = sign(orient(a, b, c, q), scale);
      if (sp * sq > 0)
        return false;
      if (sp == 0 && sq == 0)
        {
          // Coplanar: in the plane of the triangle's largest normal
          // component, pq crosses an edge or lies inside.
          const Tensor<1, 3> n = dealii::cross_product_3d(b - a, c - a);
          unsigned int       k = 0;
          for (unsigned int d = 1; d < 3; ++d)
            if (std::abs(n[d]) > std::abs(n[k]))
              k = d;
          const unsigned int i = (k + 1) % 3, j = (k + 2) % 3;
          const double       s2 = std::pow(scale, 2. / 3.);
          if (segments_meet_2d(p, q, a, b, i, j, s2) ||
              segments_meet_2d(p, q, b, c, i, j, s2) ||
              segments_meet_2d(p, q, c, a, i, j, s2))
            return true;
          const auto side = [&](const Point<3> &o, const Point<3> &u) {
            return (u[i] - o[i]) * (p[j] - o[j]) -
                   (u[j] - o[j]) * (p[i] - o[i]);
          };
          const double s_ab = side(a, b), s_bc = side(b, c), s_ca = side(c, a);
          return (s_ab >= 0 && s_bc >= 0 && s_ca >= 0) ||
                 (s_ab <= 0 && s_bc <= 0 && s_ca <= 0);
        }
      const int s1 = sign(orient(p, q, a, b), scale),
                s2 = sign(orient(p, q, b, c), scale),
                s3 = sign(orient(p, q, c, a), scale);
      return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
    }

    /// Two triangles without a common vertex intersect iff an edge of one
    /// meets the other.
    bool
    triangles_intersect(const SurfaceTriangles &s,
                        const unsigned int      t,
                        const unsigned int      u,
                        const double            scale)
    {
      const auto x = [&](const unsigned int tri, const unsigned int k) {
        return s.vertices[s.triangles[tri][k]];
      };
      for (const auto &[first, second] :
           {std::make_pair(t, u), std::make_pair(u, t)})
        for (unsigned int k = 0; k < 3; ++k)
          if (segment_meets_triangle(x(first, k),
                                     x(first, (k + 1) % 3),
                                     x(second, 0),
                                     x(second, 1),
                                     x(second, 2),
                                     scale))
            return true;
      return false;
    }

    /// The winding number of the closed, outward oriented triangles
    /// @p triangles of @p surface about @p x (1 inside, 0 outside): their
    /// solid angles (Van Oosterom and Strackee 1983) over 4 pi.
    double
    winding_number(const SurfaceTriangles          &surface,
                   const std::vector<unsigned int> &triangles,
                   const Point<3>                  &x)
    {
      double angle = 0.;
      for (const unsigned int t : triangles)
        {
          const Tensor<1, 3> a = surface.vertices[surface.triangles[t][0]] - x,
                             b = surface.vertices[surface.triangles[t][1]] - x,
                             c = surface.vertices[surface.triangles[t][2]] - x;
          const double la = a.norm(), lb = b.norm(), lc = c.norm();
          angle += 2. * std::atan2(a * dealii::cross_product_3d(b, c),
                                   la * lb * lc + (a * b) * lc + (a * c) * lb +
                                     (b * c) * la);
        }
      return angle / (4. * std::acos(-1.));
    }

    /// Per undirected edge: the (at most two) triangles using it.
    using EdgeUsers = std::map<std::pair<unsigned int, unsigned int>,
                               std::vector<unsigned int>>;

    /// The triangles of each edge of @p surface; InputError naming the first
    /// open (or over-shared) edge in the order of the triangles, since the
    /// orientation walk needs exactly two triangles at every edge.
    EdgeUsers
    closed_edges(const SurfaceTriangles &surface, const std::string &where)
    {
      const std::size_t n = surface.triangles.size();
      EdgeUsers         edges;
      for (unsigned int t = 0; t < n; ++t)
        for (unsigned int k = 0; k < 3; ++k)
          {
            const unsigned int a = surface.triangles[t][k],
                               b = surface.triangles[t][(k + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}].push_back(t);
          }
      for (unsigned int t = 0; t < n; ++t)
        for (unsigned int k = 0; k < 3; ++k)
          {
            const unsigned int a = surface.triangles[t][k],
                               b = surface.triangles[t][(k + 1) % 3];
            const std::size_t users =
              edges[{std::min(a, b), std::max(a, b)}].size();
            if (users != 2)
              throw InputError(
                where + ": the surface is not closed: the edge from " +
                coordinates(surface.vertices[a]) + " to " +
                coordinates(surface.vertices[b]) + " belongs to " +
                std::to_string(users) + " triangle" + (users == 1 ? "" : "s") +
                " (every edge of a closed surface belongs to exactly two; "
                "the first such edge, of " +
                triangle_text(surface, t) + ")");
          }
      return edges;
    }

    /// Each triangle's connected component (over the shared edges
    /// @p edges), the triangles of a component turned to agree with its
    /// first (counted in @p n_turned); InputError if a component cannot be
    /// oriented.
    std::vector<unsigned int>
    connect_and_orient(SurfaceTriangles  &surface,
                       EdgeUsers         &edges,
                       const std::string &where,
                       unsigned int      &n_components,
                       std::size_t       &n_turned)
    {
      const std::size_t n = surface.triangles.size();
      // Neighbours agree when they run along their common edge in
      // opposite directions; a breadth-first walk turns the others.
      const auto direction =
        [&](const unsigned int t, const unsigned int a, const unsigned int b) {
          for (unsigned int k = 0; k < 3; ++k)
            if (surface.triangles[t][k] == a &&
                surface.triangles[t][(k + 1) % 3] == b)
              return 1;
          return -1;
        };
      std::vector<unsigned int> component(
        n, dealii::numbers::invalid_unsigned_int);
      std::vector<unsigned int> queue;
      n_components = 0;
      for (unsigned int seed = 0; seed < n; ++seed)
        {
          if (component[seed] != dealii::numbers::invalid_unsigned_int)
            continue;
          component[seed] = n_components;
          queue.assign(1, seed);
          for (std::size_t next = 0; next < queue.size(); ++next)
            {
              const unsigned int t = queue[next];
              for (unsigned int k = 0; k < 3; ++k)
                {
                  const unsigned int a = surface.triangles[t][k],
                                     b = surface.triangles[t][(k + 1) % 3];
                  const auto &users = edges[{std::min(a, b), std::max(a, b)}];
                  const unsigned int u = users[0] == t ? users[1] : users[0];
                  const bool         agree = direction(u, a, b) == -1;
                  if (component[u] == dealii::numbers::invalid_unsigned_int)
                    {
                      component[u] = n_components;
                      if (!agree)
                        {
                          std::swap(surface.triangles[u][1],
                                    surface.triangles[u][2]);
                          ++n_turned;
                        }
                      queue.push_back(u);
                    }
                  else if (!agree)
                    throw InputError(
                      where +
                      ": the surface cannot be oriented (a Moebius strip "
                      "or Klein bottle) at the edge from " +
                      coordinates(surface.vertices[a]) + " to " +
                      coordinates(surface.vertices[b]));
                }
            }
          ++n_components;
        }
      return component;
    }

    /// Nesting: how many components hold a vertex of each; a component
    /// inside an odd number is a cavity of the innermost of them, turned to
    /// face into it. @p enclosing[c]: that innermost component, or invalid.
    void
    turn_cavities(SurfaceTriangles                &surface,
                  const std::vector<unsigned int> &component,
                  const unsigned int               n_components,
                  std::vector<unsigned int>       &enclosing)
    {
      const std::size_t                      n = surface.triangles.size();
      std::vector<std::vector<unsigned int>> triangles_of(n_components);
      for (unsigned int t = 0; t < n; ++t)
        triangles_of[component[t]].push_back(t);
      std::vector<std::vector<unsigned int>> inside(n_components);
      for (unsigned int c = 0; c < n_components && n_components > 1; ++c)
        {
          const Point<3> &x =
            surface.vertices[surface.triangles[triangles_of[c][0]][0]];
          for (unsigned int d = 0; d < n_components; ++d)
            if (d != c && winding_number(surface, triangles_of[d], x) > 0.5)
              inside[c].push_back(d);
        }
      enclosing.assign(n_components, dealii::numbers::invalid_unsigned_int);
      for (unsigned int c = 0; c < n_components; ++c)
        if (inside[c].size() % 2 == 1)
          {
            for (const unsigned int d : inside[c])
              if (inside[d].size() + 1 == inside[c].size())
                enclosing[c] = d;
            for (const unsigned int t : triangles_of[c])
              std::swap(surface.triangles[t][1], surface.triangles[t][2]);
          }
    }

    /// Each triangle's connected component (over shared edges), every
    /// component oriented consistently and outward, except a component
    /// inside another (a cavity), which faces into its cavity;
    /// @p enclosing[c]: the component a cavity c lies in (the innermost),
    /// or invalid for a body.
    std::vector<unsigned int>
    orient_components(SurfaceTriangles          &surface,
                      const std::string         &where,
                      unsigned int              &n_components,
                      std::size_t               &n_turned,
                      std::vector<unsigned int> &enclosing)
    {
      const std::size_t         n     = surface.triangles.size();
      EdgeUsers                 edges = closed_edges(surface, where);
      std::vector<unsigned int> component =
        connect_and_orient(surface, edges, where, n_components, n_turned);
      // Each component outward: a positive enclosed volume.
      std::vector<double> volume(n_components, 0.);
      for (unsigned int t = 0; t < n; ++t)
        {
          const Triangle &v = surface.triangles[t];
          volume[component[t]] += orient(Point<3>(),
                                         surface.vertices[v[0]],
                                         surface.vertices[v[1]],
                                         surface.vertices[v[2]]);
        }
      for (unsigned int t = 0; t < n; ++t)
        if (volume[component[t]] < 0.)
          std::swap(surface.triangles[t][1], surface.triangles[t][2]);
      turn_cavities(surface, component, n_components, enclosing);
      return component;
    }

    /// The length scale of the surface (for the tolerances of the tests).
    double
    extent(const SurfaceTriangles &surface)
    {
      Point<3> lower = surface.vertices[0], upper = surface.vertices[0];
      for (const Point<3> &x : surface.vertices)
        for (unsigned int d = 0; d < 3; ++d)
          {
            lower[d] = std::min(lower[d], x[d]);
            upper[d] = std::max(upper[d], x[d]);
          }
      return std::max(lower.distance(upper), 1e-300);
    }

  } // namespace

  std::size_t
  check_closed_surface(SurfaceTriangles &surface, const std::string &where)
  {
    const double scale = extent(surface);
    // Degenerate triangles: a repeated vertex or no area.
    for (unsigned int t = 0; t < surface.triangles.size(); ++t)
      {
        const Triangle &v    = surface.triangles[t];
        const double    area = dealii::cross_product_3d(surface.vertices[v[1]] -
                                                       surface.vertices[v[0]],
                                                     surface.vertices[v[2]] -
                                                       surface.vertices[v[0]])
                              .norm();
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0] ||
            !(area > 1e-14 * scale * scale))
          throw InputError(where +
                           ": the surface has a degenerate (zero area) " +
                           triangle_text(surface, t));
      }
    unsigned int                                   n_components = 0;
    std::size_t                                    n_turned     = 0;
    std::vector<unsigned int>                      enclosing;
    const std::vector<std::array<unsigned int, 3>> listed = surface.triangles;
    orient_components(surface, where, n_components, n_turned, enclosing);

    // Self-intersections: every pair of triangles whose boxes overlap and
    // which share no vertex.
    using Entry = std::pair<BoundingBox<3>, unsigned int>;
    std::vector<Entry> boxes;
    boxes.reserve(surface.triangles.size());
    for (unsigned int t = 0; t < surface.triangles.size(); ++t)
      {
        std::vector<Point<3>> corners;
        for (const unsigned int v : surface.triangles[t])
          corners.push_back(surface.vertices[v]);
        BoundingBox<3> box(corners);
        box.extend(1e-12 * scale);
        boxes.emplace_back(box, t);
      }
    const auto         tree = dealii::pack_rtree(boxes);
    std::vector<Entry> found;
    for (unsigned int t = 0; t < surface.triangles.size(); ++t)
      {
        found.clear();
        tree.query(boost::geometry::index::intersects(boxes[t].first),
                   std::back_inserter(found));
        std::vector<unsigned int> candidates;
        for (const auto &hit : found)
          if (hit.second > t)
            candidates.push_back(hit.second);
        std::sort(candidates.begin(), candidates.end());
        const Triangle &a = surface.triangles[t];
        for (const unsigned int u : candidates)
          {
            const Triangle &b        = surface.triangles[u];
            bool            adjacent = false;
            for (const unsigned int v : a)
              adjacent =
                adjacent || std::find(b.begin(), b.end(), v) != b.end();
            if (!adjacent &&
                triangles_intersect(surface, t, u, scale * scale * scale))
              {
                surface.triangles = listed; // named as the file lists them
                throw InputError(where + ": the surface intersects itself: " +
                                 triangle_text(surface, t) + " and " +
                                 triangle_text(surface, u) +
                                 " intersect (numbered from 1 in the file's "
                                 "order, polygons split into triangles)");
              }
          }
      }
    return n_turned;
  }

  double
  enclosed_volume(const SurfaceTriangles &surface)
  {
    double volume = 0.;
    for (const Triangle &v : surface.triangles)
      volume += orient(Point<3>(),
                       surface.vertices[v[0]],
                       surface.vertices[v[1]],
                       surface.vertices[v[2]]);
    return volume / 6.;
  }

  double
  mean_edge_length(const SurfaceTriangles &surface)
  {
    double sum = 0.;
    for (const Triangle &v : surface.triangles)
      for (unsigned int k = 0; k < 3; ++k)
        sum +=
          surface.vertices[v[k]].distance(surface.vertices[v[(k + 1) % 3]]);
    return sum / (3. * surface.triangles.size());
  }

  SurfaceTriangles
  split_to_size(const SurfaceTriangles &surface, const double size)
  {
    SurfaceTriangles result = surface;
    while (mean_edge_length(result) > 1.5 * size)
      {
        SurfaceTriangles finer;
        finer.vertices    = result.vertices;
        finer.group_names = result.group_names;
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> middle;
        const auto midpoint = [&](const unsigned int a, const unsigned int b) {
          const auto key   = std::make_pair(std::min(a, b), std::max(a, b));
          const auto found = middle.find(key);
          if (found != middle.end())
            return found->second;
          finer.vertices.push_back(
            Point<3>(0.5 * (result.vertices[a] + result.vertices[b])));
          return middle[key] = finer.vertices.size() - 1;
        };
        for (unsigned int t = 0; t < result.triangles.size(); ++t)
          {
            const Triangle    &v  = result.triangles[t];
            const unsigned int ab = midpoint(v[0], v[1]),
                               bc = midpoint(v[1], v[2]),
                               ca = midpoint(v[2], v[0]);
            for (const Triangle &child : {Triangle{{v[0], ab, ca}},
                                          Triangle{{ab, v[1], bc}},
                                          Triangle{{ca, bc, v[2]}},
                                          Triangle{{ab, bc, ca}}})
              {
                finer.triangles.push_back(child);
                finer.groups.push_back(result.groups[t]);
              }
          }
        result = std::move(finer);
      }
    return result;
  }

  namespace
  {
    /// The discrete surface of each (component, group) of a surface.
    using SurfaceTags = std::map<std::pair<unsigned int, unsigned int>, int>;

    /// Gives gmsh one discrete surface per (component, group) of
    /// @p oriented, in the order of first appearance, with its nodes and
    /// triangles; @p loops[c]: the surfaces of component c.
    void
    add_discrete_surfaces(const SurfaceTriangles          &oriented,
                          const std::vector<unsigned int> &component,
                          SurfaceTags                     &surface_of,
                          std::vector<std::vector<int>>   &loops)
    {
      std::map<int, std::vector<std::size_t>> nodes_of;
      std::map<int, std::vector<std::size_t>> elements_of;
      std::vector<int>            node_surface(oriented.vertices.size(), 0);
      std::map<int, unsigned int> group_of;
      for (unsigned int t = 0; t < oriented.triangles.size(); ++t)
        {
          const auto key = std::make_pair(component[t], oriented.groups[t]);
          auto       s   = surface_of.find(key);
          if (s == surface_of.end())
            {
              const int tag = gmsh::model::addDiscreteEntity(2);
              s             = surface_of.emplace(key, tag).first;
              loops[component[t]].push_back(tag);
              group_of[tag] = oriented.groups[t];
            }
          for (const unsigned int v : oriented.triangles[t])
            {
              if (node_surface[v] == 0)
                node_surface[v] = s->second;
              elements_of[s->second].push_back(v + 1);
            }
        }
      for (unsigned int v = 0; v < oriented.vertices.size(); ++v)
        nodes_of[node_surface[v]].push_back(v + 1);
      for (const auto &[tag, nodes] : nodes_of)
        {
          std::vector<double> xyz;
          for (const std::size_t n : nodes)
            for (unsigned int d = 0; d < 3; ++d)
              xyz.push_back(oriented.vertices[n - 1][d]);
          gmsh::model::mesh::addNodes(2, tag, nodes, xyz);
        }
      std::size_t next_element = 1;
      for (const auto &[tag, corners] : elements_of)
        {
          std::vector<std::size_t> numbers(corners.size() / 3);
          for (std::size_t &n : numbers)
            n = next_element++;
          gmsh::model::mesh::addElementsByType(tag, 2, numbers, corners);
        }
    }

    /// One gmsh volume per body, bounded by its own surface and those of
    /// its cavities (@p enclosing as orient_components gives it).
    std::vector<int>
    add_volumes(const std::vector<std::vector<int>> &loops,
                const std::vector<unsigned int>     &enclosing,
                const unsigned int                   n_components)
    {
      std::vector<int> volumes;
      for (unsigned int c = 0; c < n_components; ++c)
        if (enclosing[c] == dealii::numbers::invalid_unsigned_int)
          {
            std::vector<int> shells{gmsh::model::geo::addSurfaceLoop(loops[c])};
            for (unsigned int d = 0; d < n_components; ++d)
              if (enclosing[d] == c)
                shells.push_back(gmsh::model::geo::addSurfaceLoop(loops[d]));
            volumes.push_back(gmsh::model::geo::addVolume(shells));
          }
      return volumes;
    }

    /// gmsh's 3D Delaunay mesher on the model, sized @p size.
    void
    generate_tetrahedra(const double size)
    {
      gmsh::option::setNumber("Mesh.MeshSizeMax", size);
      gmsh::option::setNumber("Mesh.Algorithm3D", 1); // Delaunay
      // The optimizer on every tetrahedron of gmsh quality below 0.5
      // (the default, 0.3, left smallest dihedral angles of 14-16
      // degrees on the tests' spheres and pebble; 0.5 gives 21-23 in the
      // same time).
      gmsh::option::setNumber("Mesh.Optimize", 1);
      gmsh::option::setNumber("Mesh.OptimizeThreshold", 0.5);
      gmsh::model::mesh::generate(3);
    }

    /// The vertices of @p mesh: the surface's first, in order (found by
    /// their coordinates, which gmsh keeps, since it may renumber them),
    /// then gmsh's inside in the order of their tags; returns the mesh's
    /// vertex number of each gmsh node tag.
    std::map<std::size_t, unsigned int>
    read_gmsh_nodes(const SurfaceTriangles &oriented, GmshMesh<3> &mesh)
    {
      std::vector<std::size_t> tags;
      std::vector<double>      xyz, parametric;
      gmsh::model::mesh::getNodes(tags, xyz, parametric);
      std::map<std::array<double, 3>, unsigned int> surface_vertex;
      for (unsigned int v = 0; v < oriented.vertices.size(); ++v)
        {
          const Point<3> &x                    = oriented.vertices[v];
          surface_vertex[{{x[0], x[1], x[2]}}] = v;
        }
      mesh.vertices = oriented.vertices;
      std::vector<std::pair<std::size_t, std::size_t>> order;
      for (std::size_t i = 0; i < tags.size(); ++i)
        order.emplace_back(tags[i], i);
      std::sort(order.begin(), order.end());
      std::map<std::size_t, unsigned int> index;
      for (const auto &[tag, i] : order)
        {
          const auto found =
            surface_vertex.find({{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}});
          if (found != surface_vertex.end())
            index[tag] = found->second;
          else
            {
              index[tag] = mesh.vertices.size();
              mesh.vertices.emplace_back(xyz[3 * i],
                                         xyz[3 * i + 1],
                                         xyz[3 * i + 2]);
            }
        }
      return index;
    }

    /// The tetrahedra of @p volumes (material id 0), then the triangles of
    /// each discrete surface (boundary id: its group), numbered from 1 in
    /// that order; @p index: the mesh's vertex of each gmsh node tag.
    void
    read_gmsh_elements(const std::vector<int>                    &volumes,
                       const SurfaceTags                         &surface_of,
                       const std::map<std::size_t, unsigned int> &index,
                       GmshMesh<3>                               &mesh)
    {
      // The mesh's vertex numbers of element @p e of @p n corners.
      const auto corner_vertices = [&](const std::vector<std::size_t> &c,
                                       const std::size_t               e,
                                       const unsigned int              n) {
        std::array<unsigned int, 4> v{};
        for (unsigned int k = 0; k < n; ++k)
          v[k] = index.at(c[n * e + k]);
        return v;
      };
      long long number = 1;
      for (const int volume : volumes)
        {
          std::vector<std::size_t> elements, corners;
          gmsh::model::mesh::getElementsByType(4, elements, corners, volume);
          for (std::size_t e = 0; e < elements.size(); ++e)
            mesh.add_cell(corner_vertices(corners, e, 4), 0, number++);
        }
      for (const auto &[key, tag] : surface_of)
        {
          std::vector<std::size_t> elements, corners;
          gmsh::model::mesh::getElementsByType(2, elements, corners, tag);
          for (std::size_t e = 0; e < elements.size(); ++e)
            mesh.add_face(corner_vertices(corners, e, 3), key.second, number++);
        }
    }

    /// The bounds of the vertices of @p mesh, in each coordinate.
    void
    set_bounds(GmshMesh<3> &mesh)
    {
      for (unsigned int d = 0; d < 3; ++d)
        {
          mesh.lower[d] = std::numeric_limits<double>::infinity();
          mesh.upper[d] = -std::numeric_limits<double>::infinity();
          for (const Point<3> &x : mesh.vertices)
            {
              mesh.lower[d] = std::min(mesh.lower[d], x[d]);
              mesh.upper[d] = std::max(mesh.upper[d], x[d]);
            }
        }
    }
  } // namespace

  GmshMesh<3>
  tetrahedralise(const SurfaceTriangles &surface,
                 const double            size,
                 const std::string      &where)
  {
    // The surface is oriented already; its components (separate bodies)
    // get one volume each, bounded by one discrete surface per group.
    SurfaceTriangles                oriented     = surface;
    unsigned int                    n_components = 0;
    std::size_t                     n_turned     = 0;
    std::vector<unsigned int>       enclosing;
    const std::vector<unsigned int> component =
      orient_components(oriented, where, n_components, n_turned, enclosing);

    GmshMesh<3> mesh;
    std::string failure;
    try
      {
        GmshSession session;
        gmsh::model::add("surface");
        SurfaceTags                   surface_of;
        std::vector<std::vector<int>> loops(n_components);
        add_discrete_surfaces(oriented, component, surface_of, loops);
        const std::vector<int> volumes =
          add_volumes(loops, enclosing, n_components);
        gmsh::model::geo::synchronize();
        generate_tetrahedra(size);
        const std::map<std::size_t, unsigned int> index =
          read_gmsh_nodes(oriented, mesh);
        read_gmsh_elements(volumes, surface_of, index, mesh);
      }
    catch (const std::string &message)
      {
        failure = message;
      }
    catch (const std::exception &e)
      {
        failure = e.what();
      }
    if (!failure.empty() || mesh.cells.empty())
      throw InputError(where +
                       ": gmsh could not fill the surface with tetrahedra" +
                       (failure.empty() ? std::string() : ": " + failure));
    set_bounds(mesh);
    return mesh;
  }

  TetQuality
  tet_quality(const GmshMesh<3> &mesh)
  {
    TetQuality   quality;
    const double pi              = std::acos(-1.);
    quality.min_dihedral_degrees = 180.;
    quality.min_radius_ratio     = 1.;
    for (const dealii::CellData<3> &cell : mesh.cells)
      {
        std::array<Point<3>, 4> x;
        for (unsigned int k = 0; k < 4; ++k)
          x[k] = mesh.vertices[cell.vertices[k]];
        const Tensor<1, 3> a = x[1] - x[0], b = x[2] - x[0], c = x[3] - x[0];
        const double       det    = a * dealii::cross_product_3d(b, c);
        const double       volume = std::abs(det) / 6.;
        quality.volume += det / 6.;
        // Outward normals of the faces opposite each vertex (area vectors).
        std::array<Tensor<1, 3>, 4> normal;
        double                      area = 0.;
        for (unsigned int k = 0; k < 4; ++k)
          {
            const Point<3> &p = x[(k + 1) % 4], &q = x[(k + 2) % 4],
                           &r = x[(k + 3) % 4];
            Tensor<1, 3> n    = 0.5 * dealii::cross_product_3d(q - p, r - p);
            if (n * (p - x[k]) < 0.)
              n = -n;
            normal[k] = n;
            area += n.norm();
          }
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = i + 1; j < 4; ++j)
            {
              const double cosine =
                normal[i] * normal[j] / (normal[i].norm() * normal[j].norm());
              const double angle =
                180. / pi * (pi - std::acos(std::clamp(cosine, -1., 1.)));
              quality.min_dihedral_degrees =
                std::min(quality.min_dihedral_degrees, angle);
              quality.max_dihedral_degrees =
                std::max(quality.max_dihedral_degrees, angle);
            }
        const double       r_in = 3. * volume / area;
        const Tensor<1, 3> centre =
          (a.norm_square() * dealii::cross_product_3d(b, c) +
           b.norm_square() * dealii::cross_product_3d(c, a) +
           c.norm_square() * dealii::cross_product_3d(a, b)) /
          (2. * det);
        const double ratio       = 3. * r_in / centre.norm();
        quality.min_radius_ratio = std::min(quality.min_radius_ratio, ratio);
        quality.mean_radius_ratio += ratio;
      }
    quality.mean_radius_ratio /= std::max<std::size_t>(mesh.cells.size(), 1);
    return quality;
  }

  void
  write_gmsh_mesh(const GmshMesh<3> &mesh, const std::string &file_name)
  {
    std::ofstream out(file_name);
    if (!out)
      throw InputError("'Output/Write mesh': cannot write '" + file_name + "'");
    out << std::setprecision(17);
    // Entities: one surface per boundary id, one volume per material id
    // (id 0: no physical tag, which reads back as 0).
    std::vector<unsigned int> boundary_ids, material_ids;
    for (const auto &face : mesh.boundary.boundary_quads)
      boundary_ids.push_back(face.boundary_id);
    for (const auto &cell : mesh.cells)
      material_ids.push_back(cell.material_id);
    const auto distinct = [](std::vector<unsigned int> ids) {
      std::sort(ids.begin(), ids.end());
      ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
      return ids;
    };
    const std::vector<unsigned int> surfaces = distinct(boundary_ids),
                                    volumes  = distinct(material_ids);
    const auto box                           = [&](std::ostream &o) {
      o << mesh.lower[0] << ' ' << mesh.lower[1] << ' ' << mesh.lower[2] << ' '
        << mesh.upper[0] << ' ' << mesh.upper[1] << ' ' << mesh.upper[2];
    };
    const auto physical = [](const unsigned int id) {
      return id == 0 ? std::string("0") : "1 " + std::to_string(id);
    };
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 "
        << surfaces.size() << ' ' << volumes.size() << '\n';
    for (std::size_t s = 0; s < surfaces.size(); ++s)
      {
        out << s + 1 << ' ';
        box(out);
        out << ' ' << physical(surfaces[s]) << " 0\n";
      }
    for (std::size_t v = 0; v < volumes.size(); ++v)
      {
        out << v + 1 << ' ';
        box(out);
        out << ' ' << physical(volumes[v]) << ' ' << surfaces.size();
        for (std::size_t s = 0; s < surfaces.size(); ++s)
          out << ' ' << s + 1;
        out << '\n';
      }
    out << "$EndEntities\n$Nodes\n1 " << mesh.vertices.size() << " 1 "
        << mesh.vertices.size() << "\n3 1 0 " << mesh.vertices.size() << '\n';
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      out << v + 1 << '\n';
    for (const Point<3> &x : mesh.vertices)
      out << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
    out << "$EndNodes\n";
    // Elements in their order, in blocks of consecutive equal ids.
    std::ostringstream blocks;
    std::size_t        n_blocks = 0, number = 0;
    const auto         write_blocks = [&](const auto                      &elements,
                                  const std::vector<unsigned int> &ids,
                                  const std::vector<unsigned int> &entities,
                                  const int                        dim,
                                  const int                        type) {
      for (std::size_t first = 0; first < elements.size();)
        {
          std::size_t last = first;
          while (last < elements.size() && ids[last] == ids[first])
            ++last;
          const std::size_t entity =
            std::lower_bound(entities.begin(), entities.end(), ids[first]) -
            entities.begin() + 1;
          blocks << dim << ' ' << entity << ' ' << type << ' ' << last - first
                 << '\n';
          for (std::size_t e = first; e < last; ++e)
            {
              blocks << ++number;
              for (const unsigned int v : elements[e].vertices)
                blocks << ' ' << v + 1;
              blocks << '\n';
            }
          ++n_blocks;
          first = last;
        }
    };
    write_blocks(mesh.cells, material_ids, volumes, 3, 4);
    write_blocks(mesh.boundary.boundary_quads, boundary_ids, surfaces, 2, 2);
    out << "$Elements\n"
        << n_blocks << ' ' << number << " 1 " << number << '\n'
        << blocks.str() << "$EndElements\n";
    if (!out)
      throw InputError("'Output/Write mesh': cannot write '" + file_name + "'");
  }

  template <int dim>
  GmshMesh<dim>
  mesh_closed_surface(const MeshParameters &parameters, std::string &report)
  {
    if constexpr (dim != 3)
      {
        (void)report;
        throw InputError("scene entry 'Mesh/Source' = 'surface': a closed "
                         "surface is filled with tetrahedra: it needs "
                         "'Problem/Dimension = 3'");
      }
    else
      {
        const std::string entry = "Mesh/File";
        dealii::Timer     timer;
        SurfaceTriangles  surface = read_surface_file(parameters.file, entry);
        const std::size_t n_input = surface.triangles.size();
        const std::string where =
          "scene entry '" + entry + "' = '" + parameters.file + "'";
        const std::size_t n_turned = check_closed_surface(surface, where);
        const double      mean     = mean_edge_length(surface);
        const double      size =
          parameters.mesh_size > 0. ? parameters.mesh_size : mean;
        if (parameters.mesh_size > 0.)
          surface = split_to_size(surface, parameters.mesh_size);
        GmshMesh<3>      mesh    = tetrahedralise(surface, size, where);
        const double     elapsed = timer.wall_time();
        const TetQuality quality = tet_quality(mesh);

        std::ostringstream text;
        text << std::setprecision(4) << "mesh: closed surface '"
             << parameters.file << "', " << n_input << " triangles";
        if (surface.triangles.size() != n_input)
          text << " (" << surface.triangles.size()
               << " after splitting to 'Mesh size' = " << parameters.mesh_size
               << ")";
        text << ", enclosed volume " << enclosed_volume(surface)
             << "; filled by gmsh (Delaunay, optimized) in " << elapsed
             << " s: " << mesh.cells.size() << " tetrahedra, "
             << mesh.vertices.size() << " vertices, volume " << quality.volume
             << "\n  element quality: smallest dihedral angle "
             << quality.min_dihedral_degrees
             << " degrees, radius ratio 3 r_in / r_out mean "
             << quality.mean_radius_ratio << ", smallest "
             << quality.min_radius_ratio << "\n";
        if (n_turned > 0)
          text << "  " << n_turned
               << " triangles turned to agree with their neighbours\n";
        if (!surface.group_names.empty())
          {
            text << "  boundary ids of the surface's groups:";
            for (std::size_t g = 0; g < surface.group_names.size(); ++g)
              text << (g == 0 ? " " : ", ") << g + 1 << " '"
                   << surface.group_names[g] << "'";
            text << "\n";
          }
        if (!parameters.generated_mesh_file.empty())
          {
            const std::filesystem::path path(parameters.generated_mesh_file);
            std::error_code             ignored;
            if (path.has_parent_path())
              std::filesystem::create_directories(path.parent_path(), ignored);
            write_gmsh_mesh(mesh, parameters.generated_mesh_file);
            text << "  volume mesh written to '"
                 << parameters.generated_mesh_file << "'\n";
          }
        report = text.str();
        return mesh;
      }
  }

  template GmshMesh<2>
  mesh_closed_surface<2>(const MeshParameters &, std::string &);
  template GmshMesh<3>
  mesh_closed_surface<3>(const MeshParameters &, std::string &);
} // namespace hyperelastic
