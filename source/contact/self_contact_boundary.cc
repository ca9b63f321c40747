// The boundary that SelfContact works on: every rank's owned boundary
// vertices gathered to all, the boundary faces (3D: and edges) with their
// shares of the boundary's measure, and their incidence.
#include <deal.II/base/mpi.h>

#include <hyperelastic/contact/self_contact.h>
#include <hyperelastic/mesh/mesh_distribution.h>

#include <map>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  std::vector<types::global_dof_index>
  SelfContact<dim>::gather_vertices(const DoFHandler<dim> &dof_handler)
  {
    // The owned boundary vertices (ghost cells too: an owned vertex may lie
    // only on a neighbour's boundary face) and the boundary faces of the
    // owned cells, as first dofs; the faces where the ghost layer ends are
    // not the body's boundary.
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    std::map<types::global_dof_index, std::vector<double>> mine;
    std::vector<types::global_dof_index>                   my_faces;
    for_each_boundary_face(
      dof_handler, [&](const auto &cell, const auto &face) {
        for (unsigned int v = 0; v < face->n_vertices(); ++v)
          {
            const types::global_dof_index first = face->vertex_dof_index(v, 0);
            if (cell->is_locally_owned())
              my_faces.push_back(first);
            if (!owned.is_element(first) || mine.count(first))
              continue;
            std::vector<double> &data = mine[first];
            for (unsigned int d = 0; d < dim; ++d)
              data.push_back(face->vertex(v)[d]);
            for (unsigned int d = 0; d < dim; ++d)
              data.push_back(face->vertex_dof_index(v, d));
          }
      });
    std::vector<double> packed;
    for (const auto &[first, data] : mine)
      packed.insert(packed.end(), data.begin(), data.end());
    const std::vector<std::vector<double>> all_vertices =
      Utilities::MPI::all_gather(comm, packed);
    for (unsigned int r = 0; r < all_vertices.size(); ++r)
      {
        if (r == rank)
          first_owned = vertices.size();
        for (std::size_t i = 0; i < all_vertices[r].size(); i += 2 * dim)
          {
            Vertex v;
            for (unsigned int d = 0; d < dim; ++d)
              {
                v.X[d]    = all_vertices[r][i + d];
                v.dofs[d] = static_cast<types::global_dof_index>(
                  all_vertices[r][i + dim + d]);
              }
            v.owner = r;
            vertices.push_back(v);
          }
        if (r == rank)
          n_owned = vertices.size() - first_owned;
      }
    return my_faces;
  }

  template <int dim>
  void
  SelfContact<dim>::build_faces(
    const std::vector<types::global_dof_index> &my_faces)
  {
    // The faces, and their measures shared by their vertices (edges: a
    // third of each adjacent triangle).
    const std::vector<std::vector<types::global_dof_index>> all_faces =
      Utilities::MPI::all_gather(comm, my_faces);
    std::map<types::global_dof_index, unsigned int> index;
    for (unsigned int k = 0; k < vertices.size(); ++k)
      index.emplace(vertices[k].dofs[0], k);
    std::map<std::array<unsigned int, 2>, unsigned int> edge_index;
    for (const auto &list : all_faces)
      for (std::size_t i = 0; i < list.size(); i += dim)
        {
          std::array<unsigned int, dim> face;
          for (unsigned int d = 0; d < dim; ++d)
            face[d] = index.at(list[i + d]);
          double measure = vertices[face[0]].X.distance(vertices[face[1]].X);
          if constexpr (dim == 3)
            measure =
              0.5 * cross_product_3d(vertices[face[1]].X - vertices[face[0]].X,
                                     vertices[face[2]].X - vertices[face[0]].X)
                      .norm();
          for (const unsigned int v : face)
            vertices[v].area += measure / dim;
          for (unsigned int k = 0; k < dim; ++k)
            longest_edge = std::max(longest_edge,
                                    vertices[face[k]].X.distance(
                                      vertices[face[(k + 1) % dim]].X));
          faces.push_back(face);
          if constexpr (dim == 3)
            for (unsigned int k = 0; k < 3; ++k)
              {
                std::array<unsigned int, 2> e = {
                  {std::min(face[k], face[(k + 1) % 3]),
                   std::max(face[k], face[(k + 1) % 3])}};
                auto it = edge_index.find(e);
                if (it == edge_index.end())
                  {
                    it = edge_index.emplace(e, edges.size()).first;
                    edges.push_back(e);
                    edge_area.push_back(0.);
                    edge_length2.push_back(
                      vertices[e[0]].X.distance_square(vertices[e[1]].X));
                  }
                edge_area[it->second] += measure / 3.;
              }
        }
    std::vector<std::array<double, dim>> points(vertices.size());
    for (unsigned int k = 0; k < vertices.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        points[k][d] = vertices[k].X[d];
    incidence = BoundaryIncidence<dim>(faces, points);
  }

  template class SelfContact<2>;
  template class SelfContact<3>;
} // namespace hyperelastic
