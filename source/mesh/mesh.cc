// Serial mesh generation or reading, validation of its cells, METIS
// partitioning and distribution.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  void
  set_box_boundary_ids(Triangulation<dim> &tria)
  {
    const BoundingBox<dim> box = GridTools::compute_bounding_box(tria);
    const double           tol = 1e-10 * box.side_length(0);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<dim> c = face->center();
            for (unsigned int d = 0; d < dim; ++d)
              {
                if (std::abs(c[d] - box.lower_bound(d)) < tol)
                  face->set_boundary_id(2 * d);
                else if (std::abs(c[d] - box.upper_bound(d)) < tol)
                  face->set_boundary_id(2 * d + 1);
              }
          }
  }

  namespace
  {
    // ------------------------------------------------------------------
    // Validation of the input cells.
    //
    // What deal.II 9.4 itself does with bad simplex input (tried with
    // GridIn::read_msh and Triangulation::create_triangulation on small
    // hand-made meshes):
    // - GridIn::read_msh silently reorders the vertices of every cell with
    //   negative measure (its fix-up step calls
    //   GridTools::invert_cells_with_negative_measure, which for simplices
    //   swaps two vertices), whether all cells or only some are inverted: no
    //   error, no warning. The cells keep the order of the file.
    // - Triangulation::create_triangulation, given simplices directly,
    //   accepts inverted cells (measure() < 0) and zero-volume cells.
    // - Neither rejects zero-area triangles or zero-volume tetrahedra.
    // - For a 2D mesh GridIn keeps x and y of each node and drops z: a mesh
    //   drawn in the xz-plane becomes a mesh of zero-area triangles, a mesh in
    //   a tilted plane a silently distorted projection.
    // So the checks below read the cells as the file lists them, and check
    // the triangulation deal.II made as well.
    //
    // Policy. A cell whose orientation differs from the rest of the mesh is
    // "inverted" and rejected with its number: either the mesh is folded
    // there or the file lists that cell wrongly (hand edits, a broken
    // exporter), and silently reordering it, as deal.II does, would hide a
    // folded mesh. A mesh whose cells are all negatively
    // oriented is consistently mirrored, not broken (gmsh writes all
    // triangles clockwise for a surface whose curve loop runs clockwise); the
    // reordering by deal.II then changes no geometry and no result, so such a
    // file is accepted. Cells of zero area or volume are always rejected.

    /// A simplex as listed in the input: a number the user can find there
    /// and its vertices in the listed order.
    template <int dim>
    struct ListedSimplex
    {
      long long                       number;
      std::array<Point<dim>, dim + 1> vertices;
    };

    /// How the numbers of ListedSimplex are to be read in messages.
    struct Numbering
    {
      std::string singular; ///< "gmsh element"
      std::string plural;   ///< "gmsh elements"
      std::string note;     ///< where to find them, in parentheses
    };

    /// "3, 7, 12" (at most 10, then "and N more").
    std::string
    list_numbers(const std::vector<long long> &numbers)
    {
      const std::size_t shown = std::min<std::size_t>(numbers.size(), 10);
      std::string       text;
      for (std::size_t i = 0; i < shown; ++i)
        text += (i > 0 ? ", " : "") + std::to_string(numbers[i]);
      if (numbers.size() > shown)
        text += " and " + std::to_string(numbers.size() - shown) + " more";
      return text;
    }

    /// "1 of 6 triangles is" / "2 of 6 triangles are".
    template <int dim>
    std::string
    count_of(const std::size_t count, const std::size_t total)
    {
      const bool one = count == 1;
      return std::to_string(count) + " of " + std::to_string(total) + " " +
             (dim == 2 ? (total == 1 ? "triangle" : "triangles")
                       : (total == 1 ? "tetrahedron" : "tetrahedra")) +
             (one ? " is" : " are");
    }

    /// Throws InputError naming the cells of @p cells that have zero volume
    /// or an orientation opposite to the other cells (or negative
    /// orientation everywhere, unless @p accept_mirrored). @p where starts
    /// the message ("mesh file 'a.msh'").
    ///
    /// Zero volume: with det the determinant of the edge vectors v_k - v_0
    /// (twice the area, six times the volume, signed by orientation), L the
    /// longest edge and X the largest vertex coordinate in magnitude, a cell
    /// is degenerate if
    ///   |det| <= 1e-12 L^dim + 64 eps X L^(dim-1).
    /// The first term is scale-free: it flags cells whose height over their
    /// longest edge (2D) or volume over that of a cube of it (3D) is below
    /// 1e-12, at any cell size, so tiny cells of a graded mesh pass (a
    /// threshold relative to the whole mesh, 1e-12 h^dim, would reject a
    /// tetrahedron 1e-4 times smaller than a mesh of size h). The second
    /// bounds the rounding error of det for coordinates stored to relative
    /// precision eps: vertices that are collinear (coplanar) in the file's
    /// decimals are caught even far from the origin.
    template <int dim>
    void
    check_simplices(const std::vector<ListedSimplex<dim>> &cells,
                    const std::string                     &where,
                    const Numbering                       &numbering,
                    const bool                             accept_mirrored)
    {
      std::vector<long long> degenerate, positive, negative;
      for (const ListedSimplex<dim> &cell : cells)
        {
          Tensor<2, dim> edges;
          double         longest = 0., largest_coordinate = 0.;
          for (unsigned int a = 0; a <= dim; ++a)
            {
              if (a > 0)
                for (unsigned int d = 0; d < dim; ++d)
                  edges[d][a - 1] = cell.vertices[a][d] - cell.vertices[0][d];
              for (unsigned int d = 0; d < dim; ++d)
                largest_coordinate =
                  std::max(largest_coordinate, std::abs(cell.vertices[a][d]));
              for (unsigned int b = a + 1; b <= dim; ++b)
                longest = std::max(longest,
                                   cell.vertices[a].distance(cell.vertices[b]));
            }
          const double det = determinant(edges);
          const double tolerance =
            std::pow(longest, dim - 1) *
            (1e-12 * longest +
             64. * std::numeric_limits<double>::epsilon() * largest_coordinate);
          if (!(std::abs(det) > tolerance)) // also catches NaN coordinates
            degenerate.push_back(cell.number);
          else
            (det > 0. ? positive : negative).push_back(cell.number);
        }

      const std::string where_prefix = where + ": ";
      const auto        numbers      = [&](const std::vector<long long> &n) {
        return (n.size() == 1 ? numbering.singular : numbering.plural) + " " +
               list_numbers(n) + " " + numbering.note;
      };
      std::vector<std::string> problems;
      if (!degenerate.empty())
        problems.push_back(
          count_of<dim>(degenerate.size(), cells.size()) + " degenerate (" +
          (dim == 2 ? "zero area, collinear vertices): "
                    : "zero volume, coplanar vertices): ") +
          numbers(degenerate) +
          (degenerate.size() == cells.size()
             ? "; every cell is flat: are the coordinates right?"
             : ""));
      if (!positive.empty() && !negative.empty())
        {
          // The minority is the odd one out; on a tie, the negative ones.
          const bool minority_negative = negative.size() <= positive.size();
          const std::vector<long long> &odd =
            minority_negative ? negative : positive;
          const std::size_t n_others =
            positive.size() + negative.size() - odd.size();
          const std::string minus =
            dim == 2 ? "listed clockwise"
                     : "negatively oriented, (v1 - v0) x (v2 - v0) . "
                       "(v3 - v0) < 0,";
          const std::string plus =
            dim == 2 ? "counter-clockwise" : "positively oriented";
          const std::string odd_plus =
            dim == 2 ? "listed counter-clockwise"
                     : "positively oriented, (v1 - v0) x (v2 - v0) . "
                       "(v3 - v0) > 0,";
          const std::string others_minus =
            dim == 2 ? "clockwise" : "negatively oriented";
          problems.push_back(
            count_of<dim>(odd.size(), cells.size()) + " inverted (" +
            (minority_negative ? minus : odd_plus) + " while the other " +
            std::to_string(n_others) + " are " +
            (minority_negative ? plus : others_minus) + "): " + numbers(odd) +
            "; regenerate the mesh or swap two vertices of " +
            (odd.size() == 1 ? "this element" : "these elements"));
        }
      else if (!negative.empty() && !accept_mirrored)
        problems.push_back(
          std::string("all ") + std::to_string(negative.size()) +
          (dim == 2 ? " triangles are listed clockwise"
                    : " tetrahedra have negative orientation") +
          " (the mesh is mirrored); swap two vertices of every cell");
      if (problems.empty())
        return;
      std::string message = where_prefix;
      for (std::size_t i = 0; i < problems.size(); ++i)
        message += (i > 0 ? "; " : "") + problems[i];
      throw InputError(message);
    }

    /// The cells of a triangulation in deal.II's vertex order.
    template <int dim>
    std::vector<ListedSimplex<dim>>
    triangulation_simplices(const Triangulation<dim> &tria)
    {
      std::vector<ListedSimplex<dim>> cells;
      for (const auto &cell : tria.active_cell_iterators())
        {
          ListedSimplex<dim> listed;
          listed.number = cell->active_cell_index();
          for (unsigned int v = 0; v <= dim; ++v)
            listed.vertices[v] = cell->vertex(v);
          cells.push_back(listed);
        }
      return cells;
    }

    /// The triangles (dim = 2) or tetrahedra (dim = 3) of an ASCII gmsh file
    /// (format 1, 2 or 4) as the file lists them: element tag and the three
    /// coordinates of each vertex, in the listed order. Only for validation:
    /// deal.II's reader has already read the file successfully.
    struct GmshSimplices
    {
      std::vector<long long>               tags;
      std::vector<std::array<Point<3>, 4>> vertices; ///< the first dim + 1
    };

    /// Name of a gmsh element type (the common ones), for messages.
    std::string
    gmsh_element_name(const int type)
    {
      switch (type)
        {
        case 2:
          return "3-node triangle (type 2)";
        case 3:
          return "4-node quadrangle (type 3)";
        case 4:
          return "4-node tetrahedron (type 4)";
        case 5:
          return "8-node hexahedron (type 5)";
        case 6:
          return "6-node prism (type 6)";
        case 7:
          return "5-node pyramid (type 7)";
        case 8:
          return "3-node line (type 8)";
        case 9:
          return "6-node triangle (type 9)";
        case 10:
          return "9-node quadrangle (type 10)";
        case 11:
          return "10-node tetrahedron (type 11)";
        default:
          return "element of type " + std::to_string(type);
        }
    }

    template <int dim>
    GmshSimplices
    read_gmsh_simplices(const std::string &file_name)
    {
      std::ifstream in(file_name);
      std::string   line;
      const auto    fail = [&](const std::string &what) {
        throw InputError("cannot read mesh file '" + file_name + "': " + what);
      };
      // The next non-blank line, into @p ls.
      const auto next_line = [&](std::istringstream &ls) {
        while (std::getline(in, line))
          if (line.find_first_not_of(" \t\r") != std::string::npos)
            {
              ls.clear();
              ls.str(line);
              return;
            }
        fail("unexpected end of file");
      };
      const auto expect = [&](const std::istringstream &ls) {
        if (ls.fail())
          fail("cannot parse the line '" + line + "'");
      };

      // gmsh element types: 2 is the 3-node triangle, 4 the 4-node tet.
      const int                               simplex_type = dim == 2 ? 2 : 4;
      double                                  version      = 0.;
      std::unordered_map<long long, Point<3>> nodes;
      std::vector<std::pair<long long, std::array<long long, 4>>> elements;

      const auto read_node = [&](std::istringstream &ls, const long long tag) {
        Point<3> x;
        ls >> x[0] >> x[1] >> x[2];
        expect(ls);
        nodes[tag] = x;
      };
      // The rest of an element line after its tag and header.
      long long  unsupported_tag = 0, n_unsupported = 0;
      int        unsupported_type = 0;
      const auto read_element =
        [&](std::istringstream &ls, const long long tag, const int type) {
          // Points (15), lines (1) and, in 3D, triangles (2) carry boundary
          // ids; anything else is an element hyperelastic cannot compute on.
          if (type != simplex_type && type != 15 && type != 1 &&
              !(dim == 3 && type == 2))
            {
              if (n_unsupported++ == 0)
                {
                  unsupported_tag  = tag;
                  unsupported_type = type;
                }
              return;
            }
          if (type != simplex_type)
            return;
          std::array<long long, 4> v = {{0, 0, 0, 0}};
          for (unsigned int k = 0; k <= dim; ++k)
            ls >> v[k];
          expect(ls);
          elements.emplace_back(tag, v);
        };

      while (std::getline(in, line))
        {
          const std::string  section = Utilities::trim(line);
          std::istringstream ls;
          if (section == "$MeshFormat")
            {
              next_line(ls);
              ls >> version;
              expect(ls);
            }
          else if (section == "$NOD" || section == "$Nodes")
            {
              if (section == "$NOD") // format 1 has no $MeshFormat
                version = 1.;
              next_line(ls);
              if (version < 4.)
                {
                  long long n = 0;
                  ls >> n;
                  expect(ls);
                  for (long long i = 0; i < n; ++i)
                    {
                      next_line(ls);
                      long long tag = 0;
                      ls >> tag;
                      read_node(ls, tag);
                    }
                }
              else
                {
                  long long n_blocks = 0;
                  ls >> n_blocks;
                  expect(ls);
                  for (long long b = 0; b < n_blocks; ++b)
                    {
                      // 4.0: entity tag, entity dim; 4.1: the other way
                      // round. Then "parametric" and the node count.
                      next_line(ls);
                      long long entity_a, entity_b, parametric, n = 0;
                      ls >> entity_a >> entity_b >> parametric >> n;
                      expect(ls);
                      if (version < 4.05) // 4.0: "tag x y z" per line
                        for (long long i = 0; i < n; ++i)
                          {
                            next_line(ls);
                            long long tag = 0;
                            ls >> tag;
                            read_node(ls, tag);
                          }
                      else // 4.1: n tags, then n coordinate lines
                        {
                          std::vector<long long> tags(n);
                          for (long long &tag : tags)
                            {
                              next_line(ls);
                              ls >> tag;
                              expect(ls);
                            }
                          for (const long long tag : tags)
                            {
                              next_line(ls);
                              read_node(ls, tag);
                            }
                        }
                    }
                }
            }
          else if (section == "$ELM" || section == "$Elements")
            {
              next_line(ls);
              if (version < 4.)
                {
                  long long n = 0;
                  ls >> n;
                  expect(ls);
                  for (long long i = 0; i < n; ++i)
                    {
                      // 1: tag type physical elementary n-nodes nodes...
                      // 2: tag type n-tags tags... nodes...
                      next_line(ls);
                      long long tag  = 0;
                      int       type = 0;
                      ls >> tag >> type;
                      long long skip = 0;
                      if (version < 2.)
                        ls >> skip >> skip >> skip;
                      else
                        {
                          int n_tags = 0;
                          ls >> n_tags;
                          for (int t = 0; t < n_tags; ++t)
                            ls >> skip;
                        }
                      expect(ls);
                      read_element(ls, tag, type);
                    }
                }
              else
                {
                  long long n_blocks = 0;
                  ls >> n_blocks;
                  expect(ls);
                  for (long long b = 0; b < n_blocks; ++b)
                    {
                      // Entity tag and dim (in either order), element type,
                      // count; then "tag nodes..." per line.
                      next_line(ls);
                      long long entity_a, entity_b, n = 0;
                      int       type = 0;
                      ls >> entity_a >> entity_b >> type >> n;
                      expect(ls);
                      for (long long i = 0; i < n; ++i)
                        {
                          next_line(ls);
                          long long tag = 0;
                          ls >> tag;
                          expect(ls);
                          read_element(ls, tag, type);
                        }
                    }
                }
            }
        }

      if (n_unsupported > 0)
        throw InputError(
          "mesh file '" + file_name + "': " + std::to_string(n_unsupported) +
          " element(s) of a type hyperelastic does not read, the first gmsh "
          "element " +
          std::to_string(unsupported_tag) + ", a " +
          gmsh_element_name(unsupported_type) + ". A " + std::to_string(dim) +
          "D mesh consists of " +
          (dim == 2 ? "3-node triangles (plus lines"
                    : "4-node tetrahedra (plus triangles, lines") +
          " and points for boundary ids): mesh with simplices, first order "
          "(gmsh: no Recombine, Mesh.ElementOrder = 1), and check "
          "'Problem/Dimension'");
      if (elements.empty())
        throw InputError("mesh file '" + file_name + "' holds no " +
                         (dim == 2 ? "3-node triangles" : "4-node tetrahedra") +
                         " (gmsh element type " + std::to_string(simplex_type) +
                         "), only lower-dimensional elements: mesh the " +
                         (dim == 2 ? "surface (gmsh -2)" : "volume (gmsh -3)"));
      GmshSimplices result;
      for (const auto &[tag, node_tags] : elements)
        {
          std::array<Point<3>, 4> x;
          for (unsigned int k = 0; k <= dim; ++k)
            {
              const auto node = nodes.find(node_tags[k]);
              if (node == nodes.end())
                fail("element " + std::to_string(tag) + " refers to node " +
                     std::to_string(node_tags[k]) +
                     ", which $Nodes does not define");
              x[k] = node->second;
            }
          result.tags.push_back(tag);
          result.vertices.push_back(x);
        }
      return result;
    }

    /// Checks the cells of the gmsh file @p file_name as it lists them; see
    /// the policy above. In 2D also that all nodes of the triangles lie in a
    /// plane z = const, since only x and y are used.
    template <int dim>
    void
    check_gmsh_cells(const std::string   &file_name,
                     const GmshSimplices &listed,
                     const unsigned int   n_cells_read)
    {
      if (listed.tags.size() != n_cells_read)
        throw std::runtime_error("mesh file '" + file_name + "': found " +
                                 std::to_string(listed.tags.size()) +
                                 (dim == 2 ? " triangles" : " tetrahedra") +
                                 " but deal.II read " +
                                 std::to_string(n_cells_read) + " cells");
      const std::string where = "mesh file '" + file_name + "'";

      if (dim == 2)
        {
          Point<3> lower, upper;
          for (unsigned int d = 0; d < 3; ++d)
            {
              lower[d] = std::numeric_limits<double>::infinity();
              upper[d] = -std::numeric_limits<double>::infinity();
            }
          for (const auto &cell : listed.vertices)
            for (unsigned int k = 0; k <= dim; ++k)
              for (unsigned int d = 0; d < 3; ++d)
                {
                  lower[d] = std::min(lower[d], cell[k][d]);
                  upper[d] = std::max(upper[d], cell[k][d]);
                }
          const Tensor<1, 3> extent = upper - lower;
          // A z-variation below 1e-8 of the mesh size changes the projected
          // mesh by less than that: harmless rounding, not a mis-placed mesh.
          if (extent[2] > 1e-8 * extent.norm())
            {
              const auto range = [&](const unsigned int d) {
                std::ostringstream text;
                text << std::string(1, "xyz"[d]) << " from " << lower[d]
                     << " to " << upper[d];
                return text.str();
              };
              std::string plane;
              for (unsigned int d = 0; d < 2; ++d)
                if (extent[d] <= 1e-8 * extent.norm())
                  {
                    std::ostringstream text;
                    text << "it lies in the " << (d == 0 ? "yz" : "xz")
                         << "-plane (all nodes have "
                         << "xy"[d] << " = " << lower[d] << ", " << range(2)
                         << ")";
                    plane = text.str();
                  }
              if (plane.empty())
                plane =
                  "its nodes are not in one plane z = const (" + range(2) + ")";
              throw InputError(
                where + " is read as a 2D mesh, but " + plane +
                ". A 2D mesh uses the x and y coordinates only: draw it in "
                "the xy-plane (or rotate it there)");
            }
        }

      std::vector<ListedSimplex<dim>> cells(listed.tags.size());
      for (std::size_t c = 0; c < cells.size(); ++c)
        {
          cells[c].number = listed.tags[c];
          for (unsigned int k = 0; k <= dim; ++k)
            for (unsigned int d = 0; d < dim; ++d)
              cells[c].vertices[k][d] = listed.vertices[c][k][d];
        }
      check_simplices<dim>(cells,
                           where,
                           {"gmsh element",
                            "gmsh elements",
                            "(the element numbers of the file's $Elements "
                            "section)"},
                           /*accept_mirrored=*/true);
    }
    template <int dim>
    void
    read_gmsh(const std::string &file_name, Triangulation<dim> &tria)
    {
      std::ifstream in(file_name);
      if (!in)
        throw InputError("cannot open mesh file '" + file_name +
                         "' (Mesh/File)");
      // deal.II's reader handles ASCII files only; say so rather than let it
      // fail on binary data.
      std::string keyword, version;
      int         file_type = 0;
      in >> keyword;
      if (keyword == "$MeshFormat")
        in >> version >> file_type;
      if (file_type != 0)
        throw InputError(
          "mesh file '" + file_name +
          "' is a binary gmsh file; save it as ASCII (gmsh "
          "option -format msh41 without -bin, or Mesh.Binary = 0)");
      in.clear();
      in.seekg(0);

      // Own reading first: element types deal.II would reject with a
      // confusing list (or accept, like hexahedra), named here.
      const GmshSimplices listed = read_gmsh_simplices<dim>(file_name);

      GridIn<dim> grid_in;
      grid_in.attach_triangulation(tria);
      try
        {
          grid_in.read_msh(in);
        }
      catch (const std::exception &e)
        {
          throw InputError("cannot read mesh file '" + file_name +
                           "' as a gmsh mesh of dimension " +
                           std::to_string(dim) + ": " + exception_message(e));
        }
      if (tria.n_active_cells() == 0)
        throw InputError("mesh file '" + file_name +
                         "' has no cells of dimension " + std::to_string(dim));
      for (const auto &cell : tria.active_cell_iterators())
        if (!cell->reference_cell().is_simplex())
          throw InputError("mesh file '" + file_name + "': cell " +
                           std::to_string(cell->active_cell_index()) +
                           " is not a simplex (hyperelastic needs " +
                           (dim == 2 ? "triangles" : "tetrahedra") + ")");
      check_gmsh_cells<dim>(file_name, listed, tria.n_active_cells());
    }
  } // namespace

  template <int dim>
  std::set<types::boundary_id>
  create_mesh(const MeshParameters                           &parameters,
              parallel::fullydistributed::Triangulation<dim> &tria)
  {
    const MPI_Comm comm = tria.get_communicator();

    // Every rank builds the same serial mesh; it is dropped at the end of this
    // function, once each rank has extracted its own part.
    Triangulation<dim> serial;
    if (parameters.source == MeshSource::box)
      {
        Point<dim>                p1, p2;
        std::vector<unsigned int> repetitions(dim);
        for (unsigned int d = 0; d < dim; ++d)
          {
            p1[d]          = parameters.lower_corner[d];
            p2[d]          = parameters.upper_corner[d];
            repetitions[d] = parameters.subdivisions[d];
          }
        GridGenerator::subdivided_hyper_rectangle_with_simplices(serial,
                                                                 repetitions,
                                                                 p1,
                                                                 p2);
        set_box_boundary_ids(serial);
      }
    else
      read_gmsh(parameters.file, serial);

    // The cells deal.II made: none may be flat or negatively oriented. For a
    // file this holds after check_gmsh_cells() unless deal.II stops
    // reordering mirrored meshes; for the box it catches extreme aspect
    // ratios. Every rank checks the same serial mesh, so all ranks throw.
    check_simplices<dim>(triangulation_simplices(serial),
                         parameters.source == MeshSource::box
                           ? std::string("the generated box")
                           : "mesh file '" + parameters.file +
                               "' as read by deal.II",
                         {"cell", "cells", "(deal.II's cell numbers, from 0)"},
                         /*accept_mirrored=*/false);

    serial.refine_global(parameters.global_refinements);

    const std::vector<types::boundary_id> ids = serial.get_boundary_ids();

    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    if (n_ranks > 1)
      GridTools::partition_triangulation(n_ranks,
                                         serial,
                                         SparsityTools::Partitioner::metis);
    const auto description = TriangulationDescription::Utilities::
      create_description_from_triangulation(serial, comm);
    tria.create_triangulation(description);
    return std::set<types::boundary_id>(ids.begin(), ids.end());
  }

  template void
  set_box_boundary_ids(Triangulation<2> &);
  template void
  set_box_boundary_ids(Triangulation<3> &);
  template std::set<types::boundary_id>
  create_mesh(const MeshParameters &,
              parallel::fullydistributed::Triangulation<2> &);
  template std::set<types::boundary_id>
  create_mesh(const MeshParameters &,
              parallel::fullydistributed::Triangulation<3> &);
} // namespace hyperelastic
