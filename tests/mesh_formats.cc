// Mesh file formats: one mesh (meshes/two_regions_<dim>d.msh, two material
// tags and six boundary tags) written by this test as gmsh ASCII 2.2 and
// 4.1 and binary 2.2 and 4.1 (through the gmsh API), as big-endian binary
// 2.2 and 4.1 (written here byte by byte; 2.2 also with a binary
// $ElementData section that ends as TetWild's do, without a line end before
// $EndElementData), as MEDIT .mesh and as legacy VTK
// (ASCII version 2 with SCALARS, binary version 5.1 with OFFSETS and
// CONNECTIVITY and a FIELD array, and the other way round). Each is read
// back by read_mesh_file(): the same vertices (bit for bit), cells, material
// ids, boundary faces and ids (and for the gmsh files the element numbers)
// as the original; and a short two-material scene run on each gives the
// same CSV file as on the original, byte for byte, on the ranks the test
// runs on. Bad input: an unknown extension, truncated binary gmsh and VTK
// files and a MEDIT element naming a vertex that does not exist are input
// errors naming the file (and the entry).
//
// Usage: mpirun -np N mesh_formats DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/gmsh_reader.h>
#include <hyperelastic/mesh/mesh.h>
#include <hyperelastic/mesh/mesh_checks.h>
#include <hyperelastic/mesh/mesh_file.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/scene_run.h"
#include "support/scene_text.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <gmsh.h>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  std::string
  file_text(const std::string &name)
  {
    std::ifstream      in(name, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  void
  write_text(const std::string &name, const std::string &text)
  {
    std::ofstream out(name, std::ios::binary);
    out << text;
  }

  /// Appends @p value to @p out, big-endian if @p big.
  template <typename T>
  void
  put(std::string &out, const T value, const bool big)
  {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    const std::uint16_t one = 1;
    unsigned char       first;
    std::memcpy(&first, &one, 1);
    if (big == (first == 1)) // the machine's order is not the one asked
      std::reverse(b, b + sizeof(T));
    out.append(reinterpret_cast<const char *>(b), sizeof(T));
  }

  std::string
  exact(const double x)
  {
    std::ostringstream s;
    s << std::setprecision(17) << x;
    return s.str();
  }

  /// A face's vertices and boundary id, whatever the dimension.
  template <int dim>
  struct Faces
  {
    std::vector<std::vector<unsigned int>> vertices;
    std::vector<unsigned int>              ids;
  };

  template <int dim>
  Faces<dim>
  faces(const GmshMesh<dim> &mesh)
  {
    Faces<dim> f;
    if constexpr (dim == 2)
      for (const CellData<1> &line : mesh.boundary.boundary_lines)
        {
          f.vertices.emplace_back(line.vertices.begin(), line.vertices.end());
          f.ids.push_back(line.boundary_id);
        }
    else
      for (const CellData<2> &triangle : mesh.boundary.boundary_quads)
        {
          f.vertices.emplace_back(triangle.vertices.begin(),
                                  triangle.vertices.end());
          f.ids.push_back(triangle.boundary_id);
        }
    return f;
  }

  /// Runs of equal ids in a list: [begin, end) with the id.
  struct Run
  {
    std::size_t  begin, end;
    unsigned int id;
  };

  std::vector<Run>
  runs(const std::vector<unsigned int> &ids)
  {
    std::vector<Run> r;
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (r.empty() || r.back().id != ids[i])
        r.push_back({i, i + 1, ids[i]});
      else
        r.back().end = i + 1;
    return r;
  }

  template <int dim>
  std::vector<unsigned int>
  material_ids(const GmshMesh<dim> &mesh)
  {
    std::vector<unsigned int> ids;
    for (const CellData<dim> &cell : mesh.cells)
      ids.push_back(cell.material_id);
    return ids;
  }

  /// The mesh as a binary gmsh file of format 2.2 (big-endian if @p big),
  /// written here: node tags 1 ... n in order, the element numbers and
  /// physical tags of @p mesh.
  template <int dim>
  std::string
  gmsh_binary_22(const GmshMesh<dim> &mesh, const bool big)
  {
    std::string out = "$MeshFormat\n2.2 1 8\n";
    put<std::int32_t>(out, 1, big);
    out += "\n$EndMeshFormat\n$Nodes\n" + std::to_string(mesh.vertices.size()) +
           "\n";
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
      {
        put<std::int32_t>(out, i + 1, big);
        for (unsigned int d = 0; d < 3; ++d)
          put<double>(out, d < dim ? mesh.vertices[i][d] : 0., big);
      }
    const Faces<dim> f = faces(mesh);
    out += "\n$EndNodes\n$Elements\n" +
           std::to_string(mesh.cells.size() + f.ids.size()) + "\n";
    // Faces first (as gmsh writes them), one block per run of equal tags.
    const auto block =
      [&](const int                                               type,
          const Run                                              &run,
          const std::function<const unsigned int *(std::size_t)> &nodes,
          const std::vector<long long>                           &numbers,
          const unsigned int                                      n_nodes) {
        put<std::int32_t>(out, type, big);
        put<std::int32_t>(out, run.end - run.begin, big);
        put<std::int32_t>(out, 2, big);
        for (std::size_t i = run.begin; i < run.end; ++i)
          {
            put<std::int32_t>(out, numbers[i], big);
            put<std::int32_t>(out, run.id, big); // physical
            put<std::int32_t>(out, run.id, big); // elementary
            for (unsigned int k = 0; k < n_nodes; ++k)
              put<std::int32_t>(out, nodes(i)[k] + 1, big);
          }
      };
    for (const Run &run : runs(f.ids))
      block(
        dim == 2 ? 1 : 2,
        run,
        [&](const std::size_t i) { return f.vertices[i].data(); },
        mesh.boundary_numbers,
        dim);
    for (const Run &run : runs(material_ids(mesh)))
      block(
        dim == 2 ? 2 : 4,
        run,
        [&](const std::size_t i) { return mesh.cells[i].vertices.data(); },
        mesh.element_numbers,
        dim + 1);
    out += "\n$EndElements\n";
    return out;
  }

  /// A binary $ElementData section of one value per cell as TetWild writes
  /// it (bunny_tetwild_80.msh of wildmeshing/data): its $EndElementData
  /// follows the binary values without a line end.
  std::string
  tetwild_element_data(const std::size_t n_cells)
  {
    std::string out = "$ElementData\n1\n\"quality\"\n1\n0.0\n3\n0\n1\n" +
                      std::to_string(n_cells) + "\n";
    for (std::size_t i = 0; i < n_cells; ++i)
      {
        put<std::int32_t>(out, i + 1, false);
        put<double>(out, 0.5 * i, false);
      }
    return out + "$EndElementData\n";
  }

  /// The mesh as a binary gmsh file of format 4.1 (big-endian if @p big),
  /// written here: one entity per run of equal tags (faces, then cells),
  /// the nodes in one block of the first volume (surface) entity.
  template <int dim>
  std::string
  gmsh_binary_41(const GmshMesh<dim> &mesh, const bool big)
  {
    std::string out = "$MeshFormat\n4.1 1 8\n";
    put<std::int32_t>(out, 1, big);
    out += "\n$EndMeshFormat\n$Entities\n";
    const Faces<dim>       f         = faces(mesh);
    const std::vector<Run> face_runs = runs(f.ids);
    const std::vector<Run> cell_runs = runs(material_ids(mesh));
    std::uint64_t          counts[4] = {0, 0, 0, 0};
    counts[dim - 1]                  = face_runs.size();
    counts[dim]                      = cell_runs.size();
    for (const std::uint64_t c : counts)
      put<std::uint64_t>(out, c, big);
    const auto entity = [&](const int tag, const unsigned int physical) {
      put<std::int32_t>(out, tag, big);
      for (unsigned int k = 0; k < 6; ++k)
        put<double>(out, 0., big);
      put<std::uint64_t>(out, 1, big);
      put<std::int32_t>(out, physical, big);
      put<std::uint64_t>(out, 0, big); // no bounding entities
    };
    for (std::size_t r = 0; r < face_runs.size(); ++r)
      entity(r + 1, face_runs[r].id);
    for (std::size_t r = 0; r < cell_runs.size(); ++r)
      entity(r + 1, cell_runs[r].id);
    out += "\n$EndEntities\n$Nodes\n";
    const std::uint64_t n = mesh.vertices.size();
    for (const std::uint64_t v : {std::uint64_t(1), n, std::uint64_t(1), n})
      put<std::uint64_t>(out, v, big);
    put<std::int32_t>(out, dim, big);
    put<std::int32_t>(out, 1, big);
    put<std::int32_t>(out, 0, big);
    put<std::uint64_t>(out, n, big);
    for (std::uint64_t i = 0; i < n; ++i)
      put<std::uint64_t>(out, i + 1, big);
    for (std::uint64_t i = 0; i < n; ++i)
      for (unsigned int d = 0; d < 3; ++d)
        put<double>(out, d < dim ? mesh.vertices[i][d] : 0., big);
    out += "\n$EndNodes\n$Elements\n";
    const std::uint64_t n_elements = mesh.cells.size() + f.ids.size();
    for (const std::uint64_t v :
         {std::uint64_t(face_runs.size() + cell_runs.size()),
          n_elements,
          std::uint64_t(1),
          n_elements})
      put<std::uint64_t>(out, v, big);
    const auto block =
      [&](const int                                               entity_dim,
          const int                                               tag,
          const int                                               type,
          const Run                                              &run,
          const std::function<const unsigned int *(std::size_t)> &nodes,
          const std::vector<long long>                           &numbers,
          const unsigned int                                      n_nodes) {
        put<std::int32_t>(out, entity_dim, big);
        put<std::int32_t>(out, tag, big);
        put<std::int32_t>(out, type, big);
        put<std::uint64_t>(out, run.end - run.begin, big);
        for (std::size_t i = run.begin; i < run.end; ++i)
          {
            put<std::uint64_t>(out, numbers[i], big);
            for (unsigned int k = 0; k < n_nodes; ++k)
              put<std::uint64_t>(out, nodes(i)[k] + 1, big);
          }
      };
    for (std::size_t r = 0; r < face_runs.size(); ++r)
      block(
        dim - 1,
        r + 1,
        dim == 2 ? 1 : 2,
        face_runs[r],
        [&](const std::size_t i) { return f.vertices[i].data(); },
        mesh.boundary_numbers,
        dim);
    for (std::size_t r = 0; r < cell_runs.size(); ++r)
      block(
        dim,
        r + 1,
        dim == 2 ? 2 : 4,
        cell_runs[r],
        [&](const std::size_t i) { return mesh.cells[i].vertices.data(); },
        mesh.element_numbers,
        dim + 1);
    out += "\n$EndElements\n";
    return out;
  }

  /// The mesh as an ASCII MEDIT file, with a comment, and sections the
  /// reader skips (Corners; in 3D also Edges).
  template <int dim>
  std::string
  medit(const GmshMesh<dim> &mesh)
  {
    std::ostringstream out;
    out << std::setprecision(17);
    out << "MeshVersionFormatted 2\n\nDimension " << dim << "\n\n"
        << "# written by the mesh_formats test\nVertices\n"
        << mesh.vertices.size() << "\n";
    for (const Point<dim> &x : mesh.vertices)
      {
        for (unsigned int d = 0; d < dim; ++d)
          out << x[d] << ' ';
        out << "0\n";
      }
    out << "\nCorners\n2\n1\n2\n";
    if (dim == 3)
      out << "\nEdges\n1\n1 2 7\n";
    out << "\n"
        << (dim == 2 ? "Triangles" : "Tetrahedra") << "\n"
        << mesh.cells.size() << "\n";
    for (const CellData<dim> &cell : mesh.cells)
      {
        for (const unsigned int v : cell.vertices)
          out << v + 1 << ' ';
        out << cell.material_id << "\n";
      }
    const Faces<dim> f = faces(mesh);
    out << "\n"
        << (dim == 2 ? "Edges" : "Triangles") << "\n"
        << f.ids.size() << "\n";
    for (std::size_t i = 0; i < f.ids.size(); ++i)
      {
        for (const unsigned int v : f.vertices[i])
          out << v + 1 << ' ';
        out << f.ids[i] << "\n";
      }
    out << "\nEnd\n";
    return out.str();
  }

  /// The mesh as a legacy VTK file: @p binary (big-endian) or ASCII;
  /// @p offsets: version 5.1 (OFFSETS and CONNECTIVITY, the ids as a
  /// FIELD array gmsh:physical) or 2.0 (the cell list; the ids as SCALARS
  /// MaterialID after a FIELD array of other data). Each has POINT_DATA
  /// the reader skips. Cells first, then faces.
  template <int dim>
  std::string
  vtk(const GmshMesh<dim> &mesh, const bool binary, const bool offsets)
  {
    const Faces<dim>  f       = faces(mesh);
    const std::size_t n_cells = mesh.cells.size() + f.ids.size();
    std::string       out     = std::string("# vtk DataFile Version ") +
                      (offsets ? "5.1" : "2.0") + "\nmesh_formats test\n" +
                      (binary ? "BINARY" : "ASCII") +
                      "\nDATASET UNSTRUCTURED_GRID\n";
    const auto ints = [&](const std::vector<long long> &values,
                          const bool                    eight) {
      if (binary)
        {
          for (const long long v : values)
            if (eight)
              put<std::int64_t>(out, v, true);
            else
              put<std::int32_t>(out, v, true);
        }
      else
        for (std::size_t i = 0; i < values.size(); ++i)
          out += std::to_string(values[i]) + (i % 9 == 8 ? "\n" : " ");
      out += "\n";
    };
    out += "POINTS " + std::to_string(mesh.vertices.size()) + " double\n";
    for (const Point<dim> &x : mesh.vertices)
      for (unsigned int d = 0; d < 3; ++d)
        if (binary)
          put<double>(out, d < dim ? x[d] : 0., true);
        else
          out += exact(d < dim ? x[d] : 0.) + (d == 2 ? "\n" : " ");
    if (binary)
      out += "\n";
    std::vector<long long> list, offset_list{0}, connectivity, types, ids;
    const auto             add = [&](const auto &vertices, const int type) {
      list.push_back(vertices.size());
      for (const unsigned int v : vertices)
        {
          list.push_back(v);
          connectivity.push_back(v);
        }
      offset_list.push_back(connectivity.size());
      types.push_back(type);
    };
    for (const CellData<dim> &cell : mesh.cells)
      {
        add(cell.vertices, dim == 2 ? 5 : 10);
        ids.push_back(cell.material_id);
      }
    for (std::size_t i = 0; i < f.ids.size(); ++i)
      {
        add(f.vertices[i], dim == 2 ? 3 : 5);
        ids.push_back(f.ids[i]);
      }
    if (offsets)
      {
        out += "CELLS " + std::to_string(offset_list.size()) + " " +
               std::to_string(connectivity.size()) + "\nOFFSETS vtktypeint64\n";
        ints(offset_list, true);
        out += "CONNECTIVITY vtktypeint64\n";
        ints(connectivity, true);
      }
    else
      {
        out += "CELLS " + std::to_string(n_cells) + " " +
               std::to_string(list.size()) + "\n";
        ints(list, false);
      }
    out += "CELL_TYPES " + std::to_string(n_cells) + "\n";
    ints(types, false);
    out += "CELL_DATA " + std::to_string(n_cells) + "\n";
    std::vector<long long> other(n_cells, 3);
    if (offsets)
      {
        out +=
          "FIELD FieldData 2\nother 1 " + std::to_string(n_cells) + " int\n";
        ints(other, false);
        out += "METADATA\nINFORMATION 0\n\n";
        out += "gmsh:physical 1 " + std::to_string(n_cells) + " int\n";
        ints(ids, false);
      }
    else
      {
        out +=
          "FIELD FieldData 1\nother 1 " + std::to_string(n_cells) + " int\n";
        ints(other, false);
        out += "SCALARS MaterialID int 1\nLOOKUP_TABLE default\n";
        ints(ids, false);
      }
    out += "POINT_DATA " + std::to_string(mesh.vertices.size()) +
           "\nVECTORS displacement double\n";
    for (std::size_t i = 0; i < 3 * mesh.vertices.size(); ++i)
      if (binary)
        put<double>(out, 0.25, true);
      else
        out += "0.25\n";
    if (binary)
      out += "\n";
    return out;
  }

  /// Whether @p a and @p b are the same cell list (element numbers too if
  /// @p numbers); the first difference noted.
  template <int dim>
  bool
  same_cells(Checker             &checker,
             const GmshMesh<dim> &a,
             const GmshMesh<dim> &b,
             const bool           numbers)
  {
    std::string difference;
    if (a.vertices != b.vertices)
      difference = "vertices";
    else if (a.cells.size() != b.cells.size())
      difference = "cell count";
    else if (numbers && (a.element_numbers != b.element_numbers ||
                         a.boundary_numbers != b.boundary_numbers))
      difference = "element numbers";
    else
      {
        for (std::size_t i = 0; i < a.cells.size() && difference.empty(); ++i)
          if (a.cells[i].vertices != b.cells[i].vertices ||
              a.cells[i].material_id != b.cells[i].material_id)
            difference = "cell " + std::to_string(i);
        const Faces<dim> fa = faces(a), fb = faces(b);
        if (difference.empty() &&
            (fa.vertices != fb.vertices || fa.ids != fb.ids))
          difference = "boundary faces";
        if (difference.empty() && (a.lower != b.lower || a.upper != b.upper))
          difference = "bounds";
      }
    if (!difference.empty())
      checker.note("first difference: " + difference);
    return difference.empty();
  }

  /// The short scene on @p mesh_file: two materials (tag 1 neo-Hookean,
  /// Region 1 = tag 2 Mooney-Rivlin), clamped at boundary 1, pulled and
  /// sheared at boundary 2, two load steps.
  std::string
  scene(const int          dim,
        const std::string &mesh_file,
        const std::string &directory,
        const std::string &base_name)
  {
    const bool three = dim == 3;
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh",
                      entry("Source", "file") + entry("File", mesh_file)) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1") +
                        entry("Poisson's ratio", "0.3")) +
           subsection(
             "Region 1",
             entry("Material id", "2") +
               subsection("Material",
                          entry("Model", "Mooney-Rivlin") +
                            subsection("Mooney-Rivlin",
                                       entry("C1", "0.6") + entry("C2", "0.2") +
                                         entry("Bulk modulus", "4")))) +
           subsection("Loading", entry("Number of load steps", "2")) +
           subsection("Dirichlet 1",
                      entry("Boundary id", "1") +
                        entry("Components", three ? "x, y, z" : "x, y") +
                        entry("Displacement", three ? "0; 0; 0" : "0; 0")) +
           subsection("Dirichlet 2",
                      entry("Boundary id", "2") +
                        entry("Components", three ? "x, y, z" : "x, y") +
                        entry("Displacement",
                              three ? "0.3*t; 0.1*t; 0" : "0.3*t; 0.1*t")) +
           subsection("Traction 1",
                      entry("Boundary id", "4") +
                        entry("Traction",
                              three ? "0; 0.02*t; 0" : "0; 0.02*t")) +
           subsection("Output",
                      entry("Write VTU", "false") + entry("Verbose", "false") +
                        entry("Directory", directory) +
                        entry("Base name", base_name));
  }

  /// Whether reading @p file throws an InputError whose message contains
  /// every one of @p parts.
  template <int dim>
  bool
  input_error(Checker                        &checker,
              const std::string              &what,
              const std::string              &file,
              const std::vector<std::string> &parts)
  {
    std::string message;
    try
      {
        read_mesh_file<dim>(file);
      }
    catch (const InputError &e)
      {
        message = e.what();
      }
    bool ok = !message.empty();
    for (const std::string &part : parts)
      ok = ok && message.find(part) != std::string::npos;
    const bool passed = checker.is_true(what, ok);
    checker.note("message: " + message);
    return passed;
  }

  template <int dim>
  void
  run(Checker &checker)
  {
    const MPI_Comm     comm     = MPI_COMM_WORLD;
    const unsigned int rank     = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks  = Utilities::MPI::n_mpi_processes(comm);
    const std::string  original = std::string(SOURCE_DIR) +
                                 "/meshes/two_regions_" + std::to_string(dim) +
                                 "d.msh";
    const std::string directory =
      std::filesystem::absolute("mesh_formats_" + std::to_string(dim) + "d_np" +
                                std::to_string(n_ranks))
        .string();
    const std::string d = directory + "/";
    // name, file, whether the element numbers are the gmsh file's
    const std::vector<std::pair<std::string, std::string>> variants = {
      {"gmsh ASCII 2.2 (gmsh API)", d + "ascii22.msh"},
      {"gmsh ASCII 4.1 (gmsh API)", d + "ascii41.msh"},
      {"gmsh binary 2.2 (gmsh API)", d + "binary22.msh"},
      {"gmsh binary 4.1 (gmsh API)", d + "binary41.msh"},
      {"gmsh binary 2.2 big-endian", d + "big22.msh"},
      {"gmsh binary 4.1 big-endian", d + "big41.msh"},
      {"gmsh binary 2.2 little-endian (own writer)", d + "little22.msh"},
      {"gmsh binary 2.2 with TetWild's $ElementData", d + "tetwild22.msh"},
      {"MEDIT", d + "medit.mesh"},
      {"VTK 2.0 ASCII, SCALARS MaterialID", d + "ascii20.vtk"},
      {"VTK 5.1 binary, FIELD gmsh:physical", d + "binary51.vtk"},
      {"VTK 2.0 binary, SCALARS MaterialID", d + "binary20.vtk"},
      {"VTK 5.1 ASCII, FIELD gmsh:physical", d + "ascii51.vtk"}};

    // Rank 0 writes and reads the files; an exception there reaches every
    // rank (no rank left waiting).
    std::string rank_0_failure;
    if (rank == 0)
      try
        {
          std::filesystem::create_directories(directory);
          const GmshMesh<dim> reference = read_gmsh<dim>(original);
          checker.section(
            std::to_string(dim) + "D: " + original + ", " +
            std::to_string(reference.cells.size()) + " cells, " +
            std::to_string(faces(reference).ids.size()) + " tagged faces, " +
            std::to_string(reference.vertices.size()) + " vertices");
          gmsh::initialize(0, nullptr, false);
          gmsh::option::setNumber("General.Terminal", 0);
          gmsh::open(original);
          for (const auto &[version, binary, name] :
               {std::tuple{2.2, 0, "ascii22.msh"},
                std::tuple{4.1, 0, "ascii41.msh"},
                std::tuple{2.2, 1, "binary22.msh"},
                std::tuple{4.1, 1, "binary41.msh"}})
            {
              gmsh::option::setNumber("Mesh.MshFileVersion", version);
              gmsh::option::setNumber("Mesh.Binary", binary);
              gmsh::write(d + name);
            }
          gmsh::finalize();
          write_text(d + "big22.msh", gmsh_binary_22(reference, true));
          write_text(d + "big41.msh", gmsh_binary_41(reference, true));
          write_text(d + "little22.msh", gmsh_binary_22(reference, false));
          write_text(d + "tetwild22.msh",
                     gmsh_binary_22(reference, false) +
                       tetwild_element_data(reference.cells.size()));
          write_text(d + "medit.mesh", medit(reference));
          write_text(d + "ascii20.vtk", vtk(reference, false, false));
          write_text(d + "binary51.vtk", vtk(reference, true, true));
          write_text(d + "binary20.vtk", vtk(reference, true, false));
          write_text(d + "ascii51.vtk", vtk(reference, false, true));

          checker.section("the cell lists read against the original's");
          for (const auto &[name, file] : variants)
            {
              const GmshMesh<dim> read = read_mesh_file<dim>(file);
              const bool gmsh_numbers  = file.substr(file.size() - 4) == ".msh";
              checker.is_true(
                name + ": same cell list" +
                  (gmsh_numbers ? " and element numbers" : ""),
                same_cells(checker, reference, read, gmsh_numbers));
            }
          checker.is_true("big-endian 2.2 differs from little-endian 2.2 "
                          "(the byte order was swapped)",
                          file_text(d + "big22.msh") !=
                            file_text(d + "little22.msh"));

          checker.section("bad input");
          write_text(d + "mesh.stl", "solid x\nendsolid x\n");
          input_error<dim>(
            checker,
            "unknown extension: names Mesh/File and the formats",
            d + "mesh.stl",
            {"'Mesh/File' = '" + d + "mesh.stl'",
             "extension '.stl' is not known",
             ".msh (gmsh), .mesh (MEDIT) and .vtk (legacy VTK)"});
          for (const std::string name : {"binary22", "binary41", "big41"})
            {
              const std::string text = file_text(d + name + ".msh");
              write_text(d + "truncated_" + name + ".msh",
                         text.substr(0, text.size() * 3 / 4));
              input_error<dim>(checker,
                               "truncated " + name + ".msh",
                               d + "truncated_" + name + ".msh",
                               {"cannot read mesh file '" + d + "truncated_" +
                                  name + ".msh'",
                                "ends early"});
            }
          {
            const std::string text = file_text(d + "binary51.vtk");
            write_text(d + "truncated.vtk", text.substr(0, text.size() / 2));
            input_error<dim>(checker,
                             "truncated binary51.vtk",
                             d + "truncated.vtk",
                             {"cannot read mesh file '" + d + "truncated.vtk'",
                              "ends early"});
          }
          {
            // The first cell's first vertex number beyond the vertices.
            std::string text = file_text(d + "medit.mesh");
            const auto  at =
              text.find(dim == 2 ? "\nTriangles\n" : "\nTetrahedra\n");
            const auto line = text.find('\n', text.find('\n', at + 1) + 1) + 1;
            const auto end  = text.find(' ', line);
            text.replace(line, end - line, "100000");
            write_text(d + "bad_vertex.mesh", text);
            input_error<dim>(checker,
                             "MEDIT cell naming a vertex not listed",
                             d + "bad_vertex.mesh",
                             {"cannot read mesh file '" + d +
                                "bad_vertex.mesh'",
                              "refers to vertex 100000",
                              "(line "});
          }
          {
            // A cell listed twice: the checks name the cells by the file's
            // own numbering.
            GmshMesh<dim> twice = reference;
            twice.cells.push_back(twice.cells[0]);
            write_text(d + "twice.vtk", vtk(twice, false, false));
            write_text(d + "twice.mesh", medit(twice));
            // The cell and its twin (last of the cells) among those named.
            const std::string n  = std::to_string(reference.cells.size());
            const std::string n1 = std::to_string(reference.cells.size() + 1);
            for (const auto &[file, first, last] :
                 {std::tuple{d + "twice.vtk",
                             "VTK cells 0, ",
                             ", " + n + " (the file's cell ids, from 0)"},
                  std::tuple{d + "twice.mesh",
                             "MEDIT elements 1, ",
                             ", " + n1 + " (the positions in the file's"}})
              {
                std::string message;
                try
                  {
                    MeshStatistics statistics;
                    read_and_check_gmsh<dim>(file, statistics);
                  }
                catch (const InputError &e)
                  {
                    message = e.what();
                  }
                checker.is_true(
                  "a cell listed twice in " +
                    std::filesystem::path(file).filename().string() +
                    ": the message names '" + first + "... " + last + "'",
                  message.find(first) != std::string::npos &&
                    message.find(last) != std::string::npos);
                checker.note("message: " + message);
              }
          }
        }
      catch (const std::exception &e)
        {
          rank_0_failure = exception_message(e);
        }
    throw_input_error_of_first_rank(rank_0_failure, comm);

    // The scene on every file: the CSV of each equal to the original's.
    checker.section("the scene's CSV on " + std::to_string(n_ranks) +
                    " rank(s) against the original mesh's");
    run_scene<dim>(scene(dim, original, directory, "original"));
    for (std::size_t v = 0; v < variants.size(); ++v)
      {
        run_scene<dim>(
          scene(dim, variants[v].second, directory, "v" + std::to_string(v)));
        if (rank == 0)
          {
            const std::string a = file_text(d + "original.csv");
            const std::string b =
              file_text(d + "v" + std::to_string(v) + ".csv");
            checker.is_true(variants[v].first + ": same CSV (" +
                              std::to_string(a.size()) + " bytes)",
                            !a.empty() && a == b);
          }
      }
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  Checker   checker(Utilities::MPI::this_mpi_process(comm) == 0);
  const int dim    = argc > 1 ? std::atoi(argv[1]) : 3;
  const int status = run_and_report(
    [&]() {
      if (dim == 2)
        run<2>(checker);
      else
        run<3>(checker);
    },
    comm);
  // The checks run on rank 0: the counts summed over the ranks.
  return checker.exit_code(status, comm);
}
