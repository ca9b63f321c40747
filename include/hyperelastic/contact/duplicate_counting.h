// The barrier of a boundary without double counting.
//
// Summing b(d) over every (vertex, face) pair counts a vertex twice where its
// closest point on a boundary is a vertex or an edge shared by several faces:
// a point at gap h above a boundary vertex of a straight 2D boundary feels
// 2 b(h), above a segment's interior b(h). The barrier is corrugated at the
// mesh spacing, and sliding over it costs a force (spurious friction).
//
// Inclusion-exclusion over the features removes it. For a point p against a
// boundary of faces t, edges e and vertices v (the features not containing p):
//   2D:  sum_t b(d(p, t)) + sum_v (1 - n_v) b(|p - v|),
//   3D:  sum_t b(d(p, t)) + sum_e (1 - n_e) b(d(p, e)) + sum_v W_v b(|p - v|),
//        W_v = 1 - n_v + sum_{e at v} (n_e - 1),
// n_e the faces at edge e and n_v those at vertex v (all not containing p).
// Where p's closest point on a flat (straight) part lies in a face, on an
// edge or at a vertex, the coefficients of the features there add up to one
// and those of every other feature to zero, so the sum is b(h) exactly,
// wherever p is along the boundary. This is the "improved max approximator"
// of Li, Kaufman and Jiang (2023). Each correction is carried by the pairs
// whose face holds its feature, shared equally: a pair (p, t) adds
//   (1 - n_e) / n_e b(d(p, e)) for each edge e of t,  W_v / n_v b(|p - v|)
// for each vertex v of t (2D: (1 - n_v) / n_v b(|p - v|)).
// Edge-edge pairs (ea, eb) (3D) count the crossings of edges, whose number
// over two flat parts changes with every mesh spacing they slide. An edge
// whose two faces lie in one plane (in the reference configuration) cannot
// be the first point of a crossing: a segment reaching such an edge's
// patch first touches it with an endpoint (a point-triangle pair) or at
// the patch's border. Only the pairs of two sharp edges therefore carry
// a barrier (the others keep their place in the feasible step's CCD), and
// they treat each edge as a point against the other's sharp edges: eb's
// endpoints q carry the share of ea's weight times (1 - n_q) / n_q
// b(d(q, ea)), n_q the sharp edges at q without a vertex of ea, and the
// other way round.
//
// Pure functions of the connectivity (BoundaryIncidence) and of a pair's
// coordinates (pair_terms): nothing here knows about MPI or deal.II.
#pragma once

#include <hyperelastic/contact/barrier.h>
#include <hyperelastic/contact/primitive_distance.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace hyperelastic
{
  /// A pair's correction coefficients, relative to its own weight:
  ///  - 2D point-segment [p, a, b]: b(|p - a|), b(|p - b|);
  ///  - 3D point-triangle [p, t0, t1, t2]: p to the edges t0 t1, t1 t2,
  ///    t2 t0, then to the vertices t0, t1, t2;
  ///  - 3D edge-edge [a0, a1, b0, b1]: b0 and b1 to edge a, a0 and a1 to
  ///    edge b.
  using PairCorrection = std::array<double, 6>;

  /// Which faces meet at each vertex and edge of a boundary (faces of dim
  /// vertex indices: segments in 2D, triangles in 3D), and which edges at
  /// each vertex (3D).
  template <int dim>
  class BoundaryIncidence
  {
  public:
    BoundaryIncidence() = default;

    /// The boundary's @p faces and the reference positions @p points of its
    /// vertices (dim coordinates each; which edges are sharp).
    BoundaryIncidence(const std::vector<std::array<unsigned int, dim>> &faces,
                      const std::vector<std::array<double, dim>>       &points);

    /// Whether the edge (@p v, @p w) is sharp (3D): its faces are not two
    /// in one plane (normals within 1e-6 rad) in the reference.
    bool
    sharp(unsigned int v, unsigned int w) const;

    /// The corrections of the pair (@p p, face @p f) (@p p not a vertex of
    /// it).
    PairCorrection
    point_face(unsigned int p, unsigned int f) const;

    /// The corrections of the edge-edge pair (@p a, @p b) (3D; vertex pairs
    /// without a common vertex) whose weights (the edges' shares of the
    /// boundary) are @p weight_a and @p weight_b.
    PairCorrection
    edge_edge(const std::array<unsigned int, 2> &a,
              const std::array<unsigned int, 2> &b,
              double                             weight_a,
              double                             weight_b) const;

  private:
    /// The faces at edge (v, w), v < w, not containing @p p.
    unsigned int
    faces_at_edge(unsigned int v, unsigned int w, unsigned int p) const;

    /// The correction of vertex @p v for point @p p (per face at v).
    double
    vertex_share(unsigned int v, unsigned int p) const;

    std::vector<std::array<unsigned int, dim>> faces;
    std::vector<std::vector<unsigned int>>     faces_at_vertex;
    std::vector<std::vector<unsigned int>>     neighbours; ///< 3D edges
    std::map<std::pair<unsigned int, unsigned int>, std::vector<unsigned int>>
                                                          faces_at;
    std::map<std::pair<unsigned int, unsigned int>, bool> sharp_edge;
  };

  /// The terms of a pair at @p x (its own case and the corrections'
  /// sub-cases, point-point or point-segment, with their coefficients).
  template <int dim, std::size_t n>
  PairTerms
  pair_terms(const std::array<double, n> &x,
             const bool                   edge_edge,
             const PairCorrection        &correction)
  {
    PairTerms terms;
    terms.add(classify_pair<dim>(x, edge_edge), 1.);
    if constexpr (dim == 2)
      {
        terms.add({DistanceCase::point_point, {{0, 1, 0, 0}}}, correction[0]);
        terms.add({DistanceCase::point_point, {{0, 2, 0, 0}}}, correction[1]);
      }
    else if (edge_edge)
      {
        terms.add(classify_point_segment<3>(x, 2, 0, 1), correction[0]);
        terms.add(classify_point_segment<3>(x, 3, 0, 1), correction[1]);
        terms.add(classify_point_segment<3>(x, 0, 2, 3), correction[2]);
        terms.add(classify_point_segment<3>(x, 1, 2, 3), correction[3]);
      }
    else
      {
        terms.add(classify_point_segment<3>(x, 0, 1, 2), correction[0]);
        terms.add(classify_point_segment<3>(x, 0, 2, 3), correction[1]);
        terms.add(classify_point_segment<3>(x, 0, 3, 1), correction[2]);
        for (unsigned int v = 1; v <= 3; ++v)
          terms.add({DistanceCase::point_point, {{0, v, 0, 0}}},
                    correction[2 + v]);
      }
    return terms;
  }

  /// sum_k c_k b'(d_k) of the @p terms at @p x (those within @p d_hat).
  template <int dim, std::size_t n>
  double
  pair_barrier_slope(const std::array<double, n> &x,
                     const PairTerms             &terms,
                     const double                 d_hat)
  {
    double slope = 0.;
    for (unsigned int k = 0; k < terms.size; ++k)
      if (terms.coefficient[k] != 0.)
        {
          const double d =
            std::sqrt(std::max(squared_distance<dim>(terms.cases[k], x), 0.));
          if (d < d_hat)
            slope += terms.coefficient[k] * barrier(d, d_hat).derivative;
        }
    return slope;
  }
} // namespace hyperelastic
