// Mesh creation: a generated box of simplices or a gmsh file, read, checked,
// refined and partitioned with METIS on one rank (the reader, rank 0); every
// rank receives only the description of its own cells (plus a ghost layer),
// and the others never hold the whole mesh.
#pragma once

#include <deal.II/base/types.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/grid/tria.h>

#include <hyperelastic/mesh/mesh_parameters.h>

#include <cstddef>
#include <set>
#include <string>

namespace hyperelastic
{
  /// What create_mesh() did on this rank (for tests and benchmarks).
  struct MeshStatistics
  {
    /// Whether this rank read (or generated) and partitioned the mesh.
    bool reader = false;
    /// Cells of the whole mesh this rank held (a gmsh file's list of cells,
    /// or a serial triangulation when generated or refined): all on the
    /// reader, 0 elsewhere.
    std::size_t serial_cells = 0;
    /// Coarse cells of the description this rank received (or made).
    std::size_t description_coarse_cells = 0;
    /// Active cells of the whole refined mesh (on every rank).
    std::size_t global_cells = 0;
    /// Input cells listed with negative orientation, whose vertex order was
    /// reversed before the mesh was built (on every rank).
    std::size_t reoriented_cells = 0;
    /// Wall times in seconds. On the reader (0 elsewhere): reading (or
    /// generating), ordering the cells along a space-filling curve (a
    /// file), checking (zero measures, folds), building (face
    /// neighbours and boundary faces; for a mesh to be refined also the
    /// serial triangulation), refining and partitioning. On every rank: waiting
    /// for the reader's outcome (others), making and sending the descriptions
    /// (reader) or receiving one (others), and building the distributed
    /// triangulation.
    double read_time = 0., order_time = 0., check_time = 0., build_time = 0.,
           partition_time = 0., wait_time = 0., describe_time = 0.,
           distribute_time = 0.;
    /// The lines of the run header about a volume mesh generated from a
    /// closed surface (Mesh/Source = surface), on the reader; else empty.
    std::string generated_mesh;
  };

  /// Builds @p tria from the scene's mesh section and returns the boundary ids
  /// the whole mesh has. Collective. Rank 0 of the triangulation's
  /// communicator reads (or generates) the mesh, checks, refines and
  /// partitions it; the others wait for the outcome, so that an error found
  /// by the reader is thrown as the same InputError on every rank.
  ///
  /// A gmsh file may list the vertices of its cells in any order: cells
  /// listed with negative orientation are reoriented (two vertices swapped).
  /// Its cells are sorted along a Morton curve (order_cells_along_curve()),
  /// so that the unknowns deal.II numbers cell by cell are local in memory.
  /// Rejected with InputError: unreadable files, cells of zero area or
  /// volume, folded meshes (two cells on the same side of their shared face,
  /// as when a node is pushed through a face) and 2D meshes whose nodes do
  /// not lie in a plane z = const. The messages list the offending cells by
  /// their gmsh element numbers.
  ///
  /// @p statistics, if given, receives what this rank did.
  template <int dim>
  std::set<dealii::types::boundary_id>
  create_mesh(const MeshParameters &parameters,
              dealii::parallel::fullydistributed::Triangulation<dim> &tria,
              MeshStatistics *statistics = nullptr);

  /// A serial triangulation for a run on one MPI rank: the mesh is built
  /// directly from the box or the checked cell list, without the
  /// description and the fully distributed triangulation's construction
  /// (about half of the set-up's time, benchmarks/setup). It answers
  /// get_communicator() with the run's communicator (of one rank) instead of
  /// MPI_COMM_SELF, so that vectors made from the DoFHandler and from the
  /// run's communicator fit together.
  template <int dim>
  class SerialTriangulation : public dealii::Triangulation<dim>
  {
  public:
    explicit SerialTriangulation(const MPI_Comm comm)
        : comm(comm)
    {}

    MPI_Comm
    get_communicator() const override
    {
      return comm;
    }

  private:
    const MPI_Comm comm;
  };

  /// Builds @p tria as create_mesh() does, for a run on one rank (the same
  /// cells in the same order, the same checks, boundary ids and messages).
  /// Statistics: read, order, check, build as there; "distribute" is the
  /// construction of the triangulation.
  template <int dim>
  std::set<dealii::types::boundary_id>
  create_serial_mesh(const MeshParameters       &parameters,
                     SerialTriangulation<dim> &tria,
                     MeshStatistics             *statistics = nullptr);

  /// Boundary ids of a box: 2 d on the face x_d = min, 2 d + 1 on x_d = max.
  /// Set from face centres since deal.II 9.4 cannot colorize simplex boxes.
  template <int dim>
  void
  set_box_boundary_ids(dealii::Triangulation<dim> &tria);
} // namespace hyperelastic
