// Self contact's MPI exchange: every rank publishes the box of its boundary
// vertices; the owners send the positions (and motions, start positions)
// that fall within reach of another rank's box, point to point.
#include <deal.II/base/mpi.h>

#include <hyperelastic/contact/self_contact.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace hyperelastic
{
  using namespace dealii;

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
        if (end_state.c != 1.)
          x = end_state.end_position(owned_start[k], x);
        for (unsigned int d = 0; d < dim; ++d)
          {
            owned[k * m + d] = x[d];
            if (direction)
              owned[k * m + dim + d] = end_state.c * (*direction)(v.dofs[d]);
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

  template std::vector<double>
  SelfContact<2>::exchange(const SendLists &,
                           const std::vector<double> &,
                           unsigned int) const;
  template std::vector<double>
  SelfContact<3>::exchange(const SendLists &,
                           const std::vector<double> &,
                           unsigned int) const;
  template SelfContact<2>::State
  SelfContact<2>::state(const VectorType &, const VectorType *, double) const;
  template SelfContact<3>::State
  SelfContact<3>::state(const VectorType &, const VectorType *, double) const;
} // namespace hyperelastic
