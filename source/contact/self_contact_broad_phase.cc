// Self contact's broad phase: boxes around the boundary's vertices, faces
// and edges (swept along a motion, inflated by a margin) and the candidate
// pairs whose boxes overlap, from packed R-trees.
#include <deal.II/numerics/rtree.h>

#include <hyperelastic/contact/self_contact.h>

#include <algorithm>
#include <iterator>
#include <limits>

namespace hyperelastic
{
  using namespace dealii;

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
              pair.weight     = vertices[v].area;
              pair.correction = incidence.point_face(v, f);
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
                // Only two sharp edges carry a barrier
                // (contact/duplicate_counting.h); the others keep their
                // place in CCD.
                const bool sharp = incidence.sharp(edges[e][0], edges[e][1]) &&
                                   incidence.sharp(edges[o][0], edges[o][1]);
                pair.weight = sharp ? 0.5 * (edge_area[e] + edge_area[o]) : 0.;
                pair.mollifier = 1e-3 * edge_length2[e] * edge_length2[o];
                pair.correction = incidence.edge_edge(edges[e],
                                                      edges[o],
                                                      edge_area[e],
                                                      edge_area[o]);
                result.push_back(pair);
              }
          }
      }
    return result;
  }

  template SelfContact<2>::Boxes
  SelfContact<2>::boxes(const std::vector<Point<2>> &,
                        const std::vector<Tensor<1, 2>> *,
                        double) const;
  template SelfContact<3>::Boxes
  SelfContact<3>::boxes(const std::vector<Point<3>> &,
                        const std::vector<Tensor<1, 3>> *,
                        double) const;
  template std::vector<SelfContact<2>::Pair>
  SelfContact<2>::candidates(const Boxes &) const;
  template std::vector<SelfContact<3>::Pair>
  SelfContact<3>::candidates(const Boxes &) const;
} // namespace hyperelastic
