// What the mesh file readers share: the whole file in memory, read as text
// tokens or binary blocks, and the readers' last step.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/mesh_file_text.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <utility>

namespace hyperelastic
{
  using namespace dealii;

  FileBytes
  read_whole_file(const std::string &file_name, const std::string &entry)
  {
    std::ifstream   in(file_name, std::ios::binary);
    std::error_code error;
    if (!in || !std::filesystem::is_regular_file(file_name, error))
      throw InputError("cannot open mesh file '" + file_name + "' (" + entry +
                       ")" + (in ? ": it is not a regular file" : ""));
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0);
    if (size < 0)
      throw InputError("cannot read mesh file '" + file_name + "'");
    FileBytes file;
    file.size = size;
    file.data.reset(new char[file.size > 0 ? file.size : 1]);
    if (!in.read(file.data.get(), size))
      throw InputError("cannot read mesh file '" + file_name + "'");
    return file;
  }

  bool
  machine_is_little_endian()
  {
    const std::uint16_t one = 1;
    unsigned char       first;
    std::memcpy(&first, &one, 1);
    return first == 1;
  }

  MeshFileText::MeshFileText(FileBytes contents, std::string file_name)
      : contents(std::move(contents))
      , text(this->contents.data.get(), this->contents.size)
      , file_name(std::move(file_name))
  {
  }

  bool
  MeshFileText::more()
  {
    skip_blanks();
    return pos < text.size();
  }

  std::string_view
  MeshFileText::word()
  {
    if (!more())
      fail("unexpected end of file");
    const std::size_t start = pos;
    while (pos < text.size() && !is_blank(text[pos]))
      ++pos;
    return text.substr(start, pos - start);
  }

  void
  MeshFileText::skip_line()
  {
    const std::size_t end = text.find('\n', pos);
    pos                   = end == std::string::npos ? text.size() : end + 1;
  }

  std::string_view
  MeshFileText::skip_to_line_starting(const std::string_view prefix,
                                      const std::string_view section)
  {
    for (;;)
      {
        skip_line();
        if (!more())
          fail("unexpected end of file in section " + std::string(section));
        if (text.substr(pos, prefix.size()) == prefix)
          return word();
      }
  }

  void
  MeshFileText::skip_past(const std::string_view marker,
                          const std::string_view section)
  {
    const std::size_t found = text.find(marker, pos);
    if (found == std::string_view::npos)
      fail("unexpected end of file in section " + std::string(section));
    pos = found + marker.size();
  }

  void
  MeshFileText::skip_blanks_on_line()
  {
    while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t'))
      ++pos;
  }

  bool
  MeshFileText::next_is_digit() const
  {
    return pos < text.size() && text[pos] >= '0' && text[pos] <= '9';
  }

  bool
  MeshFileText::at_line_end() const
  {
    return pos >= text.size() || text[pos] == '\n' || text[pos] == '\r';
  }

  bool
  MeshFileText::next_starts_with(const std::string_view prefix) const
  {
    std::size_t at = pos;
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t'))
      ++at;
    return text.substr(at, prefix.size()) == prefix;
  }

  void
  MeshFileText::skip_to_empty_line()
  {
    for (;;)
      {
        skip_line();
        std::size_t at = pos;
        while (at < text.size() &&
               (text[at] == ' ' || text[at] == '\t' || text[at] == '\r'))
          ++at;
        if (at >= text.size() || text[at] == '\n')
          {
            skip_line();
            return;
          }
      }
  }

  void
  MeshFileText::expect(const std::string_view expected)
  {
    const std::string_view w = word();
    if (w != expected)
      fail("expected " + std::string(expected) + " on line " +
           std::to_string(line_number()) + " but found '" +
           std::string(w.substr(0, 40)) + "' (do the counts match the lists?)");
  }

  const char *
  MeshFileText::raw(const std::size_t n, const std::string_view section)
  {
    if (n > text.size() - pos)
      fail_truncated(section, n);
    const char *bytes = text.data() + pos;
    pos += n;
    return bytes;
  }

  void
  MeshFileText::skip_bytes(const std::size_t n, const std::string_view section)
  {
    if (n > text.size() - pos)
      fail_truncated(section, n);
    pos += n;
  }

  std::size_t
  MeshFileText::line_number() const
  {
    return 1 + std::count(text.begin(),
                          text.begin() + std::min(pos, text.size()),
                          '\n');
  }

  void
  MeshFileText::fail(const std::string &what) const
  {
    throw InputError("cannot read mesh file '" + file_name + "': " + what);
  }

  void
  MeshFileText::fail_truncated(const std::string_view section,
                               const std::size_t      wanted) const
  {
    fail("the binary data of " + std::string(section) +
         " ends early (the file ends " + std::to_string(text.size() - pos) +
         " bytes after byte " + std::to_string(pos) + ", " +
         std::to_string(wanted) +
         " more were expected): is the file truncated, or do its counts not "
         "match its lists?");
  }

  void
  MeshFileText::skip_blanks()
  {
    while (pos < text.size() && is_blank(text[pos]))
      ++pos;
  }

  template <int dim>
  void
  finish_mesh_cells(GmshMesh<dim> &mesh, std::vector<Point<3>> &&nodes)
  {
    for (unsigned int d = 0; d < 3; ++d)
      {
        mesh.lower[d] = std::numeric_limits<double>::infinity();
        mesh.upper[d] = -std::numeric_limits<double>::infinity();
      }
    // The nodes the cells use, then their bounds: one pass over the nodes
    // rather than dim + 1 scattered reads per cell.
    std::vector<char> used(nodes.size(), 0);
    for (const CellData<dim> &cell : mesh.cells)
      for (const unsigned int v : cell.vertices)
        used[v] = 1;
    for (std::size_t v = 0; v < nodes.size(); ++v)
      if (used[v])
        for (unsigned int d = 0; d < 3; ++d)
          {
            mesh.lower[d] = std::min(mesh.lower[d], nodes[v][d]);
            mesh.upper[d] = std::max(mesh.upper[d], nodes[v][d]);
          }
    if constexpr (dim == 3)
      mesh.vertices = std::move(nodes);
    else
      {
        mesh.vertices.clear();
        mesh.vertices.reserve(nodes.size());
        for (const Point<3> &x : nodes)
          mesh.vertices.emplace_back(x[0], x[1]);
        nodes.clear();
      }
  }

  template void
  finish_mesh_cells<2>(GmshMesh<2> &, std::vector<Point<3>> &&);
  template void
  finish_mesh_cells<3>(GmshMesh<3> &, std::vector<Point<3>> &&);
} // namespace hyperelastic
