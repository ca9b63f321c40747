// Reading a gmsh file into a list of cells: one pass over the file (ASCII
// formats 1, 2.2, 4.0 and 4.1; binary 2.2 and 4.1), the cells deal.II's
// GridIn::read_msh would build, with the gmsh element number of every cell and
// the physical tags as material ids (cells) and boundary ids (faces).
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// The cells of a gmsh file as read: what deal.II's GridIn::read_msh would
  /// hand to Triangulation::create_triangulation (the same vertices in the
  /// same order, cells with the physical tag as material id), plus the
  /// element numbers, for messages.
  template <int dim>
  struct GmshMesh
  {
    std::vector<dealii::Point<dim>>    vertices;
    std::vector<dealii::CellData<dim>> cells;
    /// Faces with boundary ids (2D: lines, 3D: triangles) and their
    /// element numbers. (Lines in 3D are read and dropped: only faces
    /// carry boundary ids in a distributed triangulation.)
    dealii::SubCellData    boundary;
    std::vector<long long> boundary_numbers;
    std::vector<long long> element_numbers; ///< of cells
    /// Bounds of the nodes of the cells, in all three coordinates.
    dealii::Point<3> lower, upper;

    /// Appends a cell of the vertices @p v[0 ... dim] with material id
    /// @p material_id; @p number: the element's number in the file (for
    /// messages).
    void
    add_cell(const std::array<unsigned int, 4> &v,
             const unsigned int                 material_id,
             const long long                    number)
    {
      dealii::CellData<dim> cell(dim + 1);
      std::copy(v.begin(), v.begin() + dim + 1, cell.vertices.begin());
      cell.material_id = material_id;
      cells.push_back(std::move(cell));
      element_numbers.push_back(number);
    }

    /// Appends a boundary face (a line in 2D, a triangle in 3D) of the
    /// vertices @p v[0 ... dim - 1] with boundary id @p boundary_id.
    void
    add_face(const std::array<unsigned int, 4> &v,
             const unsigned int                 boundary_id,
             const long long                    number)
    {
      dealii::CellData<dim - 1> face(dim);
      std::copy(v.begin(), v.begin() + dim, face.vertices.begin());
      face.boundary_id = boundary_id;
      if constexpr (dim == 2)
        boundary.boundary_lines.push_back(std::move(face));
      else
        boundary.boundary_quads.push_back(std::move(face));
      boundary_numbers.push_back(number);
    }
  };

  /// Reads a gmsh file (ASCII: format 1, 2 or 4; binary: format 2.2 or
  /// 4.1, little- or big-endian), as a mesh of triangles
  /// (dim = 2) or tetrahedra (dim = 3). Points, lines and, in 3D,
  /// triangles carry boundary ids; any other element type is an error.
  /// Errors name the scene entry @p entry. Without @p cells_required a
  /// file of faces alone (an obstacle's surface: lines in 2D, triangles in
  /// 3D) is read too.
  template <int dim>
  GmshMesh<dim>
  read_gmsh(const std::string &file_name,
            const std::string &entry          = "Mesh/File",
            bool               cells_required = true);
} // namespace hyperelastic
