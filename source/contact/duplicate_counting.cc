#include <hyperelastic/contact/duplicate_counting.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  namespace
  {
    std::pair<unsigned int, unsigned int>
    ordered(const unsigned int v, const unsigned int w)
    {
      return {std::min(v, w), std::max(v, w)};
    }

    template <std::size_t n>
    bool
    contains(const std::array<unsigned int, n> &list, const unsigned int v)
    {
      return std::find(list.begin(), list.end(), v) != list.end();
    }
  } // namespace

  template <int dim>
  BoundaryIncidence<dim>::BoundaryIncidence(
    const std::vector<std::array<unsigned int, dim>> &faces,
    const std::vector<std::array<double, dim>>       &points)
      : faces(faces)
  {
    unsigned int n_vertices = 0;
    for (const auto &face : faces)
      for (const unsigned int v : face)
        n_vertices = std::max(n_vertices, v + 1);
    faces_at_vertex.resize(n_vertices);
    neighbours.resize(n_vertices);
    for (unsigned int f = 0; f < faces.size(); ++f)
      for (unsigned int i = 0; i < dim; ++i)
        {
          const unsigned int v = faces[f][i];
          faces_at_vertex[v].push_back(f);
          if constexpr (dim == 3)
            {
              const unsigned int w    = faces[f][(i + 1) % 3];
              auto              &list = faces_at[ordered(v, w)];
              if (list.empty())
                {
                  neighbours[v].push_back(w);
                  neighbours[w].push_back(v);
                }
              list.push_back(f);
            }
        }
    if constexpr (dim == 3)
      {
        using namespace primitive_geometry;
        const auto normal = [&](const unsigned int f) {
          const Vec<double, 3> &a = points[faces[f][0]];
          Vec<double, 3> n = cross(minus<double, 3>(points[faces[f][1]], a),
                                   minus<double, 3>(points[faces[f][2]], a));
          const double   length = std::sqrt(dot<double, 3>(n, n));
          for (double &x : n)
            x /= length;
          return n;
        };
        for (const auto &[edge, list] : faces_at)
          {
            bool sharp = list.size() != 2;
            if (!sharp)
              {
                const Vec<double, 3> sine =
                  cross(normal(list[0]), normal(list[1]));
                const double s = std::sqrt(dot<double, 3>(sine, sine));
                // Two faces in one plane (the faces' orientation is not
                // known here: parallel or anti-parallel normals).
                sharp = !(s < 1e-6);
              }
            sharp_edge[edge] = sharp;
          }
      }
  }

  template <int dim>
  bool
  BoundaryIncidence<dim>::sharp(const unsigned int v,
                                const unsigned int w) const
  {
    const auto it = sharp_edge.find(ordered(v, w));
    return it != sharp_edge.end() && it->second;
  }

  template <int dim>
  unsigned int
  BoundaryIncidence<dim>::faces_at_edge(const unsigned int v,
                                        const unsigned int w,
                                        const unsigned int p) const
  {
    const auto  &list   = faces_at.at(ordered(v, w));
    unsigned int result = 0;
    for (const unsigned int f : list)
      result += !contains(faces[f], p);
    return result;
  }

  template <int dim>
  double
  BoundaryIncidence<dim>::vertex_share(const unsigned int v,
                                       const unsigned int p) const
  {
    unsigned int n_v = 0;
    for (const unsigned int f : faces_at_vertex[v])
      n_v += !contains(faces[f], p);
    if (n_v == 0)
      return 0.;
    // 2D: W_v = 1 - n_v; 3D: W_v = 1 - n_v + sum over the edges at v
    // (without p) of (n_e - 1), edges without a face (n_e = 0) left out.
    double weight = 1. - n_v;
    if constexpr (dim == 3)
      for (const unsigned int w : neighbours[v])
        if (w != p)
          {
            const unsigned int n_e = faces_at_edge(v, w, p);
            if (n_e > 0)
              weight += n_e - 1.;
          }
    return weight / n_v;
  }

  template <int dim>
  PairCorrection
  BoundaryIncidence<dim>::point_face(const unsigned int p,
                                     const unsigned int f) const
  {
    PairCorrection c{};
    const auto    &face = faces[f];
    if constexpr (dim == 2)
      {
        c[0] = vertex_share(face[0], p);
        c[1] = vertex_share(face[1], p);
      }
    else
      {
        for (unsigned int i = 0; i < 3; ++i)
          {
            const unsigned int n_e =
              faces_at_edge(face[i], face[(i + 1) % 3], p);
            c[i]     = (1. - n_e) / n_e; // n_e >= 1: f is one of them
            c[3 + i] = vertex_share(face[i], p);
          }
      }
    return c;
  }

  template <int dim>
  PairCorrection
  BoundaryIncidence<dim>::edge_edge(const std::array<unsigned int, 2> &a,
                                    const std::array<unsigned int, 2> &b,
                                    const double                       weight_a,
                                    const double weight_b) const
  {
    PairCorrection c{};
    if constexpr (dim == 3)
      {
        // The edges at q that share no vertex with @p other.
        const auto share = [&](const unsigned int                 q,
                               const std::array<unsigned int, 2> &other) {
          unsigned int n_q = 0;
          for (const unsigned int w : neighbours[q])
            n_q += !contains(other, w) && sharp(q, w);
          return n_q == 0 ? 0. : (1. - n_q) / n_q;
        };
        const double total = weight_a + weight_b;
        if (!(total > 0.))
          return c;
        c[0] = weight_a / total * share(b[0], a);
        c[1] = weight_a / total * share(b[1], a);
        c[2] = weight_b / total * share(a[0], b);
        c[3] = weight_b / total * share(a[1], b);
      }
    else
      {
        (void)a, (void)b, (void)weight_a, (void)weight_b;
      }
    return c;
  }

  template class BoundaryIncidence<2>;
  template class BoundaryIncidence<3>;
} // namespace hyperelastic
