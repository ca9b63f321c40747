// Reading a legacy VTK .vtk file (DATASET UNSTRUCTURED_GRID; ASCII, or
// BINARY, which is big-endian; the cell lists of versions 2 to 4 and the
// OFFSETS/CONNECTIVITY lists of version 5) into the cell list the gmsh reader
// produces, with a cell data array as material and boundary ids.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/mesh_file_text.h>
#include <hyperelastic/mesh/vtk_reader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    // VTK cell types.
    constexpr int vtk_vertex   = 1;
    constexpr int vtk_line     = 3;
    constexpr int vtk_triangle = 5;
    constexpr int vtk_tetra    = 10;

    std::string
    vtk_cell_name(const int type)
    {
      switch (type)
        {
        case 1:
          return "vertex (VTK type 1)";
        case 2:
          return "poly-vertex (VTK type 2)";
        case 3:
          return "line (VTK type 3)";
        case 4:
          return "poly-line (VTK type 4)";
        case 5:
          return "triangle (VTK type 5)";
        case 6:
          return "triangle strip (VTK type 6)";
        case 7:
          return "polygon (VTK type 7)";
        case 8:
          return "pixel (VTK type 8)";
        case 9:
          return "quadrilateral (VTK type 9)";
        case 10:
          return "tetrahedron (VTK type 10)";
        case 11:
          return "voxel (VTK type 11)";
        case 12:
          return "hexahedron (VTK type 12)";
        case 13:
          return "wedge (VTK type 13)";
        case 14:
          return "pyramid (VTK type 14)";
        case 22:
          return "quadratic triangle (VTK type 22)";
        case 24:
          return "quadratic tetrahedron (VTK type 24)";
        default:
          return "cell of VTK type " + std::to_string(type);
        }
    }

    /// The cell data arrays read as ids, most preferred first.
    constexpr std::array<std::string_view, 3> id_arrays = {
      {"MaterialID", "gmsh:physical", "CellEntityIds"}};

    std::string
    lower_case(std::string_view word)
    {
      std::string s(word);
      for (char &c : s)
        c = std::tolower(static_cast<unsigned char>(c));
      return s;
    }

    /// One pass over a legacy VTK file, keyword by keyword.
    template <int dim>
    class VtkParser
    {
    public:
      VtkParser(const std::string &file_name, const std::string &entry)
          : in(read_whole_file(file_name, entry), file_name)
          , swap(machine_is_little_endian())
      {
      }

      void
      read()
      {
        read_header();
        while (in.more())
          {
            const std::string_view word    = in.word();
            const std::string      keyword = lower_case(word);
            const std::size_t      line    = in.line_number();
            if (keyword == "points")
              read_points(line);
            else if (keyword == "cells")
              read_cells(line);
            else if (keyword == "cell_types")
              read_cell_types(line);
            else if (keyword == "cell_data")
              data_count = read_count("CELL_DATA", line), in_cell_data = true;
            else if (keyword == "point_data")
              data_count = read_count("POINT_DATA", line), in_cell_data = false;
            else if (keyword == "field")
              read_field(line);
            else if (keyword == "metadata")
              skip_metadata();
            else if (keyword == "scalars")
              read_scalars(line);
            else if (keyword == "vectors" || keyword == "normals")
              read_attribute(3, line);
            else if (keyword == "tensors")
              read_attribute(9, line);
            else if (keyword == "texture_coordinates")
              {
                in.word(); // name
                const int n = in.number<int>();
                read_attribute_values(n, line);
              }
            else if (keyword == "color_scalars")
              read_color_scalars(line);
            else if (keyword == "lookup_table")
              read_lookup_table(line);
            else
              in.fail("unknown keyword '" + std::string(word.substr(0, 40)) +
                      "' on line " + std::to_string(line) +
                      (binary ? " (or binary data whose counts do not match "
                                "their lists)"
                              : ""));
          }
      }

      GmshMesh<dim>
      finish(const bool cells_required)
      {
        if (!have_points || !have_cells || !have_types)
          in.fail(std::string("no ") +
                  (!have_points  ? "POINTS"
                   : !have_cells ? "CELLS"
                                 : "CELL_TYPES") +
                  " section: an unstructured grid lists its points, its "
                  "cells and their types");
        const std::size_t n_cells = types.size();
        if (offsets.size() != n_cells + 1)
          in.fail("CELLS lists " + std::to_string(offsets.size() - 1) +
                  " cells but CELL_TYPES " + std::to_string(n_cells));
        if (!ids.empty() && ids.size() != n_cells)
          in.fail("the cell data array " + std::string(id_arrays[id_rank]) +
                  " has " + std::to_string(ids.size()) + " values for " +
                  std::to_string(n_cells) + " cells");
        std::size_t n_unsupported = 0, first_unsupported = 0;
        for (std::size_t i = 0; i < n_cells; ++i)
          {
            const int       type  = types[i];
            const long long begin = offsets[i], end = offsets[i + 1];
            const long long n = end - begin;
            const bool cell   = type == (dim == 2 ? vtk_triangle : vtk_tetra);
            const bool face   = type == (dim == 2 ? vtk_line : vtk_triangle);
            if (!cell && !face)
              {
                if (type != vtk_vertex && !(dim == 3 && type == vtk_line) &&
                    n_unsupported++ == 0)
                  first_unsupported = i;
                continue;
              }
            if (n != (cell ? dim + 1 : dim))
              in.fail("cell " + std::to_string(i) + ", a " +
                      vtk_cell_name(type) + ", lists " + std::to_string(n) +
                      " points in CELLS");
            std::array<unsigned int, 4> v;
            for (long long k = 0; k < n; ++k)
              {
                const long long p = connectivity[begin + k];
                if (p < 0 || p >= static_cast<long long>(nodes.size()))
                  in.fail("cell " + std::to_string(i) + " refers to point " +
                          std::to_string(p) + "; POINTS lists 0 to " +
                          std::to_string(nodes.size() - 1));
                v[k] = p;
              }
            const unsigned int id = ids.empty() ? 0 : ids[i];
            add(cell, v, id, i);
          }
        if (n_unsupported > 0)
          throw InputError(
            "mesh file '" + in.name() + "': " + std::to_string(n_unsupported) +
            " cell(s) of a type hyperelastic does not read, the first cell " +
            std::to_string(first_unsupported) + ", a " +
            vtk_cell_name(types[first_unsupported]) + ". A " +
            std::to_string(dim) + "D mesh consists of " +
            (dim == 2 ? "triangles (plus lines"
                      : "tetrahedra (plus triangles") +
            " for boundary ids): check 'Problem/Dimension'");
        if (mesh.cells.empty() && cells_required)
          throw InputError(
            "mesh file '" + in.name() + "' holds no " +
            (dim == 2 ? "triangles (VTK type 5)" : "tetrahedra (VTK type 10)") +
            ", only lower-dimensional cells");
        finish_mesh_cells(mesh, std::move(nodes));
        return std::move(mesh);
      }

    private:
      void
      read_header()
      {
        // "# vtk DataFile Version x.y", a title line, ASCII or BINARY,
        // DATASET UNSTRUCTURED_GRID.
        const std::string_view hash = in.word();
        const std::string_view vtk  = in.word();
        const std::string_view data = in.word();
        const std::string_view ver  = in.word();
        if (hash != "#" || lower_case(vtk) != "vtk" ||
            lower_case(data) != "datafile" || lower_case(ver) != "version")
          in.fail("the first line is not '# vtk DataFile Version x.y' (a "
                  "legacy VTK file; XML .vtu files are not read)");
        version = in.number<double>();
        in.skip_line();
        in.skip_line(); // the title
        const std::string format = lower_case(in.word());
        if (format != "ascii" && format != "binary")
          in.fail("line 3 is '" + format + "', not ASCII or BINARY");
        binary                    = format == "binary";
        const std::string dataset = lower_case(in.word());
        const std::string type    = lower_case(in.word());
        if (dataset != "dataset" || type != "unstructured_grid")
          in.fail("line 4 is '" + dataset + " " + type +
                  "': only DATASET UNSTRUCTURED_GRID is read");
      }

      long long
      read_count(const std::string_view keyword, const std::size_t line)
      {
        const long long n = in.number<long long>();
        if (n < 0 || static_cast<std::size_t>(n) > in.size())
          in.fail(std::string(keyword) + " on line " + std::to_string(line) +
                  " has the count " + std::to_string(n) +
                  ", more than the file can hold");
        return n;
      }

      /// @p n values of the VTK data type @p type as numbers of type
      /// Number: ASCII tokens, or big-endian binary data after the line of
      /// their keyword.
      template <typename Number>
      void
      read_values(std::vector<Number>   &values,
                  const std::size_t      n,
                  const std::string     &type,
                  const std::string_view what,
                  const std::size_t      line)
      {
        values.resize(n);
        if (!binary)
          {
            for (std::size_t i = 0; i < n; ++i)
              values[i] = in.number<Number>();
            return;
          }
        const std::string section =
          std::string(what) + " (line " + std::to_string(line) + ")";
        if (type == "double")
          convert<double>(values, n, section);
        else if (type == "float")
          convert<float>(values, n, section);
        else if (type == "int" || type == "vtktypeint32")
          convert<std::int32_t>(values, n, section);
        else if (type == "unsigned_int" || type == "vtktypeuint32")
          convert<std::uint32_t>(values, n, section);
        else if (type == "long" || type == "vtktypeint64" ||
                 type == "vtkidtype")
          convert<std::int64_t>(values, n, section);
        else if (type == "unsigned_long" || type == "vtktypeuint64")
          convert<std::uint64_t>(values, n, section);
        else if (type == "short")
          convert<std::int16_t>(values, n, section);
        else if (type == "unsigned_short")
          convert<std::uint16_t>(values, n, section);
        else if (type == "char")
          convert<std::int8_t>(values, n, section);
        else if (type == "unsigned_char" || type == "bit")
          convert<std::uint8_t>(values, n, section);
        else
          in.fail("the data type '" + type + "' of " + section +
                  " is not known");
      }

      template <typename Stored, typename Number>
      void
      convert(std::vector<Number>   &values,
              const std::size_t      n,
              const std::string_view section)
      {
        if constexpr (std::is_same_v<Stored, Number>)
          in.binary(values.data(), n, swap, section);
        else
          {
            std::vector<Stored> stored(n);
            in.binary(stored.data(), n, swap, section);
            if constexpr (std::is_floating_point_v<Stored> &&
                          std::is_integral_v<Number>)
              for (std::size_t i = 0; i < n; ++i)
                {
                  if (!(std::abs(stored[i]) < 9e18) ||
                      stored[i] != std::floor(stored[i]))
                    in.fail("the value " + std::to_string(stored[i]) + " in " +
                            std::string(section) + " is not an integer");
                  values[i] = static_cast<Number>(stored[i]);
                }
            else
              std::copy(stored.begin(), stored.end(), values.begin());
          }
      }

      /// Past the line of a keyword; binary data follows it.
      void
      end_keyword_line()
      {
        if (binary)
          in.skip_line();
      }

      void
      read_points(const std::size_t line)
      {
        const long long   n    = read_count("POINTS", line);
        const std::string type = lower_case(in.word());
        end_keyword_line();
        std::vector<double> x;
        read_values(x, 3 * n, type, "POINTS", line);
        nodes.resize(n);
        for (long long i = 0; i < n; ++i)
          nodes[i] = Point<3>(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
        have_points = true;
      }

      /// CELLS: versions before 5 list per cell its point count and its
      /// points (ints); version 5 lists OFFSETS and CONNECTIVITY arrays.
      void
      read_cells(const std::size_t line)
      {
        const long long n    = read_count("CELLS", line);
        const long long size = read_count("CELLS", line);
        if (version < 5.)
          {
            end_keyword_line();
            std::vector<long long> list;
            read_values(list, size, "int", "CELLS", line);
            offsets.assign(1, 0);
            connectivity.clear();
            connectivity.reserve(size - n);
            for (long long i = 0, at = 0; i < n; ++i)
              {
                const long long count = at < size ? list[at] : -1;
                if (count < 0 || count > size - at - 1)
                  in.fail("the cell list of CELLS on line " +
                          std::to_string(line) + " does not match its size " +
                          std::to_string(size) + " at cell " +
                          std::to_string(i));
                connectivity.insert(connectivity.end(),
                                    list.begin() + at + 1,
                                    list.begin() + at + 1 + count);
                at += count + 1;
                offsets.push_back(connectivity.size());
              }
          }
        else
          {
            // "CELLS n_offsets n_connectivity", then "OFFSETS type" with
            // n_offsets values and "CONNECTIVITY type" with n_connectivity.
            for (const std::string_view array : {"offsets", "connectivity"})
              {
                const std::size_t array_line = in.line_number() + 1;
                const std::string keyword    = lower_case(in.word());
                if (keyword != array)
                  in.fail("expected " +
                          std::string(array == "offsets" ? "OFFSETS"
                                                         : "CONNECTIVITY") +
                          " after CELLS on line " + std::to_string(line) +
                          " (VTK version 5) but found '" + keyword + "'");
                const std::string type = lower_case(in.word());
                end_keyword_line();
                read_values(array == "offsets" ? offsets : connectivity,
                            array == "offsets" ? n : size,
                            type,
                            array == "offsets" ? "OFFSETS" : "CONNECTIVITY",
                            array_line);
              }
            for (std::size_t i = 0; i + 1 < offsets.size(); ++i)
              if (offsets[i] < 0 || offsets[i + 1] < offsets[i] ||
                  offsets[i + 1] > static_cast<long long>(connectivity.size()))
                in.fail("the OFFSETS of CELLS on line " + std::to_string(line) +
                        " do not match its CONNECTIVITY at cell " +
                        std::to_string(i));
            if (offsets.empty())
              offsets.assign(1, 0);
          }
        have_cells = true;
      }

      void
      read_cell_types(const std::size_t line)
      {
        const long long n = read_count("CELL_TYPES", line);
        end_keyword_line();
        read_values(types, n, "int", "CELL_TYPES", line);
        have_types = true;
      }

      /// SCALARS name type [components], an optional LOOKUP_TABLE line,
      /// the values.
      void
      read_scalars(const std::size_t line)
      {
        const std::string name = std::string(in.word());
        const std::string type = lower_case(in.word());
        // The component count is optional: the next word is a number or
        // LOOKUP_TABLE (or, binary without a table, the end of the line).
        int components = 1;
        in.skip_blanks_on_line();
        if (in.next_is_digit())
          components = in.number<int>();
        in.skip_blanks_on_line();
        if (!in.at_line_end())
          in.fail("SCALARS on line " + std::to_string(line) +
                  " has more words than name, type and components");
        in.skip_line();
        if (in.next_starts_with("LOOKUP_TABLE"))
          {
            in.word();
            in.word();
            in.skip_line();
          }
        read_array(name, type, components, line, true);
      }

      /// VECTORS, NORMALS, TENSORS: name, type, @p components values per
      /// point or cell.
      void
      read_attribute(const int components, const std::size_t line)
      {
        const std::string name = std::string(in.word());
        const std::string type = lower_case(in.word());
        end_keyword_line();
        read_array(name, type, components, line, false);
      }

      void
      read_attribute_values(const int components, const std::size_t line)
      {
        const std::string type = lower_case(in.word());
        end_keyword_line();
        read_array("", type, components, line, false);
      }

      /// COLOR_SCALARS name n: floats (ASCII) or unsigned chars (binary).
      void
      read_color_scalars(const std::size_t line)
      {
        in.word();
        const int n = in.number<int>();
        end_keyword_line();
        read_array("", binary ? "unsigned_char" : "float", n, line, false);
      }

      /// LOOKUP_TABLE name size: 4 values per entry.
      void
      read_lookup_table(const std::size_t line)
      {
        in.word();
        const long long n = read_count("LOOKUP_TABLE", line);
        end_keyword_line();
        std::vector<double> skipped;
        read_values(skipped,
                    4 * n,
                    binary ? "unsigned_char" : "float",
                    "LOOKUP_TABLE",
                    line);
      }

      /// FIELD name k, then k arrays "name components tuples type".
      void
      read_field(const std::size_t line)
      {
        in.word();
        const long long n_arrays = read_count("FIELD", line);
        for (long long a = 0; a < n_arrays; ++a)
          {
            const std::size_t array_line = in.line_number() + 1;
            const std::string name       = std::string(in.word());
            if (lower_case(name) == "metadata")
              {
                skip_metadata();
                --a;
                continue;
              }
            const long long   components = read_count("FIELD", array_line);
            const long long   tuples     = read_count("FIELD", array_line);
            const std::string type       = lower_case(in.word());
            end_keyword_line();
            read_tuples(name, type, components, tuples, array_line);
          }
      }

      /// The values of a data array over the points or cells.
      void
      read_array(const std::string &name,
                 const std::string &type,
                 const long long    components,
                 const std::size_t  line,
                 const bool         may_be_ids)
      {
        if (data_count < 0)
          in.fail("data on line " + std::to_string(line) +
                  " before CELL_DATA or POINT_DATA");
        read_tuples(may_be_ids ? name : "", type, components, data_count, line);
      }

      /// @p tuples tuples of @p components values; kept as the ids if it is
      /// cell data named as one of id_arrays (preferred over the ones found
      /// before).
      void
      read_tuples(const std::string &name,
                  const std::string &type,
                  const long long    components,
                  const long long    tuples,
                  const std::size_t  line)
      {
        unsigned int rank = id_arrays.size();
        for (unsigned int r = 0; r < id_arrays.size(); ++r)
          if (name == id_arrays[r])
            rank = r;
        const bool keep = in_cell_data && rank < id_rank;
        if (keep && components != 1)
          in.fail("the cell data array " + name + " on line " +
                  std::to_string(line) + " has " + std::to_string(components) +
                  " components (1 is read)");
        if (keep)
          {
            std::vector<double> values;
            read_values(values, tuples, type, name, line);
            ids.resize(tuples);
            for (long long i = 0; i < tuples; ++i)
              {
                const double v = values[i];
                if (!(v >= 0.) || v != std::floor(v) ||
                    v > std::numeric_limits<types::material_id>::max() - 1.)
                  in.fail("the cell data array " + name + " on line " +
                          std::to_string(line) + " has the value " +
                          std::to_string(v) + " for cell " + std::to_string(i) +
                          ", which is not a valid material or boundary id");
                ids[i] = static_cast<unsigned int>(v);
              }
            id_rank = rank;
          }
        else
          {
            std::vector<double> skipped;
            read_values(skipped, components * tuples, type, "data", line);
          }
      }

      /// METADATA (version 5): an INFORMATION block up to an empty line.
      void
      skip_metadata()
      {
        in.skip_to_empty_line();
      }

      void
      add(const bool                         cell,
          const std::array<unsigned int, 4> &v,
          const unsigned int                 id,
          const long long                    number)
      {
        if (cell)
          mesh.add_cell(v, id, number);
        else
          mesh.add_face(v, id, number);
      }

      MeshFileText              in;
      const bool                swap; ///< binary VTK is big-endian
      double                    version      = 0.;
      bool                      binary       = false;
      bool                      have_points  = false;
      bool                      have_cells   = false;
      bool                      have_types   = false;
      bool                      in_cell_data = false;
      long long                 data_count   = -1;
      std::vector<Point<3>>     nodes;
      std::vector<long long>    offsets, connectivity;
      std::vector<int>          types;
      std::vector<unsigned int> ids;
      unsigned int              id_rank = id_arrays.size();
      GmshMesh<dim>             mesh;
    };
  } // namespace

  template <int dim>
  GmshMesh<dim>
  read_vtk(const std::string &file_name,
           const std::string &entry,
           const bool         cells_required)
  {
    VtkParser<dim> parser(file_name, entry);
    parser.read();
    return parser.finish(cells_required);
  }

  template GmshMesh<2>
  read_vtk<2>(const std::string &, const std::string &, bool);
  template GmshMesh<3>
  read_vtk<3>(const std::string &, const std::string &, bool);
} // namespace hyperelastic
