// The connected parts of a distributed mesh: a union-find over the vertices
// of each rank's cells, joined across ranks through the vertices they share.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/bodies.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// Union-find with path halving.
    struct Components
    {
      std::vector<unsigned int> parent;

      unsigned int
      add()
      {
        parent.push_back(parent.size());
        return parent.size() - 1;
      }

      unsigned int
      root(unsigned int i)
      {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      }

      void
      join(const unsigned int a, const unsigned int b)
      {
        const unsigned int ra = root(a), rb = root(b);
        if (ra != rb)
          parent[std::max(ra, rb)] = std::min(ra, rb);
      }
    };

    /// The bodies from the components of every rank: rank r's are
    /// @p all_info[r] (volume tag, held, box per component), numbered from
    /// @p offset[r] on in @p global, which joined those of one body. In an
    /// order that does not depend on the partition.
    template <int dim>
    std::vector<Body<dim>>
    merge_components(const std::vector<std::vector<double>> &all_info,
                     const std::vector<unsigned int>        &offset,
                     Components                             &global,
                     std::map<unsigned int, unsigned int>   &index_of_root)
    {
      // Merge the components of each body.
      std::map<unsigned int, Body<dim>> merged;
      for (unsigned int r = 0; r < all_info.size(); ++r)
        for (unsigned int k = 0; offset[r] + k < offset[r + 1]; ++k)
          {
            const double *c = &all_info[r][k * (2 + 2 * dim)];
            Point<dim>    lower, upper;
            for (unsigned int d = 0; d < dim; ++d)
              lower[d] = c[2 + d], upper[d] = c[2 + dim + d];
            const BoundingBox<dim> box(std::make_pair(lower, upper));
            auto [it, fresh] =
              merged.emplace(global.root(offset[r] + k), Body<dim>());
            Body<dim> &b = it->second;
            if (fresh)
              {
                b.volume_tag = static_cast<types::material_id>(c[0]);
                b.box        = box;
              }
            else
              {
                b.volume_tag = std::min<types::material_id>(b.volume_tag, c[0]);
                b.box.merge_with(box);
              }
            b.held = b.held || c[1] > 0.;
          }
      // In an order that does not depend on the partition: by volume tag,
      // then by the boxes' lower corners.
      const auto key = [](const Body<dim> &b) {
        std::array<double, dim + 1> k;
        k[0] = b.volume_tag;
        for (unsigned int d = 0; d < dim; ++d)
          k[d + 1] = b.box.get_boundary_points().first[d];
        return k;
      };
      std::vector<unsigned int> roots;
      for (const auto &[root, body] : merged)
        roots.push_back(root);
      std::sort(roots.begin(), roots.end(), [&](const auto a, const auto b) {
        return key(merged.at(a)) < key(merged.at(b));
      });
      std::vector<Body<dim>> bodies;
      for (const unsigned int root : roots)
        {
          index_of_root[root] = bodies.size();
          bodies.push_back(merged.at(root));
        }
      return bodies;
    }
  } // namespace

  template <int dim>
  std::string
  Body<dim>::describe(const unsigned int k) const
  {
    std::ostringstream s;
    s << "body " << k << " (volume tag "
      << static_cast<unsigned int>(volume_tag) << ", bounding box ("
      << box.get_boundary_points().first << ") to ("
      << box.get_boundary_points().second << "))";
    return s.str();
  }

  template <int dim>
  std::vector<Body<dim>>
  find_bodies(const DoFHandler<dim>              &dof_handler,
              const std::set<types::boundary_id> &dirichlet_ids,
              std::vector<unsigned int>          *body_of_cell)
  {
    const MPI_Comm comm = dof_handler.get_communicator();
    // The vertices of the owned cells (by their first dof), joined per cell.
    std::map<types::global_dof_index, unsigned int> vertex;
    Components                                      local;
    const auto id = [&](const auto &cell, const unsigned int v) {
      const types::global_dof_index first = cell->vertex_dof_index(v, 0);
      auto                          it    = vertex.find(first);
      if (it == vertex.end())
        it = vertex.emplace(first, local.add()).first;
      return it->second;
    };
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          local.join(id(cell, 0), id(cell, v));

    // The local components: volume tag, box, held; numbered globally.
    std::map<unsigned int, unsigned int> component; // local root -> number
    for (const auto &[first, i] : vertex)
      component.emplace(local.root(i), component.size());
    const unsigned int  n_local = component.size();
    std::vector<double> info(n_local * (2 + 2 * dim));
    for (unsigned int c = 0; c < n_local; ++c)
      {
        info[c * (2 + 2 * dim)] = std::numeric_limits<double>::max();
        for (unsigned int d = 0; d < dim; ++d)
          {
            info[c * (2 + 2 * dim) + 2 + d] =
              std::numeric_limits<double>::max();
            info[c * (2 + 2 * dim) + 2 + dim + d] =
              -std::numeric_limits<double>::max();
          }
      }
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double *c =
            &info[component.at(local.root(id(cell, 0))) * (2 + 2 * dim)];
          c[0] = std::min<double>(c[0], cell->material_id());
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                dirichlet_ids.count(cell->face(f)->boundary_id()))
              c[1] = 1.;
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              {
                c[2 + d]       = std::min(c[2 + d], cell->vertex(v)[d]);
                c[2 + dim + d] = std::max(c[2 + dim + d], cell->vertex(v)[d]);
              }
        }
    // The vertices shared with ghost cells join components across ranks.
    std::set<types::global_dof_index> ghost_vertices;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_ghost())
        for (const unsigned int v : cell->vertex_indices())
          ghost_vertices.insert(cell->vertex_dof_index(v, 0));
    std::vector<types::global_dof_index> shared; // (vertex, component) pairs
    for (const auto &[first, i] : vertex)
      if (ghost_vertices.count(first))
        {
          shared.push_back(first);
          shared.push_back(component.at(local.root(i)));
        }
    const auto all_info   = Utilities::MPI::all_gather(comm, info);
    const auto all_shared = Utilities::MPI::all_gather(comm, shared);
    std::vector<unsigned int> offset(all_info.size() + 1, 0);
    for (unsigned int r = 0; r < all_info.size(); ++r)
      offset[r + 1] = offset[r] + all_info[r].size() / (2 + 2 * dim);
    Components global;
    for (unsigned int c = 0; c < offset.back(); ++c)
      global.add();
    std::map<types::global_dof_index, unsigned int> first_seen;
    for (unsigned int r = 0; r < all_shared.size(); ++r)
      for (std::size_t i = 0; i < all_shared[r].size(); i += 2)
        {
          const unsigned int c   = offset[r] + all_shared[r][i + 1];
          const auto [it, fresh] = first_seen.emplace(all_shared[r][i], c);
          if (!fresh)
            global.join(it->second, c);
        }

    std::map<unsigned int, unsigned int> index_of_root;
    std::vector<Body<dim>>               bodies =
      merge_components<dim>(all_info, offset, global, index_of_root);
    if (body_of_cell)
      {
        // This rank's component c is global component offset[rank] + c.
        const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
        body_of_cell->assign(dof_handler.get_triangulation().n_active_cells(),
                             numbers::invalid_unsigned_int);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            (*body_of_cell)[cell->active_cell_index()] = index_of_root.at(
              global.root(offset[rank] + component.at(local.root(id(cell, 0)))));
      }
    return bodies;
  }

  template <int dim>
  void
  check_supports(const DoFHandler<dim>              &dof_handler,
                 const std::set<types::boundary_id> &dirichlet_ids,
                 const bool                          contact_may_hold,
                 const unsigned int                  max_sections)
  {
    // Contact may hold bodies without a Dirichlet condition (a body
    // squeezed between plates): the rigid motions nothing resists are then
    // removed from each Newton update (UnheldRigidMotions).
    if (contact_may_hold)
      return;
    if (dirichlet_ids.empty())
      throw InputError("no Dirichlet condition is set (sections 'Dirichlet 1' "
                       "... 'Dirichlet " +
                       std::to_string(max_sections) +
                       "') and no contact can hold the body: rigid-body "
                       "motions would be free and the quasi-static problem "
                       "singular (in dynamics, 'Time integration/Scheme', the "
                       "mass makes it regular)");
    // Each body must be held: a mesh may hold several (a body clamped,
    // another pressed onto it).
    const std::vector<Body<dim>> bodies = find_bodies(dof_handler, dirichlet_ids);
    for (unsigned int k = 0; k < bodies.size(); ++k)
      if (!bodies[k].held)
        throw InputError(
          bodies[k].describe(k + 1) + " of the mesh's " +
          std::to_string(bodies.size()) +
          " has neither a Dirichlet condition nor a possible contact: it "
          "could move as a rigid body and the quasi-static problem is "
          "singular. Give one of its boundary faces a Dirichlet condition, "
          "or let contact hold it ('Contact/Self contact' or an obstacle)");
  }

  template struct Body<2>;
  template struct Body<3>;
  template void
  check_supports(const DoFHandler<2> &,
                 const std::set<types::boundary_id> &,
                 bool,
                 unsigned int);
  template void
  check_supports(const DoFHandler<3> &,
                 const std::set<types::boundary_id> &,
                 bool,
                 unsigned int);
  template std::vector<Body<2>>
  find_bodies(const DoFHandler<2> &,
              const std::set<types::boundary_id> &,
              std::vector<unsigned int> *);
  template std::vector<Body<3>>
  find_bodies(const DoFHandler<3> &,
              const std::set<types::boundary_id> &,
              std::vector<unsigned int> *);
} // namespace hyperelastic
