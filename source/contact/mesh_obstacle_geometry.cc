// Where MeshObstaclePairs finds its pairs' primitives: the sharp features
// of the meshed obstacles (vertices where the surface bends in 2D, edges
// where its triangles are not one flat piece in 3D, and their vertices) and
// the body's boundary faces and edges as this rank sees them, each with its
// share of the surface's measure.
#include <hyperelastic/contact/mesh_obstacle_pairs.h>
#include <hyperelastic/mesh/mesh_distribution.h>

#include <cmath>
#include <map>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    double
    element_measure(const Point<dim> &a,
                    const Point<dim> &b,
                    const Point<dim> *c)
    {
      if constexpr (dim == 3)
        return 0.5 * cross_product_3d(b - a, *c - a).norm();
      (void)c;
      return a.distance(b);
    }
  } // namespace

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
        const unsigned int          m       = numbers.size();
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
        const auto  Y        = [&](const unsigned int i) -> const Point<dim>  &{
          return obstacle_points[first + i];
        };
        // Every vertex's share of the area; in 3D the edges with their
        // triangles' opposite vertices and their share of the area.
        std::vector<double> area(surface.points().size());
        std::map<std::array<unsigned int, 2>, std::vector<unsigned int>>
                                                      opposite;
        std::map<std::array<unsigned int, 2>, double> edge_area;
        std::vector<std::vector<unsigned int>>        neighbours(area.size());
        for (const auto &e : elements)
          {
            const double measure =
              element_measure<dim>(Y(e[0]),
                                   Y(e[1]),
                                   dim == 3 ? &Y(e[dim - 1]) : nullptr);
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
                    {std::min(e[k], e[(k + 1) % 3]),
                     std::max(e[k], e[(k + 1) % 3])}};
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
                  const double cross   = a[0] * b[1] - a[1] * b[0];
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
                  const Tensor<1, 3> n1 = cross_product_3d(b - a,
                                                           Y(others[0]) - a),
                                     n2 = cross_product_3d(b - a,
                                                           Y(others[1]) - a);
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
    for_each_boundary_face(
      dof_handler, [&](const auto &cell, const auto &face) {
        bool any_owned = false;
        for (unsigned int v = 0; v < face->n_vertices(); ++v)
          any_owned =
            any_owned || owned.is_element(face->vertex_dof_index(v, 0));
        BodyPrimitive<dim> primitive;
        primitive.counted = cell->is_locally_owned();
        for (unsigned int v = 0; v < face->n_vertices(); ++v)
          {
            const types::global_dof_index first = face->vertex_dof_index(v, 0);
            auto                          it    = index.find(first);
            if (it == index.end())
              {
                BodyVertex vertex;
                vertex.X = face->vertex(v);
                for (unsigned int d = 0; d < dim; ++d)
                  vertex.dofs[d] = face->vertex_dof_index(v, d);
                vertex.owned = owned.is_element(first);
                it           = index.emplace(first, vertices.size()).first;
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
                {std::min(p[k], p[(k + 1) % 3]),
                 std::max(p[k], p[(k + 1) % 3])}};
              auto it = edge_data
                          .emplace(e,
                                   std::make_pair(
                                     0., dealii::numbers::invalid_unsigned_int))
                          .first;
              it->second.first += primitive.area / 3.;
              it->second.second =
                std::min(it->second.second,
                         static_cast<unsigned int>(cell->subdomain_id()));
            }
        if (primitive.counted || any_owned)
          faces.push_back(primitive);
      });
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

  template class MeshObstaclePairs<2>;
  template class MeshObstaclePairs<3>;
} // namespace hyperelastic
