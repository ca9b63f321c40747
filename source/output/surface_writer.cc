// The OBJ/PLY surface sequence: the topology gathered once, then per frame
// the vertex displacements gathered to rank 0, which writes the file.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/output/surface_writer.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <numeric>
#include <sstream>
#include <tuple>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// Whether a comes before b in the order x, then y, then z.
    template <int dim>
    bool
    lexicographically_less(const Point<dim> &a, const Point<dim> &b)
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (a[d] != b[d])
          return a[d] < b[d];
      return false;
    }

    /// The triangle's vertices rotated so that the smallest comes first
    /// (the same cyclic order, so the same orientation).
    std::array<unsigned int, 3>
    rotated(const std::array<unsigned int, 3> &t)
    {
      const unsigned int k = std::min_element(t.begin(), t.end()) - t.begin();
      return {{t[k], t[(k + 1) % 3], t[(k + 2) % 3]}};
    }
  } // namespace

  template <int dim>
  SurfaceWriter<dim>::SurfaceWriter(const DoFHandler<dim> &dof_handler,
                                    const SurfaceFormat    format,
                                    const std::string     &directory,
                                    const std::string     &base_name)
      : comm(dof_handler.get_communicator())
      , format(format)
      , directory(directory)
      , base_name(base_name)
  {
    const auto &fe = dof_handler.get_fe();
    // This rank's corners: the reference position, the displacement dofs
    // and a key naming the vertex in this run (its x dof).
    std::vector<double>                   positions;
    std::vector<types::global_dof_index>  keys;
    std::vector<types::global_dof_index>  cell_dofs(fe.dofs_per_cell);
    const auto add_triangle = [&](const auto                        &cell,
                                  std::array<unsigned int, 3> corner) {
      // Counter-clockwise seen from outside (3D) or from +z (2D).
      const Point<dim> X0 = cell->vertex(corner[0]);
      const Point<dim> X1 = cell->vertex(corner[1]);
      const Point<dim> X2 = cell->vertex(corner[2]);
      bool             flip;
      if constexpr (dim == 3)
        {
          const Tensor<1, 3> normal = cross_product_3d(X1 - X0, X2 - X0);
          flip = normal * ((X0 + X1 + X2) / 3. - cell->center()) < 0.;
        }
      else
        {
          const Tensor<1, 2> a = X1 - X0, b = X2 - X0;
          flip                 = a[0] * b[1] - a[1] * b[0] < 0.;
        }
      if (flip)
        std::swap(corner[1], corner[2]);
      for (const unsigned int v : corner)
        {
          std::array<types::global_dof_index, dim> dofs;
          for (unsigned int c = 0; c < dim; ++c)
            dofs[c] = cell_dofs[fe.component_to_system_index(c, v)];
          corner_dofs.push_back(dofs);
          corner_cells.push_back(cell->active_cell_index());
          keys.push_back(dofs[0]);
          for (unsigned int d = 0; d < dim; ++d)
            positions.push_back(cell->vertex(v)[d]);
        }
    };
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        cell->get_dof_indices(cell_dofs);
        if constexpr (dim == 2)
          add_triangle(cell, {{0, 1, 2}});
        else
          for (const unsigned int f : cell->face_indices())
            {
              if (!cell->face(f)->at_boundary())
                continue;
              std::array<unsigned int, 3> corner;
              for (unsigned int i = 0; i < 3; ++i)
                for (const unsigned int v : cell->vertex_indices())
                  if (cell->vertex_index(v) == cell->face(f)->vertex_index(i))
                    corner[i] = v;
              add_triangle(cell, corner);
            }
      }

    const auto all_positions = Utilities::MPI::gather(comm, positions, 0);
    const auto all_keys      = Utilities::MPI::gather(comm, keys, 0);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        // One vertex per key, numbered in the order of their positions.
        std::map<types::global_dof_index, Point<dim>> vertex_at;
        for (unsigned int r = 0; r < all_keys.size(); ++r)
          for (unsigned int i = 0; i < all_keys[r].size(); ++i)
            {
              Point<dim> X;
              for (unsigned int d = 0; d < dim; ++d)
                X[d] = all_positions[r][i * dim + d];
              vertex_at.emplace(all_keys[r][i], X);
            }
        std::vector<std::pair<Point<dim>, types::global_dof_index>> vertices;
        for (const auto &[key, X] : vertex_at)
          vertices.emplace_back(X, key);
        std::stable_sort(vertices.begin(),
                         vertices.end(),
                         [](const auto &a, const auto &b) {
                           return lexicographically_less(a.first, b.first);
                         });
        std::map<types::global_dof_index, unsigned int> number;
        for (unsigned int k = 0; k < vertices.size(); ++k)
          {
            number[vertices[k].second] = k;
            reference.push_back(vertices[k].first);
          }
        corner_vertex.resize(all_keys.size());
        for (unsigned int r = 0; r < all_keys.size(); ++r)
          for (unsigned int i = 0; i < all_keys[r].size(); ++i)
            {
              corner_vertex[r].push_back(number.at(all_keys[r][i]));
              if (i % 3 == 2)
                triangles.push_back(rotated({{corner_vertex[r][i - 2],
                                              corner_vertex[r][i - 1],
                                              corner_vertex[r][i]}}));
            }
        std::sort(triangles.begin(), triangles.end());
        n_surface_vertices  = reference.size();
        n_surface_triangles = triangles.size();
      }
    n_surface_vertices  = Utilities::MPI::broadcast(comm, n_surface_vertices, 0);
    n_surface_triangles = Utilities::MPI::broadcast(comm, n_surface_triangles, 0);
  }

  template <int dim>
  std::string
  SurfaceWriter<dim>::file(const unsigned int frame) const
  {
    return directory + "/" + base_name + "_surface_" +
           Utilities::int_to_string(frame, 4) +
           (format == SurfaceFormat::ply ? ".ply" : ".obj");
  }

  template <int dim>
  void
  SurfaceWriter<dim>::write(const unsigned int                   frame,
                            const double                         t,
                            const TrilinosWrappers::MPI::Vector &u,
                            const Vector<double>                *von_mises) const
  {
    // Per corner: the displacement, then the cell's von Mises stress.
    const unsigned int  stride = dim + 1;
    std::vector<double> values(corner_dofs.size() * stride);
    for (unsigned int i = 0; i < corner_dofs.size(); ++i)
      {
        for (unsigned int c = 0; c < dim; ++c)
          values[i * stride + c] = u[corner_dofs[i][c]];
        values[i * stride + dim] =
          von_mises ? (*von_mises)[corner_cells[i]] : 0.;
      }
    const auto  all_values = Utilities::MPI::gather(comm, values, 0);
    std::string error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::vector<Point<dim>> x = reference;
        std::vector<double>     stress(x.size(), 0.);
        std::vector<unsigned>   count(x.size(), 0);
        for (unsigned int r = 0; r < all_values.size(); ++r)
          for (unsigned int i = 0; i < corner_vertex[r].size(); ++i)
            {
              const unsigned int k = corner_vertex[r][i];
              for (unsigned int c = 0; c < dim; ++c)
                x[k][c] = reference[k][c] + all_values[r][i * stride + c];
              stress[k] += all_values[r][i * stride + dim];
              ++count[k];
            }
        std::ostringstream out;
        out << std::setprecision(15);
        const auto coordinates = [&](const Point<dim> &p) {
          out << p[0] << ' ' << p[1] << ' ' << (dim == 3 ? p[dim - 1] : 0.);
        };
        if (format == SurfaceFormat::obj)
          {
            out << "# hyperelastic deformed " << (dim == 3 ? "boundary " : "")
                << "surface, frame " << frame << ", t = " << t << "\n";
            for (const auto &p : x)
              {
                out << "v ";
                coordinates(p);
                out << '\n';
              }
            for (const auto &tri : triangles)
              out << "f " << tri[0] + 1 << ' ' << tri[1] + 1 << ' '
                  << tri[2] + 1 << '\n';
          }
        else
          {
            out << "ply\nformat ascii 1.0\n"
                << "comment hyperelastic deformed surface, frame " << frame
                << ", t = " << t << "\nelement vertex " << x.size()
                << "\nproperty double x\nproperty double y\nproperty double z"
                << (von_mises ? "\nproperty double von_mises" : "")
                << "\nelement face " << triangles.size()
                << "\nproperty list uchar int vertex_indices\nend_header\n";
            for (unsigned int k = 0; k < x.size(); ++k)
              {
                coordinates(x[k]);
                if (von_mises)
                  out << ' ' << stress[k] / std::max(count[k], 1u);
                out << '\n';
              }
            for (const auto &tri : triangles)
              out << "3 " << tri[0] << ' ' << tri[1] << ' ' << tri[2] << '\n';
          }
        // Written then renamed: a reader never sees half a frame.
        const std::string name = file(frame), partial = name + ".partial";
        {
          std::ofstream stream(partial);
          stream << out.str();
          if (!stream)
            error = "cannot write '" + partial + "' (Output/Directory)";
        }
        std::error_code ec;
        if (error.empty())
          std::filesystem::rename(partial, name, ec);
        if (ec)
          error = "cannot rename '" + partial + "': " + ec.message();
      }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
  }

  template class SurfaceWriter<2>;
  template class SurfaceWriter<3>;
} // namespace hyperelastic
