// Reading speed of the mesh file formats: each file read REPEATS times (in
// rounds over the files) by read_mesh_file() (what 'Mesh/File' does on rank 0
// before the checks), one CSV row per file with the median, smallest and
// largest wall time, the file size and what was read (cells, tagged faces,
// vertices, and a checksum of the material and boundary ids, equal for the same
// mesh in any format).
//
// Usage: hyperelastic_read_speed DIM REPEATS FILE...
#include <hyperelastic/mesh/mesh_file.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  /// What a read gave, for the row of its file.
  struct Outcome
  {
    std::vector<double> seconds;
    std::size_t         cells = 0, faces = 0, vertices = 0, id_sum = 0;
  };

  /// One timed read of @p file; the mesh is freed outside the timed part.
  template <int dim>
  void
  read_once(const std::string &file, Outcome &outcome)
  {
    const auto start = std::chrono::steady_clock::now();
    const auto mesh  = hyperelastic::read_mesh_file<dim>(file);
    outcome.seconds.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count());
    outcome.cells    = mesh.cells.size();
    outcome.vertices = mesh.vertices.size();
    outcome.faces    = 0;
    outcome.id_sum   = 0;
    for (const auto &cell : mesh.cells)
      outcome.id_sum += cell.material_id;
    if constexpr (dim == 2)
      for (const auto &line : mesh.boundary.boundary_lines)
        ++outcome.faces, outcome.id_sum += line.boundary_id;
    else
      for (const auto &triangle : mesh.boundary.boundary_quads)
        ++outcome.faces, outcome.id_sum += triangle.boundary_id;
  }
} // namespace

int
main(int argc, char *argv[])
{
  if (argc < 4)
    {
      std::cerr << "usage: " << argv[0] << " DIM REPEATS FILE..." << std::endl;
      return 1;
    }
  const int dim     = std::atoi(argv[1]);
  const int repeats = std::max(1, std::atoi(argv[2]));
  std::cout << "file,bytes,median_s,min_s,max_s,cells,faces,vertices,"
               "id_sum"
            << std::endl;
  // Round by round over the files, so that a change of the machine's
  // speed touches every format alike.
  const std::vector<std::string> files(argv + 3, argv + argc);
  std::vector<Outcome>           outcomes(files.size());
  try
    {
      for (int r = 0; r < repeats; ++r)
        for (std::size_t f = 0; f < files.size(); ++f)
          if (dim == 2)
            read_once<2>(files[f], outcomes[f]);
          else
            read_once<3>(files[f], outcomes[f]);
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << std::endl;
      return 1;
    }
  for (std::size_t f = 0; f < files.size(); ++f)
    {
      std::vector<double> &t = outcomes[f].seconds;
      std::sort(t.begin(), t.end());
      std::cout << std::filesystem::path(files[f]).filename().string() << ','
                << std::filesystem::file_size(files[f]) << ','
                << std::setprecision(4) << t[t.size() / 2] << ',' << t.front()
                << ',' << t.back() << ',' << outcomes[f].cells << ','
                << outcomes[f].faces << ',' << outcomes[f].vertices << ','
                << outcomes[f].id_sum << std::endl;
    }
  return 0;
}
