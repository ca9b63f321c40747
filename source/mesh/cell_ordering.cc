// Cells sorted along a Morton curve of their centroids, vertices renumbered
// in the order the sorted cells use them.
#include <hyperelastic/mesh/cell_ordering.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// The Morton key of @p x in the box [@p lower, @p upper] (the first
    /// dim coordinates of the bounds): the bits of the coordinates'
    /// positions on a grid of 2^(63/dim) points per direction, interleaved
    /// (NaN and points outside the box are clamped).
    template <int dim>
    unsigned long long
    morton_key(const Point<dim> &x,
               const Point<3>   &lower,
               const Point<3>   &upper)
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
  } // namespace

  template <int dim>
  void
  order_cells_along_curve(GmshMesh<dim> &mesh)
  {
    // Cells: sorted by key (equal keys keep the file's order).
    const std::size_t n_cells = mesh.cells.size();
    std::vector<std::pair<unsigned long long, std::size_t>> keyed(n_cells);
    for (std::size_t c = 0; c < n_cells; ++c)
      {
        Point<dim> centroid;
        for (const unsigned int v : mesh.cells[c].vertices)
          centroid += mesh.vertices[v];
        centroid /= double(mesh.cells[c].vertices.size());
        keyed[c] = {morton_key<dim>(centroid, mesh.lower, mesh.upper), c};
      }
    std::sort(keyed.begin(), keyed.end());
    std::vector<CellData<dim>> sorted_cells;
    std::vector<long long>     sorted_numbers;
    sorted_cells.reserve(n_cells);
    sorted_numbers.reserve(n_cells);
    for (const auto &[key, c] : keyed)
      {
        sorted_cells.push_back(std::move(mesh.cells[c]));
        sorted_numbers.push_back(mesh.element_numbers[c]);
      }
    mesh.cells.swap(sorted_cells);
    mesh.element_numbers.swap(sorted_numbers);

    // Vertices: in the order of first use.
    constexpr unsigned int    unused = std::numeric_limits<unsigned int>::max();
    std::vector<unsigned int> new_index(mesh.vertices.size(), unused);
    unsigned int              next = 0;
    for (const CellData<dim> &cell : mesh.cells)
      for (const unsigned int v : cell.vertices)
        if (new_index[v] == unused)
          new_index[v] = next++;
    for (unsigned int &index : new_index)
      if (index == unused)
        index = next++;
    std::vector<Point<dim>> sorted_vertices(mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      sorted_vertices[new_index[v]] = mesh.vertices[v];
    mesh.vertices.swap(sorted_vertices);
    for (CellData<dim> &cell : mesh.cells)
      for (unsigned int &v : cell.vertices)
        v = new_index[v];
    for (CellData<1> &line : mesh.boundary.boundary_lines)
      for (unsigned int &v : line.vertices)
        v = new_index[v];
    for (CellData<2> &quad : mesh.boundary.boundary_quads)
      for (unsigned int &v : quad.vertices)
        v = new_index[v];
  }

  template void
  order_cells_along_curve<2>(GmshMesh<2> &);
  template void
  order_cells_along_curve<3>(GmshMesh<3> &);
} // namespace hyperelastic
