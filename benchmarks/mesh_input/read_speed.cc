// Reading speed of the mesh file formats: each file read REPEATS times by
// read_mesh_file() (what 'Mesh/File' does on rank 0 before the checks), one
// CSV row per file with the median, smallest and largest wall time, the
// file size and what was read (cells, tagged faces, vertices, and a
// checksum of the material and boundary ids, equal for the same mesh in any
// format).
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
  template <int dim>
  void
  measure(const std::string &file, const int repeats)
  {
    std::vector<double>         seconds;
    hyperelastic::GmshMesh<dim> mesh;
    for (int r = 0; r < repeats; ++r)
      {
        const auto start = std::chrono::steady_clock::now();
        mesh             = hyperelastic::read_mesh_file<dim>(file);
        seconds.push_back(std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - start)
                            .count());
      }
    std::sort(seconds.begin(), seconds.end());
    std::size_t faces = 0, ids = 0;
    for (const auto &cell : mesh.cells)
      ids += cell.material_id;
    if constexpr (dim == 2)
      for (const auto &line : mesh.boundary.boundary_lines)
        ++faces, ids += line.boundary_id;
    else
      for (const auto &triangle : mesh.boundary.boundary_quads)
        ++faces, ids += triangle.boundary_id;
    std::cout << std::filesystem::path(file).filename().string() << ','
              << std::filesystem::file_size(file) << ',' << std::setprecision(4)
              << seconds[seconds.size() / 2] << ',' << seconds.front() << ','
              << seconds.back() << ',' << mesh.cells.size() << ',' << faces
              << ',' << mesh.vertices.size() << ',' << ids << std::endl;
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
  try
    {
      for (int i = 3; i < argc; ++i)
        if (dim == 2)
          measure<2>(argv[i], repeats);
        else
          measure<3>(argv[i], repeats);
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << std::endl;
      return 1;
    }
  return 0;
}
