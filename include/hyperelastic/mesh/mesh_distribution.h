// Partition and distribution of a checked mesh: the METIS partition of its
// cells, the description of one rank's part, and the messages by which the
// reader (rank 0) tells the other ranks its outcome and sends them their
// parts.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria_description.h>

#include <hyperelastic/mesh/mesh_checks.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// METIS partition of the cells of @p mesh into @p n_parts, computed
  /// as GridTools::partition_triangulation() does for a triangulation of
  /// these cells (the same graph of face neighbours, hence the same
  /// partition).
  template <int dim>
  std::vector<unsigned int>
  partition_cells(const CheckedMesh<dim> &mesh, const unsigned int n_parts);

  /// The boundary id of the faces where a rank's ghost layer ends (faces
  /// between cells of the mesh, not on its boundary). Without it deal.II
  /// gives them boundary id 0, and a Dirichlet condition on id 0 would
  /// constrain the ghost dofs on them (harmless to cell-wise assembly, wrong
  /// for the vertex rows of stiffness warping). Scenes cannot name it
  /// (boundary ids in scenes are int).
  constexpr dealii::types::boundary_id partition_edge_boundary_id =
    dealii::numbers::internal_face_boundary_id - 1;

  /// Calls @p f(cell, face) for every face of the body's boundary that an
  /// owned or ghost cell of @p dof_handler has (the faces where the ghost
  /// layer ends are not the body's boundary).
  template <typename DoFHandlerType, typename F>
  void
  for_each_boundary_face(const DoFHandlerType &dof_handler, const F &f)
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int i : cell->face_indices())
          if (cell->face(i)->at_boundary() &&
              cell->face(i)->boundary_id() != partition_edge_boundary_id)
            f(cell, cell->face(i));
  }

  /// Gives the faces of @p tria (just made from @p description) that are on
  /// its boundary but not on the mesh's (the description lists every face
  /// on the mesh's boundary, by cell id and face number on every level)
  /// partition_edge_boundary_id. Only owned and ghost cells are marked
  /// (after a global refinement the artificial children of a coarse cell
  /// are not described).
  template <int dim>
  void
  mark_partition_edges(
    const dealii::TriangulationDescription::Description<dim, dim> &description,
    dealii::Triangulation<dim>                                    &tria);

  /// The description of the part of rank @p rank: its cells and the
  /// ghost layer (every cell with a vertex of one of its cells), as
  /// TriangulationDescription::Utilities::
  /// create_description_from_triangulation() makes it from a serial
  /// triangulation of these cells that is not refined.
  template <int dim>
  dealii::TriangulationDescription::Description<dim, dim>
  describe_part(const CheckedMesh<dim>          &mesh,
                const std::vector<unsigned int> &owner,
                const unsigned int               rank,
                const MPI_Comm                   comm);

  // Messages from the reader: tags of their own, on the triangulation's
  // communicator.
  constexpr int outcome_tag = 20151, description_tag = 20152;

  /// Sends @p buffer as one message (an error if it is too large for one).
  void
  send(const std::vector<char> &buffer,
       const unsigned int       destination,
       const int                tag,
       const MPI_Comm           comm);

  /// The message of @p tag from @p source. Polls, sleeping in between,
  /// instead of blocking in MPI: Open MPI spins while it blocks, and a
  /// rank waiting for the reader would take a core from it on a node
  /// shared with other jobs or with more ranks than cores.
  std::vector<char>
  receive(const unsigned int source, const int tag, const MPI_Comm comm);

  /// What the reader tells the other ranks before the distribution.
  struct ReaderOutcome
  {
    enum Status : int
    {
      ok,
      input_error,
      other_error
    };
    int                                     status = ok;
    std::string                             message;
    std::vector<dealii::types::boundary_id> boundary_ids;
    std::size_t                             global_cells     = 0;
    std::size_t                             reoriented_cells = 0;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &status &message &boundary_ids &global_cells &reoriented_cells;
    }
  };
} // namespace hyperelastic
