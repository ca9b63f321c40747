// Reading an ASCII MEDIT .mesh file (INRIA's format; TetWild writes it): the
// keyword sections Vertices, Triangles, Tetrahedra and Edges into the cell
// list the gmsh reader produces, with references as material and boundary
// ids.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/medit_reader.h>
#include <hyperelastic/mesh/mesh_file_text.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// Numbers per entry of the sections hyperelastic skips (the MEDIT
    /// keywords of geometric data and of the elements it does not read);
    /// 0 for a keyword not known. @p space_dim is the file's Dimension.
    int
    skipped_entry_size(const std::string &keyword, const int space_dim)
    {
      if (keyword == "corners" || keyword == "requiredvertices" ||
          keyword == "ridges" || keyword == "requirededges" ||
          keyword == "requiredtriangles" ||
          keyword == "requiredquadrilaterals" ||
          keyword == "requiredtetrahedra")
        return 1;
      if (keyword == "normalatvertices" || keyword == "tangentatvertices")
        return 2;
      if (keyword == "normalattrianglevertices")
        return 3;
      if (keyword == "tangentatedges")
        return 3;
      if (keyword == "normals" || keyword == "tangents")
        return space_dim;
      return 0;
    }

    /// Nodes of the element sections hyperelastic does not read (for the
    /// message); 0 for other keywords.
    int
    unsupported_element_nodes(const std::string &keyword)
    {
      if (keyword == "quadrilaterals")
        return 4;
      if (keyword == "hexahedra")
        return 8;
      if (keyword == "prisms")
        return 6;
      if (keyword == "pyramids")
        return 5;
      if (keyword == "edgesp2")
        return 3;
      if (keyword == "trianglesp2")
        return 6;
      if (keyword == "tetrahedrap2")
        return 10;
      return 0;
    }

    /// One pass over a MEDIT file, keyword by keyword.
    template <int dim>
    class MeditParser
    {
    public:
      MeditParser(const std::string &file_name, const std::string &entry)
          : in(read_whole_file(file_name, entry), file_name)
      {
      }

      void
      read_sections()
      {
        while (in.more())
          {
            const std::string_view word = in.word();
            if (word[0] == '#') // a comment line
              {
                in.skip_line();
                continue;
              }
            std::string keyword(word);
            std::transform(keyword.begin(),
                           keyword.end(),
                           keyword.begin(),
                           [](const unsigned char c) {
                             return std::tolower(c);
                           });
            const std::size_t line = in.line_number();
            if (keyword == "end")
              break;
            if (keyword == "meshversionformatted")
              in.number<int>();
            else if (keyword == "dimension")
              read_dimension();
            else if (keyword == "vertices")
              read_vertices(line);
            else if (keyword == "tetrahedra")
              read_elements(4,
                            dim == 3 ? Role::cell : Role::unsupported,
                            word,
                            line);
            else if (keyword == "triangles")
              read_elements(3, dim == 2 ? Role::cell : Role::face, word, line);
            else if (keyword == "edges")
              read_elements(2,
                            dim == 2 ? Role::face : Role::dropped,
                            word,
                            line);
            else if (const int n = unsupported_element_nodes(keyword); n > 0)
              read_elements(n, Role::unsupported, word, line);
            else if (const int n = skipped_entry_size(keyword, space_dim);
                     n > 0)
              {
                const long long count = read_count(word, line);
                for (long long i = 0; i < count * n; ++i)
                  in.number<double>();
              }
            else
              in.fail("unknown section '" + std::string(word.substr(0, 40)) +
                      "' on line " + std::to_string(line) +
                      " (a MEDIT .mesh file of Vertices, Edges, Triangles and "
                      "Tetrahedra is read; binary .meshb is not)");
          }
      }

      GmshMesh<dim>
      finish(const bool cells_required)
      {
        if (!unsupported_section.empty())
          throw InputError(
            "mesh file '" + in.name() + "': section " + unsupported_section +
            " on line " + std::to_string(unsupported_line) +
            " holds elements hyperelastic does not read: a " +
            std::to_string(dim) + "D mesh consists of " +
            (dim == 2 ? "Triangles (plus Edges for boundary ids)"
                      : "Tetrahedra (plus Triangles for boundary ids)"));
        if (mesh.cells.empty() && cells_required)
          throw InputError("mesh file '" + in.name() + "' holds no " +
                           (dim == 2 ? "Triangles" : "Tetrahedra") +
                           ", only lower-dimensional elements");
        finish_mesh_cells(mesh, std::move(nodes));
        return std::move(mesh);
      }

    private:
      enum class Role
      {
        cell,
        face,
        dropped,
        unsupported
      };

      void
      read_dimension()
      {
        const std::size_t line = in.line_number();
        space_dim              = in.number<int>();
        if (space_dim != 2 && space_dim != 3)
          in.fail("Dimension " + std::to_string(space_dim) + " on line " +
                  std::to_string(line) + " (2 or 3 are read)");
        if (space_dim < dim)
          in.fail("the file is of Dimension 2 (line " + std::to_string(line) +
                  ") but is read as a 3D mesh: check 'Problem/Dimension'");
      }

      long long
      read_count(const std::string_view keyword, const std::size_t line)
      {
        const long long n = in.number<long long>();
        if (n < 0 || static_cast<std::size_t>(n) > in.size())
          in.fail("section " + std::string(keyword) + " on line " +
                  std::to_string(line) + " has the count " + std::to_string(n));
        return n;
      }

      /// Vertices: x y (z) ref per vertex; the reference is not used.
      void
      read_vertices(const std::size_t line)
      {
        if (space_dim == 0)
          in.fail("section Vertices on line " + std::to_string(line) +
                  " comes before the Dimension");
        const long long n = read_count("Vertices", line);
        nodes.reserve(nodes.size() + n);
        for (long long i = 0; i < n; ++i)
          {
            Point<3> x;
            for (int d = 0; d < space_dim; ++d)
              x[d] = in.number<double>();
            in.number<long long>(); // reference
            nodes.push_back(x);
          }
      }

      /// An element section of @p n_nodes vertex numbers and a reference
      /// per element.
      void
      read_elements(const int              n_nodes,
                    const Role             role,
                    const std::string_view keyword,
                    const std::size_t      line)
      {
        const long long n = read_count(keyword, line);
        if (role == Role::unsupported && n > 0 && unsupported_section.empty())
          {
            unsupported_section = std::string(keyword);
            unsupported_line    = line;
          }
        if (role == Role::cell)
          {
            mesh.cells.reserve(mesh.cells.size() + n);
            mesh.element_numbers.reserve(mesh.cells.size() + n);
          }
        std::array<unsigned int, 4> v;
        for (long long i = 0; i < n; ++i)
          {
            for (int k = 0; k < n_nodes; ++k)
              {
                const long long number = in.number<long long>();
                if (role == Role::unsupported)
                  continue;
                if (number < 1 || number > static_cast<long long>(nodes.size()))
                  in.fail(std::string(keyword) + " " + std::to_string(i + 1) +
                          " (line " + std::to_string(in.line_number()) +
                          ") refers to vertex " + std::to_string(number) +
                          "; the Vertices before it are 1 to " +
                          std::to_string(nodes.size()));
                v[k] = number - 1;
              }
            const long long reference = in.number<long long>();
            if (role == Role::unsupported || role == Role::dropped)
              continue;
            if (reference < 0 ||
                reference >
                  static_cast<long long>(
                    std::numeric_limits<types::material_id>::max() - 1))
              in.fail(std::string(keyword) + " " + std::to_string(i + 1) +
                      " (line " + std::to_string(in.line_number()) +
                      ") has the reference " + std::to_string(reference) +
                      ", which is not a valid " +
                      (role == Role::cell ? "material" : "boundary") + " id");
            add(role, v, reference, i + 1);
          }
      }

      void
      add(const Role                         role,
          const std::array<unsigned int, 4> &v,
          const long long                    reference,
          const long long                    number)
      {
        if (role == Role::cell)
          mesh.add_cell(v, reference, number);
        else
          mesh.add_face(v, reference, number);
      }

      MeshFileText          in;
      int                   space_dim = 0;
      GmshMesh<dim>         mesh;
      std::vector<Point<3>> nodes;
      std::string           unsupported_section;
      std::size_t           unsupported_line = 0;
    };
  } // namespace

  template <int dim>
  GmshMesh<dim>
  read_medit(const std::string &file_name,
             const std::string &entry,
             const bool         cells_required)
  {
    MeditParser<dim> parser(file_name, entry);
    parser.read_sections();
    return parser.finish(cells_required);
  }

  template GmshMesh<2>
  read_medit<2>(const std::string &, const std::string &, bool);
  template GmshMesh<3>
  read_medit<3>(const std::string &, const std::string &, bool);
} // namespace hyperelastic
