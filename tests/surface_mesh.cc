// Closed surfaces meshed on the fly (Mesh/Source = surface).
//
// - A unit icosphere (1280 triangles) written as OBJ (two groups), binary
//   PLY (a face property) and OFF reads back as the same surface; filled
//   with tetrahedra, as it is and split to a mesh size: the tetrahedra's
//   volume equals the enclosed polyhedral volume (1e-12), no cell is
//   inverted or flat (smallest dihedral angle above 5 degrees), every
//   surface vertex is a vertex of the volume mesh, and the surface's
//   triangles are exactly the volume mesh's boundary faces.
// - A unit cube, binary STL and ASCII STL with one solid per face: volume 1
//   to 1e-12, the same checks.
// - The cube (its solids as boundary ids 1 ... 6) stretched uniaxially to
//   1.5 through the program on 2 ranks: the stretches and reactions of the
//   analytic solution to 1e-10; the mesh written by 'Output/Write mesh'
//   and read back through Mesh/Source = file gives the same CSV (0
//   difference); the same on one rank (the serial path).
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/surface_file.h>
#include <hyperelastic/mesh/surface_mesher.h>
#include <hyperelastic/problem/problem.h>

#include "support/analytic_bar.h"
#include "support/checker.h"
#include "support/scene_text.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using dealii::Point;

namespace
{
  const std::string folder = "surface_mesh_output";

  /// The icosahedron's 20 faces split @p levels times, on the unit sphere;
  /// group 1 for triangles whose centre has z >= 0, else 2.
  SurfaceTriangles
  icosphere(const unsigned int levels)
  {
    SurfaceTriangles s;
    const double     t = (1. + std::sqrt(5.)) / 2.;
    // vertices: 0-3 (x, y, 0), 4-7 (0, y, z), 8-11 (x, 0, z)
    s.vertices  = {Point<3>(-1, t, 0),
                   Point<3>(1, t, 0),
                   Point<3>(-1, -t, 0),
                   Point<3>(1, -t, 0),
                   Point<3>(0, -1, t),
                   Point<3>(0, 1, t),
                   Point<3>(0, -1, -t),
                   Point<3>(0, 1, -t),
                   Point<3>(t, 0, -1),
                   Point<3>(t, 0, 1),
                   Point<3>(-t, 0, -1),
                   Point<3>(-t, 0, 1)};
    s.triangles = {{{0, 11, 5}},  {{0, 5, 1}},  {{0, 1, 7}},  {{0, 7, 10}},
                   {{0, 10, 11}}, {{1, 5, 9}},  {{5, 11, 4}}, {{11, 10, 2}},
                   {{10, 7, 6}},  {{7, 1, 8}},  {{3, 9, 4}},  {{3, 4, 2}},
                   {{3, 2, 6}},   {{3, 6, 8}},  {{3, 8, 9}},  {{4, 9, 5}},
                   {{2, 4, 11}},  {{6, 2, 10}}, {{8, 6, 7}},  {{9, 8, 1}}};
    for (Point<3> &x : s.vertices)
      x /= x.norm();
    for (unsigned int level = 0; level < levels; ++level)
      {
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> middle;
        const auto mid = [&](unsigned int a, unsigned int b) {
          const auto key = std::make_pair(std::min(a, b), std::max(a, b));
          if (middle.count(key) == 0)
            {
              Point<3> x = 0.5 * (s.vertices[a] + s.vertices[b]);
              s.vertices.push_back(x / x.norm());
              middle[key] = s.vertices.size() - 1;
            }
          return middle[key];
        };
        std::vector<std::array<unsigned int, 3>> finer;
        for (const auto &v : s.triangles)
          {
            const unsigned int ab = mid(v[0], v[1]), bc = mid(v[1], v[2]),
                               ca = mid(v[2], v[0]);
            finer.push_back({{v[0], ab, ca}});
            finer.push_back({{ab, v[1], bc}});
            finer.push_back({{ca, bc, v[2]}});
            finer.push_back({{ab, bc, ca}});
          }
        s.triangles = finer;
      }
    for (const auto &v : s.triangles)
      s.groups.push_back(
        s.vertices[v[0]][2] + s.vertices[v[1]][2] + s.vertices[v[2]][2] >= 0.
          ? 1
          : 2);
    s.group_names = {"north", "south"};
    return s;
  }

  /// The unit cube [0, 1]^3 with group k + 1 on face k (x = 0, x = 1,
  /// y = 0, ...), outward.
  SurfaceTriangles
  unit_cube()
  {
    SurfaceTriangles s;
    for (unsigned int v = 0; v < 8; ++v)
      s.vertices.emplace_back(v & 1, (v >> 1) & 1, (v >> 2) & 1);
    // Faces as quads, outward, in the order x0, x1, y0, y1, z0, z1.
    const unsigned int quads[6][4] = {{0, 4, 6, 2},
                                      {1, 3, 7, 5},
                                      {0, 1, 5, 4},
                                      {2, 6, 7, 3},
                                      {0, 2, 3, 1},
                                      {4, 5, 7, 6}};
    for (unsigned int f = 0; f < 6; ++f)
      {
        s.triangles.push_back({{quads[f][0], quads[f][1], quads[f][2]}});
        s.triangles.push_back({{quads[f][0], quads[f][2], quads[f][3]}});
        s.groups.push_back(f + 1);
        s.groups.push_back(f + 1);
      }
    return s;
  }

  void
  write_obj(const SurfaceTriangles &s, const std::string &file)
  {
    std::ofstream out(file);
    out << std::setprecision(17);
    for (const Point<3> &x : s.vertices)
      out << "v " << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
    unsigned int group = 0;
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
      {
        if (s.groups[t] != group)
          out << "g " << s.group_names[s.groups[t] - 1] << '\n';
        group = s.groups[t];
        out << "f " << s.triangles[t][0] + 1 << "//1 " << s.triangles[t][1] + 1
            << " " << s.triangles[t][2] + 1 << '\n';
      }
  }

  void
  write_ply_binary(const SurfaceTriangles &s, const std::string &file)
  {
    std::ofstream out(file, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex "
        << s.vertices.size()
        << "\nproperty double x\nproperty double y\nproperty double z\n"
           "element face "
        << s.triangles.size()
        << "\nproperty list uchar int vertex_indices\nproperty int "
           "group\nend_header\n";
    for (const Point<3> &x : s.vertices)
      for (unsigned int d = 0; d < 3; ++d)
        out.write(reinterpret_cast<const char *>(&x[d]), 8);
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
      {
        const unsigned char n = 3;
        out.write(reinterpret_cast<const char *>(&n), 1);
        for (const unsigned int v : s.triangles[t])
          {
            const std::int32_t i = v;
            out.write(reinterpret_cast<const char *>(&i), 4);
          }
        const std::int32_t g = 10 * s.groups[t]; // any values: 10, 20
        out.write(reinterpret_cast<const char *>(&g), 4);
      }
  }

  void
  write_off(const SurfaceTriangles &s, const std::string &file)
  {
    std::ofstream out(file);
    out << std::setprecision(17) << "OFF\n# icosphere\n"
        << s.vertices.size() << ' ' << s.triangles.size() << " 0\n";
    for (const Point<3> &x : s.vertices)
      out << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
    for (const auto &v : s.triangles)
      out << "3 " << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
  }

  /// ASCII STL with one solid per group; binary STL without groups.
  void
  write_stl(const SurfaceTriangles &s, const std::string &file, bool binary)
  {
    std::ofstream out(file, std::ios::binary);
    if (binary)
      {
        char header[80] = "binary STL of the unit cube";
        out.write(header, 80);
        const std::uint32_t n = s.triangles.size();
        out.write(reinterpret_cast<const char *>(&n), 4);
        for (const auto &v : s.triangles)
          {
            float values[12] = {0.f};
            for (unsigned int k = 0; k < 3; ++k)
              for (unsigned int d = 0; d < 3; ++d)
                values[3 + 3 * k + d] = s.vertices[v[k]][d];
            out.write(reinterpret_cast<const char *>(values), 48);
            const std::uint16_t attribute = 0;
            out.write(reinterpret_cast<const char *>(&attribute), 2);
          }
        return;
      }
    unsigned int group = 0;
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
      {
        if (s.groups[t] != group)
          {
            if (group != 0)
              out << "endsolid face" << group << '\n';
            group = s.groups[t];
            out << "solid face" << group << '\n';
          }
        out << " facet normal 0 0 0\n  outer loop\n";
        for (const unsigned int v : s.triangles[t])
          out << "   vertex " << s.vertices[v][0] << ' ' << s.vertices[v][1]
              << ' ' << s.vertices[v][2] << '\n';
        out << "  endloop\n endfacet\n";
      }
    out << "endsolid face" << group << '\n';
  }

  /// The checks of a volume mesh generated from the checked @p surface.
  void
  check_volume_mesh(Checker                &checker,
                    const std::string      &name,
                    const SurfaceTriangles &surface,
                    const GmshMesh<3>      &mesh,
                    const double            tolerance)
  {
    const TetQuality q = tet_quality(mesh);
    checker.note(name + ": " + std::to_string(mesh.cells.size()) +
                 " tetrahedra, " + std::to_string(mesh.vertices.size()) +
                 " vertices; smallest dihedral angle " +
                 std::to_string(q.min_dihedral_degrees) +
                 " degrees, radius ratio mean " +
                 std::to_string(q.mean_radius_ratio) + ", smallest " +
                 std::to_string(q.min_radius_ratio));
    double       volume   = 0.;
    unsigned int negative = 0;
    for (const auto &cell : mesh.cells)
      {
        const auto  &x = mesh.vertices;
        const auto  &v = cell.vertices;
        const double det =
          (x[v[1]] - x[v[0]]) *
          dealii::cross_product_3d(x[v[2]] - x[v[0]], x[v[3]] - x[v[0]]);
        volume += std::abs(det) / 6.;
        negative += det < 0. ? 1 : 0;
      }
    const double enclosed = enclosed_volume(surface);
    checker.close(name + ": volume of the tetrahedra",
                  volume,
                  enclosed,
                  enclosed,
                  tolerance);
    checker.is_true(name + ": all tetrahedra of one orientation",
                    negative == 0 || negative == mesh.cells.size());
    checker.above(name + ": smallest dihedral angle (degrees)",
                  q.min_dihedral_degrees,
                  5.);
    checker.above(name + ": smallest radius ratio", q.min_radius_ratio, 0.05);
    // The surface's vertices come first, unchanged.
    bool same = mesh.vertices.size() >= surface.vertices.size();
    for (std::size_t v = 0; same && v < surface.vertices.size(); ++v)
      same = mesh.vertices[v].distance(surface.vertices[v]) == 0.;
    checker.is_true(name + ": every surface vertex is a mesh vertex", same);
    // The faces of one tetrahedron only are exactly the surface's triangles.
    std::map<std::array<unsigned int, 3>, unsigned int> faces;
    for (const auto &cell : mesh.cells)
      for (unsigned int k = 0; k < 4; ++k)
        {
          std::array<unsigned int, 3> f;
          for (unsigned int j = 0; j < 3; ++j)
            f[j] = cell.vertices[(k + 1 + j) % 4];
          std::sort(f.begin(), f.end());
          ++faces[f];
        }
    std::set<std::array<unsigned int, 3>> boundary;
    for (const auto &[f, n] : faces)
      if (n == 1)
        boundary.insert(f);
    std::set<std::array<unsigned int, 3>> triangles;
    for (auto f : surface.triangles)
      {
        std::sort(f.begin(), f.end());
        triangles.insert(f);
      }
    checker.is_true(name + ": boundary faces = the surface's triangles (" +
                      std::to_string(boundary.size()) + ")",
                    boundary == triangles);
    // Every boundary face carries its triangle's group.
    std::map<std::array<unsigned int, 3>, unsigned int> group;
    for (std::size_t t = 0; t < surface.triangles.size(); ++t)
      {
        auto f = surface.triangles[t];
        std::sort(f.begin(), f.end());
        group[f] = surface.groups[t];
      }
    bool ids = mesh.boundary.boundary_quads.size() == triangles.size();
    for (const auto &face : mesh.boundary.boundary_quads)
      {
        std::array<unsigned int, 3> f{
          {face.vertices[0], face.vertices[1], face.vertices[2]}};
        std::sort(f.begin(), f.end());
        ids = ids && group.count(f) == 1 && group[f] == face.boundary_id;
      }
    checker.is_true(name + ": boundary ids = the surface's groups", ids);
  }

  /// The test's surface files, written by rank 0.
  void
  write_surfaces()
  {
    std::filesystem::create_directories(folder);
    const SurfaceTriangles sphere = icosphere(3);
    write_obj(sphere, folder + "/sphere.obj");
    write_ply_binary(sphere, folder + "/sphere.ply");
    write_off(sphere, folder + "/sphere.off");
    {
      // Each triangle with its own three corners, and an unused vertex.
      std::ofstream out(folder + "/sphere_soup.obj");
      out << std::setprecision(17) << "v 5 5 5\n";
      for (const auto &v : sphere.triangles)
        for (const unsigned int k : v)
          out << "v " << sphere.vertices[k][0] << ' ' << sphere.vertices[k][1]
              << ' ' << sphere.vertices[k][2] << '\n';
      for (std::size_t t = 0; t < sphere.triangles.size(); ++t)
        out << "f " << 3 * t + 2 << ' ' << 3 * t + 3 << ' ' << 3 * t + 4
            << '\n';
    }
    SurfaceTriangles cube = unit_cube();
    write_stl(cube, folder + "/cube.stl", false);
    std::swap(cube.triangles[3][1], cube.triangles[3][2]);
    write_stl(cube, folder + "/cube_binary.stl", true);
  }

  void
  check_surfaces(Checker &checker)
  {
    checker.section("surface files and tetrahedralisation");
    const SurfaceTriangles sphere = icosphere(3);
    const double           exact  = enclosed_volume(sphere);
    for (const std::string extension : {"obj", "ply", "off"})
      {
        const SurfaceTriangles read =
          read_surface_file(folder + "/sphere." + extension);
        checker.is_true(extension + ": the same triangles",
                        read.triangles == sphere.triangles &&
                          read.vertices.size() == sphere.vertices.size());
        checker.close(extension + ": enclosed volume",
                      enclosed_volume(read),
                      exact,
                      exact,
                      1e-15);
        checker.is_true(extension + ": groups",
                        extension == "off"
                          ? read.group_names.empty() &&
                              read.groups ==
                                std::vector<unsigned int>(read.triangles.size(),
                                                          0)
                          : read.groups == sphere.groups);
      }
    {
      const SurfaceTriangles soup =
        read_surface_file(folder + "/sphere_soup.obj");
      checker.is_true("OBJ with separate corners per face and an unused "
                      "vertex: joined to the sphere's 642 vertices",
                      soup.vertices.size() == sphere.vertices.size() &&
                        soup.triangles.size() == sphere.triangles.size());
      checker.close("OBJ with separate corners: enclosed volume",
                    enclosed_volume(soup),
                    exact,
                    exact,
                    1e-14);
    }
    checker.close("icosphere (1280 triangles): polyhedral volume against "
                  "the sphere's 4 pi / 3 (within 1 %)",
                  exact,
                  4. * M_PI / 3.,
                  4. * M_PI / 3.,
                  0.01);

    SurfaceTriangles surface = read_surface_file(folder + "/sphere.obj");
    checker.is_true("sphere: closed and outward (no triangle turned)",
                    check_closed_surface(surface, "test") == 0);
    check_volume_mesh(checker,
                      "sphere",
                      surface,
                      tetrahedralise(surface,
                                     mean_edge_length(surface),
                                     "test"),
                      1e-12);
    const SurfaceTriangles split = split_to_size(surface, 0.1);
    checker.is_true("sphere split to size 0.1: 4 x 1280 triangles",
                    split.triangles.size() == 4 * 1280);
    check_volume_mesh(checker,
                      "sphere split",
                      split,
                      tetrahedralise(split, 0.1, "test"),
                      1e-12);

    // The cube: binary STL (no groups), ASCII STL with a solid per face;
    // one triangle listed inward (turned back).
    // A hollow sphere: the icosphere and, inside, a smaller one (a cavity)
    // in one file, both listed outward.
    {
      SurfaceTriangles  hollow = read_surface_file(folder + "/sphere.obj");
      const std::size_t n      = hollow.vertices.size();
      for (std::size_t v = 0; v < n; ++v)
        hollow.vertices.push_back(Point<3>(0.5 * hollow.vertices[v]));
      for (std::size_t t = 0, m = hollow.triangles.size(); t < m; ++t)
        {
          auto inner = hollow.triangles[t];
          for (unsigned int &v : inner)
            v += n;
          hollow.triangles.push_back(inner);
          hollow.groups.push_back(3);
        }
      hollow.group_names.push_back("cavity");
      checker.is_true(
        "hollow sphere: the cavity's 1280 triangles turned inward",
        check_closed_surface(hollow, "test") == 0 &&
          hollow.triangles[1280][1] == sphere.triangles[0][2] + n);
      checker.close("hollow sphere: enclosed volume (7/8 of the sphere's)",
                    enclosed_volume(hollow),
                    7. / 8. * exact,
                    exact,
                    1e-13);
      check_volume_mesh(checker,
                        "hollow sphere",
                        hollow,
                        tetrahedralise(hollow, 0.15, "test"),
                        1e-12);
    }

    SurfaceTriangles binary = read_surface_file(folder + "/cube_binary.stl");
    checker.is_true("binary STL: 8 vertices, 12 triangles, no groups",
                    binary.vertices.size() == 8 &&
                      binary.triangles.size() == 12 &&
                      binary.group_names.empty());
    checker.is_true("binary STL: one triangle turned outward",
                    check_closed_surface(binary, "test") == 1);
    checker.close(
      "cube: enclosed volume", enclosed_volume(binary), 1., 1., 1e-15);
    const SurfaceTriangles fine = split_to_size(binary, 0.2);
    check_volume_mesh(
      checker, "cube", fine, tetrahedralise(fine, 0.2, "test"), 1e-12);
    SurfaceTriangles ascii = read_surface_file(folder + "/cube.stl");
    check_closed_surface(ascii, "test");
    checker.is_true("ASCII STL: 6 solids as groups 1 ... 6",
                    ascii.group_names.size() == 6 &&
                      ascii.groups == unit_cube().groups);
  }

  std::string
  cube_scene(const std::string &source,
             const std::string &file,
             const std::string &base_name,
             const double       displacement)
  {
    const double       mu = 1., lambda = 1.;
    std::ostringstream value;
    value << std::setprecision(17) << displacement;
    return subsection("Problem", entry("Dimension", "3")) +
           subsection("Mesh",
                      entry("Source", source) + entry("File", file) +
                        entry("Mesh size", "0.3")) +
           material_section("neo-Hookean",
                            entry("Elastic constants", "Lame") +
                              entry("Shear modulus", number(mu)) +
                              entry("Lame lambda", number(lambda)),
                            lame_parameters(mu, lambda)) +
           subsection("Loading", entry("Number of load steps", "2")) +
           dirichlet(1, 1, "x", "0") + dirichlet(2, 3, "y", "0") +
           dirichlet(3, 5, "z", "0") +
           dirichlet(4, 2, "x", value.str() + "*t") + tight_solver("cg") +
           subsection(
             "Output",
             entry("Directory", folder) + entry("Base name", base_name) +
               entry("Write VTU", "false") + entry("Verbose", "false") +
               entry("Write mesh", source == "surface" ? "true" : "false"));
  }

  std::string
  file_text(const std::string &file)
  {
    std::ifstream     in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  void
  check_stretch(Checker &checker, const MPI_Comm comm)
  {
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    checker.section("the cube stretched to 1.5 on " + std::to_string(n_ranks) +
                    " rank(s)");
    const double        l1    = 1.5;
    const UniaxialState exact = uniaxial("neo-Hookean", 3, l1, 1., 1.);
    const std::string   base  = "cube_np" + std::to_string(n_ranks);
    Parameters          parameters;
    parameters.read_from_string(
      cube_scene("surface",
                 std::filesystem::absolute(folder + "/cube.stl").string(),
                 base,
                 l1 - 1.),
      ".",
      base);
    {
      Problem<3> problem(parameters, comm, false);
      problem.run();
      const StepSummary<3> &s = problem.summaries().back();
      checker.close(
        "axial stretch", s.deformed_max[0] - s.deformed_min[0], l1, l1, 1e-10);
      for (unsigned int d = 1; d < 3; ++d)
        checker.close("lateral stretch",
                      s.deformed_max[d] - s.deformed_min[d],
                      exact.l2,
                      exact.l2,
                      1e-10);
      for (const auto &[id, force] : s.reactions)
        {
          const double expected = id == 1   ? -exact.P11
                                  : id == 2 ? exact.P11
                                            : 0.;
          checker.close("reaction x on boundary " + std::to_string(id),
                        force[0],
                        expected,
                        exact.P11,
                        1e-10);
        }
    }
    // The written mesh read back: the same run.
    Parameters again;
    again.read_from_string(
      cube_scene(
        "file",
        std::filesystem::absolute(folder + "/" + base + "_mesh.msh").string(),
        base + "_file",
        l1 - 1.),
      ".",
      base + "_file");
    {
      Problem<3> problem(again, comm, false);
      problem.run();
    }
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        const std::string a = file_text(folder + "/" + base + ".csv"),
                          b = file_text(folder + "/" + base + "_file.csv");
        checker.is_true("the written mesh read back gives the same CSV (" +
                          std::to_string(a.size()) + " characters)",
                        !a.empty() && a == b);
      }
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  Checker   checker(rank == 0);
  const int status = run_and_report(
    [&]() {
      // Every rank checks (so that a failure stops all alike); rank 0
      // prints.
      if (rank == 0)
        write_surfaces();
      MPI_Barrier(MPI_COMM_WORLD);
      check_surfaces(checker);
      check_stretch(checker, MPI_COMM_WORLD);
      // One rank: the serial path, the same CSV as on all ranks.
      MPI_Comm self;
      MPI_Comm_split(MPI_COMM_WORLD, rank == 0 ? 0 : MPI_UNDEFINED, 0, &self);
      if (rank == 0)
        {
          check_stretch(checker, self);
          MPI_Comm_free(&self);
        }
      MPI_Barrier(MPI_COMM_WORLD);
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
