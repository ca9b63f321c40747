// The deformed surface per output frame, for animation tools ('Output/
// Surface format = obj | ply': Blender and most pipelines import an OBJ or
// PLY sequence). 3D: the boundary triangles, each oriented outward (its
// vertices counter-clockwise seen from outside). 2D: the body's triangles in
// the plane z = 0, counter-clockwise (normal +z), since a plane-strain body
// is a slab. The surface is linear per face (P2: its vertices only).
//
// Vertex order: the lexicographic order of the reference coordinates (x,
// then y, then z), triangles sorted likewise by their vertex numbers: the
// same order in every frame and for any number of ranks. The topology is
// gathered once, at construction; a frame sends only each rank's vertex
// displacements (and cell von Mises stresses for PLY) to rank 0, which
// writes <Directory>/<Base name>_surface_NNNN.<obj|ply> (NNNN: the frame
// number, 0 for the initial state, one per output step like the PVD's
// entries).
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/output/output_parameters.h>

#include <array>
#include <string>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class SurfaceWriter
  {
  public:
    /// Gathers the surface of the mesh of @p dof_handler (collective).
    SurfaceWriter(const dealii::DoFHandler<dim> &dof_handler,
                  SurfaceFormat                  format,
                  const std::string             &directory,
                  const std::string             &base_name);

    /// Writes frame @p frame of the displacement @p u (ghosted) at load
    /// factor or time @p t; @p von_mises: the cells' von Mises stress by
    /// active cell index (PLY writes its average over the cells of each
    /// vertex's faces), or null. Collective.
    void
    write(unsigned int                                 frame,
          double                                       t,
          const dealii::TrilinosWrappers::MPI::Vector &u,
          const dealii::Vector<double>                *von_mises) const;

    /// The file of frame @p frame.
    std::string
    file(unsigned int frame) const;

    /// Vertices and triangles of the surface (on every rank).
    unsigned int
    n_vertices() const
    {
      return n_surface_vertices;
    }

    unsigned int
    n_triangles() const
    {
      return n_surface_triangles;
    }

  private:
    const MPI_Comm      comm;
    const SurfaceFormat format;
    const std::string   directory;
    const std::string   base_name;

    /// This rank's triangle corners, three per triangle of its own cells:
    /// the dofs of the displacement components at the corner and the
    /// cell's active index.
    std::vector<std::array<dealii::types::global_dof_index, dim>> corner_dofs;
    std::vector<unsigned int>                                     corner_cells;

    // Rank 0: the surface.
    unsigned int                             n_surface_vertices  = 0;
    unsigned int                             n_surface_triangles = 0;
    std::vector<dealii::Point<dim>>          reference;
    std::vector<std::array<unsigned int, 3>> triangles;
    /// [rank][corner]: the vertex of each corner of that rank.
    std::vector<std::vector<unsigned int>> corner_vertex;
  };
} // namespace hyperelastic
