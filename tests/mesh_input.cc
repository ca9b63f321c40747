// Mesh input (source/mesh/: gmsh_reader, mesh_checks, mesh_distribution,
// mesh.cc): one rank reads, checks and partitions
// the mesh; the others receive their part.
//
// 1. Vertex order: the gmsh bar (meshes/bar_DIMd.msh) and the same mesh with
//    two vertices swapped in every other cell
//    (tests/scenes/mixed_order_bar_DIMd.msh, half the cells negatively
//    oriented) give the same energies, reactions, deformed bounding boxes and
//    point displacements to 1e-12 (a clamped bar pulled, sheared or twisted,
//    under a body force and a traction; P1 and P2, direct solver).
// 2. Errors found by the reader reach every rank as the same InputError: a
//    folded mesh (a node pushed through a face), a cell of zero area or
//    volume (both naming the gmsh element), a missing file.
// 3. Distribution: a rank other than the reader builds no serial mesh, and
//    (without refinement) constructs exactly its own cells plus ghosts; with
//    a global refinement, fewer cells than the whole mesh. The faces where
//    a rank's ghost layer ends carry partition_edge_boundary_id (deal.II
//    would give them id 0, and a Dirichlet condition on id 0 would
//    constrain the ghost dofs there); every other boundary face lies on the
//    mesh's surface.
// 4. The distributed triangulation equals deal.II's own reading (GridIn) of
//    the file cell by cell: vertices in the same order, material and
//    boundary ids (gmsh formats 2 and 4, mixed vertex order).
//
// Usage: mpirun -np N mesh_input DIM
//        mpirun -np N mesh_input bench MESH_FILE DIM
//   'bench' builds the mesh of MESH_FILE only and prints per rank the
//   statistics of create_mesh() and the peak resident memory (benchmarks).
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_in.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/cell_ordering.h>
#include <hyperelastic/mesh/gmsh_reader.h>
#include <hyperelastic/mesh/mesh.h>
#include <hyperelastic/mesh/mesh_distribution.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/scene_text.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  const std::string source_dir = SOURCE_DIR;

  std::string
  scene_mesh(const std::string &name)
  {
    return source_dir + "/tests/scenes/" + name;
  }

  MeshParameters
  file_mesh(const std::string &file, const unsigned int refinements = 0)
  {
    MeshParameters mesh;
    mesh.source             = MeshSource::file;
    mesh.file               = file;
    mesh.global_refinements = refinements;
    return mesh;
  }

  /// A kB entry of /proc/self/status ("VmHWM": peak resident memory).
  double
  status_kb(const std::string &key)
  {
    std::ifstream in("/proc/self/status");
    for (std::string line; std::getline(in, line);)
      if (line.rfind(key + ":", 0) == 0)
        return std::stod(line.substr(key.size() + 1));
    return 0.;
  }

  // ---------------------------------------------------------------------
  // 1. Vertex order.

  /// The bar clamped at x = 0 and pulled and sheared (2D) or twisted (3D)
  /// at x = 3, under a body force and a traction on y = 1; or, if
  /// @p homogeneous, stretched to 1.2 times its length on symmetry rollers
  /// (a homogeneous state that P1 and P2 reproduce exactly, whatever the
  /// quadrature).
  std::string
  scene(const int          dim,
        const unsigned int degree,
        const bool         homogeneous,
        const std::string &mesh_file,
        const std::string &name)
  {
    const bool  three = dim == 3;
    std::string text =
      subsection("Problem",
                 entry("Dimension", std::to_string(dim)) +
                   entry("Finite element degree", std::to_string(degree))) +
      subsection("Mesh", entry("Source", "file") + entry("File", mesh_file)) +
      subsection("Material",
                 entry("Model", "neo-Hookean") + entry("Young's modulus", "1") +
                   entry("Poisson's ratio", "0.3"));
    // gmsh physical tags: 1 x = 0, 2 x = 3, 3 y = 0, 4 y = 1 (5, 6: z).
    if (homogeneous)
      {
        text += subsection("Loading", entry("Number of load steps", "2"));
        text += dirichlet(1, 1, "x", "0") + dirichlet(2, 3, "y", "0") +
                dirichlet(3, 2, "x", "0.6*t");
        if (three)
          text += dirichlet(4, 5, "z", "0");
      }
    else
      {
        text += subsection("Loading",
                           entry("Number of load steps", "2") +
                             entry("Body force",
                                   three ? "0; 0; -0.05*t" : "0; -0.05*t"));
        text += dirichlet(1,
                          1,
                          three ? "x, y, z" : "x, y",
                          three ? "0; 0; 0" : "0; 0");
        text += dirichlet(2,
                          2,
                          three ? "x, y, z" : "x, y",
                          three ? "0.3*t; (cos(0.5*t) - 1)*(y - 0.5) - "
                                  "sin(0.5*t)*(z - 0.5); sin(0.5*t)*(y - 0.5) "
                                  "+ (cos(0.5*t) - 1)*(z - 0.5)"
                                : "0.3*t; 0.1*t");
        text +=
          subsection("Traction 1",
                     entry("Boundary id", "4") +
                       entry("Traction", three ? "0.02*t; 0; 0" : "0.02*t; 0"));
      }
    text += tight_solver("direct");
    text +=
      subsection("Output",
                 entry("Directory", "mesh_input_output") +
                   entry("Base name", name) + entry("Write VTU", "false") +
                   entry("Verbose", "false") +
                   entry("Points",
                         three ? "1.3, 0.4, 0.6; 2.1, 0.77, 0.3; 3, 1, 1"
                               : "1.3, 0.4; 2.1, 0.77; 3, 1"));
    return text;
  }

  struct Numbers
  {
    std::vector<std::string> names;
    std::vector<double>      values;
    void
    add(const std::string &name, const double value)
    {
      names.push_back(name);
      values.push_back(value);
    }
  };

  template <int dim>
  Numbers
  solve(const std::string &mesh_file,
        const unsigned int degree,
        const bool         homogeneous)
  {
    const std::string name = "P" + std::to_string(degree) +
                             (homogeneous ? "_stretch_" : "_twist_") +
                             mesh_file.substr(mesh_file.rfind('/') + 1);
    Parameters parameters;
    parameters.read_from_string(
      scene(dim, degree, homogeneous, mesh_file, name), ".", name);
    Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
    problem.run();
    Numbers numbers;
    for (const auto &s : problem.summaries())
      {
        const std::string step = "step " + std::to_string(s.step) + " ";
        numbers.add(step + "energy", s.energy);
        for (const auto &[id, force] : s.reactions)
          for (unsigned int d = 0; d < dim; ++d)
            numbers.add(step + "reaction " + std::to_string(id) + " " +
                          std::string(1, "xyz"[d]),
                        force[d]);
        for (unsigned int d = 0; d < dim; ++d)
          {
            numbers.add(step + "deformed min " + std::string(1, "xyz"[d]),
                        s.deformed_min[d]);
            numbers.add(step + "deformed max " + std::string(1, "xyz"[d]),
                        s.deformed_max[d]);
          }
        for (unsigned int p = 0; p < s.point_displacements.size(); ++p)
          for (unsigned int d = 0; d < dim; ++d)
            numbers.add(step + "point " + std::to_string(p + 1) + " u" +
                          std::string(1, "xyz"[d]),
                        s.point_displacements[p][d]);
      }
    return numbers;
  }

  template <int dim>
  void
  check_vertex_order(Checker &checker, const bool print)
  {
    const std::string d = std::to_string(dim) + "D";
    const std::string ordered =
      source_dir + "/meshes/bar_" + std::to_string(dim) + "d.msh";
    const std::string mixed =
      scene_mesh("mixed_order_bar_" + std::to_string(dim) + "d.msh");
    const unsigned int n_cells = dim == 2 ? 126 : 768;

    // The mixed file really is mixed, and is reoriented cell by cell.
    MeshStatistics ordered_stats, mixed_stats;
    {
      parallel::fullydistributed::Triangulation<dim> tria(MPI_COMM_WORLD);
      create_mesh(file_mesh(ordered), tria, &ordered_stats);
    }
    {
      parallel::fullydistributed::Triangulation<dim> tria(MPI_COMM_WORLD);
      create_mesh(file_mesh(mixed), tria, &mixed_stats);
    }
    if (print)
      std::cout << "  " << d
                << ": cells reoriented: " << ordered_stats.reoriented_cells
                << " of " << ordered_stats.global_cells << " (bar_" << dim
                << "d.msh), " << mixed_stats.reoriented_cells << " of "
                << mixed_stats.global_cells << " (mixed order)" << std::endl;
    checker.is_true(d + " mesh sizes " + std::to_string(n_cells),
                    ordered_stats.global_cells == n_cells &&
                      mixed_stats.global_cells == n_cells);
    checker.is_true(d + " ordered mesh: all or no cells reoriented",
                    ordered_stats.reoriented_cells == 0 ||
                      ordered_stats.reoriented_cells == n_cells);
    checker.is_true(d + " mixed mesh: half the cells reoriented",
                    mixed_stats.reoriented_cells == n_cells / 2);

    // P1: the same discrete problem, so round-off only. P2 (and every
    // degree): the homogeneous stretch, which any quadrature reproduces.
    // P2 on the general scene differs by the quadrature's lack of symmetry
    // (QGaussSimplex(2) of deal.II 9.4, the stress quadrature of P2, is not
    // invariant under a permutation of the vertices, so reoriented cells put
    // their quadrature points elsewhere): bounded loosely, it is not a mesh
    // matter.
    for (const auto &[degree, homogeneous, bound] :
         {std::make_tuple(1u, false, 1e-12),
          std::make_tuple(1u, true, 1e-12),
          std::make_tuple(2u, true, 1e-12),
          std::make_tuple(2u, false, 1e-4)})
      {
        const std::string what = d + " P" + std::to_string(degree) +
                                 (homogeneous ? " stretch" : " twist");
        const Numbers a = solve<dim>(ordered, degree, homogeneous);
        const Numbers b = solve<dim>(mixed, degree, homogeneous);
        checker.is_true(what + ": same number of values",
                        a.values.size() == b.values.size() &&
                          a.values.size() > 0);
        double scale = 0.;
        for (const double v : a.values)
          scale = std::max(scale, std::abs(v));
        double       worst = 0.;
        unsigned int where = 0;
        for (unsigned int i = 0; i < std::min(a.values.size(), b.values.size());
             ++i)
          {
            const double error = std::abs(a.values[i] - b.values[i]) /
                                 std::max(std::abs(a.values[i]), 1e-3 * scale);
            if (error > worst)
              where = i;
            worst = std::max(worst, error);
          }
        if (print && !a.values.empty())
          std::cout << "    " << what << ", largest difference at "
                    << a.names[where] << ": " << std::setprecision(16)
                    << a.values[where] << " (ordered) vs " << b.values[where]
                    << " (mixed)" << std::setprecision(6) << std::endl;
        checker.at_most(what + ": " + std::to_string(a.values.size()) +
                          " values, mixed vs ordered, max rel. diff",
                        worst,
                        bound);
      }
  }

  // ---------------------------------------------------------------------
  // 2. Errors of the reader on every rank.

  template <int dim>
  void
  check_error(Checker                        &checker,
              const std::string              &what,
              const std::string              &file,
              const std::vector<std::string> &expected)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    std::string    message;
    bool           thrown = false;
    try
      {
        parallel::fullydistributed::Triangulation<dim> tria(comm);
        create_mesh(file_mesh(file), tria);
      }
    catch (const InputError &e)
      {
        message = e.what();
        thrown  = true;
      }
    bool ok = thrown;
    for (const auto &s : expected)
      ok = ok && message.find(s) != std::string::npos;
    const std::vector<std::string> all = Utilities::MPI::gather(comm, message);
    const bool every_rank = Utilities::MPI::min(ok ? 1 : 0, comm) == 1;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        bool same = true;
        for (const std::string &m : all)
          same = same && m == message;
        std::cout << "  " << what << ": " << message << std::endl;
        checker.is_true(what + ": InputError on every rank, as expected",
                        every_rank);
        checker.is_true(what + ": the same message on all " +
                          std::to_string(all.size()) + " ranks",
                        same);
      }
  }

  template <int dim>
  void
  check_errors(Checker &checker)
  {
    if (dim == 2)
      {
        check_error<2>(checker,
                       "2D folded mesh",
                       scene_mesh("bad_folded_mesh_2d.msh"),
                       {"1 of 126 triangles is inverted",
                        "gmsh element 52 ",
                        "folded"});
        check_error<2>(checker,
                       "2D zero-area cell",
                       scene_mesh("bad_flat_cell_mesh_2d.msh"),
                       {"1 of 126 triangles is degenerate (zero area",
                        "gmsh element 52 "});
      }
    else
      {
        check_error<3>(checker,
                       "3D folded mesh (mixed vertex order)",
                       scene_mesh("bad_folded_mesh_3d.msh"),
                       {"1 of 768 tetrahedra is inverted (it lies on the same "
                        "side of a face as the neighbour across it)",
                        "gmsh element 458 ",
                        "folded"});
        check_error<3>(checker,
                       "3D zero-volume cell",
                       scene_mesh("bad_flat_cell_mesh_3d.msh"),
                       {"1 of 768 tetrahedra is degenerate (zero volume",
                        "gmsh element 868 "});
        check_error<3>(checker,
                       "3D folded mesh, 12 cells",
                       scene_mesh("bad_inverted_mesh_3d.msh"),
                       {"12 of 48 tetrahedra are inverted",
                        "gmsh elements 20, 21, 22, 23, 24, 25, 26, 27, 28, 29 "
                        "and 2 more "});
      }
    check_error<dim>(checker,
                     std::to_string(dim) + "D missing file",
                     scene_mesh("no_such_mesh.msh"),
                     {"cannot open mesh file"});
  }

  // ---------------------------------------------------------------------
  // 3. Distribution.

  template <int dim>
  void
  check_distribution(Checker &checker, const bool print)
  {
    const MPI_Comm     comm    = MPI_COMM_WORLD;
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const std::string  d       = std::to_string(dim) + "D";
    for (const unsigned int refinements : {0u, 1u})
      {
        parallel::fullydistributed::Triangulation<dim> tria(comm);
        MeshStatistics                                 stats;
        const auto                                     ids =
          create_mesh(file_mesh(scene_mesh("mixed_order_bar_" +
                                           std::to_string(dim) + "d.msh"),
                                refinements),
                      tria,
                      &stats);
        unsigned int owned = 0, ghost = 0;
        for (const auto &cell : tria.active_cell_iterators())
          {
            owned += cell->is_locally_owned() ? 1 : 0;
            ghost += cell->is_ghost() ? 1 : 0;
          }
        const unsigned int global = (dim == 2 ? 126 : 768)
                                    << (dim * refinements);
        const std::vector<unsigned int> row = {
          static_cast<unsigned int>(stats.serial_cells),
          owned,
          ghost,
          tria.n_active_cells(),
          static_cast<unsigned int>(stats.description_coarse_cells)};
        const auto rows = Utilities::MPI::gather(comm, row);
        if (print)
          for (unsigned int r = 0; r < rows.size(); ++r)
            std::cout << "  " << d << ", " << refinements
                      << " refinement(s), rank " << r << ": whole mesh "
                      << rows[r][0] << " cells, owned " << rows[r][1]
                      << ", ghost " << rows[r][2] << ", active " << rows[r][3]
                      << ", coarse cells received " << rows[r][4] << " (of "
                      << global << " active in all)" << std::endl;
        bool ok = ids.size() == 2u * dim && stats.global_cells == global &&
                  Utilities::MPI::sum(owned, comm) == global;
        if (rank == 0)
          ok = ok && stats.reader && stats.serial_cells == global;
        else
          ok = ok && !stats.reader && stats.serial_cells == 0 &&
               tria.n_active_cells() < global &&
               (refinements > 0 || tria.n_active_cells() == owned + ghost);
        // Boundary faces of the local part: on the bar's surface (its
        // bounding box), or where the ghost layer ends, marked as such (not
        // boundary id 0, which a Dirichlet condition could name).
        Point<dim> lower, upper;
        for (unsigned int c = 0; c < dim; ++c)
          {
            lower[c] = std::numeric_limits<double>::max();
            upper[c] = -std::numeric_limits<double>::max();
          }
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int c = 0; c < dim; ++c)
              {
                lower[c] = std::min(lower[c], cell->vertex(v)[c]);
                upper[c] = std::max(upper[c], cell->vertex(v)[c]);
              }
        for (unsigned int c = 0; c < dim; ++c)
          {
            lower[c] = Utilities::MPI::min(lower[c], comm);
            upper[c] = Utilities::MPI::max(upper[c], comm);
          }
        unsigned int edges = 0, misplaced = 0;
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (!cell->is_artificial() && cell->face(f)->at_boundary())
              {
                const Point<dim> x       = cell->face(f)->center();
                bool             surface = false;
                for (unsigned int c = 0; c < dim; ++c)
                  surface = surface || std::abs(x[c] - lower[c]) < 1e-9 ||
                            std::abs(x[c] - upper[c]) < 1e-9;
                if (cell->face(f)->boundary_id() == partition_edge_boundary_id)
                  {
                    ++edges;
                    misplaced += surface ? 1 : 0;
                  }
                else
                  misplaced += surface ? 0 : 1;
              }
        edges     = Utilities::MPI::sum(edges, comm);
        misplaced = Utilities::MPI::sum(misplaced, comm);
        checker.is_true(
          d + ", " + std::to_string(refinements) +
            " refinement(s): boundary faces of every part on the bar's "
            "surface or marked as the ghost layer's end (" +
            std::to_string(edges) + " marked, " + std::to_string(misplaced) +
            " misplaced)",
          misplaced == 0 && (n_ranks == 1 || edges > 0));
        const bool all = Utilities::MPI::min(ok ? 1 : 0, comm) == 1;
        checker.is_true(d + ", " + std::to_string(refinements) +
                          " refinement(s): only rank 0 built the whole mesh" +
                          (n_ranks > 1 && refinements == 0
                             ? "; others: own + ghost cells only"
                             : ""),
                        all);
      }
  }

  /// The distributed triangulation of a gmsh file against the serial one
  /// of deal.II's own reader (GridIn, which reorients negatively oriented
  /// cells the same way): the same cells (found by their centres: the
  /// reader sorts the cells along a space-filling curve) with the same
  /// vertices in the same order, material ids and boundary ids, and every
  /// cell owned by one rank.
  template <int dim>
  void
  check_against_grid_in(Checker &checker, const std::string &file)
  {
    const MPI_Comm                                 comm = MPI_COMM_WORLD;
    parallel::fullydistributed::Triangulation<dim> tria(comm);
    create_mesh(file_mesh(file), tria);
    Triangulation<dim> serial;
    {
      GridIn<dim> grid_in;
      grid_in.attach_triangulation(serial);
      std::ifstream in(file);
      grid_in.read_msh(in);
    }
    // The serial cells by centre (the same vertices in the same order give
    // the same centre to the last bit).
    const auto less = [](const Point<dim> &a, const Point<dim> &b) {
      for (unsigned int d = 0; d < dim; ++d)
        if (a[d] != b[d])
          return a[d] < b[d];
      return false;
    };
    std::map<Point<dim>,
             typename Triangulation<dim>::active_cell_iterator,
             decltype(less)>
      by_centre(less);
    for (const auto &cell : serial.active_cell_iterators())
      by_centre.emplace(cell->center(), cell);
    unsigned int n_owned = 0, n_compared = 0, n_differ = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        n_owned += cell->is_locally_owned() ? 1 : 0;
        ++n_compared;
        const auto found = by_centre.find(cell->center());
        bool       equal = found != by_centre.end() &&
                     found->second->material_id() == cell->material_id();
        const auto same = equal ? found->second : serial.begin_active();
        for (unsigned int v = 0; equal && v <= dim; ++v)
          equal = same->vertex(v) == cell->vertex(v);
        // (The outer faces of the ghost layer are boundary faces of the
        // distributed triangulation, with id 0.)
        for (unsigned int f = 0; equal && f <= dim; ++f)
          if (same->at_boundary(f))
            equal = cell->at_boundary(f) && same->face(f)->boundary_id() ==
                                              cell->face(f)->boundary_id();
          else
            equal = !cell->at_boundary(f) || !cell->is_locally_owned();
        n_differ += equal ? 0 : 1;
      }
    const unsigned int all_owned = Utilities::MPI::sum(n_owned, comm);
    const unsigned int differ    = Utilities::MPI::sum(n_differ, comm);
    const unsigned int compared  = Utilities::MPI::sum(n_compared, comm);
    checker.is_true(std::to_string(dim) + "D " +
                      file.substr(file.rfind('/') + 1) + ": " +
                      std::to_string(compared) +
                      " owned and ghost cells as GridIn reads them, " +
                      std::to_string(all_owned) + " owned of " +
                      std::to_string(serial.n_active_cells()),
                    differ == 0 && all_owned == serial.n_active_cells());
  }

  /// The reader's cell order (order_cells_along_curve): on a gmsh mesh, the
  /// mean spread of the vertex indices of a cell (largest minus smallest,
  /// the band a cell's unknowns occupy) at most half the file's (0.31 and
  /// 0.33 on the Cook meshes, 1 without the ordering); the
  /// same cells (vertex coordinates in the same order) and element numbers.
  template <int dim>
  void
  check_cell_order(Checker &checker, const std::string &file)
  {
    GmshMesh<dim> mesh            = read_gmsh<dim>(file);
    const auto    cells_as_listed = [&]() {
      std::multimap<long long, std::vector<Point<dim>>> cells;
      for (std::size_t c = 0; c < mesh.cells.size(); ++c)
        {
          std::vector<Point<dim>> x;
          for (const unsigned int v : mesh.cells[c].vertices)
            x.push_back(mesh.vertices[v]);
          cells.emplace(mesh.element_numbers[c], x);
        }
      return cells;
    };
    const auto mean_spread = [&]() {
      double sum = 0.;
      for (const auto &cell : mesh.cells)
        sum += *std::max_element(cell.vertices.begin(), cell.vertices.end()) -
               *std::min_element(cell.vertices.begin(), cell.vertices.end());
      return sum / mesh.cells.size();
    };
    const auto   before        = cells_as_listed();
    const double spread_before = mean_spread();
    order_cells_along_curve(mesh);
    const double       spread_after = mean_spread();
    std::ostringstream text;
    text << dim << "D " << file.substr(file.rfind('/') + 1)
         << ": cells along a Morton curve, mean vertex-index spread per cell "
         << spread_before << " -> " << spread_after
         << " (at most half), the same cells";
    checker.is_true(text.str(),
                    spread_after <= 0.5 * spread_before &&
                      cells_as_listed() == before);
  }

  template <int dim>
  void
  run_all(Checker &checker, const bool print)
  {
    check_errors<dim>(checker);
    check_distribution<dim>(checker, print);
    for (const std::string &file :
         {source_dir + "/meshes/bar_" + std::to_string(dim) + "d.msh",
          scene_mesh("mixed_order_bar_" + std::to_string(dim) + "d.msh"),
          scene_mesh("vertex_order_" + std::to_string(dim) + "d.msh"),
          dim == 2 ? source_dir + "/meshes/block_with_hole_2d.msh"
                   : source_dir + "/meshes/cook_3d_4.msh",
          scene_mesh("formats/bar_" + std::to_string(dim) + "d_format22.msh"),
          scene_mesh("formats/bar_" + std::to_string(dim) + "d_format40.msh"),
          dim == 2 ? scene_mesh("formats/bar_2d_format1.msh")
                   : source_dir + "/meshes/cook_3d_2.msh"})
      check_against_grid_in<dim>(checker, file);
    check_cell_order<dim>(checker,
                          dim == 2 ? source_dir + "/meshes/cook_2d_32.msh"
                                   : source_dir + "/meshes/cook_3d_8.msh");
    check_vertex_order<dim>(checker, print);
  }

  template <int dim>
  int
  bench(const std::string &file)
  {
    const MPI_Comm comm       = MPI_COMM_WORLD;
    const double   rss_before = status_kb("VmHWM");
    MeshStatistics stats;
    Timer          timer;
    parallel::fullydistributed::Triangulation<dim> tria(comm);
    create_mesh(file_mesh(file), tria, &stats);
    const double total = timer.wall_time();
    unsigned int owned = 0, ghost = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        owned += cell->is_locally_owned() ? 1 : 0;
        ghost += cell->is_ghost() ? 1 : 0;
      }
    const std::vector<double> row  = {total,
                                      stats.read_time,
                                      stats.check_time,
                                      stats.build_time,
                                      stats.partition_time,
                                      stats.wait_time,
                                      stats.describe_time,
                                      stats.distribute_time,
                                      double(stats.serial_cells),
                                      double(owned),
                                      double(ghost),
                                      double(tria.n_active_cells()),
                                      rss_before,
                                      status_kb("VmHWM")};
    const auto                rows = Utilities::MPI::gather(comm, row);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::cout << "create_mesh on " << rows.size() << " rank(s), "
                  << stats.global_cells << " cells, " << stats.reoriented_cells
                  << " reoriented\n"
                  << "rank  total[s]  read  check  build  refine+partition  "
                     "wait  describe  distribute  serial_cells  owned  ghost  "
                     "active  "
                     "VmHWM_before[MB]  VmHWM_after[MB]\n";
        for (unsigned int r = 0; r < rows.size(); ++r)
          {
            std::cout << r << std::fixed << std::setprecision(2);
            for (unsigned int k = 0; k < 8; ++k)
              std::cout << "  " << rows[r][k];
            std::cout << std::setprecision(0);
            for (unsigned int k = 8; k < 12; ++k)
              std::cout << "  " << rows[r][k];
            std::cout << "  " << rows[r][12] / 1024. << "  "
                      << rows[r][13] / 1024. << std::endl;
          }
      }
    return 0;
  }
} // namespace

int
main(int argc, char *argv[])
{
  if (argc == 4 && std::string(argv[1]) == "bench")
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      return run_and_report(
        [&]() {
          if (std::atoi(argv[3]) == 2)
            bench<2>(argv[2]);
          else
            bench<3>(argv[2]);
        },
        MPI_COMM_WORLD);
    }
  return run_checks_for_dimension(
    argc,
    argv,
    [](Checker &checker, const bool print) { run_all<2>(checker, print); },
    [](Checker &checker, const bool print) { run_all<3>(checker, print); });
}
