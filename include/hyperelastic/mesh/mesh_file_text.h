// What the mesh file readers (gmsh, MEDIT, VTK) share: the whole file read
// into memory once, walked as whitespace-separated tokens or as blocks of
// binary numbers (copied with memcpy, byte-swapped where the file's byte
// order is not the machine's), with errors that name the file and the line
// or section; and the last step of every reader (bounds, dim coordinates).
#pragma once

#include <deal.II/base/point.h>

#include <hyperelastic/mesh/gmsh_reader.h>

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace hyperelastic
{
  /// The bytes of a file (not zeroed before they are read: a large mesh
  /// file is read once).
  struct FileBytes
  {
    std::unique_ptr<char[]> data;
    std::size_t             size = 0;
  };

  /// The whole file @p file_name, or an InputError naming it and the scene
  /// entry @p entry.
  FileBytes
  read_whole_file(const std::string &file_name, const std::string &entry);

  /// The number of type T stored at @p bytes, its bytes reversed if
  /// @p swap.
  template <typename T>
  T
  load_binary(const char *bytes, const bool swap)
  {
    static_assert(std::is_arithmetic_v<T>);
    T value;
    if (swap)
      {
        char reversed[sizeof(T)];
        std::reverse_copy(bytes, bytes + sizeof(T), reversed);
        std::memcpy(&value, reversed, sizeof(T));
      }
    else
      std::memcpy(&value, bytes, sizeof(T));
    return value;
  }

  /// Whether this machine stores numbers little-endian.
  bool
  machine_is_little_endian();

  /// A mesh file in memory, read front to back: tokens of text, or binary
  /// numbers. Every error is an InputError that names the file.
  class MeshFileText
  {
  public:
    MeshFileText(FileBytes contents, std::string file_name);

    /// Whether another token follows (blanks skipped).
    bool
    more();

    /// The next whitespace-separated token.
    std::string_view
    word();

    /// The next token as a number of type @p Number (a leading '+' is
    /// allowed for floating point numbers).
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
    skip_line();

    /// Moves to the start of the next line that begins with @p prefix
    /// (after blanks) and past its first word, which it returns; InputError
    /// naming @p section at the end of the file.
    std::string_view
    skip_to_line_starting(const std::string_view prefix,
                          const std::string_view section);

    /// Moves past the next occurrence of @p marker anywhere (binary data
    /// need not end with a line end before it); InputError naming
    /// @p section at the end of the file.
    void
    skip_past(const std::string_view marker, const std::string_view section);

    /// Skips spaces and tabs, not line ends.
    void
    skip_blanks_on_line();

    /// Whether the next character is a decimal digit.
    bool
    next_is_digit() const;

    /// Whether the current position is at the end of a line (or the file).
    bool
    at_line_end() const;

    /// Whether the text at the current position, after spaces and tabs,
    /// starts with @p prefix (nothing is consumed).
    bool
    next_starts_with(const std::string_view prefix) const;

    /// Moves past the lines up to and including the next empty one (or to
    /// the end of the file), starting at the line after the current one.
    void
    skip_to_empty_line();

    /// Throws unless the next word is @p expected.
    void
    expect(const std::string_view expected);

    /// Copies @p n binary numbers of type T at the current position into
    /// @p values and moves past them, swapping the bytes of each if
    /// @p swap; InputError naming @p section if the file ends before.
    template <typename T>
    void
    binary(T                     *values,
           const std::size_t      n,
           const bool             swap,
           const std::string_view section)
    {
      static_assert(std::is_arithmetic_v<T>);
      const std::size_t bytes = n * sizeof(T);
      if (bytes / sizeof(T) != n || bytes > text.size() - pos)
        fail_truncated(section, bytes);
      std::memcpy(values, text.data() + pos, bytes);
      pos += bytes;
      if (swap && sizeof(T) > 1)
        for (std::size_t i = 0; i < n; ++i)
          {
            auto *b = reinterpret_cast<unsigned char *>(values + i);
            std::reverse(b, b + sizeof(T));
          }
    }

    /// One binary number of type T (see binary()).
    template <typename T>
    T
    binary(const bool swap, const std::string_view section)
    {
      T value{};
      binary(&value, 1, swap, section);
      return value;
    }

    /// The next @p n bytes (moved past); InputError naming @p section if
    /// the file ends before.
    const char *
    raw(const std::size_t n, const std::string_view section);

    /// Moves past @p n bytes; InputError naming @p section if the file
    /// ends before.
    void
    skip_bytes(const std::size_t n, const std::string_view section);

    /// The 1-based line of the current position.
    std::size_t
    line_number() const;

    /// The size of the file in bytes.
    std::size_t
    size() const
    {
      return text.size();
    }

    /// The name of the file, as given.
    const std::string &
    name() const
    {
      return file_name;
    }

    [[noreturn]] void
    fail(const std::string &what) const;

  private:
    [[noreturn]] void
    fail_truncated(const std::string_view section,
                   const std::size_t      wanted) const;

    static bool
    is_blank(const char c)
    {
      return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\f' ||
             c == '\v';
    }

    void
    skip_blanks();

    const FileBytes        contents;
    const std::string_view text; ///< of contents
    const std::string      file_name;
    std::size_t            pos = 0;
  };

  /// The last step of every reader: the bounds of the cells' nodes and the
  /// vertices as points of @p dim coordinates (the first dim of @p nodes).
  template <int dim>
  void
  finish_mesh_cells(GmshMesh<dim> &mesh, std::vector<dealii::Point<3>> &&nodes);
} // namespace hyperelastic
