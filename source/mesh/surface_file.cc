// Reading closed surfaces: OBJ (v, f, g, o), STL (ASCII, several solids as
// groups, and binary), PLY (ASCII and binary little-endian; an integer face
// property as groups) and OFF into one triangle list on shared vertices.
#include <deal.II/base/types.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/surface_file.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace hyperelastic
{
  using dealii::Point;

  namespace
  {
    /// Errors about the file, naming the scene entry.
    struct FileContext
    {
      std::string entry, file;

      [[noreturn]] void
      fail(const std::string &what) const
      {
        throw InputError("scene entry '" + entry + "' = '" + file +
                         "': " + what);
      }
    };

    std::string
    lower_case(std::string s)
    {
      for (char &c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return s;
    }

    /// Groups numbered 1, 2, ... by first appearance of their key.
    class GroupNumbers
    {
    public:
      unsigned int
      number(const std::string &key, SurfaceTriangles &surface)
      {
        const auto found = numbers.find(key);
        if (found != numbers.end())
          return found->second;
        surface.group_names.push_back(key);
        return numbers[key] = surface.group_names.size();
      }

    private:
      std::map<std::string, unsigned int> numbers;
    };

    /// A polygon of vertex indices split into triangles around its first
    /// vertex.
    void
    add_polygon(const std::vector<long long> &polygon,
                const unsigned int            group,
                SurfaceTriangles             &surface,
                const FileContext            &context,
                const std::string            &where)
    {
      if (polygon.size() < 3)
        context.fail(where + " has fewer than 3 vertices");
      for (const long long v : polygon)
        if (v < 0 || v >= static_cast<long long>(surface.vertices.size()))
          context.fail(where + " refers to vertex " + std::to_string(v + 1) +
                       " of " + std::to_string(surface.vertices.size()));
      for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
        {
          surface.triangles.push_back(
            {{static_cast<unsigned int>(polygon[0]),
              static_cast<unsigned int>(polygon[k]),
              static_cast<unsigned int>(polygon[k + 1])}});
          surface.groups.push_back(group);
        }
    }

    SurfaceTriangles
    read_obj(std::istream &in, const FileContext &context)
    {
      SurfaceTriangles surface;
      GroupNumbers     groups;
      unsigned int     group = 0;
      std::string      line;
      for (unsigned int line_number = 1; std::getline(in, line); ++line_number)
        {
          std::istringstream words(line);
          std::string        key;
          if (!(words >> key))
            continue;
          const std::string where = "line " + std::to_string(line_number);
          if (key == "v")
            {
              Point<3> x;
              if (!(words >> x[0] >> x[1] >> x[2]))
                context.fail(where + ": a vertex needs 3 coordinates");
              surface.vertices.push_back(x);
            }
          else if (key == "f")
            {
              std::vector<long long> polygon;
              std::string            token;
              while (words >> token)
                {
                  // "i", "i/t", "i//n" or "i/t/n"; negative: relative.
                  long long   index = 0;
                  std::size_t used  = 0;
                  try
                    {
                      index = std::stoll(token, &used);
                    }
                  catch (const std::exception &)
                    {
                      used = 0;
                    }
                  if (used == 0 || index == 0 ||
                      (used < token.size() && token[used] != '/'))
                    context.fail(where + ": '" + token +
                                 "' is not a vertex number");
                  polygon.push_back(index > 0 ? index - 1
                                              : static_cast<long long>(
                                                  surface.vertices.size()) +
                                                  index);
                }
              add_polygon(polygon, group, surface, context, where + ", a face");
            }
          else if (key == "g" || key == "o")
            {
              std::string name, word;
              while (words >> word)
                name += (name.empty() ? "" : " ") + word;
              group = groups.number(name.empty() ? "(unnamed)" : name, surface);
            }
        }
      return surface;
    }

    /// STL facets as triangles; their corners joined at equal coordinates.
    class StlVertices
    {
    public:
      unsigned int
      index(const Point<3> &x, SurfaceTriangles &surface)
      {
        const std::array<double, 3> key{{x[0], x[1], x[2]}};
        const auto                  found = numbers.find(key);
        if (found != numbers.end())
          return found->second;
        surface.vertices.push_back(x);
        return numbers[key] = surface.vertices.size() - 1;
      }

    private:
      std::map<std::array<double, 3>, unsigned int> numbers;
    };

    SurfaceTriangles
    read_stl(const std::string &text, const FileContext &context)
    {
      SurfaceTriangles surface;
      StlVertices      vertices;
      // Binary: an 80-byte header, a count, then 50 bytes per triangle.
      std::uint32_t n = 0;
      if (text.size() >= 84)
        std::memcpy(&n, text.data() + 80, 4);
      const bool binary =
        text.size() >= 84 && text.size() == 84 + 50 * std::size_t(n);
      if (binary)
        {
          for (std::size_t t = 0; t < n; ++t)
            {
              const char                 *facet = text.data() + 84 + 50 * t;
              std::array<unsigned int, 3> triangle;
              for (unsigned int k = 0; k < 3; ++k)
                {
                  float xyz[3];
                  std::memcpy(xyz, facet + 12 + 12 * k, 12);
                  triangle[k] =
                    vertices.index(Point<3>(xyz[0], xyz[1], xyz[2]), surface);
                }
              surface.triangles.push_back(triangle);
              surface.groups.push_back(0);
            }
          return surface;
        }
      std::istringstream words(text);
      std::string        word;
      if (!(words >> word) || lower_case(word) != "solid")
        context.fail("neither an ASCII STL file (starting with 'solid') nor "
                     "a binary one (84 + 50 n bytes)");
      // Several solids: each one a group; one solid: no groups.
      unsigned int                solid = 1;
      std::vector<Point<3>>       corners;
      std::array<unsigned int, 3> triangle;
      while (words >> word)
        {
          word = lower_case(word);
          if (word == "vertex")
            {
              Point<3> x;
              if (!(words >> x[0] >> x[1] >> x[2]))
                context.fail("a vertex without 3 coordinates in facet " +
                             std::to_string(surface.triangles.size() + 1));
              corners.push_back(x);
            }
          else if (word == "endloop")
            {
              if (corners.size() != 3)
                context.fail("facet " +
                             std::to_string(surface.triangles.size() + 1) +
                             " has " + std::to_string(corners.size()) +
                             " vertices, not 3");
              for (unsigned int k = 0; k < 3; ++k)
                triangle[k] = vertices.index(corners[k], surface);
              surface.triangles.push_back(triangle);
              surface.groups.push_back(solid);
              corners.clear();
            }
          else if (word == "solid")
            ++solid;
        }
      if (solid == 1)
        std::fill(surface.groups.begin(), surface.groups.end(), 0);
      else
        for (unsigned int s = 1; s <= solid; ++s)
          surface.group_names.push_back("solid " + std::to_string(s));
      return surface;
    }

    /// A PLY property: its type, and for a list the type of the count.
    struct PlyProperty
    {
      std::string name, type, count_type;
      bool        list = false;
    };

    struct PlyElement
    {
      std::string              name;
      std::size_t              count = 0;
      std::vector<PlyProperty> properties;
    };

    /// Values of a PLY body, ASCII or binary little-endian.
    class PlyValues
    {
    public:
      PlyValues(const std::string &text,
                const std::size_t  start,
                const bool         binary,
                const FileContext &context)
          : text(text)
          , position(start)
          , binary(binary)
          , context(context)
          , words(text.substr(start))
      {
      }

      double
      next(const std::string &type)
      {
        if (!binary)
          {
            double value;
            if (!(words >> value))
              context.fail("the PLY data end early");
            return value;
          }
        const std::size_t size = type_size(type);
        if (position + size > text.size())
          context.fail("the PLY data end early");
        const char *p = text.data() + position;
        position += size;
        return decode(type, p);
      }

      std::size_t
      type_size(const std::string &type) const
      {
        if (type == "char" || type == "uchar" || type == "int8" ||
            type == "uint8")
          return 1;
        if (type == "short" || type == "ushort" || type == "int16" ||
            type == "uint16")
          return 2;
        if (type == "int" || type == "uint" || type == "int32" ||
            type == "uint32" || type == "float" || type == "float32")
          return 4;
        if (type == "double" || type == "float64")
          return 8;
        context.fail("unknown PLY property type '" + type + "'");
      }

    private:
      template <typename T>
      static double
      load(const char *p)
      {
        T value;
        std::memcpy(&value, p, sizeof(T));
        return static_cast<double>(value);
      }

      double
      decode(const std::string &type, const char *p) const
      {
        if (type == "char" || type == "int8")
          return load<std::int8_t>(p);
        if (type == "uchar" || type == "uint8")
          return load<std::uint8_t>(p);
        if (type == "short" || type == "int16")
          return load<std::int16_t>(p);
        if (type == "ushort" || type == "uint16")
          return load<std::uint16_t>(p);
        if (type == "int" || type == "int32")
          return load<std::int32_t>(p);
        if (type == "uint" || type == "uint32")
          return load<std::uint32_t>(p);
        if (type == "float" || type == "float32")
          return load<float>(p);
        return load<double>(p);
      }

      const std::string &text;
      std::size_t        position;
      const bool         binary;
      const FileContext &context;
      std::istringstream words;
    };

    bool
    integer_type(const std::string &type)
    {
      return type != "float" && type != "float32" && type != "double" &&
             type != "float64";
    }

    SurfaceTriangles
    read_ply(const std::string &text, const FileContext &context)
    {
      std::istringstream      header(text);
      std::string             line;
      std::vector<PlyElement> elements;
      std::string             format;
      std::size_t             body = std::string::npos;
      while (std::getline(header, line))
        {
          std::istringstream words(line);
          std::string        key;
          words >> key;
          if (key == "format")
            words >> format;
          else if (key == "element")
            {
              PlyElement element;
              words >> element.name >> element.count;
              elements.push_back(element);
            }
          else if (key == "property" && !elements.empty())
            {
              PlyProperty property;
              words >> property.type;
              if (property.type == "list")
                {
                  property.list = true;
                  words >> property.count_type >> property.type;
                }
              words >> property.name;
              elements.back().properties.push_back(property);
            }
          else if (key == "end_header")
            {
              body = header.tellg();
              break;
            }
        }
      if (body == std::string::npos || text.compare(0, 3, "ply") != 0)
        context.fail("not a PLY file (no 'ply' ... 'end_header' header)");
      if (format != "ascii" && format != "binary_little_endian")
        context.fail("PLY format '" + format +
                     "' is not read (ascii and binary_little_endian are)");

      SurfaceTriangles surface;
      GroupNumbers     groups;
      PlyValues        values(text, body, format != "ascii", context);
      for (const PlyElement &element : elements)
        {
          // The face property that becomes the group: the first integer
          // scalar that is not a colour.
          int group_property = -1;
          if (element.name == "face")
            for (std::size_t p = 0; p < element.properties.size(); ++p)
              {
                const PlyProperty &property = element.properties[p];
                if (!property.list && integer_type(property.type) &&
                    property.name != "red" && property.name != "green" &&
                    property.name != "blue" && property.name != "alpha")
                  {
                    group_property = p;
                    break;
                  }
              }
          for (std::size_t i = 0; i < element.count; ++i)
            {
              Point<3>               x;
              std::vector<long long> polygon;
              unsigned int           group = 0;
              for (std::size_t p = 0; p < element.properties.size(); ++p)
                {
                  const PlyProperty &property = element.properties[p];
                  if (property.list)
                    {
                      const std::size_t n = static_cast<std::size_t>(
                        values.next(property.count_type));
                      for (std::size_t k = 0; k < n; ++k)
                        polygon.push_back(
                          static_cast<long long>(values.next(property.type)));
                      continue;
                    }
                  const double value = values.next(property.type);
                  if (element.name == "vertex")
                    {
                      if (property.name == "x")
                        x[0] = value;
                      else if (property.name == "y")
                        x[1] = value;
                      else if (property.name == "z")
                        x[2] = value;
                    }
                  else if (static_cast<int>(p) == group_property)
                    {
                      std::ostringstream key;
                      key << element.properties[p].name << " " << value;
                      group = groups.number(key.str(), surface);
                    }
                }
              if (element.name == "vertex")
                surface.vertices.push_back(x);
              else if (element.name == "face")
                add_polygon(polygon,
                            group,
                            surface,
                            context,
                            "face " + std::to_string(i + 1) + " (from 1)");
            }
        }
      return surface;
    }

    SurfaceTriangles
    read_off(std::istream &in, const FileContext &context)
    {
      // Comments (#) dropped, then whitespace-separated numbers.
      std::string text, line;
      while (std::getline(in, line))
        text += line.substr(0, line.find('#')) + "\n";
      std::istringstream words(text);
      std::string        key;
      std::size_t        n_vertices = 0, n_faces = 0, n_edges = 0;
      if (!(words >> key) || key != "OFF" ||
          !(words >> n_vertices >> n_faces >> n_edges))
        context.fail("not an OFF file ('OFF', then the vertex, face and edge "
                     "counts)");
      SurfaceTriangles surface;
      for (std::size_t v = 0; v < n_vertices; ++v)
        {
          Point<3> x;
          if (!(words >> x[0] >> x[1] >> x[2]))
            context.fail("vertex " + std::to_string(v) + " is incomplete");
          surface.vertices.push_back(x);
        }
      for (std::size_t f = 0; f < n_faces; ++f)
        {
          std::size_t            n = 0;
          std::vector<long long> polygon;
          words >> n;
          for (std::size_t k = 0; k < n; ++k)
            {
              long long v = -1;
              words >> v;
              polygon.push_back(v);
            }
          if (!words)
            context.fail("face " + std::to_string(f) + " is incomplete");
          add_polygon(polygon,
                      0,
                      surface,
                      context,
                      "face " + std::to_string(f) + " (from 0)");
        }
      return surface;
    }
  } // namespace

  SurfaceTriangles
  read_surface_file(const std::string &file_name, const std::string &entry)
  {
    const FileContext context{entry, file_name};
    std::ifstream     in(file_name, std::ios::binary);
    if (!in)
      context.fail("cannot open the surface file");
    const auto        dot = file_name.rfind('.');
    const std::string extension =
      dot == std::string::npos ? "" : lower_case(file_name.substr(dot + 1));
    SurfaceTriangles surface;
    if (extension == "obj")
      surface = read_obj(in, context);
    else if (extension == "off")
      surface = read_off(in, context);
    else if (extension == "stl" || extension == "ply")
      {
        std::stringstream text;
        text << in.rdbuf();
        surface = extension == "stl" ? read_stl(text.str(), context)
                                     : read_ply(text.str(), context);
      }
    else
      context.fail("a surface file is read by its extension: .obj, .stl, "
                   ".ply or .off");
    if (surface.triangles.empty())
      context.fail("the file holds no triangles");
    for (const Point<3> &x : surface.vertices)
      for (unsigned int d = 0; d < 3; ++d)
        if (!std::isfinite(x[d]))
          context.fail("a vertex coordinate is not a finite number");
    // No groups at all: boundary id 0 everywhere.
    if (surface.group_names.empty())
      std::fill(surface.groups.begin(), surface.groups.end(), 0);
    // Vertices at equal coordinates joined (exporters that write each
    // face's corners separately), those no triangle uses dropped; the
    // others keep their order.
    std::map<std::array<double, 3>, unsigned int> first_at;
    std::vector<unsigned int> joined(surface.vertices.size());
    for (unsigned int v = 0; v < surface.vertices.size(); ++v)
      {
        const Point<3> &x = surface.vertices[v];
        joined[v] =
          first_at.emplace(std::array<double, 3>{{x[0], x[1], x[2]}}, v)
            .first->second;
      }
    std::vector<unsigned int> number(surface.vertices.size(),
                                     dealii::numbers::invalid_unsigned_int);
    for (const auto &triangle : surface.triangles)
      for (const unsigned int v : triangle)
        number[joined[v]] = 0;
    std::vector<Point<3>> used;
    for (unsigned int v = 0; v < surface.vertices.size(); ++v)
      if (number[v] == 0)
        {
          number[v] = used.size();
          used.push_back(surface.vertices[v]);
        }
    for (auto &triangle : surface.triangles)
      for (unsigned int &v : triangle)
        v = number[joined[v]];
    surface.vertices = std::move(used);
    return surface;
  }
} // namespace hyperelastic
