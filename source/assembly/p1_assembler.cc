// The P1 kernel: precomputed hat-function gradients and volumes, F from the
// nodal values, closed-form element forces and tangent written straight into
// the owned rows of the Trilinos matrix.
#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>

#include <hyperelastic/assembly/material_point.h>
#include <hyperelastic/assembly/p1_assembler.h>
#include <hyperelastic/base/error_handling.h>

#include <Epetra_CrsMatrix.h>
#include <cmath>
#include <limits>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    using TrilinosIndex = TrilinosWrappers::types::int_type;

    constexpr double not_prescribed = std::numeric_limits<double>::quiet_NaN();
  } // namespace

  template <int dim>
  P1Assembler<dim>::P1Assembler(const DoFHandler<dim>      &dof_handler,
                                const MaterialRegions<dim> &material)
      : dof_handler(dof_handler)
      , material(material)
      , materials(material, dof_handler)
  {
    const FiniteElement<dim> &fe    = dof_handler.get_fe();
    const IndexSet            owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    n_owned   = owned.n_elements();
    n_ghosted = relevant.n_elements();
    bool ok   = fe.degree == 1 && fe.n_components() == dim &&
              fe.n_dofs_per_vertex() == dim &&
              fe.n_dofs_per_cell() == dim * n_nodes && owned.is_contiguous() &&
              dof_handler.get_triangulation().all_reference_cells_are_simplex();
    if (ok && n_owned > 0)
      {
        first_owned             = *owned.begin();
        owned_offset_in_ghosted = relevant.index_within_set(first_owned);
      }

    prescribed_owned.reinit(owned, dof_handler.get_communicator());
    prescribed_ghosted.reinit(owned, relevant, dof_handler.get_communicator());
    if (ok)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            Cell           c;
            Tensor<2, dim> Dm; // columns: edges from vertex 0
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int i = 0; i < dim; ++i)
                Dm[i][d] = cell->vertex(d + 1)[i] - cell->vertex(0)[i];
            const double         det    = determinant(Dm);
            const Tensor<2, dim> Dm_inv = invert(Dm);
            c.volume                    = std::abs(det) / (dim == 2 ? 2. : 6.);
            // x = x_0 + Dm xi and N_a = xi_(a-1): grad N_a is row a-1 of
            // Dm^-1; the hat functions sum to one.
            c.grad[0] = Tensor<1, dim>();
            for (unsigned int a = 1; a < n_nodes; ++a)
              {
                c.grad[a] = Dm_inv[a - 1];
                c.grad[0] -= c.grad[a];
              }
            for (unsigned int v = 0; v < n_nodes; ++v)
              {
                const types::global_dof_index first =
                  cell->vertex_dof_index(v, 0);
                for (unsigned int i = 1; i < dim; ++i)
                  ok = ok && cell->vertex_dof_index(v, i) == first + i;
                c.node[v] = relevant.index_within_set(first);
                c.row[v]  = owned.is_element(first)
                              ? static_cast<int>(first - first_owned)
                              : -1;
              }
            c.owned        = cell->is_locally_owned();
            c.active_index = cell->active_cell_index();
            c.writes_rows  = false;
            for (unsigned int v = 0; v < n_nodes; ++v)
              c.writes_rows = c.writes_rows || c.row[v] >= 0;
            if (c.owned || c.writes_rows)
              cells.push_back(c);
          }
    layout_ok =
      Utilities::MPI::min(ok ? 1 : 0, dof_handler.get_communicator()) == 1;
  }

  template <int dim>
  inline Tensor<2, dim>
  P1Assembler<dim>::deformation_gradient(const Cell &c, const double *u) const
  {
    Tensor<2, dim> F = unit_symmetric_tensor<dim>();
    for (unsigned int a = 0; a < n_nodes; ++a)
      for (unsigned int i = 0; i < dim; ++i)
        F[i] += u[c.node[a] + i] * c.grad[a];
    return F;
  }

  template <int dim>
  const double *
  P1Assembler<dim>::ghosted_values(const VectorType &u) const
  {
    // On one rank the relevant dofs are the owned ones and deal.II reports
    // no ghosts: the length of the local array is what matters.
    if (static_cast<unsigned int>(u.trilinos_vector().MyLength()) != n_ghosted)
      throw std::logic_error("P1Assembler: the displacement must be a vector "
                             "with the locally relevant dofs as ghosts");
    return u.trilinos_vector()[0];
  }

  template <int dim>
  void
  P1Assembler<dim>::report(const std::string &error,
                           const unsigned int active_index) const
  {
    std::string message;
    if (!error.empty())
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->active_cell_index() == active_index)
          {
            message = cell_failure_text(active_index, cell->center(), error);
            break;
          }
    throw_convergence_failure_if_any(message, dof_handler.get_communicator());
  }

  template <int dim>
  double
  P1Assembler<dim>::internal_forces(const VectorType &u,
                                    VectorType       &internal) const
  {
    const double *U = ghosted_values(u);
    internal        = 0.;
    double      *f  = internal.begin();
    RoundOff     round_off(material);
    std::string  error;
    unsigned int bad_cell = 0;
    for (const Cell &c : cells)
      {
        Tensor<2, dim> F, P;
        try
          {
            F = deformation_gradient(c, U);
            P = materials(c.active_index, 0).first_piola_kirchhoff(F);
          }
        catch (const std::exception &e)
          {
            error    = exception_message(e);
            bad_cell = c.active_index;
            break;
          }
        for (unsigned int a = 0; a < n_nodes; ++a)
          if (c.row[a] >= 0)
            {
              const Tensor<1, dim> force = c.volume * (P * c.grad[a]);
              for (unsigned int i = 0; i < dim; ++i)
                f[c.row[a] + i] += force[i];
            }
        if (c.owned)
          {
            double gradient_sum = 0.;
            for (unsigned int a = 0; a < n_nodes; ++a)
              gradient_sum += dim * c.grad[a].norm();
            round_off.add_force(F, gradient_sum, c.volume);
            round_off.end_cell();
          }
      }
    report(error, bad_cell);
    return round_off.force_noise(dof_handler.get_communicator());
  }

  template <int dim>
  bool
  P1Assembler<dim>::find_block_positions(const MatrixType &matrix) const
  {
    const Epetra_CrsMatrix &E       = matrix.trilinos_matrix();
    int                    *offsets = nullptr, *indices = nullptr;
    double                 *values = nullptr;
    bool                    ok     = E.StorageOptimized() &&
              E.ExtractCrsDataPointers(offsets, indices, values) == 0 &&
              static_cast<unsigned int>(E.NumMyRows()) == n_owned;
    // The position of local column @p column in owned row @p r, or -1.
    const auto find = [&](const int r, const int column) -> int {
      for (int p = offsets[r]; p < offsets[r + 1]; ++p)
        if (indices[p] == column)
          return p - offsets[r];
      return -1;
    };
    const auto column_of = [&](const types::global_dof_index g) {
      return E.LCID(static_cast<TrilinosIndex>(g));
    };

    diagonal_position.assign(ok ? n_owned : 0, 0);
    for (unsigned int r = 0; ok && r < n_owned; ++r)
      {
        const types::global_dof_index g = first_owned + r;
        ok = E.LRID(static_cast<TrilinosIndex>(g)) == static_cast<int>(r);
        const int p          = ok ? find(r, column_of(g)) : -1;
        ok                   = ok && p >= 0;
        diagonal_position[r] = p;
      }

    block_position.assign(ok ? cells.size() : 0, {});
    for (unsigned int ci = 0; ok && ci < cells.size(); ++ci)
      for (unsigned int a = 0; ok && a < n_nodes; ++a)
        if (cells[ci].row[a] >= 0)
          for (unsigned int b = 0; ok && b < n_nodes; ++b)
            {
              // Node b's dim columns must follow each other, at the same
              // position in each of node a's dim rows.
              const types::global_dof_index g =
                relevant.nth_index_in_set(cells[ci].node[b]);
              const int r0 = cells[ci].row[a];
              const int p  = find(r0, column_of(g));
              ok           = p >= 0;
              for (unsigned int i = 0; ok && i < dim; ++i)
                for (unsigned int k = 0; ok && k < dim; ++k)
                  ok = offsets[r0 + i] + p + static_cast<int>(k) <
                         offsets[r0 + i + 1] &&
                       indices[offsets[r0 + i] + p + k] == column_of(g + k);
              block_position[ci][a * n_nodes + b] = p;
            }
    return Utilities::MPI::min(ok ? 1 : 0, dof_handler.get_communicator()) == 1;
  }

  template <int dim>
  inline void
  P1Assembler<dim>::element_matrix(const Cell               &c,
                                   const StressTangent<dim> &A,
                                   ElementMatrix            &K) const
  {
    // K_ab[i][k] = |T| sum_JL g_a[J] A[i][J][k][L] g_b[L]. Two savings:
    // dP/dF is a Hessian (A[i][J][k][L] = A[k][L][i][J]), so K_ba is the
    // transpose of K_ab; and the gradients sum to zero, so the blocks of
    // node 0 are minus the sums of the others. Only K_ab for 1 <= a <= b
    // is contracted.
    double C[n_nodes][dim][dim][dim]; // C[b][i][J][k] = sum_L A_iJkL g_b[L]
    for (unsigned int n = 1; n < n_nodes; ++n)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int J = 0; J < dim; ++J)
          for (unsigned int k = 0; k < dim; ++k)
            {
              double s = 0.;
              for (unsigned int L = 0; L < dim; ++L)
                s += A[i][J][k][L] * c.grad[n][L];
              C[n][i][J][k] = c.volume * s;
            }
    for (unsigned int a = 1; a < n_nodes; ++a)
      for (unsigned int n = a; n < n_nodes; ++n)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int k = 0; k < dim; ++k)
            {
              double s = 0.;
              for (unsigned int J = 0; J < dim; ++J)
                s += c.grad[a][J] * C[n][i][J][k];
              K[a][n][i][k] = s;
              K[n][a][k][i] = s;
            }
    for (unsigned int n = 1; n < n_nodes; ++n)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int k = 0; k < dim; ++k)
          {
            double s = 0.;
            for (unsigned int a = 1; a < n_nodes; ++a)
              s += K[a][n][i][k];
            K[0][n][i][k] = -s;
            K[n][0][k][i] = -s;
          }
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int k = 0; k < dim; ++k)
        {
          double s = 0.;
          for (unsigned int n = 1; n < n_nodes; ++n)
            s += K[0][n][i][k];
          K[0][0][i][k] = -s;
        }
  }

  template <int dim>
  bool
  P1Assembler<dim>::gather_prescribed_values(
    const AffineConstraints<double> &constraints) const
  {
    // The prescribed value of every ghosted dof (NaN where free). The owner
    // of a dof knows whether it is constrained (every cell around it is
    // owned or ghost there); a ghost cell's far nodes may lie on a boundary
    // face this rank never sees, so the values come from the owners. Only
    // Dirichlet constraints (no entries) can be eliminated here.
    for (double &value : prescribed_owned)
      value = not_prescribed;
    bool dirichlet_only = true;
    for (const auto &line : constraints.get_lines())
      if (line.index >= first_owned && line.index < first_owned + n_owned)
        {
          dirichlet_only               = dirichlet_only && line.entries.empty();
          prescribed_owned(line.index) = line.inhomogeneity;
        }
    if (Utilities::MPI::min(block_ok && dirichlet_only ? 1 : 0,
                            dof_handler.get_communicator()) == 0)
      return false;
    prescribed_ghosted = prescribed_owned;
    return true;
  }

  template <int dim>
  void
  P1Assembler<dim>::add_cell_rows(const unsigned int    ci,
                                  const Tensor<2, dim> &P,
                                  const ElementMatrix  &K,
                                  const double         *prescribed,
                                  const int            *offsets,
                                  double               *values,
                                  double               *b) const
  {
    const Cell &c                  = cells[ci];
    bool        touches_constraint = false;
    for (unsigned int n = 0; n < n_nodes; ++n)
      for (unsigned int i = 0; i < dim; ++i)
        touches_constraint =
          touches_constraint || !std::isnan(prescribed[c.node[n] + i]);

    for (unsigned int a = 0; a < n_nodes; ++a)
      if (c.row[a] >= 0)
        {
          const Tensor<1, dim> force = c.volume * (P * c.grad[a]);
          for (unsigned int i = 0; i < dim; ++i)
            {
              const int     r   = c.row[a] + i;
              double *const row = values + offsets[r];
              if (!touches_constraint)
                {
                  // The common case: plain adds.
                  b[r] -= force[i];
                  for (unsigned int n = 0; n < n_nodes; ++n)
                    {
                      double *const block =
                        row + block_position[ci][a * n_nodes + n];
                      for (unsigned int k = 0; k < dim; ++k)
                        block[k] += K[a][n][i][k];
                    }
                  continue;
                }
              if (!std::isnan(prescribed[c.node[a] + i]))
                {
                  // A constrained row keeps only a diagonal.
                  constrained_diagonal[r] += std::abs(K[a][a][i][i]);
                  continue;
                }
              b[r] -= force[i];
              for (unsigned int n = 0; n < n_nodes; ++n)
                {
                  double *const block =
                    row + block_position[ci][a * n_nodes + n];
                  for (unsigned int k = 0; k < dim; ++k)
                    {
                      const double g = prescribed[c.node[n] + k];
                      if (std::isnan(g))
                        block[k] += K[a][n][i][k];
                      else
                        b[r] -= K[a][n][i][k] * g; // column to the rhs
                    }
                }
            }
        }
  }

  template <int dim>
  bool
  P1Assembler<dim>::system(const VectorType                &u,
                           const AffineConstraints<double> &constraints,
                           const TangentProjection          project_tangent,
                           MatrixType                      &matrix,
                           VectorType                      &rhs) const
  {
    if (&matrix.trilinos_matrix() != block_matrix)
      {
        block_matrix = &matrix.trilinos_matrix();
        block_ok     = find_block_positions(matrix);
      }
    if (!gather_prescribed_values(constraints))
      return false;
    const double *prescribed = ghosted_values(prescribed_ghosted);

    const double *U = ghosted_values(u);
    matrix          = 0.;
    rhs             = 0.;
    int    *offsets = nullptr, *indices = nullptr;
    double *values = nullptr;
    matrix.trilinos_matrix().ExtractCrsDataPointers(offsets, indices, values);
    double *b = rhs.begin();
    constrained_diagonal.assign(n_owned, 0.);

    Tensor<2, dim>     P;
    StressTangent<dim> A;
    ElementMatrix      K;
    std::string        error;
    unsigned int       bad_cell = 0;
    for (unsigned int ci = 0; ci < cells.size(); ++ci)
      {
        const Cell &c = cells[ci];
        if (!c.writes_rows)
          continue;
        bool finite = false;
        try
          {
            finite = stress_and_tangent_at(materials(c.active_index, 0),
                                           deformation_gradient(c, U),
                                           project_tangent,
                                           P,
                                           A);
          }
        catch (const std::exception &e)
          {
            error    = exception_message(e);
            bad_cell = c.active_index;
            break;
          }
        if (!finite)
          {
            error    = non_finite_stress_message();
            bad_cell = c.active_index;
            break;
          }

        element_matrix(c, A, K);
        add_cell_rows(ci, P, K, prescribed, offsets, values, b);
      }
    report(error, bad_cell);

    // A constrained row reads d u_r = d g_r with a diagonal of the size of
    // the others, as AffineConstraints would make it.
    for (unsigned int r = 0; r < n_owned; ++r)
      {
        const double g = prescribed[owned_offset_in_ghosted + r];
        if (!std::isnan(g))
          {
            const double d =
              constrained_diagonal[r] > 0. ? constrained_diagonal[r] : 1.;
            values[offsets[r] + diagonal_position[r]] = d;
            b[r]                                      = d * g;
          }
      }
    matrix.compress(VectorOperation::add);
    return true;
  }

  template <int dim>
  EnergyEvaluation
  P1Assembler<dim>::stored_energy(const VectorType &u,
                                  const bool        with_energy) const
  {
    const double *U      = ghosted_values(u);
    double        energy = 0.;
    double        min_J  = std::numeric_limits<double>::infinity();
    RoundOff      round_off(material);
    std::string   error;
    unsigned int  bad_cell = 0;
    for (const Cell &c : cells)
      if (c.owned)
        {
          const Tensor<2, dim> F = deformation_gradient(c, U);
          min_J = std::min(min_J, static_cast<double>(determinant(F)));
          if (!with_energy)
            continue;
          double psi;
          try
            {
              psi = materials(c.active_index, 0).energy_density(F);
            }
          catch (const std::exception &e)
            {
              error    = exception_message(e);
              bad_cell = c.active_index;
              break;
            }
          energy += psi * c.volume;
          round_off.add_energy(psi, F, c.volume);
        }
    report(error, bad_cell);
    return reduce_energy_evaluation(min_J,
                                    with_energy,
                                    energy,
                                    round_off.local_energy_magnitude(),
                                    dof_handler.get_communicator());
  }

  template <int dim>
  std::vector<double>
  P1Assembler<dim>::region_energies(const VectorType &u) const
  {
    const double       *U = ghosted_values(u);
    std::vector<double> energy(material.n_regions(), 0.);
    for (const Cell &c : cells)
      if (c.owned)
        energy[material.region(c.active_index)] +=
          materials(c.active_index, 0)
            .energy_density(deformation_gradient(c, U)) *
          c.volume;
    return summed_over_ranks(energy, dof_handler.get_communicator());
  }

  template <int dim>
  void
  P1Assembler<dim>::accept_step(const VectorType &u)
  {
    if (!materials.has_history())
      return;
    const double *U = ghosted_values(u);
    for (const Cell &c : cells)
      materials.accept_step(c.active_index, 0, deformation_gradient(c, U));
  }

  template class P1Assembler<2>;
  template class P1Assembler<3>;
} // namespace hyperelastic
