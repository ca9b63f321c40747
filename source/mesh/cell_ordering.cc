// Cells sorted along a Morton curve of their centroids, vertices renumbered
// in the order the sorted cells use them.
#include <hyperelastic/mesh/cell_ordering.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  unsigned long long
  morton_key(const Point<dim> &x,
             const Point<dim> &lower,
             const Point<dim> &upper)
  {
    constexpr unsigned int bits                = 63 / dim;
    constexpr double       cells_per_direction = double(1ull << bits);
    unsigned long long     grid[dim];
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double width = upper[d] - lower[d];
        double       s     = width > 0. ? (x[d] - lower[d]) / width : 0.;
        if (!(s > 0.)) // also NaN
          s = 0.;
        grid[d] = static_cast<unsigned long long>(
          std::min(s * cells_per_direction, cells_per_direction - 1.));
      }
    unsigned long long key = 0;
    for (unsigned int b = bits; b-- > 0;)
      for (unsigned int d = 0; d < dim; ++d)
        key = (key << 1) | ((grid[d] >> b) & 1ull);
    return key;
  }

  template <int dim>
  void
  order_cells_along_curve(std::vector<Point<dim>>    &vertices,
                          std::vector<CellData<dim>> &cells,
                          std::vector<long long>     &element_numbers,
                          SubCellData                &boundary)
  {
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::numeric_limits<double>::max();
        upper[d] = -std::numeric_limits<double>::max();
      }
    for (const Point<dim> &x : vertices)
      for (unsigned int d = 0; d < dim; ++d)
        if (std::isfinite(x[d]))
          {
            lower[d] = std::min(lower[d], x[d]);
            upper[d] = std::max(upper[d], x[d]);
          }

    // Cells: stable sort by key (equal keys keep the file's order).
    const std::size_t n_cells = cells.size();
    std::vector<std::pair<unsigned long long, std::size_t>> keyed(n_cells);
    for (std::size_t c = 0; c < n_cells; ++c)
      {
        Point<dim> centroid;
        for (const unsigned int v : cells[c].vertices)
          centroid += vertices[v];
        keyed[c] = {morton_key<dim>(centroid / double(cells[c].vertices.size()),
                                    lower,
                                    upper),
                    c};
      }
    std::sort(keyed.begin(), keyed.end());
    std::vector<CellData<dim>> sorted_cells;
    std::vector<long long>     sorted_numbers;
    sorted_cells.reserve(n_cells);
    sorted_numbers.reserve(element_numbers.size());
    for (const auto &[key, c] : keyed)
      {
        sorted_cells.push_back(std::move(cells[c]));
        if (!element_numbers.empty())
          sorted_numbers.push_back(element_numbers[c]);
      }
    cells.swap(sorted_cells);
    if (!element_numbers.empty())
      element_numbers.swap(sorted_numbers);

    // Vertices: in the order of first use.
    constexpr unsigned int    unused = std::numeric_limits<unsigned int>::max();
    std::vector<unsigned int> new_index(vertices.size(), unused);
    unsigned int              next = 0;
    for (const CellData<dim> &cell : cells)
      for (const unsigned int v : cell.vertices)
        if (new_index[v] == unused)
          new_index[v] = next++;
    for (unsigned int &index : new_index)
      if (index == unused)
        index = next++;
    std::vector<Point<dim>> sorted_vertices(vertices.size());
    for (std::size_t v = 0; v < vertices.size(); ++v)
      sorted_vertices[new_index[v]] = vertices[v];
    vertices.swap(sorted_vertices);
    for (CellData<dim> &cell : cells)
      for (unsigned int &v : cell.vertices)
        v = new_index[v];
    for (CellData<1> &line : boundary.boundary_lines)
      for (unsigned int &v : line.vertices)
        v = new_index[v];
    for (CellData<2> &quad : boundary.boundary_quads)
      for (unsigned int &v : quad.vertices)
        v = new_index[v];
  }

  template unsigned long long
  morton_key<2>(const Point<2> &, const Point<2> &, const Point<2> &);
  template unsigned long long
  morton_key<3>(const Point<3> &, const Point<3> &, const Point<3> &);
  template void
  order_cells_along_curve<2>(std::vector<Point<2>> &,
                             std::vector<CellData<2>> &,
                             std::vector<long long> &,
                             SubCellData &);
  template void
  order_cells_along_curve<3>(std::vector<Point<3>> &,
                             std::vector<CellData<3>> &,
                             std::vector<long long> &,
                             SubCellData &);
} // namespace hyperelastic
