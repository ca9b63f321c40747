// Mesh creation: the orchestration of create_mesh() (the reader, rank 0,
// generates the box or reads and checks a gmsh file, refines and partitions
// it; every other rank receives only the description of its own part), its
// one-rank form create_serial_mesh(), the generated box and its boundary ids.
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/mesh.h>
#include <hyperelastic/mesh/mesh_checks.h>
#include <hyperelastic/mesh/mesh_distribution.h>

#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
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
    /// The triangulation of the checked cells of mesh file @p file; what
    /// deal.II still rejects becomes an input error naming the file.
    template <int dim>
    void
    triangulate_checked_mesh(const std::string      &file,
                             const CheckedMesh<dim> &mesh,
                             Triangulation<dim>     &tria)
    {
      try
        {
          tria.create_triangulation(mesh.vertices, mesh.cells, mesh.boundary);
        }
      catch (const std::exception &e)
        {
          throw InputError("cannot read mesh file '" + file +
                           "' as a gmsh mesh of dimension " +
                           std::to_string(dim) + ": " + exception_message(e));
        }
    }

    /// The generated box; its cells are checked as deal.II made them
    /// (extreme aspect ratios can make them flat).
    template <int dim>
    void
    build_box(const MeshParameters &parameters, Triangulation<dim> &serial)
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

      std::vector<long long> degenerate, negative;
      for (const auto &cell : serial.active_cell_iterators())
        {
          const SimplexMeasure measure = simplex_measure<dim>(
            [&](const unsigned int k) -> const Point<dim> & {
              return cell->vertex(k);
            });
          if (measure.degenerate)
            degenerate.push_back(cell->active_cell_index());
          else if (measure.det < 0.)
            negative.push_back(cell->active_cell_index());
        }
      if (!degenerate.empty())
        throw InputError(
          "the generated box: " +
          cell_problems<dim>(
            serial.n_active_cells(),
            degenerate,
            {},
            0,
            {"cell", "cells", "(deal.II's cell numbers, from 0)"}));
      AssertThrow(negative.empty(),
                  ExcMessage("the generated box has " +
                             std::to_string(negative.size()) +
                             " negatively oriented cells"));
    }

    /// The reader's part of create_mesh(): the whole mesh generated, or
    /// read and checked (kept as @p mesh's list of cells, partitioned into
    /// @p owner, if @p from_cells; else triangulated into @p serial, refined
    /// and partitioned). A failure is recorded in @p outcome rather than
    /// thrown, so that the other ranks learn of it; the exception other than
    /// an InputError is returned to be rethrown as it was.
    template <int dim>
    std::exception_ptr
    prepare_whole_mesh(const MeshParameters      &parameters,
                       const unsigned int         n_ranks,
                       const bool                 from_cells,
                       CheckedMesh<dim>          &mesh,
                       std::vector<unsigned int> &owner,
                       Triangulation<dim>        &serial,
                       MeshStatistics            &stats,
                       ReaderOutcome             &outcome)
    {
      std::exception_ptr reader_exception;
      stats.reader = true;
      try
        {
          if (parameters.source == MeshSource::box)
            {
              Timer timer;
              build_box(parameters, serial);
              stats.read_time = timer.wall_time();
            }
          else
            {
              mesh = read_and_check_gmsh<dim>(parameters.file, stats, &parameters);
              outcome.reoriented_cells = mesh.n_reoriented;
            }
          if (!from_cells && parameters.source != MeshSource::box)
            {
              Timer timer;
              triangulate_checked_mesh(parameters.file, mesh, serial);
              mesh = CheckedMesh<dim>();
              stats.build_time += timer.wall_time();
            }

          Timer timer;
          if (from_cells)
            {
              owner = partition_cells(mesh, n_ranks);
              std::set<types::boundary_id> ids;
              for (std::size_t i = 0; i < mesh.neighbors.size(); ++i)
                if (mesh.neighbors[i] < 0)
                  ids.insert(mesh.face_ids[i]);
              outcome.boundary_ids.assign(ids.begin(), ids.end());
              outcome.global_cells = mesh.cells.size();
            }
          else
            {
              serial.refine_global(parameters.global_refinements);
              outcome.boundary_ids = serial.get_boundary_ids();
              if (n_ranks > 1)
                GridTools::partition_triangulation(
                  n_ranks, serial, SparsityTools::Partitioner::metis);
              outcome.global_cells = serial.n_active_cells();
            }
          stats.partition_time = timer.wall_time();
        }
      catch (const InputError &e)
        {
          outcome.status  = ReaderOutcome::input_error;
          outcome.message = e.what();
        }
      catch (const std::exception &e)
        {
          outcome.status   = ReaderOutcome::other_error;
          outcome.message  = exception_message(e);
          reader_exception = std::current_exception();
        }
      catch (...)
        {
          outcome.status   = ReaderOutcome::other_error;
          outcome.message  = "unknown exception";
          reader_exception = std::current_exception();
        }
      return reader_exception;
    }

    /// The reader's @p outcome sent to every other rank; a failure thrown
    /// on every rank (on the reader as the exception it caught).
    void
    share_outcome(ReaderOutcome            &outcome,
                  const std::exception_ptr &reader_exception,
                  const bool                is_reader,
                  const unsigned int        reader,
                  const MPI_Comm            comm)
    {
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
      if (n_ranks > 1)
        {
          if (is_reader)
            {
              const std::vector<char> buffer = Utilities::pack(outcome, false);
              for (unsigned int r = 0; r < n_ranks; ++r)
                if (r != reader)
                  send(buffer, r, outcome_tag, comm);
            }
          else
            outcome = Utilities::unpack<ReaderOutcome>(
              receive(reader, outcome_tag, comm), false);
        }
      if (outcome.status == ReaderOutcome::input_error)
        throw InputError(outcome.message);
      if (outcome.status == ReaderOutcome::other_error)
        {
          if (reader_exception)
            std::rethrow_exception(reader_exception);
          throw std::runtime_error("creating the mesh failed on MPI rank " +
                                   std::to_string(reader) + ": " +
                                   outcome.message);
        }
    }
  } // namespace

  template <int dim>
  std::set<types::boundary_id>
  create_mesh(const MeshParameters                           &parameters,
              parallel::fullydistributed::Triangulation<dim> &tria,
              MeshStatistics                                 *statistics)
  {
    const MPI_Comm     comm    = tria.get_communicator();
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int reader  = 0;
    const bool is_reader = Utilities::MPI::this_mpi_process(comm) == reader;

    // The whole mesh, on the reader only: a file's checked list of cells,
    // from which the parts are described directly, or (for a box, or a
    // file to be refined) a serial triangulation.
    MeshStatistics            stats;
    CheckedMesh<dim>          mesh;
    std::vector<unsigned int> owner; // of each cell of mesh
    Triangulation<dim>        serial;
    const bool from_cells = parameters.source != MeshSource::box &&
                            parameters.global_refinements == 0;
    ReaderOutcome      outcome;
    std::exception_ptr reader_exception;
    if (is_reader)
      reader_exception = prepare_whole_mesh(
        parameters, n_ranks, from_cells, mesh, owner, serial, stats, outcome);

    // The other ranks wait for the outcome first, so that a failure of the
    // reader reaches them as the same exception.
    Timer timer;
    share_outcome(outcome, reader_exception, is_reader, reader, comm);

    // The reader makes and sends one description per rank, one at a time
    // (as TriangulationDescription::Utilities::
    // create_description_from_triangulation_in_groups() does for a single
    // group), the others first, so that they build their part while it
    // makes its own; then it frees the whole mesh.
    stats.wait_time = timer.wall_time();
    timer.restart();
    stats.serial_cells  = is_reader ? outcome.global_cells : 0;
    const auto describe = [&](const unsigned int rank) {
      return from_cells
               ? describe_part(mesh, owner, rank, comm)
               : TriangulationDescription::Utilities::
                   create_description_from_triangulation(
                     serial,
                     comm,
                     TriangulationDescription::Settings::default_setting,
                     rank);
    };
    TriangulationDescription::Description<dim, dim> description;
    if (is_reader)
      {
        for (unsigned int r = 0; r < n_ranks; ++r)
          if (r != reader)
            send(Utilities::pack(describe(r), false), r, description_tag, comm);
        description = describe(reader);
        mesh        = CheckedMesh<dim>();
        serial.clear();
      }
    else
      {
        description =
          Utilities::unpack<TriangulationDescription::Description<dim, dim>>(
            receive(reader, description_tag, comm), false);
        description.comm = comm; // not serialized
      }
    stats.describe_time = timer.wall_time();
    timer.restart();
    stats.description_coarse_cells = description.coarse_cells.size();
    tria.create_triangulation(description);
    mark_partition_edges(description, tria);
    stats.distribute_time  = timer.wall_time();
    stats.global_cells     = outcome.global_cells;
    stats.reoriented_cells = outcome.reoriented_cells;
    if (statistics)
      *statistics = stats;
    return std::set<types::boundary_id>(outcome.boundary_ids.begin(),
                                        outcome.boundary_ids.end());
  }

  template <int dim>
  std::set<types::boundary_id>
  create_serial_mesh(const MeshParameters     &parameters,
                     SerialTriangulation<dim> &tria,
                     MeshStatistics           *statistics)
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(tria.get_communicator()) == 1,
                ExcMessage("a serial triangulation is for one MPI rank"));
    MeshStatistics stats;
    stats.reader = true;
    if (parameters.source == MeshSource::box)
      {
        Timer timer;
        build_box(parameters, tria);
        stats.read_time = timer.wall_time();
      }
    else
      {
        CheckedMesh<dim> mesh =
          read_and_check_gmsh<dim>(parameters.file, stats, &parameters);
        stats.reoriented_cells = mesh.n_reoriented;
        Timer timer;
        // Nodes no cell uses (gmsh files may list them) are dropped, as the
        // description of the distributed path drops them.
        GridTools::delete_unused_vertices(mesh.vertices,
                                          mesh.cells,
                                          mesh.boundary);
        triangulate_checked_mesh(parameters.file, mesh, tria);
        stats.distribute_time = timer.wall_time();
      }
    Timer timer;
    tria.refine_global(parameters.global_refinements);
    stats.partition_time   = timer.wall_time();
    stats.global_cells     = tria.n_active_cells();
    stats.serial_cells     = stats.global_cells;
    if (statistics)
      *statistics = stats;
    const std::vector<types::boundary_id> ids = tria.get_boundary_ids();
    return std::set<types::boundary_id>(ids.begin(), ids.end());
  }

  template void
  set_box_boundary_ids(Triangulation<2> &);
  template void
  set_box_boundary_ids(Triangulation<3> &);
  template std::set<types::boundary_id>
  create_mesh(const MeshParameters &,
              parallel::fullydistributed::Triangulation<2> &,
              MeshStatistics *);
  template std::set<types::boundary_id>
  create_mesh(const MeshParameters &,
              parallel::fullydistributed::Triangulation<3> &,
              MeshStatistics *);
  template std::set<types::boundary_id>
  create_serial_mesh(const MeshParameters &,
                     SerialTriangulation<2> &,
                     MeshStatistics *);
  template std::set<types::boundary_id>
  create_serial_mesh(const MeshParameters &,
                     SerialTriangulation<3> &,
                     MeshStatistics *);
} // namespace hyperelastic
