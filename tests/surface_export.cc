// The OBJ/PLY surface sequence (issue 31; output/surface_writer.h) of the
// unit box [0,1]^dim of n^dim boxes (3D n = 3, 2D n = 4) on symmetry rollers
// (x = 0, y = 0, z = 0), its face x = 1 pulled to the stretch 1.3 in two
// load steps: a homogeneous deformation x = diag(l) X, l read from the CSV's
// deformed extents.
//   surface_export DIM obj|ply   writes frames 0, 1, 2 into
//       surface_export_<DIM>d_<format>_np<ranks>/ and checks them: vertex
//       and triangle counts (3D 6 n^2 + 2 and 12 n^2; 2D the mesh's
//       vertices and cells), frame 0 = the reference grid in lexicographic
//       order, the same triangles in every frame, frame 2's vertices =
//       diag(l) X (1e-10: the same vertex order), closed and outward (3D:
//       every edge once in each direction, signed volume = l1 l2 l3; 2D:
//       every triangle counter-clockwise, signed area = l1 l2; 1e-10); PLY:
//       the per-vertex von Mises stress of the homogeneous state, the same
//       at every vertex (1e-10) and positive.
//   surface_export DIM compare FORMAT   the np1 and np2 folders' files:
//       identical triangles, vertices equal to 1e-12 (round-off of the two
//       partitions' solves).
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/stretched_box.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using namespace hyperelastic;
  using namespace hyperelastic::testing;

  struct Surface
  {
    std::vector<std::array<double, 3>>       vertices;
    std::vector<double>                      von_mises;
    std::vector<std::array<unsigned int, 3>> triangles; // 0-based
  };

  /// Reads an OBJ or PLY file written by SurfaceWriter.
  Surface
  read_surface(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      throw std::runtime_error("cannot read '" + file + "'");
    Surface     s;
    std::string line;
    if (file.substr(file.size() - 4) == ".obj")
      {
        while (std::getline(in, line))
          {
            std::istringstream words(line);
            std::string        kind;
            words >> kind;
            if (kind == "v")
              {
                std::array<double, 3> x;
                words >> x[0] >> x[1] >> x[2];
                s.vertices.push_back(x);
              }
            else if (kind == "f")
              {
                std::array<unsigned int, 3> t;
                words >> t[0] >> t[1] >> t[2];
                s.triangles.push_back({{t[0] - 1, t[1] - 1, t[2] - 1}});
              }
          }
        return s;
      }
    unsigned int n_vertices = 0, n_faces = 0;
    bool         stress = false;
    while (std::getline(in, line) && line != "end_header")
      {
        std::istringstream words(line);
        std::string        a, b;
        words >> a >> b;
        if (a == "element" && b == "vertex")
          words >> n_vertices;
        else if (a == "element" && b == "face")
          words >> n_faces;
        else if (line == "property double von_mises")
          stress = true;
      }
    for (unsigned int k = 0; k < n_vertices; ++k)
      {
        std::array<double, 3> x;
        in >> x[0] >> x[1] >> x[2];
        s.vertices.push_back(x);
        if (stress)
          {
            double v;
            in >> v;
            s.von_mises.push_back(v);
          }
      }
    for (unsigned int k = 0; k < n_faces; ++k)
      {
        unsigned int                corners;
        std::array<unsigned int, 3> t;
        in >> corners >> t[0] >> t[1] >> t[2];
        s.triangles.push_back(t);
      }
    return s;
  }

  std::string
  folder(const int dim, const std::string &format, const unsigned int ranks)
  {
    return "surface_export_" + std::to_string(dim) + "d_" + format + "_np" +
           std::to_string(ranks);
  }

  std::string
  frame_file(const std::string &dir, const std::string &format, int frame)
  {
    return dir + "/cube_surface_000" + std::to_string(frame) + "." + format;
  }

  template <int dim>
  void
  export_surface(Checker &checker, const std::string &format)
  {
    const bool         three = dim == 3;
    const unsigned int n     = three ? 3 : 4;
    const std::string  dir   = folder(
      dim, format, Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
    const auto problem = run_scene<dim>(stretched_unit_box(
      dim,
      three ? "3, 3, 3" : "4, 4",
      entry("Directory", dir) + entry("Base name", "cube") +
        entry("Write VTU", "false") + entry("Surface format", format)));
    const std::string           tag = std::to_string(dim) + "D " + format + ": ";
    const std::array<double, 3> l   = box_stretches(problem->summaries().back());
    checker.is_true(tag + "frames 0, 1, 2 and no frame 3",
                    std::filesystem::exists(frame_file(dir, format, 2)) &&
                      !std::filesystem::exists(frame_file(dir, format, 3)));
    const Surface first = read_surface(frame_file(dir, format, 0));
    const Surface end   = read_surface(frame_file(dir, format, 2));
    const unsigned int n_vertices =
      three ? 6 * n * n + 2 : (n + 1) * (n + 1);
    const unsigned int n_triangles =
      three ? 12 * n * n
            : problem->get_dof_handler().get_triangulation().n_global_active_cells();
    checker.is_true(tag + "vertices " + std::to_string(end.vertices.size()) +
                      " = " + std::to_string(n_vertices),
                    end.vertices.size() == n_vertices &&
                      first.vertices.size() == n_vertices);
    checker.is_true(tag + "triangles " + std::to_string(end.triangles.size()) +
                      " = " + std::to_string(n_triangles),
                    end.triangles.size() == n_triangles);
    checker.is_true(tag + "the same triangles in frames 0, 1, 2",
                    first.triangles == end.triangles &&
                      read_surface(frame_file(dir, format, 1)).triangles ==
                        end.triangles);
    // Frame 0: the grid points, in lexicographic order.
    bool   sorted   = true;
    double off_grid = 0.;
    for (unsigned int k = 0; k < first.vertices.size(); ++k)
      {
        for (unsigned int d = 0; d < 3; ++d)
          off_grid =
            std::max(off_grid,
                     std::abs(first.vertices[k][d] * n -
                              std::round(first.vertices[k][d] * n)));
        if (k > 0)
          sorted = sorted && first.vertices[k - 1] < first.vertices[k];
      }
    checker.is_true(tag + "frame 0 in lexicographic order", sorted);
    checker.at_most(tag + "frame 0 on the reference grid", off_grid, 1e-14);
    double moved = 0.;
    for (unsigned int k = 0; k < end.vertices.size(); ++k)
      for (unsigned int d = 0; d < 3; ++d)
        moved = std::max(moved,
                         std::abs(end.vertices[k][d] -
                                  l[d] * first.vertices[k][d]));
    checker.at_most(tag + "frame 2 = diag(l) X vertex by vertex", moved, 1e-10);

    // Closed and outward.
    double measure = 0., smallest = 1.;
    std::map<std::pair<unsigned int, unsigned int>, int> edges;
    for (const auto &t : end.triangles)
      {
        const auto &a = end.vertices[t[0]], &b = end.vertices[t[1]],
                   &c = end.vertices[t[2]];
        if (three)
          measure += (a[0] * (b[1] * c[2] - b[2] * c[1]) -
                      a[1] * (b[0] * c[2] - b[2] * c[0]) +
                      a[2] * (b[0] * c[1] - b[1] * c[0])) /
                     6.;
        else
          {
            const double area = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) -
                                       (b[1] - a[1]) * (c[0] - a[0]));
            measure += area;
            smallest = std::min(smallest, area);
          }
        for (unsigned int i = 0; i < 3; ++i)
          ++edges[{t[i], t[(i + 1) % 3]}];
      }
    const double exact = l[0] * l[1] * l[2];
    checker.close(tag + (three ? "signed volume = l1 l2 l3"
                               : "signed area = l1 l2"),
                  measure,
                  exact,
                  exact,
                  1e-10);
    if (three)
      {
        bool closed = true;
        for (const auto &[edge, count] : edges)
          closed = closed && count == 1 &&
                   edges.count({edge.second, edge.first}) == 1;
        checker.is_true(tag + "every edge once in each direction (closed, "
                              "consistently oriented)",
                        closed);
      }
    else
      checker.above(tag + "every triangle counter-clockwise", smallest, 0.);
    if (format == "ply")
      {
        checker.is_true(tag + "a von Mises value per vertex",
                        end.von_mises.size() == end.vertices.size());
        double spread = 0.;
        for (const double v : end.von_mises)
          spread = std::max(spread, std::abs(v - end.von_mises.front()));
        checker.above(tag + "von Mises stress", end.von_mises.front(), 0.);
        checker.at_most(tag + "von Mises the same at every vertex "
                              "(homogeneous)",
                        spread / end.von_mises.front(),
                        1e-10);
      }
  }

  void
  compare(Checker &checker, const int dim, const std::string &format)
  {
    for (int frame = 0; frame < 3; ++frame)
      {
        const Surface one = read_surface(frame_file(folder(dim, format, 1), format, frame));
        const Surface two = read_surface(frame_file(folder(dim, format, 2), format, frame));
        const std::string tag = std::to_string(dim) + "D " + format +
                                " frame " + std::to_string(frame) +
                                ", 1 and 2 ranks: ";
        checker.is_true(tag + "identical triangles",
                        one.triangles == two.triangles &&
                          !one.triangles.empty());
        double difference = one.vertices.size() == two.vertices.size() ? 0. : 1.;
        for (unsigned int k = 0; difference < 1. && k < one.vertices.size(); ++k)
          for (unsigned int d = 0; d < 3; ++d)
            difference = std::max(difference,
                                  std::abs(one.vertices[k][d] - two.vertices[k][d]));
        checker.at_most(tag + "vertices", difference, 1e-12);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_for_dimension(
    argc, argv, 1, [&](const int dim, Checker &checker, bool) {
      const std::string what = argc > 2 ? argv[2] : "";
      if (what == "compare")
        compare(checker, dim, argc > 3 ? argv[3] : "");
      else if (what == "obj" || what == "ply")
        dim == 2 ? export_surface<2>(checker, what)
                 : export_surface<3>(checker, what);
      else
        throw InputError("unknown case '" + what + "'");
    });
}
