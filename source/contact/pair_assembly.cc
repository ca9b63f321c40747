// The sums over a list of contact pairs: scatter, projection, held
// columns and collectives (contact/pair_assembly.h).
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/contact/pair_assembly.h>

#include <cmath>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim, unsigned int n_points>
  void
  PairStencil<dim, n_points>::set_vertex(
    const unsigned int                              i,
    const std::array<types::global_dof_index, dim> &vertex_dofs,
    const bool                                      written,
    const AffineConstraints<double>                *constraints)
  {
    writes[i] = written;
    for (unsigned int d = 0; d < dim; ++d)
      {
        dofs[i * dim + d] = vertex_dofs[d];
        if (constraints)
          held[i * dim + d] = prescribed_value(*constraints, vertex_dofs[d]);
      }
  }

  template <int dim, unsigned int n_points>
  void
  PairStencil<dim, n_points>::set_obstacle_point(const unsigned int    i,
                                                 const Tensor<1, dim> &motion)
  {
    writes[i] = false;
    for (unsigned int d = 0; d < dim; ++d)
      {
        dofs[i * dim + d] = numbers::invalid_dof_index;
        held[i * dim + d] = motion[d];
      }
  }

  namespace
  {
    /// One row of a pair's Hessian as it enters the matrix: the unknowns'
    /// columns, and what the held ones move to the right-hand side.
    template <std::size_t n, typename Stencil>
    double
    gather_row(const Stencil                        &s,
               const SmallMatrix<n>                 &K,
               const SmallMatrix<n>                 &hessian,
               const std::size_t                     row,
               std::vector<types::global_dof_index> &columns,
               std::vector<double>                  &entries)
    {
      columns.clear();
      entries.clear();
      // The obstacles' motion through the exact Hessian, the constrained
      // dofs' through the assembled block.
      double moved = 0., constrained = 0.;
      for (std::size_t c = 0; c < n; ++c)
        if (std::isnan(s.held[c]))
          {
            columns.push_back(s.dofs[c]);
            entries.push_back(K[row][c]);
          }
        else if (s.dofs[c] == numbers::invalid_dof_index)
          moved += hessian[row][c] * s.held[c];
        else
          constrained += K[row][c] * s.held[c];
      return moved + constrained;
    }
  } // namespace

  template <int dim, unsigned int n_points>
  double
  PairSums<dim, n_points>::sum_energy(const Visit &visit, const MPI_Comm comm)
  {
    double     sum = 0.;
    const bool touching =
      visit({0,
             nullptr,
             [&](const Stencil &, const Barrier &b, const bool counted, bool) {
               if (counted)
                 sum += b.energy;
             }});
    return Utilities::MPI::sum(
      touching ? std::numeric_limits<double>::infinity() : sum, comm);
  }

  template <int dim, unsigned int n_points>
  void
  PairSums<dim, n_points>::sum_forces(const Visit       &visit,
                                      VectorType        &forces,
                                      const MPI_Comm     comm,
                                      const std::string &touching)
  {
    std::vector<types::global_dof_index> rows;
    std::vector<double>                  values;
    const bool                           touches =
      visit({1, nullptr, [&](const Stencil &s, const Barrier &b, bool, bool) {
               for (unsigned int i = 0; i < n_points; ++i)
                 if (s.writes[i])
                   for (unsigned int d = 0; d < dim; ++d)
                     {
                       rows.push_back(s.dofs[i * dim + d]);
                       values.push_back(-b.gradient[i * dim + d]);
                     }
             }});
    // On every rank, even without contact: the first add after an insert
    // makes Trilinos assemble the vector, a collective operation.
    forces.add(rows, values);
    if (Utilities::MPI::max(touches ? 1 : 0, comm) != 0)
      throw ConvergenceFailure(touching);
  }

  template <int dim, unsigned int n_points>
  void
  PairSums<dim, n_points>::sum_stiffness(
    const Visit                          &visit,
    const AffineConstraints<double>      &constraints,
    const bool                            project,
    MatrixType                           &matrix,
    VectorType                           &rhs,
    std::vector<types::global_dof_index> *written)
  {
    std::vector<types::global_dof_index> rhs_rows, columns;
    std::vector<double>                  rhs_values, entries;
    if (written)
      written->clear();
    visit(
      {2,
       &constraints,
       [&](const Stencil &s, const Barrier &b, bool, const bool projectable) {
         // The body's block (an obstacle's coordinates are no
         // unknowns), projected where asked.
         SmallMatrix<n> K = b.hessian;
         for (std::size_t i = 0; i < n; ++i)
           for (std::size_t j = 0; j < n; ++j)
             if (s.dofs[i] == numbers::invalid_dof_index ||
                 s.dofs[j] == numbers::invalid_dof_index)
               K[i][j] = 0.;
         if (project && projectable)
           K = positive_semidefinite_part<n>(K);
         for (unsigned int i = 0; i < n_points; ++i)
           for (unsigned int r = 0; r < dim && s.writes[i]; ++r)
             {
               const std::size_t row = i * dim + r;
               if (!std::isnan(s.held[row]))
                 continue; // a constrained row reads d du_r = d g_r
               const double moved =
                 gather_row<n>(s, K, b.hessian, row, columns, entries);
               matrix.add(s.dofs[row],
                          columns.size(),
                          columns.data(),
                          entries.data());
               if (written)
                 written->push_back(s.dofs[row]);
               if (moved != 0.)
                 {
                   rhs_rows.push_back(s.dofs[row]);
                   rhs_values.push_back(-moved);
                 }
             }
       }});
    rhs.add(rhs_rows, rhs_values);
  }

  // The obstacles' vertex and obstacle point; the self contact's and
  // meshed obstacles' pairs of dim + 1 points.
  template struct PairStencil<2, 2>;
  template struct PairStencil<2, 3>;
  template struct PairStencil<3, 2>;
  template struct PairStencil<3, 4>;
  template class PairSums<2, 2>;
  template class PairSums<2, 3>;
  template class PairSums<3, 2>;
  template class PairSums<3, 4>;
} // namespace hyperelastic
