// Partition and distribution of a checked mesh: METIS on the graph of face
// neighbours, the description of each rank's part (its cells and the ghost
// layer), and the messages by which the reader (rank 0) sends its outcome
// and the descriptions to the other ranks, who poll for them.
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <hyperelastic/mesh/mesh_distribution.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  std::vector<unsigned int>
  partition_cells(const CheckedMesh<dim> &mesh, const unsigned int n_parts)
  {
    const unsigned int        n = mesh.cells.size();
    std::vector<unsigned int> owner(n, 0);
    if (n_parts == 1)
      return owner;
    // Each row: the cell itself and its face neighbours (the sparsity
    // pattern sorts the columns, as when copied from the
    // DynamicSparsityPattern that GridTools builds).
    std::vector<unsigned int> row_lengths(n, 1);
    for (unsigned int c = 0; c < n; ++c)
      for (unsigned int f = 0; f <= dim; ++f)
        row_lengths[c] += mesh.neighbors[c * (dim + 1) + f] >= 0 ? 1 : 0;
    SparsityPattern pattern(n, n, row_lengths);
    for (unsigned int c = 0; c < n; ++c)
      {
        pattern.add(c, c);
        for (unsigned int f = 0; f <= dim; ++f)
          {
            const int j = mesh.neighbors[c * (dim + 1) + f];
            if (j >= 0)
              pattern.add(c, j);
          }
      }
    pattern.compress();
    SparsityTools::partition(pattern,
                             std::vector<unsigned int>(),
                             n_parts,
                             owner,
                             SparsityTools::Partitioner::metis);
    return owner;
  }

  template <int dim>
  TriangulationDescription::Description<dim, dim>
  describe_part(const CheckedMesh<dim>          &mesh,
                const std::vector<unsigned int> &owner,
                const unsigned int               rank,
                const MPI_Comm                   comm)
  {
    constexpr unsigned int n_faces = dim + 1;
    const unsigned int     n       = mesh.cells.size();
    std::vector<char>      near(mesh.vertices.size(), 0);
    for (unsigned int c = 0; c < n; ++c)
      if (owner[c] == rank)
        for (const unsigned int v : mesh.cells[c].vertices)
          near[v] = 1;
    std::vector<unsigned int> relevant;
    std::vector<unsigned int> local(mesh.vertices.size(),
                                    numbers::invalid_unsigned_int);
    for (unsigned int c = 0; c < n; ++c)
      {
        bool is_relevant = false;
        for (const unsigned int v : mesh.cells[c].vertices)
          is_relevant = is_relevant || near[v] != 0;
        if (is_relevant)
          {
            relevant.push_back(c);
            for (const unsigned int v : mesh.cells[c].vertices)
              local[v] = 0;
          }
      }

    TriangulationDescription::Description<dim, dim> description;
    description.comm      = comm;
    description.settings  = TriangulationDescription::Settings::default_setting;
    description.smoothing = Triangulation<dim>::none;
    unsigned int n_local  = 0;
    for (unsigned int v = 0; v < mesh.vertices.size(); ++v)
      if (local[v] == 0)
        {
          local[v] = n_local++;
          description.coarse_cell_vertices.push_back(mesh.vertices[v]);
        }
    description.coarse_cells.reserve(relevant.size());
    description.coarse_cell_index_to_coarse_cell_id.reserve(relevant.size());
    description.cell_infos.resize(1);
    description.cell_infos[0].reserve(relevant.size());
    for (const unsigned int c : relevant)
      {
        CellData<dim> cell(dim + 1);
        for (unsigned int k = 0; k <= dim; ++k)
          cell.vertices[k] = local[mesh.cells[c].vertices[k]];
        cell.material_id = mesh.cells[c].material_id;
        cell.manifold_id = numbers::flat_manifold_id;
        description.coarse_cells.push_back(std::move(cell));
        description.coarse_cell_index_to_coarse_cell_id.push_back(c);

        TriangulationDescription::CellData<dim> info;
        info.id = CellId(c, std::vector<std::uint8_t>()).to_binary<dim>();
        info.subdomain_id       = owner[c];
        info.level_subdomain_id = 0;
        info.manifold_id        = numbers::flat_manifold_id;
        info.manifold_line_ids.fill(numbers::flat_manifold_id);
        info.manifold_quad_ids.fill(numbers::flat_manifold_id);
        for (unsigned int f = 0; f < n_faces; ++f)
          if (mesh.neighbors[c * n_faces + f] < 0)
            info.boundary_ids.emplace_back(f, mesh.face_ids[c * n_faces + f]);
        description.cell_infos[0].push_back(std::move(info));
      }
    return description;
  }

  template <int dim>
  void
  mark_partition_edges(
    const TriangulationDescription::Description<dim, dim> &description,
    Triangulation<dim>                                    &tria)
  {
    // (cell, face number) of every face on the mesh's boundary, for the
    // cells of every level the description lists (with a global refinement
    // the active cells are children, named by their whole CellId).
    std::set<std::pair<CellId, unsigned int>> on_boundary;
    for (const auto &level : description.cell_infos)
      for (const auto &info : level)
        for (const auto &[face, id] : info.boundary_ids)
          on_boundary.emplace(CellId(info.id), face);
    // Artificial cells (children of a refined coarse cell that neither this
    // rank owns nor sees as ghosts) are not listed and carry no dofs: they
    // are left alone.
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              on_boundary.count({cell->id(), f}) == 0)
            cell->face(f)->set_boundary_id(partition_edge_boundary_id);
  }

  void
  send(const std::vector<char> &buffer,
       const unsigned int       destination,
       const int                tag,
       const MPI_Comm           comm)
  {
    AssertThrow(buffer.size() <=
                  static_cast<std::size_t>(std::numeric_limits<int>::max()),
                ExcMessage("a mesh message of " +
                           std::to_string(buffer.size()) +
                           " bytes is too large for one MPI message: use "
                           "more ranks"));
    const int ierr = MPI_Send(buffer.data(),
                              static_cast<int>(buffer.size()),
                              MPI_CHAR,
                              destination,
                              tag,
                              comm);
    AssertThrowMPI(ierr);
  }

  std::vector<char>
  receive(const unsigned int source, const int tag, const MPI_Comm comm)
  {
    std::chrono::microseconds pause(20);
    MPI_Status                status;
    for (int found = 0;;)
      {
        const int ierr = MPI_Iprobe(source, tag, comm, &found, &status);
        AssertThrowMPI(ierr);
        if (found)
          break;
        std::this_thread::sleep_for(pause);
        pause = std::min(2 * pause, std::chrono::microseconds(2000));
      }
    int size = 0;
    MPI_Get_count(&status, MPI_CHAR, &size);
    std::vector<char> buffer(size);
    const int         ierr = MPI_Recv(
      buffer.data(), size, MPI_CHAR, source, tag, comm, MPI_STATUS_IGNORE);
    AssertThrowMPI(ierr);
    return buffer;
  }

  template std::vector<unsigned int>
  partition_cells(const CheckedMesh<2> &, const unsigned int);
  template std::vector<unsigned int>
  partition_cells(const CheckedMesh<3> &, const unsigned int);
  template void
  mark_partition_edges(const TriangulationDescription::Description<2, 2> &,
                       Triangulation<2> &);
  template void
  mark_partition_edges(const TriangulationDescription::Description<3, 3> &,
                       Triangulation<3> &);
  template TriangulationDescription::Description<2, 2>
  describe_part(const CheckedMesh<2> &,
                const std::vector<unsigned int> &,
                const unsigned int,
                const MPI_Comm);
  template TriangulationDescription::Description<3, 3>
  describe_part(const CheckedMesh<3> &,
                const std::vector<unsigned int> &,
                const unsigned int,
                const MPI_Comm);
} // namespace hyperelastic
