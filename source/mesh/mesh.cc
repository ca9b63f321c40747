// Mesh creation on one rank (the reader): box generation or gmsh reading,
// validation and reorientation of the cells, refinement and METIS
// partitioning; then distribution, every other rank receiving only the
// description of its own part.
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/mesh.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  void
  set_box_boundary_ids(Triangulation<dim> &tria)
  {
    const BoundingBox<dim> box = GridTools::compute_bounding_box(tria);
    const double           tol = 1e-10 * box.side_length(0);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<dim> c = face->center();
            for (unsigned int d = 0; d < dim; ++d)
              {
                if (std::abs(c[d] - box.lower_bound(d)) < tol)
                  face->set_boundary_id(2 * d);
                else if (std::abs(c[d] - box.upper_bound(d)) < tol)
                  face->set_boundary_id(2 * d + 1);
              }
          }
  }

  namespace
  {
    // ------------------------------------------------------------------
    // Policy for the input cells.
    //
    // Vertex order: any. Mesh writers differ: gmsh and TetGen list cells
    // positively oriented, gmsh writes every triangle clockwise for a
    // surface whose curve loop runs clockwise, and DOLFIN/FEniCS and meshio
    // write cells in sorted vertex order, so that about half of them are
    // negatively oriented. A cell listed with negative orientation is
    // reoriented (its last two vertices swapped, as deal.II's GridIn does);
    // this changes no geometry and no result.
    //
    // What is rejected, with the gmsh element numbers:
    // - cells of zero area or volume (see simplex_measure() for the test);
    // - folds: two cells sharing a face whose opposite vertices lie on the
    //   same side of it overlap, as when a node is pushed through a face.
    //   Reorienting cells cannot hide this, since the test depends on the
    //   positions only. The cells named are the inverted ones: across every
    //   face the orientation is propagated (kept, or flipped where the face
    //   is folded), and in each connected part of the mesh the minority is
    //   inverted.
    // - 2D meshes whose nodes are not in a plane z = const (deal.II would
    //   drop z and compute on a distorted projection).
    //
    // What deal.II 9.4 itself does (tried with GridIn::read_msh and
    // Triangulation::create_triangulation on small hand-made meshes):
    // GridIn reorders negatively oriented simplices silently;
    // create_triangulation accepts inverted and zero-volume cells; neither
    // notices folds. Hence the checks here.

    /// How cell numbers are to be read in messages.
    struct Numbering
    {
      std::string singular; ///< "gmsh element"
      std::string plural;   ///< "gmsh elements"
      std::string note;     ///< where to find them, in parentheses
    };

    const Numbering gmsh_numbering = {
      "gmsh element",
      "gmsh elements",
      "(the element numbers of the file's $Elements section)"};

    /// "3, 7, 12" (at most 10, then "and N more").
    std::string
    list_numbers(const std::vector<long long> &numbers)
    {
      const std::size_t shown = std::min<std::size_t>(numbers.size(), 10);
      std::string       text;
      for (std::size_t i = 0; i < shown; ++i)
        text += (i > 0 ? ", " : "") + std::to_string(numbers[i]);
      if (numbers.size() > shown)
        text += " and " + std::to_string(numbers.size() - shown) + " more";
      return text;
    }

    /// "1 of 6 triangles is" / "2 of 6 triangles are".
    template <int dim>
    std::string
    count_of(const std::size_t count, const std::size_t total)
    {
      const bool one = count == 1;
      return std::to_string(count) + " of " + std::to_string(total) + " " +
             (dim == 2 ? (total == 1 ? "triangle" : "triangles")
                       : (total == 1 ? "tetrahedron" : "tetrahedra")) +
             (one ? " is" : " are");
    }

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

    template <int dim, typename VertexOf>
    SimplexMeasure
    simplex_measure(const VertexOf &vertex)
    {
      Tensor<2, dim> edges;
      double         longest = 0., largest_coordinate = 0.;
      for (unsigned int a = 0; a <= dim; ++a)
        {
          const Point<dim> &x = vertex(a);
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
                  const Numbering              &numbering)
    {
      const auto numbers = [&](const std::vector<long long> &n) {
        return (n.size() == 1 ? numbering.singular : numbering.plural) + " " +
               list_numbers(n) + " " + numbering.note;
      };
      std::vector<std::string> problems;
      if (!degenerate.empty())
        problems.push_back(
          count_of<dim>(degenerate.size(), n_cells) + " degenerate (" +
          (dim == 2 ? "zero area, collinear vertices): "
                    : "zero volume, coplanar vertices): ") +
          numbers(degenerate) +
          (degenerate.size() == n_cells
             ? "; every cell is flat: are the coordinates right?"
             : ""));
      if (!inverted.empty())
        {
          const std::size_t n_others =
            n_cells - degenerate.size() - inverted.size();
          std::string why;
          if (inverted_listed < 0)
            why = dim == 2
                    ? "listed clockwise while the other " +
                        std::to_string(n_others) + " are counter-clockwise"
                    : "negatively oriented, (v1 - v0) x (v2 - v0) . "
                      "(v3 - v0) < 0, while the other " +
                        std::to_string(n_others) + " are positively oriented";
          else if (inverted_listed > 0)
            why = dim == 2
                    ? "listed counter-clockwise while the other " +
                        std::to_string(n_others) + " are clockwise"
                    : "positively oriented, (v1 - v0) x (v2 - v0) . "
                      "(v3 - v0) > 0, while the other " +
                        std::to_string(n_others) + " are negatively oriented";
          else
            why = std::string(inverted.size() == 1 ? "it" : "each") +
                  " lies on the same side of a " +
                  (dim == 2 ? "edge" : "face") + " as the neighbour across it";
          problems.push_back(
            count_of<dim>(inverted.size(), n_cells) + " inverted (" + why +
            "): " + numbers(inverted) +
            "; the mesh is folded there, as when a node is pushed through a " +
            (dim == 2 ? "edge" : "face") +
            ": correct the node coordinates or regenerate the mesh (the "
            "vertex order is not the problem: cells listed in either "
            "orientation are accepted)");
        }
      std::string text;
      for (std::size_t i = 0; i < problems.size(); ++i)
        text += (i > 0 ? "; " : "") + problems[i];
      return text;
    }

    /// Name of a gmsh element type (the common ones), for messages.
    std::string
    gmsh_element_name(const int type)
    {
      switch (type)
        {
        case 2:
          return "3-node triangle (type 2)";
        case 3:
          return "4-node quadrangle (type 3)";
        case 4:
          return "4-node tetrahedron (type 4)";
        case 5:
          return "8-node hexahedron (type 5)";
        case 6:
          return "6-node prism (type 6)";
        case 7:
          return "5-node pyramid (type 7)";
        case 8:
          return "3-node line (type 8)";
        case 9:
          return "6-node triangle (type 9)";
        case 10:
          return "9-node quadrangle (type 10)";
        case 11:
          return "10-node tetrahedron (type 11)";
        default:
          return "element of type " + std::to_string(type);
        }
    }

    // ------------------------------------------------------------------
    // gmsh reading: the file is read into memory once and parsed once,
    // into what deal.II's GridIn::read_msh would hand to
    // Triangulation::create_triangulation (the same vertices in the same
    // order, cells with the physical tag as material id, boundary lines and
    // triangles with the physical tag as boundary id) plus the element
    // number of every cell, for messages.

    /// The text of a gmsh file, read as whitespace-separated tokens; line
    /// ends matter only where skip_line() is called.
    class GmshText
    {
    public:
      GmshText(std::string text, const std::string &file_name)
          : text(std::move(text))
          , file_name(file_name)
      {
      }

      /// Whether another token follows.
      bool
      more()
      {
        skip_blanks();
        return pos < text.size();
      }

      std::string_view
      word()
      {
        if (!more())
          fail("unexpected end of file");
        const std::size_t start = pos;
        while (pos < text.size() && !is_blank(text[pos]))
          ++pos;
        return std::string_view(text).substr(start, pos - start);
      }

      template <typename Number>
      Number
      number()
      {
        std::string_view token = word();
        if (std::is_floating_point_v<Number> && token.size() > 1 &&
            token[0] == '+')
          token.remove_prefix(1);
        Number     value{};
        const auto end    = token.data() + token.size();
        const auto result = std::from_chars(token.data(), end, value);
        if (result.ec != std::errc() || result.ptr != end)
          fail("cannot parse '" + std::string(token) + "' on line " +
               std::to_string(line_number()) + " as " +
               (std::is_floating_point_v<Number> ? "a number" : "an integer"));
        return value;
      }

      /// Moves past the end of the current line.
      void
      skip_line()
      {
        const std::size_t end = text.find('\n', pos);
        pos = end == std::string::npos ? text.size() : end + 1;
      }

      /// Skips the section that begins with @p name, up to the word that
      /// starts with "$End" (or "$END").
      void
      skip_section(const std::string_view name)
      {
        for (;;)
          {
            skip_line();
            if (!more())
              fail("unexpected end of file in section " + std::string(name));
            if (text.compare(pos, 4, "$End") == 0 ||
                text.compare(pos, 4, "$END") == 0)
              {
                word();
                return;
              }
          }
      }

      /// Throws unless the next word is @p end.
      void
      expect(const std::string_view end)
      {
        const std::string_view w = word();
        if (w != end)
          fail("expected " + std::string(end) + " on line " +
               std::to_string(line_number()) + " but found '" + std::string(w) +
               "' (do the counts match the lists?)");
      }

      [[noreturn]] void
      fail(const std::string &what) const
      {
        throw InputError("cannot read mesh file '" + file_name + "': " + what);
      }

    private:
      static bool
      is_blank(const char c)
      {
        return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\f' ||
               c == '\v';
      }

      void
      skip_blanks()
      {
        while (pos < text.size() && is_blank(text[pos]))
          ++pos;
      }

      std::size_t
      line_number() const
      {
        return 1 + std::count(text.begin(),
                              text.begin() + std::min(pos, text.size()),
                              '\n');
      }

      const std::string text;
      const std::string file_name;
      std::size_t       pos = 0;
    };

    /// Node tag -> position in the list of nodes.
    class NodeIndex
    {
    public:
      explicit NodeIndex(const std::vector<long long> &tags)
      {
        long long largest  = 0;
        bool      negative = false;
        for (const long long tag : tags)
          {
            largest  = std::max(largest, tag);
            negative = negative || tag < 0;
          }
        // gmsh numbers nodes 1 ... n: a table then; a hash map for sparse
        // numbers.
        dense = !negative &&
                largest <= 2 * static_cast<long long>(tags.size()) + 1024;
        if (dense)
          table.assign(largest + 1, numbers::invalid_unsigned_int);
        for (std::size_t i = 0; i < tags.size(); ++i)
          if (dense)
            table[tags[i]] = i; // a repeated tag: the last one, as in GridIn
          else
            map[tags[i]] = i;
      }

      /// numbers::invalid_unsigned_int if there is no such node.
      unsigned int
      operator()(const long long tag) const
      {
        if (dense)
          return tag >= 0 && tag < static_cast<long long>(table.size())
                   ? table[tag]
                   : numbers::invalid_unsigned_int;
        const auto it = map.find(tag);
        return it == map.end() ? numbers::invalid_unsigned_int : it->second;
      }

    private:
      bool                                        dense = true;
      std::vector<unsigned int>                   table;
      std::unordered_map<long long, unsigned int> map;
    };

    template <int dim>
    struct GmshMesh
    {
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;
      /// Faces with boundary ids (2D: lines, 3D: triangles) and their
      /// element numbers. (Lines in 3D are read and dropped: only faces
      /// carry boundary ids in a distributed triangulation.)
      SubCellData            boundary;
      std::vector<long long> boundary_numbers;
      std::vector<long long> element_numbers; ///< of cells
      /// Bounds of the nodes of the cells, in all three coordinates.
      Point<3> lower, upper;
    };

    /// The whole file, or InputError.
    std::string
    read_file(const std::string &file_name)
    {
      std::ifstream   in(file_name, std::ios::binary);
      std::error_code error;
      if (!in || !std::filesystem::is_regular_file(file_name, error))
        throw InputError("cannot open mesh file '" + file_name +
                         "' (Mesh/File)" +
                         (in ? ": it is not a regular file" : ""));
      in.seekg(0, std::ios::end);
      const std::streamoff size = in.tellg();
      in.seekg(0);
      std::string text(size > 0 ? size : 0, '\0');
      if (size < 0 || !in.read(text.data(), size))
        throw InputError("cannot read mesh file '" + file_name + "'");
      return text;
    }

    /// Reads an ASCII gmsh file, format 1, 2 or 4, as a mesh of triangles
    /// (dim = 2) or tetrahedra (dim = 3). Points, lines and, in 3D,
    /// triangles carry boundary ids; any other element type is an error.
    template <int dim>
    GmshMesh<dim>
    read_gmsh(const std::string &file_name)
    {
      GmshText in(read_file(file_name), file_name);

      // gmsh element types: 2 is the 3-node triangle, 4 the 4-node tet.
      const int     simplex_type = dim == 2 ? 2 : 4;
      double        version      = 0.;
      GmshMesh<dim> mesh;
      // Per entity dimension: entity tag -> physical tag (format 4).
      std::array<std::map<long long, int>, 4> physical_tags;
      std::vector<Point<3>>                   nodes;
      std::vector<long long>                  node_tags;
      std::unique_ptr<NodeIndex>              node_index;
      long long                               unsupported_tag  = 0;
      long long                               n_unsupported    = 0;
      int                                     unsupported_type = 0;

      const auto vertex = [&](const long long element, const long long node) {
        const unsigned int v =
          node_index ? (*node_index)(node) : numbers::invalid_unsigned_int;
        if (v == numbers::invalid_unsigned_int)
          in.fail("element " + std::to_string(element) + " refers to node " +
                  std::to_string(node) + ", which $Nodes does not define");
        return v;
      };

      const auto read_entities = [&]() {
        std::array<long long, 4> n;
        for (long long &count : n)
          count = in.number<long long>();
        in.skip_line();
        for (unsigned int d = 0; d < 4; ++d)
          for (long long i = 0; i < n[d]; ++i)
            {
              // Points: tag x y z (4.0: a box of 6 numbers); curves, surfaces
              // and volumes: tag and a box; then the physical tags, then the
              // bounding entities (skipped).
              const long long tag     = in.number<long long>();
              const int n_coordinates = (d == 0 && version >= 4.05) ? 3 : 6;
              for (int k = 0; k < n_coordinates; ++k)
                in.number<double>();
              const long long n_physical = in.number<long long>();
              if (n_physical > 1)
                in.fail("entity " + std::to_string(tag) + " of dimension " +
                        std::to_string(d) + " has " +
                        std::to_string(n_physical) +
                        " physical tags; one is read as the boundary id, "
                        "more are not supported");
              int physical = 0; // none: 0, as GridIn
              if (n_physical == 1)
                physical = in.number<int>();
              physical_tags[d][tag] = physical;
              in.skip_line();
            }
        in.expect("$EndEntities");
      };

      const auto read_nodes = [&]() {
        if (version == 0.)
          in.fail("no $MeshFormat section before $Nodes");
        long long n_blocks = 1, n_nodes = 0;
        if (version >= 4.)
          n_blocks = in.number<long long>();
        n_nodes = in.number<long long>();
        in.skip_line(); // format 4.1: smallest and largest tag
        nodes.reserve(n_nodes);
        node_tags.reserve(n_nodes);
        const auto coordinates = [&]() {
          Point<3> x;
          for (unsigned int d = 0; d < 3; ++d)
            x[d] = in.number<double>();
          nodes.push_back(x);
          in.skip_line(); // parametric coordinates, if any
        };
        for (long long b = 0; b < n_blocks; ++b)
          {
            long long n = n_nodes;
            if (version >= 4.)
              {
                // Entity tag and dimension (4.1: the other way round),
                // "parametric", the node count.
                in.number<long long>();
                in.number<long long>();
                in.number<long long>();
                n = in.number<long long>();
                in.skip_line();
              }
            if (version >= 4.05) // n tags, then n coordinate lines
              {
                for (long long i = 0; i < n; ++i)
                  node_tags.push_back(in.number<long long>());
                for (long long i = 0; i < n; ++i)
                  coordinates();
              }
            else // "tag x y z" per line
              for (long long i = 0; i < n; ++i)
                {
                  node_tags.push_back(in.number<long long>());
                  coordinates();
                }
          }
        in.expect(version < 2. ? "$ENDNOD" : "$EndNodes");
        node_index = std::make_unique<NodeIndex>(node_tags);
        node_tags.clear();
        node_tags.shrink_to_fit();
      };

      // One element: its number, type and physical tag read, its nodes next.
      const auto read_element =
        [&](const long long tag, const int type, const int physical) {
          if (type == simplex_type)
            {
              CellData<dim> cell(dim + 1);
              for (unsigned int k = 0; k <= dim; ++k)
                cell.vertices[k] = vertex(tag, in.number<long long>());
              cell.material_id = physical;
              mesh.cells.push_back(std::move(cell));
              mesh.element_numbers.push_back(tag);
            }
          else if (type == 1) // line: a face in 2D
            {
              CellData<1> line;
              for (unsigned int k = 0; k < 2; ++k)
                line.vertices[k] = vertex(tag, in.number<long long>());
              line.boundary_id = physical;
              if (dim == 2)
                {
                  mesh.boundary.boundary_lines.push_back(line);
                  mesh.boundary_numbers.push_back(tag);
                }
            }
          else if (dim == 3 && type == 2) // triangle: boundary id of a face
            {
              CellData<2> triangle(3);
              for (unsigned int k = 0; k < 3; ++k)
                triangle.vertices[k] = vertex(tag, in.number<long long>());
              triangle.boundary_id = physical;
              mesh.boundary.boundary_quads.push_back(std::move(triangle));
              mesh.boundary_numbers.push_back(tag);
            }
          else if (type != 15) // points carry nothing for dim > 1
            {
              if (n_unsupported++ == 0)
                {
                  unsupported_tag  = tag;
                  unsupported_type = type;
                }
            }
          in.skip_line();
        };

      const auto read_elements = [&]() {
        long long n_blocks = 1, n_elements = 0;
        if (version >= 4.)
          n_blocks = in.number<long long>();
        n_elements = in.number<long long>();
        in.skip_line();
        mesh.cells.reserve(n_elements);
        mesh.element_numbers.reserve(n_elements);
        for (long long b = 0; b < n_blocks; ++b)
          {
            long long n        = n_elements;
            int       type     = 0;
            int       physical = 0;
            if (version >= 4.)
              {
                // 4.0: entity tag, entity dimension; 4.1: the other way
                // round; then element type and count.
                const long long a = in.number<long long>();
                const long long c = in.number<long long>();
                type              = in.number<int>();
                n                 = in.number<long long>();
                in.skip_line();
                const long long entity_dim = version >= 4.05 ? a : c;
                const long long entity_tag = version >= 4.05 ? c : a;
                if (entity_dim < 0 || entity_dim > 3)
                  in.fail("element block of entity dimension " +
                          std::to_string(entity_dim));
                const auto found = physical_tags[entity_dim].find(entity_tag);
                physical =
                  found == physical_tags[entity_dim].end() ? 0 : found->second;
              }
            for (long long i = 0; i < n; ++i)
              {
                const long long tag = in.number<long long>();
                if (version < 4.)
                  {
                    type = in.number<int>();
                    if (version < 2.) // physical, elementary, node count
                      {
                        physical = in.number<int>();
                        in.number<long long>();
                        in.number<long long>();
                      }
                    else // tag count, tags (the first is the physical one)
                      {
                        const int n_tags = in.number<int>();
                        physical         = 0;
                        for (int t = 0; t < n_tags; ++t)
                          {
                            const int value = in.number<int>();
                            if (t == 0)
                              physical = value;
                          }
                      }
                  }
                read_element(tag, type, physical);
              }
          }
        in.expect(version < 2. ? "$ENDELM" : "$EndElements");
      };

      while (in.more())
        {
          const std::string_view section = in.word();
          if (section == "$MeshFormat")
            {
              version             = in.number<double>();
              const int file_type = in.number<int>();
              // deal.II's reader never took binary files either; say so rather
              // than fail on binary data.
              if (file_type != 0)
                throw InputError(
                  "mesh file '" + file_name +
                  "' is a binary gmsh file; save it as ASCII (gmsh "
                  "option -format msh41 without -bin, or Mesh.Binary = 0)");
              if (!((version >= 2. && version < 3.) ||
                    (version >= 4. && version < 4.15)))
                in.fail("gmsh format version " + std::to_string(version) +
                        " is not supported (1, 2, 4.0 and 4.1 are)");
              in.skip_line();
              in.expect("$EndMeshFormat");
            }
          else if (section == "$NOD" || section == "$Nodes")
            {
              if (section == "$NOD") // format 1 has no $MeshFormat
                version = 1.;
              read_nodes();
            }
          else if (section == "$ELM" || section == "$Elements")
            read_elements();
          else if (section == "$Entities")
            read_entities();
          else if (section[0] == '$')
            in.skip_section(section);
          else
            in.fail("unexpected '" + std::string(section) +
                    "' outside a section");
        }

      if (n_unsupported > 0)
        throw InputError(
          "mesh file '" + file_name + "': " + std::to_string(n_unsupported) +
          " element(s) of a type hyperelastic does not read, the first gmsh "
          "element " +
          std::to_string(unsupported_tag) + ", a " +
          gmsh_element_name(unsupported_type) + ". A " + std::to_string(dim) +
          "D mesh consists of " +
          (dim == 2 ? "3-node triangles (plus lines"
                    : "4-node tetrahedra (plus triangles, lines") +
          " and points for boundary ids): mesh with simplices, first order "
          "(gmsh: no Recombine, Mesh.ElementOrder = 1), and check "
          "'Problem/Dimension'");
      if (mesh.cells.empty())
        throw InputError("mesh file '" + file_name + "' holds no " +
                         (dim == 2 ? "3-node triangles" : "4-node tetrahedra") +
                         " (gmsh element type " + std::to_string(simplex_type) +
                         "), only lower-dimensional elements: mesh the " +
                         (dim == 2 ? "surface (gmsh -2)" : "volume (gmsh -3)"));

      for (unsigned int d = 0; d < 3; ++d)
        {
          mesh.lower[d] = std::numeric_limits<double>::infinity();
          mesh.upper[d] = -std::numeric_limits<double>::infinity();
        }
      for (const CellData<dim> &cell : mesh.cells)
        for (const unsigned int v : cell.vertices)
          for (unsigned int d = 0; d < 3; ++d)
            {
              mesh.lower[d] = std::min(mesh.lower[d], nodes[v][d]);
              mesh.upper[d] = std::max(mesh.upper[d], nodes[v][d]);
            }
      if constexpr (dim == 3)
        mesh.vertices = std::move(nodes);
      else
        {
          mesh.vertices.reserve(nodes.size());
          for (const Point<3> &x : nodes)
            mesh.vertices.emplace_back(x[0], x[1]);
        }
      return mesh;
    }

    /// A 2D mesh must lie in a plane z = const: only x and y are used.
    void
    check_plane(const std::string &where,
                const Point<3>    &lower,
                const Point<3>    &upper)
    {
      const Tensor<1, 3> extent = upper - lower;
      // A z-variation below 1e-8 of the mesh size changes the projected
      // mesh by less than that: harmless rounding, not a mis-placed mesh.
      if (!(extent[2] > 1e-8 * extent.norm()))
        return;
      const auto range = [&](const unsigned int d) {
        std::ostringstream text;
        text << std::string(1, "xyz"[d]) << " from " << lower[d] << " to "
             << upper[d];
        return text.str();
      };
      std::string plane;
      for (unsigned int d = 0; d < 2; ++d)
        if (extent[d] <= 1e-8 * extent.norm())
          {
            std::ostringstream text;
            text << "it lies in the " << (d == 0 ? "yz" : "xz")
                 << "-plane (all nodes have "
                 << "xy"[d] << " = " << lower[d] << ", " << range(2) << ")";
            plane = text.str();
          }
      if (plane.empty())
        plane = "its nodes are not in one plane z = const (" + range(2) + ")";
      throw InputError(where + " is read as a 2D mesh, but " + plane +
                       ". A 2D mesh uses the x and y coordinates only: draw it "
                       "in the xy-plane (or rotate it there)");
    }

    // ------------------------------------------------------------------
    // The checked cell list of a gmsh file, with face neighbours and
    // boundary ids, from which the descriptions of the ranks' parts are made
    // directly, without a serial triangulation (unless the mesh is to be
    // refined).

    template <int dim>
    struct CheckedMesh
    {
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells; ///< positively oriented
      SubCellData                boundary;
      std::vector<long long>     element_numbers;
      /// Per cell c and face f (deal.II's numbering of the faces of a
      /// simplex), at c (dim + 1) + f: the neighbour's index, or -1 on the
      /// boundary, and the boundary id (internal_face_boundary_id inside).
      std::vector<int>                neighbors;
      std::vector<types::boundary_id> face_ids;
      std::size_t                     n_reoriented = 0;
    };

    /// Face neighbours and boundary ids of @p mesh.cells, from the faces'
    /// vertex sets. Throws InputError for faces of more than two cells and
    /// for boundary ids given to faces inside the mesh.
    template <int dim>
    void
    find_faces(CheckedMesh<dim>             &mesh,
               const std::vector<long long> &boundary_numbers,
               const std::string            &where)
    {
      constexpr unsigned int n_faces = dim + 1;
      const ReferenceCell    simplex = ReferenceCells::get_simplex<dim>();
      struct Face
      {
        std::array<unsigned int, dim> key; ///< sorted vertex indices
        unsigned int                  cell;
        unsigned int                  face;
      };
      const std::size_t n_cells = mesh.cells.size();
      std::vector<Face> faces;
      faces.reserve(n_cells * n_faces);
      for (unsigned int c = 0; c < n_cells; ++c)
        for (unsigned int f = 0; f < n_faces; ++f)
          {
            Face face{{}, c, f};
            for (unsigned int k = 0; k < dim; ++k)
              face.key[k] =
                mesh.cells[c].vertices[simplex.face_to_cell_vertices(f, k, 1)];
            std::sort(face.key.begin(), face.key.end());
            faces.push_back(face);
          }
      std::sort(faces.begin(), faces.end(), [](const Face &a, const Face &b) {
        return a.key < b.key;
      });

      mesh.neighbors.assign(n_cells * n_faces, -1);
      mesh.face_ids.assign(n_cells * n_faces,
                           numbers::internal_face_boundary_id);
      std::vector<long long> crowded;
      std::size_t            n_crowded = 0;
      for (std::size_t i = 0; i < faces.size();)
        {
          std::size_t j = i + 1;
          while (j < faces.size() && faces[j].key == faces[i].key)
            ++j;
          if (j == i + 1)
            mesh.face_ids[faces[i].cell * n_faces + faces[i].face] = 0;
          else if (j == i + 2)
            {
              mesh.neighbors[faces[i].cell * n_faces + faces[i].face] =
                faces[i + 1].cell;
              mesh.neighbors[faces[i + 1].cell * n_faces + faces[i + 1].face] =
                faces[i].cell;
            }
          else
            {
              ++n_crowded;
              for (std::size_t k = i; k < j; ++k)
                crowded.push_back(mesh.element_numbers[faces[k].cell]);
            }
          i = j;
        }
      if (n_crowded > 0)
        {
          std::sort(crowded.begin(), crowded.end());
          crowded.erase(std::unique(crowded.begin(), crowded.end()),
                        crowded.end());
          throw InputError(
            where + ": " + std::to_string(n_crowded) + " " +
            (dim == 2 ? "edge" : "face") + (n_crowded == 1 ? " is" : "s are") +
            " shared by more than two cells (the mesh is not a manifold "
            "there, or has duplicated cells): gmsh elements " +
            list_numbers(crowded) + " " + gmsh_numbering.note);
        }

      // Boundary ids from the lower-dimensional elements; a later element
      // of the same face wins.
      std::vector<long long> inside;
      const auto             assign = [&](const auto &objects) {
        for (std::size_t o = 0; o < objects.size(); ++o)
          {
            Face key{{}, 0, 0};
            if (objects[o].vertices.size() != dim)
              continue;
            std::copy(objects[o].vertices.begin(),
                      objects[o].vertices.end(),
                      key.key.begin());
            std::sort(key.key.begin(), key.key.end());
            const auto found =
              std::lower_bound(faces.begin(),
                               faces.end(),
                               key,
                               [](const Face &a, const Face &b) {
                                 return a.key < b.key;
                               });
            if (found == faces.end() || found->key != key.key)
              continue; // not a face of the mesh: ignored, as by deal.II
            const std::size_t at = found->cell * n_faces + found->face;
            if (mesh.neighbors[at] >= 0)
              inside.push_back(boundary_numbers[o]);
            else
              mesh.face_ids[at] = objects[o].boundary_id;
          }
      };
      if constexpr (dim == 2)
        assign(mesh.boundary.boundary_lines);
      else
        assign(mesh.boundary.boundary_quads);
      if (!inside.empty())
        throw InputError(
          where + ": " + std::to_string(inside.size()) + " " +
          (dim == 2 ? "line" : "triangle") +
          (inside.size() == 1 ? " element lies" : " elements lie") +
          " inside the mesh, on " + (dim == 2 ? "edges" : "faces") +
          " between two cells, where a physical tag cannot be a boundary id: "
          "gmsh " +
          (inside.size() == 1 ? "element " : "elements ") +
          list_numbers(inside) + " " + gmsh_numbering.note);
    }

    template <int dim>
    class FoldTest
    {
    public:
      explicit FoldTest(const CheckedMesh<dim> &mesh)
          : mesh(mesh)
      {
      }

      /// Whether the face neighbours @p a and @p b lie on the same side of
      /// their shared face. Both must be non-degenerate: then the signs
      /// below are those of their measures, well separated from zero.
      bool
      operator()(const unsigned int a, const unsigned int b) const
      {
        const std::vector<unsigned int> &va = mesh.cells[a].vertices;
        const std::vector<unsigned int> &vb = mesh.cells[b].vertices;
        const auto                       in = [](const unsigned int               v,
                           const std::vector<unsigned int> &list) {
          return std::find(list.begin(), list.end(), v) != list.end();
        };
        std::array<unsigned int, dim> face;
        unsigned int                  n_shared = 0;
        unsigned int                  p = numbers::invalid_unsigned_int, q = p;
        for (const unsigned int v : va)
          if (!in(v, vb))
            p = v;
          else if (n_shared < dim)
            face[n_shared++] = v;
        for (const unsigned int v : vb)
          if (!in(v, va))
            q = v;
        if (n_shared != dim || p == numbers::invalid_unsigned_int ||
            q == numbers::invalid_unsigned_int)
          return false; // not face neighbours
        Tensor<2, dim>    columns;
        const Point<dim> &x0 = mesh.vertices[face[0]];
        for (unsigned int k = 1; k < dim; ++k)
          for (unsigned int d = 0; d < dim; ++d)
            columns[d][k - 1] = mesh.vertices[face[k]][d] - x0[d];
        const auto side = [&](const unsigned int v) {
          for (unsigned int d = 0; d < dim; ++d)
            columns[d][dim - 1] = mesh.vertices[v][d] - x0[d];
          return determinant(columns);
        };
        const double sp = side(p), sq = side(q);
        return (sp > 0. && sq > 0.) || (sp < 0. && sq < 0.);
      }

    private:
      const CheckedMesh<dim> &mesh;
    };

    /// The cells (by index) that are inverted relative to the rest of their
    /// connected part of the mesh, cells marked @p degenerate left out.
    /// @p listed_negative serves to break ties.
    template <int dim>
    std::vector<unsigned int>
    find_inverted_cells(const CheckedMesh<dim>  &mesh,
                        const std::vector<bool> &degenerate,
                        const std::vector<bool> &listed_negative)
    {
      constexpr unsigned int n_faces = dim + 1;
      const unsigned int     n       = mesh.cells.size();
      const FoldTest<dim>    folded(mesh);
      // Cheap pass first: most meshes have no fold.
      bool any_fold = false;
      for (unsigned int c = 0; c < n && !any_fold; ++c)
        if (!degenerate[c])
          for (unsigned int f = 0; f < n_faces; ++f)
            {
              const int j = mesh.neighbors[c * n_faces + f];
              if (j > static_cast<int>(c) && !degenerate[j] && folded(c, j))
                any_fold = true;
            }
      if (!any_fold)
        return {};

      // Relative orientation g = +-1, kept across a face, flipped across a
      // folded one; per connected part the minority is inverted.
      std::vector<signed char>  g(n, 0);
      std::vector<unsigned int> inverted, part;
      for (unsigned int seed = 0; seed < n; ++seed)
        {
          if (degenerate[seed] || g[seed] != 0)
            continue;
          part.assign(1, seed);
          g[seed] = 1;
          for (std::size_t next = 0; next < part.size(); ++next)
            {
              const unsigned int c = part[next];
              for (unsigned int f = 0; f < n_faces; ++f)
                {
                  const int j = mesh.neighbors[c * n_faces + f];
                  if (j < 0 || degenerate[j] || g[j] != 0)
                    continue;
                  g[j] = folded(c, j) ? -g[c] : g[c];
                  part.push_back(j);
                }
            }
          std::size_t plus = 0, plus_listed_negative = 0,
                      minus_listed_negative = 0;
          for (const unsigned int i : part)
            {
              plus += g[i] > 0 ? 1 : 0;
              (g[i] > 0 ? plus_listed_negative : minus_listed_negative) +=
                listed_negative[i] ? 1 : 0;
            }
          const std::size_t minus = part.size() - plus;
          // The minority; on a tie the part listed negatively, else the
          // part without the seed.
          const signed char odd = plus < minus   ? 1
                                  : minus < plus ? -1
                                  : plus_listed_negative > minus_listed_negative
                                    ? 1
                                    : -1;
          for (const unsigned int i : part)
            if (g[i] == odd)
              inverted.push_back(i);
        }
      std::sort(inverted.begin(), inverted.end());
      return inverted;
    }

    /// The mesh of a gmsh file, checked, with every cell positively
    /// oriented, and its faces.
    template <int dim>
    CheckedMesh<dim>
    read_and_check_gmsh(const std::string &file_name,
                        MeshStatistics    &statistics)
    {
      Timer         timer;
      GmshMesh<dim> file   = read_gmsh<dim>(file_name);
      statistics.read_time = timer.wall_time();
      timer.restart();

      const std::string where = "mesh file '" + file_name + "'";
      if (dim == 2)
        check_plane(where, file.lower, file.upper);

      CheckedMesh<dim> mesh;
      mesh.vertices        = std::move(file.vertices);
      mesh.cells           = std::move(file.cells);
      mesh.boundary        = std::move(file.boundary);
      mesh.element_numbers = std::move(file.element_numbers);

      // Zero measure and orientation as listed; negatively oriented cells
      // reoriented as deal.II's GridIn does it (last two vertices swapped).
      const std::size_t      n_cells = mesh.cells.size();
      std::vector<bool>      degenerate(n_cells, false);
      std::vector<bool>      listed_negative(n_cells, false);
      std::vector<long long> degenerate_numbers;
      for (std::size_t c = 0; c < n_cells; ++c)
        {
          std::vector<unsigned int> &v       = mesh.cells[c].vertices;
          const SimplexMeasure       measure = simplex_measure<dim>(
            [&](const unsigned int k) -> const Point<dim>       &{
              return mesh.vertices[v[k]];
            });
          if (measure.degenerate)
            {
              degenerate[c] = true;
              degenerate_numbers.push_back(mesh.element_numbers[c]);
            }
          else if (measure.det < 0.)
            {
              listed_negative[c] = true;
              std::swap(v[dim - 1], v[dim]);
              ++mesh.n_reoriented;
            }
        }

      find_faces(mesh, file.boundary_numbers, where);
      statistics.build_time = timer.wall_time();

      // Folds.
      const std::vector<unsigned int> inverted =
        find_inverted_cells(mesh, degenerate, listed_negative);
      if (!degenerate_numbers.empty() || !inverted.empty())
        {
          std::vector<long long> inverted_numbers;
          std::vector<bool>      is_inverted(n_cells, false);
          for (const unsigned int c : inverted)
            {
              inverted_numbers.push_back(mesh.element_numbers[c]);
              is_inverted[c] = true;
            }
          std::sort(inverted_numbers.begin(), inverted_numbers.end());
          std::sort(degenerate_numbers.begin(), degenerate_numbers.end());
          // Does the listing tell the same story (a consistently listed
          // mesh with a fold)? Then say it in its terms.
          int inverted_listed = 0;
          if (!inverted.empty())
            {
              const bool first = listed_negative[inverted[0]];
              bool       same  = true;
              for (std::size_t c = 0; c < n_cells && same; ++c)
                if (!degenerate[c])
                  same =
                    listed_negative[c] == (is_inverted[c] ? first : !first);
              if (same)
                inverted_listed = first ? -1 : 1;
            }
          throw InputError(where + ": " +
                           cell_problems<dim>(n_cells,
                                              degenerate_numbers,
                                              inverted_numbers,
                                              inverted_listed,
                                              gmsh_numbering));
        }
      statistics.check_time = timer.wall_time() - statistics.build_time;
      return mesh;
    }

    /// METIS partition of the cells of @p mesh into @p n_parts, computed
    /// as GridTools::partition_triangulation() does for a triangulation of
    /// these cells (the same graph of face neighbours, hence the same
    /// partition).
    template <int dim>
    std::vector<unsigned int>
    partition_cells(const CheckedMesh<dim> &mesh, const unsigned int n_parts)
    {
      const unsigned int        n = mesh.cells.size();
      std::vector<unsigned int> owner(n, 0);
      if (n_parts == 1)
        return owner;
      // Each row: the cell itself and its face neighbours (the sparsity
      // pattern sorts the columns, as when copied from the
      // DynamicSparsityPattern that GridTools builds).
      std::vector<unsigned int> row_lengths(n, 1);
      for (unsigned int c = 0; c < n; ++c)
        for (unsigned int f = 0; f <= dim; ++f)
          row_lengths[c] += mesh.neighbors[c * (dim + 1) + f] >= 0 ? 1 : 0;
      SparsityPattern pattern(n, n, row_lengths);
      for (unsigned int c = 0; c < n; ++c)
        {
          pattern.add(c, c);
          for (unsigned int f = 0; f <= dim; ++f)
            {
              const int j = mesh.neighbors[c * (dim + 1) + f];
              if (j >= 0)
                pattern.add(c, j);
            }
        }
      pattern.compress();
      SparsityTools::partition(pattern,
                               std::vector<unsigned int>(),
                               n_parts,
                               owner,
                               SparsityTools::Partitioner::metis);
      return owner;
    }

    /// The description of the part of rank @p rank: its cells and the
    /// ghost layer (every cell with a vertex of one of its cells), as
    /// TriangulationDescription::Utilities::
    /// create_description_from_triangulation() makes it from a serial
    /// triangulation of these cells that is not refined.
    template <int dim>
    TriangulationDescription::Description<dim, dim>
    describe_part(const CheckedMesh<dim>          &mesh,
                  const std::vector<unsigned int> &owner,
                  const unsigned int               rank,
                  const MPI_Comm                   comm)
    {
      constexpr unsigned int n_faces = dim + 1;
      const unsigned int     n       = mesh.cells.size();
      std::vector<char>      near(mesh.vertices.size(), 0);
      for (unsigned int c = 0; c < n; ++c)
        if (owner[c] == rank)
          for (const unsigned int v : mesh.cells[c].vertices)
            near[v] = 1;
      std::vector<unsigned int> relevant;
      std::vector<unsigned int> local(mesh.vertices.size(),
                                      numbers::invalid_unsigned_int);
      for (unsigned int c = 0; c < n; ++c)
        {
          bool is_relevant = false;
          for (const unsigned int v : mesh.cells[c].vertices)
            is_relevant = is_relevant || near[v] != 0;
          if (is_relevant)
            {
              relevant.push_back(c);
              for (const unsigned int v : mesh.cells[c].vertices)
                local[v] = 0;
            }
        }

      TriangulationDescription::Description<dim, dim> description;
      description.comm = comm;
      description.settings =
        TriangulationDescription::Settings::default_setting;
      description.smoothing = Triangulation<dim>::none;
      unsigned int n_local  = 0;
      for (unsigned int v = 0; v < mesh.vertices.size(); ++v)
        if (local[v] == 0)
          {
            local[v] = n_local++;
            description.coarse_cell_vertices.push_back(mesh.vertices[v]);
          }
      description.coarse_cells.reserve(relevant.size());
      description.coarse_cell_index_to_coarse_cell_id.reserve(relevant.size());
      description.cell_infos.resize(1);
      description.cell_infos[0].reserve(relevant.size());
      for (const unsigned int c : relevant)
        {
          CellData<dim> cell(dim + 1);
          for (unsigned int k = 0; k <= dim; ++k)
            cell.vertices[k] = local[mesh.cells[c].vertices[k]];
          cell.material_id = mesh.cells[c].material_id;
          cell.manifold_id = numbers::flat_manifold_id;
          description.coarse_cells.push_back(std::move(cell));
          description.coarse_cell_index_to_coarse_cell_id.push_back(c);

          TriangulationDescription::CellData<dim> info;
          info.id = CellId(c, std::vector<std::uint8_t>()).to_binary<dim>();
          info.subdomain_id       = owner[c];
          info.level_subdomain_id = 0;
          info.manifold_id        = numbers::flat_manifold_id;
          info.manifold_line_ids.fill(numbers::flat_manifold_id);
          info.manifold_quad_ids.fill(numbers::flat_manifold_id);
          for (unsigned int f = 0; f < n_faces; ++f)
            if (mesh.neighbors[c * n_faces + f] < 0)
              info.boundary_ids.emplace_back(f, mesh.face_ids[c * n_faces + f]);
          description.cell_infos[0].push_back(std::move(info));
        }
      return description;
    }

    /// The generated box; its cells are checked as deal.II made them
    /// (extreme aspect ratios can make them flat).
    template <int dim>
    void
    build_box(const MeshParameters &parameters, Triangulation<dim> &serial)
    {
      Point<dim>                p1, p2;
      std::vector<unsigned int> repetitions(dim);
      for (unsigned int d = 0; d < dim; ++d)
        {
          p1[d]          = parameters.lower_corner[d];
          p2[d]          = parameters.upper_corner[d];
          repetitions[d] = parameters.subdivisions[d];
        }
      GridGenerator::subdivided_hyper_rectangle_with_simplices(serial,
                                                               repetitions,
                                                               p1,
                                                               p2);
      set_box_boundary_ids(serial);

      std::vector<long long> degenerate, negative;
      for (const auto &cell : serial.active_cell_iterators())
        {
          const SimplexMeasure measure = simplex_measure<dim>(
            [&](const unsigned int k) -> const Point<dim> & {
              return cell->vertex(k);
            });
          if (measure.degenerate)
            degenerate.push_back(cell->active_cell_index());
          else if (measure.det < 0.)
            negative.push_back(cell->active_cell_index());
        }
      if (!degenerate.empty())
        throw InputError(
          "the generated box: " +
          cell_problems<dim>(
            serial.n_active_cells(),
            degenerate,
            {},
            0,
            {"cell", "cells", "(deal.II's cell numbers, from 0)"}));
      AssertThrow(negative.empty(),
                  ExcMessage("the generated box has " +
                             std::to_string(negative.size()) +
                             " negatively oriented cells"));
    }

    // ------------------------------------------------------------------
    // Messages from the reader: tags of their own, on the triangulation's
    // communicator.
    constexpr int outcome_tag = 20151, description_tag = 20152;

    void
    send(const std::vector<char> &buffer,
         const unsigned int       destination,
         const int                tag,
         const MPI_Comm           comm)
    {
      AssertThrow(buffer.size() <=
                    static_cast<std::size_t>(std::numeric_limits<int>::max()),
                  ExcMessage("a mesh message of " +
                             std::to_string(buffer.size()) +
                             " bytes is too large for one MPI message: use "
                             "more ranks"));
      const int ierr = MPI_Send(buffer.data(),
                                static_cast<int>(buffer.size()),
                                MPI_CHAR,
                                destination,
                                tag,
                                comm);
      AssertThrowMPI(ierr);
    }

    /// The message of @p tag from @p source. Polls, sleeping in between,
    /// instead of blocking in MPI: Open MPI spins while it blocks, and a
    /// rank waiting for the reader would take a core from it on a node
    /// shared with other jobs or with more ranks than cores.
    std::vector<char>
    receive(const unsigned int source, const int tag, const MPI_Comm comm)
    {
      std::chrono::microseconds pause(20);
      MPI_Status                status;
      for (int found = 0;;)
        {
          const int ierr = MPI_Iprobe(source, tag, comm, &found, &status);
          AssertThrowMPI(ierr);
          if (found)
            break;
          std::this_thread::sleep_for(pause);
          pause = std::min(2 * pause, std::chrono::microseconds(2000));
        }
      int size = 0;
      MPI_Get_count(&status, MPI_CHAR, &size);
      std::vector<char> buffer(size);
      const int         ierr = MPI_Recv(
        buffer.data(), size, MPI_CHAR, source, tag, comm, MPI_STATUS_IGNORE);
      AssertThrowMPI(ierr);
      return buffer;
    }

    /// What the reader tells the other ranks before the distribution.
    struct ReaderOutcome
    {
      enum Status : int
      {
        ok,
        input_error,
        other_error
      };
      int                             status = ok;
      std::string                     message;
      std::vector<types::boundary_id> boundary_ids;
      std::size_t                     global_cells     = 0;
      std::size_t                     reoriented_cells = 0;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &status &message &boundary_ids &global_cells &reoriented_cells;
      }
    };
  } // namespace

  template <int dim>
  std::set<types::boundary_id>
  create_mesh(const MeshParameters                           &parameters,
              parallel::fullydistributed::Triangulation<dim> &tria,
              MeshStatistics                                 *statistics)
  {
    const MPI_Comm     comm    = tria.get_communicator();
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int reader  = 0;
    const bool is_reader = Utilities::MPI::this_mpi_process(comm) == reader;

    // The whole mesh, on the reader only: a file's checked list of cells,
    // from which the parts are described directly, or (for a box, or a
    // file to be refined) a serial triangulation.
    MeshStatistics            stats;
    CheckedMesh<dim>          mesh;
    std::vector<unsigned int> owner; // of each cell of mesh
    Triangulation<dim>        serial;
    const bool from_cells = parameters.source == MeshSource::file &&
                            parameters.global_refinements == 0;
    ReaderOutcome      outcome;
    std::exception_ptr reader_exception;
    if (is_reader)
      {
        stats.reader = true;
        try
          {
            if (parameters.source == MeshSource::box)
              {
                Timer timer;
                build_box(parameters, serial);
                stats.read_time = timer.wall_time();
              }
            else
              {
                mesh = read_and_check_gmsh<dim>(parameters.file, stats);
                outcome.reoriented_cells = mesh.n_reoriented;
              }
            if (!from_cells && parameters.source == MeshSource::file)
              {
                Timer timer;
                try
                  {
                    serial.create_triangulation(mesh.vertices,
                                                mesh.cells,
                                                mesh.boundary);
                  }
                catch (const std::exception &e)
                  {
                    throw InputError(
                      "cannot read mesh file '" + parameters.file +
                      "' as a gmsh mesh of dimension " + std::to_string(dim) +
                      ": " + exception_message(e));
                  }
                mesh = CheckedMesh<dim>();
                stats.build_time += timer.wall_time();
              }

            Timer timer;
            if (from_cells)
              {
                owner = partition_cells(mesh, n_ranks);
                std::set<types::boundary_id> ids;
                for (std::size_t i = 0; i < mesh.neighbors.size(); ++i)
                  if (mesh.neighbors[i] < 0)
                    ids.insert(mesh.face_ids[i]);
                outcome.boundary_ids.assign(ids.begin(), ids.end());
                outcome.global_cells = mesh.cells.size();
              }
            else
              {
                serial.refine_global(parameters.global_refinements);
                outcome.boundary_ids = serial.get_boundary_ids();
                if (n_ranks > 1)
                  GridTools::partition_triangulation(
                    n_ranks, serial, SparsityTools::Partitioner::metis);
                outcome.global_cells = serial.n_active_cells();
              }
            stats.partition_time = timer.wall_time();
          }
        catch (const InputError &e)
          {
            outcome.status  = ReaderOutcome::input_error;
            outcome.message = e.what();
          }
        catch (const std::exception &e)
          {
            outcome.status   = ReaderOutcome::other_error;
            outcome.message  = exception_message(e);
            reader_exception = std::current_exception();
          }
        catch (...)
          {
            outcome.status   = ReaderOutcome::other_error;
            outcome.message  = "unknown exception";
            reader_exception = std::current_exception();
          }
      }

    // The other ranks wait for the outcome first, so that a failure of the
    // reader reaches them as the same exception.
    Timer timer;
    if (n_ranks > 1)
      {
        if (is_reader)
          {
            const std::vector<char> buffer = Utilities::pack(outcome, false);
            for (unsigned int r = 0; r < n_ranks; ++r)
              if (r != reader)
                send(buffer, r, outcome_tag, comm);
          }
        else
          outcome =
            Utilities::unpack<ReaderOutcome>(receive(reader, outcome_tag, comm),
                                             false);
      }
    if (outcome.status == ReaderOutcome::input_error)
      throw InputError(outcome.message);
    if (outcome.status == ReaderOutcome::other_error)
      {
        if (reader_exception)
          std::rethrow_exception(reader_exception);
        throw std::runtime_error("creating the mesh failed on MPI rank " +
                                 std::to_string(reader) + ": " +
                                 outcome.message);
      }

    // The reader makes and sends one description per rank, one at a time
    // (as TriangulationDescription::Utilities::
    // create_description_from_triangulation_in_groups() does for a single
    // group), the others first, so that they build their part while it
    // makes its own; then it frees the whole mesh.
    stats.wait_time = timer.wall_time();
    timer.restart();
    stats.serial_cells  = is_reader ? outcome.global_cells : 0;
    const auto describe = [&](const unsigned int rank) {
      return from_cells
               ? describe_part(mesh, owner, rank, comm)
               : TriangulationDescription::Utilities::
                   create_description_from_triangulation(
                     serial,
                     comm,
                     TriangulationDescription::Settings::default_setting,
                     rank);
    };
    TriangulationDescription::Description<dim, dim> description;
    if (is_reader)
      {
        for (unsigned int r = 0; r < n_ranks; ++r)
          if (r != reader)
            send(Utilities::pack(describe(r), false), r, description_tag, comm);
        description = describe(reader);
        mesh        = CheckedMesh<dim>();
        serial.clear();
      }
    else
      {
        description =
          Utilities::unpack<TriangulationDescription::Description<dim, dim>>(
            receive(reader, description_tag, comm), false);
        description.comm = comm; // not serialized
      }
    stats.describe_time = timer.wall_time();
    timer.restart();
    stats.description_coarse_cells = description.coarse_cells.size();
    tria.create_triangulation(description);
    stats.distribute_time  = timer.wall_time();
    stats.global_cells     = outcome.global_cells;
    stats.reoriented_cells = outcome.reoriented_cells;
    if (statistics)
      *statistics = stats;
    return std::set<types::boundary_id>(outcome.boundary_ids.begin(),
                                        outcome.boundary_ids.end());
  }

  template void
  set_box_boundary_ids(Triangulation<2> &);
  template void
  set_box_boundary_ids(Triangulation<3> &);
  template std::set<types::boundary_id>
  create_mesh(const MeshParameters &,
              parallel::fullydistributed::Triangulation<2> &,
              MeshStatistics *);
  template std::set<types::boundary_id>
  create_mesh(const MeshParameters &,
              parallel::fullydistributed::Triangulation<3> &,
              MeshStatistics *);
} // namespace hyperelastic
