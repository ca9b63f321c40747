// Checks of the cells of a gmsh file: zero measures, reorientation of
// negatively listed cells, face neighbours and boundary faces, folds, the
// plane of a 2D mesh; the checked mesh that is partitioned and distributed.
// Errors name the gmsh element numbers.
#include <deal.II/base/timer.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/cell_ordering.h>
#include <hyperelastic/mesh/mesh_checks.h>
#include <hyperelastic/mesh/mesh_file.h>
#include <hyperelastic/mesh/surface_mesher.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    // ------------------------------------------------------------------
    // Policy for the input cells.
    //
    // Vertex order: any. Mesh writers differ: gmsh and TetGen list cells
    // positively oriented, gmsh writes every triangle clockwise for a
    // surface whose curve loop runs clockwise, and DOLFIN/FEniCS and meshio
    // write cells in sorted vertex order, so that about half of them are
    // negatively oriented. A cell listed with negative orientation is
    // reoriented (its last two vertices swapped, as deal.II's GridIn does);
    // this changes no geometry and no result.
    //
    // What is rejected, with the gmsh element numbers:
    // - cells of zero area or volume (see simplex_measure() for the test);
    // - folds: two cells sharing a face whose opposite vertices lie on the
    //   same side of it overlap, as when a node is pushed through a face.
    //   Reorienting cells cannot hide this, since the test depends on the
    //   positions only. The cells named are the inverted ones: across every
    //   face the orientation is propagated (kept, or flipped where the face
    //   is folded), and in each connected part of the mesh the minority is
    //   inverted.
    // - 2D meshes whose nodes are not in a plane z = const (deal.II would
    //   drop z and compute on a distorted projection).
    //
    // What deal.II 9.4 itself does (tried with GridIn::read_msh and
    // Triangulation::create_triangulation on small hand-made meshes):
    // GridIn reorders negatively oriented simplices silently;
    // create_triangulation accepts inverted and zero-volume cells; neither
    // notices folds. Hence the checks here.

    /// The element numbers of a mesh file as its format has them (see
    /// read_mesh_file()).
    Numbering
    file_numbering(const std::string &file_name)
    {
      std::string extension =
        std::filesystem::path(file_name).extension().string();
      for (char &c : extension)
        c = std::tolower(static_cast<unsigned char>(c));
      if (extension == ".mesh")
        return {"MEDIT element",
                "MEDIT elements",
                "(the positions in the file's Tetrahedra, Triangles or Edges "
                "section, from 1)"};
      if (extension == ".vtk")
        return {"VTK cell", "VTK cells", "(the file's cell ids, from 0)"};
      return {"gmsh element",
              "gmsh elements",
              "(the element numbers of the file's $Elements section)"};
    }

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
  } // namespace

  template <int dim>
  std::string
  cell_problems(const std::size_t             n_cells,
                const std::vector<long long> &degenerate,
                const std::vector<long long> &inverted,
                const int                     inverted_listed,
                const Numbering              &numbering)
  {
    const auto numbers = [&](const std::vector<long long> &n) {
      return (n.size() == 1 ? numbering.singular : numbering.plural) + " " +
             list_numbers(n) + " " + numbering.note;
    };
    std::vector<std::string> problems;
    if (!degenerate.empty())
      problems.push_back(count_of<dim>(degenerate.size(), n_cells) +
                         " degenerate (" +
                         (dim == 2 ? "zero area, collinear vertices): "
                                   : "zero volume, coplanar vertices): ") +
                         numbers(degenerate) +
                         (degenerate.size() == n_cells
                            ? "; every cell is flat: are the coordinates right?"
                            : ""));
    if (!inverted.empty())
      {
        const std::size_t n_others =
          n_cells - degenerate.size() - inverted.size();
        std::string why;
        if (inverted_listed < 0)
          why = dim == 2
                  ? "listed clockwise while the other " +
                      std::to_string(n_others) + " are counter-clockwise"
                  : "negatively oriented, (v1 - v0) x (v2 - v0) . "
                    "(v3 - v0) < 0, while the other " +
                      std::to_string(n_others) + " are positively oriented";
        else if (inverted_listed > 0)
          why = dim == 2
                  ? "listed counter-clockwise while the other " +
                      std::to_string(n_others) + " are clockwise"
                  : "positively oriented, (v1 - v0) x (v2 - v0) . "
                    "(v3 - v0) > 0, while the other " +
                      std::to_string(n_others) + " are negatively oriented";
        else
          why = std::string(inverted.size() == 1 ? "it" : "each") +
                " lies on the same side of a " + (dim == 2 ? "edge" : "face") +
                " as the neighbour across it";
        problems.push_back(
          count_of<dim>(inverted.size(), n_cells) + " inverted (" + why +
          "): " + numbers(inverted) +
          "; the mesh is folded there, as when a node is pushed through a " +
          (dim == 2 ? "edge" : "face") +
          ": correct the node coordinates or regenerate the mesh (the "
          "vertex order is not the problem: cells listed in either "
          "orientation are accepted)");
      }
    std::string text;
    for (std::size_t i = 0; i < problems.size(); ++i)
      text += (i > 0 ? "; " : "") + problems[i];
    return text;
  }

  void
  check_plane(const std::string &where,
              const Point<3>    &lower,
              const Point<3>    &upper)
  {
    const Tensor<1, 3> extent = upper - lower;
    // A z-variation below 1e-8 of the mesh size changes the projected
    // mesh by less than that: harmless rounding, not a mis-placed mesh.
    if (!(extent[2] > 1e-8 * extent.norm()))
      return;
    const auto range = [&](const unsigned int d) {
      std::ostringstream text;
      text << std::string(1, "xyz"[d]) << " from " << lower[d] << " to "
           << upper[d];
      return text.str();
    };
    std::string plane;
    for (unsigned int d = 0; d < 2; ++d)
      if (extent[d] <= 1e-8 * extent.norm())
        {
          std::ostringstream text;
          text << "it lies in the " << (d == 0 ? "yz" : "xz")
               << "-plane (all nodes have "
               << "xy"[d] << " = " << lower[d] << ", " << range(2) << ")";
          plane = text.str();
        }
    if (plane.empty())
      plane = "its nodes are not in one plane z = const (" + range(2) + ")";
    throw InputError(where + " is read as a 2D mesh, but " + plane +
                     ". A 2D mesh uses the x and y coordinates only: draw it "
                     "in the xy-plane (or rotate it there)");
  }

  namespace
  {
    /// Face neighbours and boundary ids of @p mesh.cells, from the faces'
    /// vertex sets. Throws InputError for faces of more than two cells and
    /// for boundary ids given to faces inside the mesh.
    template <int dim>
    void
    find_faces(CheckedMesh<dim>             &mesh,
               const std::vector<long long> &boundary_numbers,
               const std::string            &where,
               const Numbering              &numbering)
    {
      constexpr unsigned int n_faces = dim + 1;
      const ReferenceCell    simplex = ReferenceCells::get_simplex<dim>();
      struct Face
      {
        std::array<unsigned int, dim> key; ///< sorted vertex indices
        unsigned int                  cell;
        unsigned int                  face;
      };
      const std::size_t n_cells = mesh.cells.size();
      std::vector<Face> faces;
      faces.reserve(n_cells * n_faces);
      for (unsigned int c = 0; c < n_cells; ++c)
        for (unsigned int f = 0; f < n_faces; ++f)
          {
            Face face{{}, c, f};
            for (unsigned int k = 0; k < dim; ++k)
              face.key[k] =
                mesh.cells[c].vertices[simplex.face_to_cell_vertices(f, k, 1)];
            std::sort(face.key.begin(), face.key.end());
            faces.push_back(face);
          }
      std::sort(faces.begin(), faces.end(), [](const Face &a, const Face &b) {
        return a.key < b.key;
      });

      mesh.neighbors.assign(n_cells * n_faces, -1);
      mesh.face_ids.assign(n_cells * n_faces,
                           numbers::internal_face_boundary_id);
      std::vector<long long> crowded;
      std::size_t            n_crowded = 0;
      for (std::size_t i = 0; i < faces.size();)
        {
          std::size_t j = i + 1;
          while (j < faces.size() && faces[j].key == faces[i].key)
            ++j;
          if (j == i + 1)
            mesh.face_ids[faces[i].cell * n_faces + faces[i].face] = 0;
          else if (j == i + 2)
            {
              mesh.neighbors[faces[i].cell * n_faces + faces[i].face] =
                faces[i + 1].cell;
              mesh.neighbors[faces[i + 1].cell * n_faces + faces[i + 1].face] =
                faces[i].cell;
            }
          else
            {
              ++n_crowded;
              for (std::size_t k = i; k < j; ++k)
                crowded.push_back(mesh.element_numbers[faces[k].cell]);
            }
          i = j;
        }
      if (n_crowded > 0)
        {
          std::sort(crowded.begin(), crowded.end());
          crowded.erase(std::unique(crowded.begin(), crowded.end()),
                        crowded.end());
          throw InputError(
            where + ": " + std::to_string(n_crowded) + " " +
            (dim == 2 ? "edge" : "face") + (n_crowded == 1 ? " is" : "s are") +
            " shared by more than two cells (the mesh is not a manifold "
            "there, or has duplicated cells): " +
            numbering.plural + " " + list_numbers(crowded) + " " +
            numbering.note);
        }

      // Boundary ids from the lower-dimensional elements; a later element
      // of the same face wins.
      std::vector<long long> inside;
      const auto             assign = [&](const auto &objects) {
        for (std::size_t o = 0; o < objects.size(); ++o)
          {
            Face key{{}, 0, 0};
            if (objects[o].vertices.size() != dim)
              continue;
            std::copy(objects[o].vertices.begin(),
                      objects[o].vertices.end(),
                      key.key.begin());
            std::sort(key.key.begin(), key.key.end());
            const auto found =
              std::lower_bound(faces.begin(),
                               faces.end(),
                               key,
                               [](const Face &a, const Face &b) {
                                 return a.key < b.key;
                               });
            if (found == faces.end() || found->key != key.key)
              continue; // not a face of the mesh: ignored, as by deal.II
            const std::size_t at = found->cell * n_faces + found->face;
            if (mesh.neighbors[at] >= 0)
              inside.push_back(boundary_numbers[o]);
            else
              mesh.face_ids[at] = objects[o].boundary_id;
          }
      };
      if constexpr (dim == 2)
        assign(mesh.boundary.boundary_lines);
      else
        assign(mesh.boundary.boundary_quads);
      if (!inside.empty())
        throw InputError(
          where + ": " + std::to_string(inside.size()) + " " +
          (dim == 2 ? "line" : "triangle") +
          (inside.size() == 1 ? " element lies" : " elements lie") +
          " inside the mesh, on " + (dim == 2 ? "edges" : "faces") +
          " between two cells, where a physical tag cannot be a boundary id: " +
          (inside.size() == 1 ? numbering.singular : numbering.plural) + " " +
          list_numbers(inside) + " " + numbering.note);
    }

    template <int dim>
    class FoldTest
    {
    public:
      explicit FoldTest(const CheckedMesh<dim> &mesh)
          : mesh(mesh)
      {
      }

      /// Whether the face neighbours @p a and @p b lie on the same side of
      /// their shared face. Both must be non-degenerate: then the signs
      /// below are those of their measures, well separated from zero.
      bool
      operator()(const unsigned int a, const unsigned int b) const
      {
        const std::vector<unsigned int> &va = mesh.cells[a].vertices;
        const std::vector<unsigned int> &vb = mesh.cells[b].vertices;
        const auto                       in = [](const unsigned int               v,
                           const std::vector<unsigned int> &list) {
          return std::find(list.begin(), list.end(), v) != list.end();
        };
        std::array<unsigned int, dim> face;
        unsigned int                  n_shared = 0;
        unsigned int                  p = numbers::invalid_unsigned_int, q = p;
        for (const unsigned int v : va)
          if (!in(v, vb))
            p = v;
          else if (n_shared < dim)
            face[n_shared++] = v;
        for (const unsigned int v : vb)
          if (!in(v, va))
            q = v;
        if (n_shared != dim || p == numbers::invalid_unsigned_int ||
            q == numbers::invalid_unsigned_int)
          return false; // not face neighbours
        Tensor<2, dim>    columns;
        const Point<dim> &x0 = mesh.vertices[face[0]];
        for (unsigned int k = 1; k < dim; ++k)
          for (unsigned int d = 0; d < dim; ++d)
            columns[d][k - 1] = mesh.vertices[face[k]][d] - x0[d];
        const auto side = [&](const unsigned int v) {
          for (unsigned int d = 0; d < dim; ++d)
            columns[d][dim - 1] = mesh.vertices[v][d] - x0[d];
          return determinant(columns);
        };
        const double sp = side(p), sq = side(q);
        return (sp > 0. && sq > 0.) || (sp < 0. && sq < 0.);
      }

    private:
      const CheckedMesh<dim> &mesh;
    };

    /// The cells (by index) that are inverted relative to the rest of their
    /// connected part of the mesh, cells marked @p degenerate left out.
    /// @p listed_negative serves to break ties.
    template <int dim>
    std::vector<unsigned int>
    find_inverted_cells(const CheckedMesh<dim>  &mesh,
                        const std::vector<bool> &degenerate,
                        const std::vector<bool> &listed_negative)
    {
      constexpr unsigned int n_faces = dim + 1;
      const unsigned int     n       = mesh.cells.size();
      const FoldTest<dim>    folded(mesh);
      // Cheap pass first: most meshes have no fold.
      bool any_fold = false;
      for (unsigned int c = 0; c < n && !any_fold; ++c)
        if (!degenerate[c])
          for (unsigned int f = 0; f < n_faces; ++f)
            {
              const int j = mesh.neighbors[c * n_faces + f];
              if (j > static_cast<int>(c) && !degenerate[j] && folded(c, j))
                any_fold = true;
            }
      if (!any_fold)
        return {};

      // Relative orientation g = +-1, kept across a face, flipped across a
      // folded one; per connected part the minority is inverted.
      std::vector<signed char>  g(n, 0);
      std::vector<unsigned int> inverted, part;
      for (unsigned int seed = 0; seed < n; ++seed)
        {
          if (degenerate[seed] || g[seed] != 0)
            continue;
          part.assign(1, seed);
          g[seed] = 1;
          for (std::size_t next = 0; next < part.size(); ++next)
            {
              const unsigned int c = part[next];
              for (unsigned int f = 0; f < n_faces; ++f)
                {
                  const int j = mesh.neighbors[c * n_faces + f];
                  if (j < 0 || degenerate[j] || g[j] != 0)
                    continue;
                  g[j] = folded(c, j) ? -g[c] : g[c];
                  part.push_back(j);
                }
            }
          std::size_t plus = 0, plus_listed_negative = 0,
                      minus_listed_negative = 0;
          for (const unsigned int i : part)
            {
              plus += g[i] > 0 ? 1 : 0;
              (g[i] > 0 ? plus_listed_negative : minus_listed_negative) +=
                listed_negative[i] ? 1 : 0;
            }
          const std::size_t minus = part.size() - plus;
          // The minority; on a tie the part listed negatively, else the
          // part without the seed.
          const signed char odd = plus < minus   ? 1
                                  : minus < plus ? -1
                                  : plus_listed_negative > minus_listed_negative
                                    ? 1
                                    : -1;
          for (const unsigned int i : part)
            if (g[i] == odd)
              inverted.push_back(i);
        }
      std::sort(inverted.begin(), inverted.end());
      return inverted;
    }
  } // namespace

  template <int dim>
  CheckedMesh<dim>
  read_and_check_gmsh(const std::string    &file_name,
                      MeshStatistics       &statistics,
                      const MeshParameters *parameters)
  {
    Timer         timer;
    GmshMesh<dim> file =
      parameters && parameters->source == MeshSource::surface
        ? mesh_closed_surface<dim>(*parameters, statistics.generated_mesh)
        : read_mesh_file<dim>(file_name);
    statistics.read_time = timer.wall_time();
    timer.restart();

    const std::string where = "mesh file '" + file_name + "'";
    if (dim == 2)
      check_plane(where, file.lower, file.upper);

    order_cells_along_curve(file);
    statistics.order_time = timer.wall_time();
    CheckedMesh<dim> mesh;
    mesh.vertices        = std::move(file.vertices);
    mesh.cells           = std::move(file.cells);
    mesh.boundary        = std::move(file.boundary);
    mesh.element_numbers = std::move(file.element_numbers);

    // Zero measure and orientation as listed; negatively oriented cells
    // reoriented as deal.II's GridIn does it (last two vertices swapped).
    const std::size_t      n_cells = mesh.cells.size();
    std::vector<bool>      degenerate(n_cells, false);
    std::vector<bool>      listed_negative(n_cells, false);
    std::vector<long long> degenerate_numbers;
    for (std::size_t c = 0; c < n_cells; ++c)
      {
        std::vector<unsigned int> &v = mesh.cells[c].vertices;
        const SimplexMeasure       measure =
          simplex_measure<dim>([&](const unsigned int k) -> const Point<dim> & {
            return mesh.vertices[v[k]];
          });
        if (measure.degenerate)
          {
            degenerate[c] = true;
            degenerate_numbers.push_back(mesh.element_numbers[c]);
          }
        else if (measure.det < 0.)
          {
            listed_negative[c] = true;
            std::swap(v[dim - 1], v[dim]);
            ++mesh.n_reoriented;
          }
      }

    const Numbering numbering = file_numbering(file_name);
    find_faces(mesh, file.boundary_numbers, where, numbering);
    statistics.build_time = timer.wall_time() - statistics.order_time;

    // Folds.
    const std::vector<unsigned int> inverted =
      find_inverted_cells(mesh, degenerate, listed_negative);
    if (!degenerate_numbers.empty() || !inverted.empty())
      {
        std::vector<long long> inverted_numbers;
        std::vector<bool>      is_inverted(n_cells, false);
        for (const unsigned int c : inverted)
          {
            inverted_numbers.push_back(mesh.element_numbers[c]);
            is_inverted[c] = true;
          }
        std::sort(inverted_numbers.begin(), inverted_numbers.end());
        std::sort(degenerate_numbers.begin(), degenerate_numbers.end());
        // Does the listing tell the same story (a consistently listed
        // mesh with a fold)? Then say it in its terms.
        int inverted_listed = 0;
        if (!inverted.empty())
          {
            const bool first = listed_negative[inverted[0]];
            bool       same  = true;
            for (std::size_t c = 0; c < n_cells && same; ++c)
              if (!degenerate[c])
                same = listed_negative[c] == (is_inverted[c] ? first : !first);
            if (same)
              inverted_listed = first ? -1 : 1;
          }
        throw InputError(where + ": " +
                         cell_problems<dim>(n_cells,
                                            degenerate_numbers,
                                            inverted_numbers,
                                            inverted_listed,
                                            numbering));
      }
    statistics.check_time =
      timer.wall_time() - statistics.build_time - statistics.order_time;
    return mesh;
  }

  template std::string
  cell_problems<2>(const std::size_t,
                   const std::vector<long long> &,
                   const std::vector<long long> &,
                   const int,
                   const Numbering &);
  template std::string
  cell_problems<3>(const std::size_t,
                   const std::vector<long long> &,
                   const std::vector<long long> &,
                   const int,
                   const Numbering &);
  template CheckedMesh<2>
  read_and_check_gmsh<2>(const std::string &,
                         MeshStatistics &,
                         const MeshParameters *);
  template CheckedMesh<3>
  read_and_check_gmsh<3>(const std::string &,
                         MeshStatistics &,
                         const MeshParameters *);
} // namespace hyperelastic
