// A rigid obstacle given as a surface mesh (Contact/Obstacle k/Type = mesh):
// segments in 2D, triangles in 3D, read from a gmsh file, with a bounding-
// volume tree (deal.II's boost R-tree) of its elements.
//
// The distance of a point x to the surface is the smallest distance to its
// elements (point-segment, point-triangle in closed form), attained at a
// closest point c on a feature: an element's interior, an edge or a vertex.
// With r = x - c and d = |r|:
//   grad d = r / d,   d2 d = (P - r r^T / d^2) / d,
// P the projection orthogonal to the feature (a face: n n^T, so d2 d = 0;
// an edge with unit direction t: I - t t^T; a vertex: I). The distance is
// smooth away from the points equally close to two features of a concave
// part of the surface.
#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/numerics/rtree.h>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class ObstacleSurface
  {
  public:
    /// Reads the segments (2D) or triangles (3D) of gmsh file @p file_name;
    /// an unreadable file or one without such elements is an InputError
    /// naming @p entry.
    ObstacleSurface(const std::string &file_name, const std::string &entry);

    /// Builds the surface from its vertices and elements (dim vertex
    /// indices each).
    ObstacleSurface(std::vector<dealii::Point<dim>>            vertices,
                    std::vector<std::array<unsigned int, dim>> elements);

    /// The distance of @p x to the surface if it is below @p reach, else
    /// @p reach (a lower bound: nothing is closer); with the gradient and
    /// Hessian of the distance where asked (zero beyond the reach).
    double
    distance(const dealii::Point<dim> &x,
             double                    reach,
             dealii::Tensor<1, dim>   *gradient = nullptr,
             dealii::Tensor<2, dim>   *hessian  = nullptr) const;

    /// The largest alpha in [0, 1] for which every point of x + s p, s in
    /// [0, alpha], keeps a distance of at least @p keep times the one at x
    /// (conservative advancement: a point moving by |p| ds comes at most
    /// that much closer).
    double
    largest_step(const dealii::Point<dim>     &x,
                 const dealii::Tensor<1, dim> &p,
                 double                        keep) const;

    /// The same along the curve @p path(s), s in [0, 1], whose speed
    /// |path'(s)| is at most @p speed (a point moving relative to a
    /// turning surface, given in the surface's coordinates).
    double
    largest_step_along(const std::function<dealii::Point<dim>(double)> &path,
                       double                                           speed,
                       double keep) const;

    unsigned int
    n_elements() const
    {
      return elements.size();
    }

    /// The vertices (file coordinates) and the elements (dim vertex
    /// indices each).
    const std::vector<dealii::Point<dim>> &
    points() const
    {
      return vertices;
    }
    const std::vector<std::array<unsigned int, dim>> &
    element_vertices() const
    {
      return elements;
    }

  private:
    void
    build_tree();

    std::vector<dealii::Point<dim>>            vertices;
    std::vector<std::array<unsigned int, dim>> elements;
    using Entry = std::pair<dealii::BoundingBox<dim>, unsigned int>;
    dealii::RTree<Entry> tree;
  };
} // namespace hyperelastic
