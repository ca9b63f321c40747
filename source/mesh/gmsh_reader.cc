// Reading a gmsh file: the whole file read into memory once and parsed
// once (ASCII, formats 1, 2.2, 4.0 and 4.1; binary, formats 2.2 and 4.1 in
// either byte order) into a list of cells with their gmsh element numbers
// and physical tags.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/gmsh_reader.h>
#include <hyperelastic/mesh/mesh_file_text.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <string_view>
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

    /// Nodes of a gmsh element type (binary files list no count per
    /// element); 0 for a type not in this table.
    int
    gmsh_nodes_per_element(const int type)
    {
      // Types 1 ... 31 of gmsh's element list (lines, triangles,
      // quadrangles, tetrahedra, hexahedra, prisms, pyramids and their
      // higher-order versions), then the 4th- and 5th-order tetrahedra.
      static constexpr std::array<int, 32> n = {
        {0, 2,  3,  4,  4, 8,  6,  5,  3,  6,  9, 10, 27, 18, 14, 1,
         8, 20, 15, 13, 9, 10, 12, 15, 15, 21, 4, 5,  6,  20, 35, 56}};
      if (type > 0 && type < static_cast<int>(n.size()))
        return n[type];
      if (type == 92)
        return 64;
      if (type == 93)
        return 125;
      return 0;
    }

    /// One pass over a gmsh file, section by section: each section's
    /// reader adds to the mesh (or to what later sections need: the format
    /// version, the entities' physical tags, the node index). ASCII files
    /// are read token by token; binary files (formats 2.2 and 4.1, either
    /// byte order) block by block.
    template <int dim>
    class GmshParser
    {
    public:
      GmshParser(const std::string &file_name, const std::string &entry)
          : file_name(file_name)
          , in(read_whole_file(file_name, entry), file_name)
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
                if (binary)
                  read_binary_nodes();
                else
                  read_nodes();
              }
            else if (section == "$ELM" || section == "$Elements")
              {
                if (binary)
                  read_binary_elements();
                else
                  read_elements();
              }
            else if (section == "$Entities")
              {
                if (binary)
                  read_binary_entities();
                else
                  read_entities();
              }
            else if (section[0] == '$')
              skip_section(section);
            else
              in.fail(
                "unexpected '" + std::string(section.substr(0, 40)) +
                "' outside a section" +
                (binary ? "" : " on line " + std::to_string(in.line_number())));
          }
      }

      /// The mesh read: InputError if it holds elements of other types, or
      /// (if @p cells_required) no cells.
      GmshMesh<dim>
      finish(const bool cells_required)
      {
        check_element_types(cells_required);
        finish_mesh_cells(mesh, std::move(nodes));
        return std::move(mesh);
      }

    private:
      /// $MeshFormat: the version, and for a binary file the size of its
      /// integers and its byte order (the int 1 after the header line).
      void
      read_mesh_format()
      {
        version             = in.number<double>();
        const int file_type = in.number<int>();
        data_size           = in.number<int>();
        if (!((version >= 2. && version < 3.) ||
              (version >= 4. && version < 4.15)))
          in.fail("gmsh format version " + std::to_string(version) +
                  " is not supported (1, 2, 4.0 and 4.1 are)");
        if (file_type != 0 && file_type != 1)
          in.fail("file type " + std::to_string(file_type) +
                  " in $MeshFormat (0 is ASCII, 1 binary)");
        binary = file_type == 1;
        in.skip_line();
        if (binary)
          {
            if (version >= 4. && version < 4.05)
              in.fail("binary gmsh format 4.0 is not read (binary 2.2 and "
                      "4.1 are, and ASCII 4.0): save it as format 4.1 "
                      "(gmsh option -format msh41)");
            if (version < 4. && data_size != 8)
              in.fail("binary gmsh format 2 with data size " +
                      std::to_string(data_size) +
                      " (only 8-byte doubles are read)");
            if (version >= 4. && data_size != 4 && data_size != 8)
              in.fail("binary gmsh format 4.1 with size_t of " +
                      std::to_string(data_size) + " bytes (4 or 8 are read)");
            // The int 1 as the writing machine stored it.
            const auto   one = in.binary<std::int32_t>(false, "$MeshFormat");
            std::int32_t swapped = one;
            auto        *b       = reinterpret_cast<unsigned char *>(&swapped);
            std::reverse(b, b + sizeof(swapped));
            if (one != 1 && swapped != 1)
              in.fail("the binary $MeshFormat does not hold the int 1 after "
                      "its header line (the byte order cannot be told)");
            swap = one != 1;
          }
        in.expect("$EndMeshFormat");
      }

      /// Skips the section that begins with @p name, up to the word that
      /// starts with "$End" (or "$END").
      void
      skip_section(const std::string_view name)
      {
        // Binary data (TetWild's $ElementData) may run up to its $End
        // marker without a line end.
        if (binary)
          {
            in.skip_past("$End" + std::string(name.substr(1)), name);
            return;
          }
        for (;;)
          {
            const std::string_view w = in.skip_to_line_starting("$E", name);
            if (w.substr(0, 4) == "$End" || w.substr(0, 4) == "$END")
              return;
          }
      }

      // ---------------------------------------------------------------
      // ASCII

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
              check_physical_count(tag, d, n_physical);
              int physical = 0; // none: 0, as GridIn
              if (n_physical == 1)
                physical = in.number<int>();
              physical_tags[d][tag] = physical;
              in.skip_line();
            }
        in.expect("$EndEntities");
      }

      void
      check_physical_count(const long long    tag,
                           const unsigned int d,
                           const long long    n_physical) const
      {
        if (n_physical > 1)
          in.fail("entity " + std::to_string(tag) + " of dimension " +
                  std::to_string(d) + " has " + std::to_string(n_physical) +
                  " physical tags; one is read as the boundary id, "
                  "more are not supported");
        if (n_physical < 0)
          in.fail("entity " + std::to_string(tag) + " of dimension " +
                  std::to_string(d) +
                  " has a negative count of physical "
                  "tags in $Entities");
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
        reserve_nodes(n_nodes);
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
        index_nodes();
      }

      void
      reserve_nodes(const long long n_nodes)
      {
        if (n_nodes < 0)
          in.fail("negative node count in $Nodes");
        // A count beyond what the file can hold is an error found when the
        // data ends; do not reserve for it.
        const auto bound = static_cast<long long>(in.size() / 8 + 1);
        nodes.reserve(std::min(n_nodes, bound));
        node_tags.reserve(std::min(n_nodes, bound));
      }

      void
      index_nodes()
      {
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
        reserve_elements(n_elements);
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
                physical = block_physical_tag(version >= 4.05 ? a : c,
                                              version >= 4.05 ? c : a);
              }
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

      void
      reserve_elements(const long long n_elements)
      {
        if (n_elements < 0)
          in.fail("negative element count in $Elements");
        const auto bound = static_cast<long long>(in.size() / 8 + 1);
        mesh.cells.reserve(std::min(n_elements, bound));
        mesh.element_numbers.reserve(std::min(n_elements, bound));
      }

      /// Format 4: the physical tag of the entity of an element block.
      int
      block_physical_tag(const long long entity_dim,
                         const long long entity_tag) const
      {
        if (entity_dim < 0 || entity_dim > 3)
          in.fail("element block of entity dimension " +
                  std::to_string(entity_dim));
        const auto found = physical_tags[entity_dim].find(entity_tag);
        return found == physical_tags[entity_dim].end() ? 0 : found->second;
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

      /// One element of an ASCII file: its number, type and physical tag
      /// read, its nodes next.
      void
      read_element(const long long tag, const int type, const int physical)
      {
        const int n = is_read(type) ? gmsh_nodes_per_element(type) : 0;
        std::array<long long, 4> element_nodes;
        for (int k = 0; k < n; ++k)
          element_nodes[k] = in.number<long long>();
        add_element(tag, type, physical, element_nodes.data());
        in.skip_line();
      }

      // ---------------------------------------------------------------
      // Binary (formats 2.2 and 4.1): the counts of format 2 are text,
      // everything else binary; the data of a section ends with a line
      // end before its $End line.

      /// A size_t of format 4.1 (data_size bytes).
      long long
      binary_size(const std::string_view section)
      {
        std::uint64_t value;
        if (data_size == 8)
          value = in.binary<std::uint64_t>(swap, section);
        else
          value = in.binary<std::uint32_t>(swap, section);
        if (value >
            static_cast<std::uint64_t>(std::numeric_limits<long long>::max()))
          in.fail("a count or tag out of range in " + std::string(section));
        return static_cast<long long>(value);
      }

      /// The size_t of format 4.1 at @p bytes (an element's number or
      /// node tag); -1 (no such node) beyond the range of long long.
      long long
      size_at(const char *bytes) const
      {
        const std::uint64_t value = data_size == 8
                                      ? load_binary<std::uint64_t>(bytes, swap)
                                      : load_binary<std::uint32_t>(bytes, swap);
        return value > static_cast<std::uint64_t>(
                         std::numeric_limits<long long>::max())
                 ? -1
                 : static_cast<long long>(value);
      }

      /// @p n size_t of format 4.1 into @p values.
      void
      binary_sizes(std::vector<long long> &values,
                   const std::size_t       n,
                   const std::string_view  section)
      {
        values.resize(n);
        if (data_size == 8)
          {
            static_assert(sizeof(long long) == 8);
            in.binary(values.data(), n, swap, section);
          }
        else
          {
            std::vector<std::uint32_t> narrow(n);
            in.binary(narrow.data(), n, swap, section);
            std::copy(narrow.begin(), narrow.end(), values.begin());
          }
      }

      /// A count of a binary section that the data can hold.
      long long
      checked_count(const long long        n,
                    const std::size_t      bytes_each,
                    const std::string_view section) const
      {
        if (n < 0 || static_cast<std::size_t>(n) > in.size() / bytes_each)
          in.fail("the count " + std::to_string(n) + " in " +
                  std::string(section) +
                  " exceeds what the file holds: is it truncated?");
        return n;
      }

      /// $Entities of binary format 4.1.
      void
      read_binary_entities()
      {
        const std::string_view section = "$Entities";
        in.skip_line();
        std::array<long long, 4> n;
        for (long long &count : n)
          count = checked_count(binary_size(section), 4, section);
        std::vector<std::int32_t> tags;
        for (unsigned int d = 0; d < 4; ++d)
          for (long long i = 0; i < n[d]; ++i)
            {
              const std::int32_t tag = in.binary<std::int32_t>(swap, section);
              in.skip_bytes((d == 0 ? 3 : 6) * sizeof(double), section);
              const long long n_physical = binary_size(section);
              check_physical_count(tag, d, n_physical);
              int physical = 0;
              if (n_physical == 1)
                physical = in.binary<std::int32_t>(swap, section);
              physical_tags[d][tag] = physical;
              if (d > 0) // bounding entities
                {
                  const long long n_bounding =
                    checked_count(binary_size(section), 4, section);
                  in.skip_bytes(n_bounding * sizeof(std::int32_t), section);
                }
            }
        in.expect("$EndEntities");
      }

      /// $Nodes of a binary file.
      void
      read_binary_nodes()
      {
        if (version == 0.)
          in.fail("no $MeshFormat section before $Nodes");
        const std::string_view section = "$Nodes";
        if (version < 4.)
          {
            // Count as text; per node an int tag and 3 doubles.
            const long long n = checked_count(in.number<long long>(),
                                              4 + 3 * sizeof(double),
                                              section);
            in.skip_line();
            reserve_nodes(n);
            nodes.resize(n);
            node_tags.resize(n);
            for (long long i = 0; i < n; ++i)
              {
                node_tags[i] = in.binary<std::int32_t>(swap, section);
                in.binary(&nodes[i][0], 3, swap, section);
              }
          }
        else
          {
            in.skip_line();
            const long long n_blocks =
              checked_count(binary_size(section), 12, section);
            const long long n_nodes =
              checked_count(binary_size(section), 3 * sizeof(double), section);
            binary_size(section); // smallest and largest tag
            binary_size(section);
            reserve_nodes(n_nodes);
            std::vector<long long> block_tags;
            std::vector<double>    coordinates;
            for (long long b = 0; b < n_blocks; ++b)
              {
                const std::int32_t entity_dim =
                  in.binary<std::int32_t>(swap, section);
                in.binary<std::int32_t>(swap, section); // entity tag
                const std::int32_t parametric =
                  in.binary<std::int32_t>(swap, section);
                const long long n = checked_count(binary_size(section),
                                                  3 * sizeof(double),
                                                  section);
                binary_sizes(block_tags, n, section);
                node_tags.insert(node_tags.end(),
                                 block_tags.begin(),
                                 block_tags.end());
                // x y z, and the parametric coordinates (as many as the
                // entity's dimension) if the block has them.
                const long long per_node =
                  3 + (parametric != 0 ? std::max(0, entity_dim) : 0);
                coordinates.resize(n * per_node);
                in.binary(coordinates.data(), n * per_node, swap, section);
                for (long long i = 0; i < n; ++i)
                  nodes.emplace_back(coordinates[i * per_node],
                                     coordinates[i * per_node + 1],
                                     coordinates[i * per_node + 2]);
              }
          }
        in.expect("$EndNodes");
        index_nodes();
      }

      /// $Elements of a binary file.
      void
      read_binary_elements()
      {
        const std::string_view section = "$Elements";
        if (version < 4.)
          {
            // Count as text, then blocks: type, count, number of tags (3
            // ints); per element its number, the tags and the nodes.
            const long long n_elements =
              checked_count(in.number<long long>(), 8, section);
            in.skip_line();
            reserve_elements(n_elements);
            std::array<long long, 4> element_nodes;
            for (long long read = 0; read < n_elements;)
              {
                std::array<std::int32_t, 3> header;
                in.binary(header.data(), 3, swap, section);
                const int       type   = header[0];
                const long long n      = header[1];
                const int       n_tags = header[2];
                const int       n_node = nodes_of_binary_type(type);
                if (n <= 0 || n > n_elements - read || n_tags < 0)
                  in.fail("an element block header (type " +
                          std::to_string(type) + ", " + std::to_string(n) +
                          " elements, " + std::to_string(n_tags) +
                          " tags) that does not fit the element count " +
                          std::to_string(n_elements) + " in " +
                          std::string(section));
                const long long   per_element = 1 + n_tags + n_node;
                const std::size_t bytes       = 4 * per_element;
                const char       *e =
                  in.raw(checked_count(n, bytes, section) * bytes, section);
                const bool keep = is_read(type);
                for (long long i = 0; i < n; ++i, e += bytes)
                  {
                    if (keep)
                      for (int k = 0; k < n_node; ++k)
                        element_nodes[k] =
                          load_binary<std::int32_t>(e + 4 * (1 + n_tags + k),
                                                    swap);
                    add_element(load_binary<std::int32_t>(e, swap),
                                type,
                                n_tags > 0
                                  ? load_binary<std::int32_t>(e + 4, swap)
                                  : 0,
                                element_nodes.data());
                  }
                read += n;
              }
          }
        else
          {
            in.skip_line();
            const long long n_blocks =
              checked_count(binary_size(section), 12, section);
            const long long n_elements =
              checked_count(binary_size(section), data_size, section);
            binary_size(section); // smallest and largest tag
            binary_size(section);
            reserve_elements(n_elements);
            std::array<long long, 4> element_nodes;
            for (long long b = 0; b < n_blocks; ++b)
              {
                std::array<std::int32_t, 3> header; // dim, tag, type
                in.binary(header.data(), 3, swap, section);
                const int type     = header[2];
                const int physical = block_physical_tag(header[0], header[1]);
                const int n_node   = nodes_of_binary_type(type);
                const long long per_element = 1 + n_node;
                const long long n = checked_count(binary_size(section),
                                                  data_size * per_element,
                                                  section);
                // Straight from the file's bytes, element by element.
                const std::size_t bytes = data_size * per_element;
                const char       *e     = in.raw(n * bytes, section);
                const bool        keep  = is_read(type);
                for (long long i = 0; i < n; ++i, e += bytes)
                  {
                    if (keep)
                      for (int k = 0; k < n_node; ++k)
                        element_nodes[k] = size_at(e + (1 + k) * data_size);
                    add_element(size_at(e),
                                type,
                                physical,
                                element_nodes.data());
                  }
              }
          }
        in.expect("$EndElements");
      }

      /// The node count of element type @p type, which a binary file does
      /// not list: InputError for a type not known.
      int
      nodes_of_binary_type(const int type) const
      {
        const int n = gmsh_nodes_per_element(type);
        if (n == 0)
          in.fail("binary element block of gmsh element type " +
                  std::to_string(type) +
                  ", whose node count is not known: mesh with 4-node "
                  "tetrahedra (3D) or 3-node triangles (2D)");
        return n;
      }

      // ---------------------------------------------------------------
      // Elements of either kind of file

      /// Whether elements of @p type are kept (their nodes read).
      static bool
      is_read(const int type)
      {
        return type == simplex_type || type == 1 || (dim == 3 && type == 2);
      }

      /// One element: a cell, a face with its boundary id, something
      /// dropped (points, lines in 3D) or an element of a type not read
      /// (counted for the message). @p element_nodes holds the node tags
      /// of the types read.
      void
      add_element(const long long  tag,
                  const int        type,
                  const int        physical,
                  const long long *element_nodes)
      {
        const auto vertices = [&](const unsigned int n) {
          std::array<unsigned int, 4> v{};
          for (unsigned int k = 0; k < n; ++k)
            v[k] = vertex(tag, element_nodes[k]);
          return v;
        };
        if (type == simplex_type)
          mesh.add_cell(vertices(dim + 1), physical, tag);
        else if (type == 1) // line: a face in 2D (checked, dropped in 3D)
          {
            const auto v = vertices(2);
            if (dim == 2)
              mesh.add_face(v, physical, tag);
          }
        else if (dim == 3 && type == 2) // triangle: boundary id of a face
          mesh.add_face(vertices(3), physical, tag);
        else if (type != 15) // points carry nothing for dim > 1
          {
            if (n_unsupported++ == 0)
              {
                unsupported_tag  = tag;
                unsupported_type = type;
              }
          }
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
      MeshFileText       in;
      double             version   = 0.;
      bool               binary    = false;
      bool               swap      = false; ///< binary byte order not ours
      int                data_size = 8;
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
