// Reading a gmsh file: the whole file read into memory once and parsed
// once (ASCII, formats 1, 2.2, 4.0 and 4.1) into a list of cells with their
// gmsh element numbers and physical tags.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/gmsh_reader.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
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

    /// The whole file, or InputError.
    std::string
    read_file(const std::string &file_name, const std::string &entry)
    {
      std::ifstream   in(file_name, std::ios::binary);
      std::error_code error;
      if (!in || !std::filesystem::is_regular_file(file_name, error))
        throw InputError("cannot open mesh file '" + file_name + "' (" + entry +
                         ")" + (in ? ": it is not a regular file" : ""));
      in.seekg(0, std::ios::end);
      const std::streamoff size = in.tellg();
      in.seekg(0);
      std::string text(size > 0 ? size : 0, '\0');
      if (size < 0 || !in.read(text.data(), size))
        throw InputError("cannot read mesh file '" + file_name + "'");
      return text;
    }

    /// One pass over a gmsh file, section by section: each section's
    /// reader adds to the mesh (or to what later sections need: the format
    /// version, the entities' physical tags, the node index).
    template <int dim>
    class GmshParser
    {
    public:
      GmshParser(const std::string &file_name, const std::string &entry)
          : file_name(file_name)
          , in(read_file(file_name, entry), file_name)
      {
      }

      /// Reads every section; unknown ones are skipped.
      void
      read_sections()
      {
        while (in.more())
          {
            const std::string_view section = in.word();
            if (section == "$MeshFormat")
              read_mesh_format();
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
      }

      /// The mesh read: InputError if it holds elements of other types, or
      /// (if @p cells_required) no cells.
      GmshMesh<dim>
      finish(const bool cells_required)
      {
        check_element_types(cells_required);
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
        return std::move(mesh);
      }

    private:
      /// $MeshFormat: the version (ASCII files of formats 2 and 4 only).
      void
      read_mesh_format()
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

      /// $Entities (format 4): the physical tag of every entity.
      void
      read_entities()
      {
        std::array<long long, 4> n;
        for (long long &count : n)
          count = in.number<long long>();
        in.skip_line();
        for (unsigned int d = 0; d < 4; ++d)
          for (long long i = 0; i < n[d]; ++i)
            {
              // Points: tag x y z (4.0: a box of 6 numbers); curves,
              // surfaces and volumes: tag and a box; then the physical tags,
              // then the bounding entities (skipped).
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
      }

      /// $Nodes (or format 1's $NOD): the positions, and the index of the
      /// node tags.
      void
      read_nodes()
      {
        if (version == 0.)
          in.fail("no $MeshFormat section before $Nodes");
        long long n_blocks = 1, n_nodes = 0;
        if (version >= 4.)
          n_blocks = in.number<long long>();
        n_nodes = in.number<long long>();
        in.skip_line(); // format 4.1: smallest and largest tag
        nodes.reserve(n_nodes);
        node_tags.reserve(n_nodes);
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
                  read_coordinates();
              }
            else // "tag x y z" per line
              for (long long i = 0; i < n; ++i)
                {
                  node_tags.push_back(in.number<long long>());
                  read_coordinates();
                }
          }
        in.expect(version < 2. ? "$ENDNOD" : "$EndNodes");
        node_index = std::make_unique<NodeIndex>(node_tags);
        node_tags.clear();
        node_tags.shrink_to_fit();
      }

      /// One node's x y z, the rest of its line skipped.
      void
      read_coordinates()
      {
        Point<3> x;
        for (unsigned int d = 0; d < 3; ++d)
          x[d] = in.number<double>();
        nodes.push_back(x);
        in.skip_line(); // parametric coordinates, if any
      }

      /// $Elements (or format 1's $ELM): block by block (format 4) or one
      /// element per line with its type and tags (formats 1 and 2).
      void
      read_elements()
      {
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
              read_element_block_header(type, n, physical);
            for (long long i = 0; i < n; ++i)
              {
                const long long tag = in.number<long long>();
                if (version < 4.)
                  read_element_tags(type, physical);
                read_element(tag, type, physical);
              }
          }
        in.expect(version < 2. ? "$ENDELM" : "$EndElements");
      }

      /// Format 4: a block's element type, element count and the physical
      /// tag of its entity.
      void
      read_element_block_header(int &type, long long &n, int &physical)
      {
        // 4.0: entity tag, entity dimension; 4.1: the other way round;
        // then element type and count.
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
        physical = found == physical_tags[entity_dim].end() ? 0 : found->second;
      }

      /// Formats 1 and 2: an element's type and physical tag, after its
      /// number.
      void
      read_element_tags(int &type, int &physical)
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

      /// One element: its number, type and physical tag read, its nodes
      /// next.
      void
      read_element(const long long tag, const int type, const int physical)
      {
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
      }

      /// The position in the list of nodes of node @p node of element
      /// @p element.
      unsigned int
      vertex(const long long element, const long long node)
      {
        const unsigned int v =
          node_index ? (*node_index)(node) : numbers::invalid_unsigned_int;
        if (v == numbers::invalid_unsigned_int)
          in.fail("element " + std::to_string(element) + " refers to node " +
                  std::to_string(node) + ", which $Nodes does not define");
        return v;
      }

      /// Elements of types hyperelastic does not read, or no cells at all,
      /// are InputErrors.
      void
      check_element_types(const bool cells_required) const
      {
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
        if (mesh.cells.empty() && cells_required)
          throw InputError(
            "mesh file '" + file_name + "' holds no " +
            (dim == 2 ? "3-node triangles" : "4-node tetrahedra") +
            " (gmsh element type " + std::to_string(simplex_type) +
            "), only lower-dimensional elements: mesh the " +
            (dim == 2 ? "surface (gmsh -2)" : "volume (gmsh -3)"));
      }

      // gmsh element types: 2 is the 3-node triangle, 4 the 4-node tet.
      static constexpr int simplex_type = dim == 2 ? 2 : 4;

      const std::string &file_name;
      GmshText           in;
      double             version = 0.;
      GmshMesh<dim>      mesh;
      // Per entity dimension: entity tag -> physical tag (format 4).
      std::array<std::map<long long, int>, 4> physical_tags;
      std::vector<Point<3>>                   nodes;
      std::vector<long long>                  node_tags;
      std::unique_ptr<NodeIndex>              node_index;
      long long                               unsupported_tag  = 0;
      long long                               n_unsupported    = 0;
      int                                     unsupported_type = 0;
    };
  } // namespace

  template <int dim>
  GmshMesh<dim>
  read_gmsh(const std::string &file_name,
            const std::string &entry,
            const bool         cells_required)
  {
    GmshParser<dim> parser(file_name, entry);
    parser.read_sections();
    return parser.finish(cells_required);
  }

  template GmshMesh<2>
  read_gmsh<2>(const std::string &, const std::string &, bool);
  template GmshMesh<3>
  read_gmsh<3>(const std::string &, const std::string &, bool);
} // namespace hyperelastic
