// Stiffness warping: the rest stiffness read into per-vertex rows once, then
// warped by the vertex rotations at every state.
#include <hyperelastic/assembly/rest_stiffness.h>
#include <hyperelastic/assembly/warped_assembler.h>
#include <hyperelastic/materials/polar_decomposition.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <unordered_map>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  WarpedAssembler<dim>::WarpedAssembler(const DoFHandler<dim>      &dof_handler,
                                        const Mapping<dim>         &mapping,
                                        const MaterialRegions<dim> &material)
      : dof_handler(dof_handler)
      , corotational(dof_handler, mapping, material)
  {
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    if (fe.degree != 1 || fe.n_components() != dim)
      throw std::logic_error(
        "stiffness warping needs P1 displacement elements");

    // The vertices of the owned and ghost cells, and which vertex and
    // component every dof there belongs to.
    std::unordered_map<types::global_dof_index,
                       std::pair<unsigned int, unsigned int>>
      dof_to_vertex;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          {
            std::array<types::global_dof_index, dim> vertex_dofs;
            for (unsigned int c = 0; c < dim; ++c)
              vertex_dofs[c] = cell->vertex_dof_index(v, c);
            if (dof_to_vertex.count(vertex_dofs[0]) != 0)
              continue;
            const unsigned int index = vertices.size();
            vertices.push_back({cell->vertex(v), vertex_dofs});
            for (unsigned int c = 0; c < dim; ++c)
              dof_to_vertex[vertex_dofs[c]] = {index, c};
          }

    MatrixType stiffness;
    assemble_rest_stiffness(dof_handler, mapping, material, stiffness);

    // The owned vertices in the order of their dofs, and their rows.
    const IndexSet owned = dof_handler.locally_owned_dofs();
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (owned.is_element(vertices[v].dofs[0]))
        rows.owned_vertices.push_back(v);
    std::sort(rows.owned_vertices.begin(),
              rows.owned_vertices.end(),
              [&](const unsigned int a, const unsigned int b) {
                return vertices[a].dofs[0] < vertices[b].dofs[0];
              });
    rows.start.push_back(0);
    for (const unsigned int i : rows.owned_vertices)
      {
        std::map<unsigned int, Tensor<2, dim>> blocks;
        for (unsigned int a = 0; a < dim; ++a)
          for (auto entry = stiffness.begin(vertices[i].dofs[a]);
               entry != stiffness.end(vertices[i].dofs[a]);
               ++entry)
            {
              const auto found = dof_to_vertex.find(entry->column());
              if (found == dof_to_vertex.end())
                throw std::logic_error("stiffness warping: a coupling of an "
                                       "owned vertex lies outside the ghost "
                                       "layer");
              blocks[found->second.first][a][found->second.second] =
                entry->value();
            }
        for (const auto &[j, block] : blocks)
          {
            if (j == i)
              rows.diagonal.push_back(rows.neighbour.size());
            rows.neighbour.push_back(j);
            rows.block.push_back(block);
          }
        rows.start.push_back(rows.neighbour.size());
      }
  }

  template <int dim>
  WarpedAssembler<dim>::~WarpedAssembler() = default;

  template <int dim>
  Tensor<2, dim>
  WarpedAssembler<dim>::rotation(const unsigned int           r,
                                 const VectorType            &u,
                                 std::vector<Tensor<1, dim>> &dx) const
  {
    const Vertex  &vi = vertices[rows.owned_vertices[r]];
    Tensor<1, dim> ui;
    for (unsigned int c = 0; c < dim; ++c)
      ui[c] = u(vi.dofs[c]);
    Tensor<2, dim> A;
    dx.resize(rows.start[r + 1] - rows.start[r]);
    for (unsigned int k = rows.start[r]; k < rows.start[r + 1]; ++k)
      {
        const Vertex        &vj = vertices[rows.neighbour[k]];
        Tensor<1, dim>       d  = vj.X - vi.X;
        const Tensor<1, dim> dX = d;
        for (unsigned int c = 0; c < dim; ++c)
          d[c] += u(vj.dofs[c]) - ui[c];
        dx[k - rows.start[r]] = d;
        A += outer_product(d, dX);
      }
    if (A.norm() == 0.)
      return unit_symmetric_tensor<dim>();
    return polar_decomposition(A).R;
  }

  template <int dim>
  Tensor<1, dim>
  WarpedAssembler<dim>::force(const unsigned int                 r,
                              const Tensor<2, dim>              &R,
                              const std::vector<Tensor<1, dim>> &dx,
                              double &magnitude) const
  {
    const Vertex  &vi = vertices[rows.owned_vertices[r]];
    Tensor<1, dim> f;
    magnitude = 0.;
    for (unsigned int k = rows.start[r]; k < rows.start[r + 1]; ++k)
      {
        const Tensor<1, dim> &d  = dx[k - rows.start[r]];
        const Tensor<1, dim>  dX = vertices[rows.neighbour[k]].X - vi.X;
        f += rows.block[k] * (transpose(R) * d - dX);
        magnitude += rows.block[k].norm() * d.norm();
      }
    return R * f;
  }

  template <int dim>
  double
  WarpedAssembler<dim>::internal_forces(const VectorType &u,
                                        VectorType       &internal) const
  {
    std::vector<Tensor<1, dim>> dx;
    double                      force_squared = 0., magnitude = 0.;
    for (unsigned int r = 0; r < rows.owned_vertices.size(); ++r)
      {
        const Tensor<2, dim> R = rotation(r, u, dx);
        const Tensor<1, dim> f = force(r, R, dx, magnitude);
        for (unsigned int c = 0; c < dim; ++c)
          internal[vertices[rows.owned_vertices[r]].dofs[c]] = f[c];
        force_squared += magnitude * magnitude;
      }
    internal.compress(VectorOperation::insert);
    return std::numeric_limits<double>::epsilon() *
           std::sqrt(Utilities::MPI::sum(force_squared,
                                         dof_handler.get_communicator()));
  }

  template <int dim>
  bool
  WarpedAssembler<dim>::system(const VectorType                &u,
                               const AffineConstraints<double> &constraints,
                               TangentProjection /*project_tangent*/,
                               MatrixType &matrix,
                               VectorType &rhs) const
  {
    matrix = 0.;
    rhs    = 0.;
    std::vector<Tensor<1, dim>>          dx;
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    std::vector<Tensor<2, dim>>          warped;
    double                               magnitude = 0.;
    for (unsigned int r = 0; r < rows.owned_vertices.size(); ++r)
      {
        const Tensor<2, dim> R  = rotation(r, u, dx);
        const Tensor<1, dim> f  = force(r, R, dx, magnitude);
        const Vertex        &vi = vertices[rows.owned_vertices[r]];
        warped.clear();
        for (unsigned int k = rows.start[r]; k < rows.start[r + 1]; ++k)
          warped.push_back(R * rows.block[k] * transpose(R));
        for (unsigned int a = 0; a < dim; ++a)
          {
            const types::global_dof_index row = vi.dofs[a];
            if (constraints.is_constrained(row))
              {
                // d du_r = d g_r with d the row's rest diagonal.
                const double d = rows.block[rows.diagonal[r]][a][a];
                matrix.add(row, row, d);
                rhs[row] = d * constraints.get_inhomogeneity(row);
                continue;
              }
            // Row a of the blocks R K_ij R^T.
            columns.clear();
            values.clear();
            for (unsigned int k = rows.start[r]; k < rows.start[r + 1]; ++k)
              for (unsigned int b = 0; b < dim; ++b)
                {
                  columns.push_back(vertices[rows.neighbour[k]].dofs[b]);
                  values.push_back(warped[k - rows.start[r]][a][b]);
                }
            const double moved = condense_row(constraints, columns, values);
            matrix.add(row, columns.size(), columns.data(), values.data());
            rhs[row] = -f[a] - moved;
          }
      }
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::insert);
    return true;
  }

  template <int dim>
  EnergyEvaluation
  WarpedAssembler<dim>::stored_energy(const VectorType &u,
                                      const bool        with_energy) const
  {
    return corotational.stored_energy(u, with_energy);
  }

  template <int dim>
  std::vector<Tensor<2, dim>>
  WarpedAssembler<dim>::vertex_rotations(const VectorType &u) const
  {
    std::vector<Tensor<2, dim>> rotations;
    std::vector<Tensor<1, dim>> dx;
    for (unsigned int r = 0; r < rows.owned_vertices.size(); ++r)
      rotations.push_back(rotation(r, u, dx));
    return rotations;
  }

  template class WarpedAssembler<2>;
  template class WarpedAssembler<3>;
} // namespace hyperelastic
