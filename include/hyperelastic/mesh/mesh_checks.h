// Checks of the cells of a mesh: the signed measure of a simplex and its
// degeneracy test, the text of the problems found (naming cell numbers), the
// plane of a 2D mesh, and the checked mesh of a gmsh file (cells reoriented,
// face neighbours, boundary ids) on which the partition works.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria_description.h>

#include <hyperelastic/mesh/mesh.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// How cell numbers are to be read in messages.
  struct Numbering
  {
    std::string singular; ///< "gmsh element"
    std::string plural;   ///< "gmsh elements"
    std::string note;     ///< where to find them, in parentheses
  };

  /// The signed measure of a simplex: det, the determinant of the edge
  /// vectors v_k - v_0 (twice the area, six times the volume, signed by
  /// orientation), and whether the simplex is degenerate. With L the
  /// longest edge and X the largest vertex coordinate in magnitude, it is
  /// degenerate if
  ///   |det| <= 1e-12 L^dim + 64 eps X L^(dim-1).
  /// The first term is scale-free: it flags cells whose height over their
  /// longest edge (2D) or volume over that of a cube of it (3D) is below
  /// 1e-12, at any cell size, so tiny cells of a graded mesh pass (a
  /// threshold relative to the whole mesh, 1e-12 h^dim, would reject a
  /// tetrahedron 1e-4 times smaller than a mesh of size h). The second
  /// bounds the rounding error of det for coordinates stored to relative
  /// precision eps: vertices that are collinear (coplanar) in the file's
  /// decimals are caught even far from the origin. NaN coordinates make a
  /// cell degenerate.
  struct SimplexMeasure
  {
    double det;
    bool   degenerate;
  };

  /// The SimplexMeasure of the simplex whose vertex k is @p vertex(k).
  template <int dim, typename VertexOf>
  SimplexMeasure
  simplex_measure(const VertexOf &vertex)
  {
    dealii::Tensor<2, dim> edges;
    double                 longest = 0., largest_coordinate = 0.;
    for (unsigned int a = 0; a <= dim; ++a)
      {
        const dealii::Point<dim> &x = vertex(a);
        if (a > 0)
          for (unsigned int d = 0; d < dim; ++d)
            edges[d][a - 1] = x[d] - vertex(0)[d];
        for (unsigned int d = 0; d < dim; ++d)
          largest_coordinate = std::max(largest_coordinate, std::abs(x[d]));
        for (unsigned int b = a + 1; b <= dim; ++b)
          longest = std::max(longest, x.distance(vertex(b)));
      }
    const double det = determinant(edges);
    const double tolerance =
      std::pow(longest, dim - 1) *
      (1e-12 * longest +
       64. * std::numeric_limits<double>::epsilon() * largest_coordinate);
    return {det, !(std::abs(det) > tolerance)};
  }

  /// The problems found in the cells as one text ("" if none):
  /// @p degenerate and @p inverted hold cell numbers. @p inverted_listed:
  /// -1 (+1) if exactly the inverted cells are listed with negative
  /// (positive) orientation, so that the file's vertex order shows the
  /// fold too; 0 if the listing says nothing.
  template <int dim>
  std::string
  cell_problems(const std::size_t             n_cells,
                const std::vector<long long> &degenerate,
                const std::vector<long long> &inverted,
                const int                     inverted_listed,
                const Numbering              &numbering);

  /// A 2D mesh must lie in a plane z = const: only x and y are used.
  void
  check_plane(const std::string      &where,
              const dealii::Point<3> &lower,
              const dealii::Point<3> &upper);

  // The checked cell list of a gmsh file, with face neighbours and
  // boundary ids, from which the descriptions of the ranks' parts are made
  // directly, without a serial triangulation (unless the mesh is to be
  // refined).
  template <int dim>
  struct CheckedMesh
  {
    std::vector<dealii::Point<dim>>    vertices;
    std::vector<dealii::CellData<dim>> cells; ///< positively oriented
    dealii::SubCellData                boundary;
    std::vector<long long>             element_numbers;
    /// Per cell c and face f (deal.II's numbering of the faces of a
    /// simplex), at c (dim + 1) + f: the neighbour's index, or -1 on the
    /// boundary, and the boundary id (internal_face_boundary_id inside).
    std::vector<int>                        neighbors;
    std::vector<dealii::types::boundary_id> face_ids;
    std::size_t                             n_reoriented = 0;
  };

  /// The mesh of a gmsh file, checked, with every cell positively
  /// oriented, and its faces. Sets the read, build and check times of
  /// @p statistics. With @p parameters of Mesh/Source = surface, the
  /// mesh is generated from the closed surface of @p file_name instead
  /// (surface_mesher.h) and checked the same way.
  template <int dim>
  CheckedMesh<dim>
  read_and_check_gmsh(const std::string    &file_name,
                      MeshStatistics       &statistics,
                      const MeshParameters *parameters = nullptr);
} // namespace hyperelastic
