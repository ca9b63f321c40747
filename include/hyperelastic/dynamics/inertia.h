// The inertia of an implicit time step as one more load term: with the mass
// matrix M (consistent or lumped) and the step's scale c and target w, set
// by the time integrator,
//   g(u) = -c M (u - w),   load stiffness c M,   potential c/2 |u - w|_M^2,
// so that the step minimises c/2 |u - w|_M^2 + Psi(u) - W(u) (backward
// Euler: c = 1/h^2, w = u_n + h v_n; mass damping shifts c and w).
// Also gives the products with M that kinetic energy and momentum need.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/full_matrix.h>

#include <hyperelastic/assembly/energy_term.h>

namespace hyperelastic
{
  template <int dim>
  class InertiaTerm : public EnergyTerm<dim>
  {
  public:
    /// @p density: mass per unit reference volume; @p lumped: the diagonal
    /// (HRZ) mass instead of the consistent one. Only the displacement
    /// components carry mass (a mixed formulation's pressure has none).
    /// @p cell_density: the density of each active cell by index (regions
    /// of their own density); empty: @p density everywhere.
    InertiaTerm(const dealii::DoFHandler<dim> &dof_handler,
                double                         density,
                bool                           lumped,
                std::vector<double>            cell_density = {});

    std::string
    name() const override
    {
      return "Time integration (inertia)";
    }

    TermKind
    kind() const override
    {
      return TermKind::conservative;
    }

    /// The step's scale c > 0 and target @p w (owned entries; copied with
    /// ghosts).
    void
    set_step(double c, const VectorType &w);

    /// Adds -c M (u - w); returns the norm of these forces and of their
    /// round-off (a long rigid motion cancels large u and w).
    ForceSize
    add_forces(const VectorType &u,
               double            t,
               VectorType       &forces) const override;

    void
    add_stiffness(const VectorType                        &u,
                  double                                   t,
                  TangentProjection                        projection,
                  const dealii::AffineConstraints<double> &constraints,
                  MatrixType                              &matrix,
                  VectorType                              &rhs) const override;

    double
    energy(const VectorType &u, double t) const override;

    /// M v (owned entries, compressed); @p v with ghost entries.
    void
    mass_product(const VectorType &v, VectorType &product) const;

    /// Solves M x = @p b on the dofs that @p constraints leave free (x = 0
    /// on the others) by CG with the diagonal of M, to 1e-12 relative.
    /// For the initial acceleration M a_0 = f_ext - f_int (Newmark).
    void
    solve_mass(const VectorType                        &b,
               const dealii::AffineConstraints<double> &constraints,
               VectorType                              &x) const;

  private:
    /// Calls @p worker(cell dofs, cell mass matrix) for every owned cell;
    /// the matrix couples only equal displacement components.
    template <typename Worker>
    void
    for_each_cell(Worker &&worker) const;

    /// Calls @p worker(cell dofs, d, M_cell d) for every owned cell, with
    /// d the cell's values of @p v minus those of @p subtracted (if any).
    template <typename Worker>
    void
    for_each_cell_product(const VectorType &v,
                          const VectorType *subtracted,
                          Worker          &&worker) const;

    const dealii::DoFHandler<dim> &dof_handler;
    const double                   density;
    const std::vector<double>      cell_density;
    const bool                     lumped;
    /// The scalar mass matrix of the reference simplex (its weights sum to
    /// the reference volume 1/dim!), lumped if asked; a cell's is
    /// rho |det J| times it.
    dealii::FullMatrix<double> reference_mass;
    double                     c = 0.;
    VectorType                 target; ///< w, with ghost entries
    /// Scratch of add_forces(): the term's forces and their round-off.
    mutable VectorType own_forces, own_round_off;
  };
} // namespace hyperelastic
