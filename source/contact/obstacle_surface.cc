// A rigid obstacle surface: closest points on segments and triangles, the
// distance's derivatives, the R-tree and conservative advancement.
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/contact/obstacle_surface.h>
#include <hyperelastic/mesh/mesh_file.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// The closest point of an element to x and the projection P
    /// orthogonal to the feature it lies on.
    template <int dim>
    struct Closest
    {
      Point<dim>              point;
      SymmetricTensor<2, dim> orthogonal;
    };

    template <int dim>
    SymmetricTensor<2, dim>
    across_edge(const Tensor<1, dim> &edge)
    {
      const Tensor<1, dim> t = edge / edge.norm();
      return unit_symmetric_tensor<dim>() - symmetrize(outer_product(t, t));
    }

    /// On the segment [a, b].
    template <int dim>
    Closest<dim>
    closest_on_segment(const Point<dim> &x,
                       const Point<dim> &a,
                       const Point<dim> &b)
    {
      const Tensor<1, dim> ab = b - a;
      const double         s  = ((x - a) * ab) / ab.norm_square();
      if (s <= 0.)
        return {a, unit_symmetric_tensor<dim>()};
      if (s >= 1.)
        return {b, unit_symmetric_tensor<dim>()};
      return {a + s * ab, across_edge(ab)};
    }

    /// On the triangle (a, b, c): the Voronoi regions of its vertices, edges
    /// and face in turn, from the dot products of the edges with x - a,
    /// x - b, x - c (Ericson, Real-Time Collision Detection, 5.1.5).
    Closest<3>
    closest_on_triangle(const Point<3> &x,
                        const Point<3> &a,
                        const Point<3> &b,
                        const Point<3> &c)
    {
      const SymmetricTensor<2, 3> I  = unit_symmetric_tensor<3>();
      const Tensor<1, 3>          ab = b - a, ac = c - a, ap = x - a;
      const double                d1 = ab * ap, d2 = ac * ap;
      if (d1 <= 0. && d2 <= 0.)
        return {a, I};
      const Tensor<1, 3> bp = x - b;
      const double       d3 = ab * bp, d4 = ac * bp;
      if (d3 >= 0. && d4 <= d3)
        return {b, I};
      const double vc = d1 * d4 - d3 * d2;
      if (vc <= 0. && d1 >= 0. && d3 <= 0.)
        return {a + d1 / (d1 - d3) * ab, across_edge(ab)};
      const Tensor<1, 3> cp = x - c;
      const double       d5 = ab * cp, d6 = ac * cp;
      if (d6 >= 0. && d5 <= d6)
        return {c, I};
      const double vb = d5 * d2 - d1 * d6;
      if (vb <= 0. && d2 >= 0. && d6 <= 0.)
        return {a + d2 / (d2 - d6) * ac, across_edge(ac)};
      const double va = d3 * d6 - d5 * d4;
      if (va <= 0. && d4 - d3 >= 0. && d5 - d6 >= 0.)
        return {b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b),
                across_edge(c - b)};
      const double       denominator = 1. / (va + vb + vc);
      const Tensor<1, 3> n           = cross_product_3d(ab, ac);
      const Tensor<1, 3> e           = n / n.norm();
      return {a + vb * denominator * ab + vc * denominator * ac,
              symmetrize(outer_product(e, e))};
    }
  } // namespace

  template <int dim>
  ObstacleSurface<dim>::ObstacleSurface(const std::string &file_name,
                                        const std::string &entry)
  {
    const GmshMesh<dim> mesh = read_mesh_file<dim>(file_name, entry, false);
    vertices                 = mesh.vertices;
    if constexpr (dim == 2)
      for (const auto &line : mesh.boundary.boundary_lines)
        elements.push_back({{line.vertices[0], line.vertices[1]}});
    else
      for (const auto &triangle : mesh.boundary.boundary_quads)
        elements.push_back(
          {{triangle.vertices[0], triangle.vertices[1], triangle.vertices[2]}});
    if (elements.empty())
      throw InputError("'" + entry + "' = '" + file_name + "' holds no " +
                       (dim == 2 ? "lines" : "triangles") +
                       ": an obstacle's surface is meshed with " +
                       (dim == 2 ? "lines (gmsh -1)" : "triangles (gmsh -2)"));
    build_tree();
  }

  template <int dim>
  ObstacleSurface<dim>::ObstacleSurface(
    std::vector<Point<dim>>                    vertices,
    std::vector<std::array<unsigned int, dim>> elements)
      : vertices(std::move(vertices))
      , elements(std::move(elements))
  {
    build_tree();
  }

  template <int dim>
  void
  ObstacleSurface<dim>::build_tree()
  {
    std::vector<Entry> boxes;
    boxes.reserve(elements.size());
    for (unsigned int e = 0; e < elements.size(); ++e)
      {
        std::vector<Point<dim>> corners;
        for (const unsigned int v : elements[e])
          corners.push_back(vertices[v]);
        boxes.emplace_back(BoundingBox<dim>(corners), e);
      }
    tree = pack_rtree(boxes);
  }

  template <int dim>
  double
  ObstacleSurface<dim>::distance(const Point<dim> &x,
                                 const double      reach,
                                 Tensor<1, dim>   *gradient,
                                 Tensor<2, dim>   *hessian) const
  {
    Point<dim> lower = x, upper = x;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] -= reach;
        upper[d] += reach;
      }
    std::vector<Entry> near;
    tree.query(boost::geometry::index::intersects(
                 BoundingBox<dim>(std::make_pair(lower, upper))),
               std::back_inserter(near));
    double       best = reach;
    Closest<dim> closest;
    for (const auto &[box, e] : near)
      {
        const auto  &v = elements[e];
        Closest<dim> c;
        if constexpr (dim == 2)
          c = closest_on_segment(x, vertices[v[0]], vertices[v[1]]);
        else
          c = closest_on_triangle(x,
                                  vertices[v[0]],
                                  vertices[v[1]],
                                  vertices[v[2]]);
        const double d = x.distance(c.point);
        if (d < best)
          {
            best    = d;
            closest = c;
          }
      }
    if (gradient)
      *gradient = Tensor<1, dim>();
    if (hessian)
      *hessian = Tensor<2, dim>();
    if (best < reach && best > 0.)
      {
        const Tensor<1, dim> e = (x - closest.point) / best;
        if (gradient)
          *gradient = e;
        if (hessian)
          *hessian = Tensor<2, dim>(closest.orthogonal -
                                    symmetrize(outer_product(e, e))) /
                     best;
      }
    return best;
  }

  template <int dim>
  double
  ObstacleSurface<dim>::largest_step(const Point<dim>     &x,
                                     const Tensor<1, dim> &p,
                                     const double          keep) const
  {
    return largest_step_along([&](const double s) { return x + s * p; },
                              p.norm(),
                              keep);
  }

  template <int dim>
  double
  ObstacleSurface<dim>::largest_step_along(
    const std::function<Point<dim>(double)> &path,
    const double                             speed,
    const double                             keep) const
  {
    if (!(speed > 0.))
      return 1.;
    // Nothing within twice the way: the full step stays clear.
    const Point<dim> x  = path(0.);
    const double     d0 = distance(x, 2. * speed);
    if (!(d0 < 2. * speed))
      return 1.;
    const double target = keep * d0;
    double       alpha = 0., d = d0;
    for (unsigned int it = 0; it < 200; ++it)
      {
        const double gap = d - target;
        if (gap <= 1e-3 * (d0 - target))
          return alpha;
        // The distance falls by at most speed per unit alpha.
        alpha += gap / speed;
        if (alpha >= 1.)
          return 1.;
        d = distance(path(alpha), d0 + 2. * speed);
      }
    return alpha;
  }

  template class ObstacleSurface<2>;
  template class ObstacleSurface<3>;
} // namespace hyperelastic
