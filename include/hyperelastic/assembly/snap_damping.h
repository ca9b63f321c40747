// The damping energy of snap sub-steps (pseudo-transient continuation,
// solvers/snap_sequence.h) as an energy term: c/2 (u - w)^T D (u - w) with D
// a diagonal metric (the lumped mass of unit density on the free unknowns,
// zero on prescribed ones and on pressures), c > 0 the damping (1 / h^2 of a
// pseudo time step h) and w the centre (the start of the sub-step). It is
// conservative: its force -c D (u - w), its stiffness c D and its energy join
// the other terms'. Inactive (c = 0) it adds nothing. The equilibrium system
// adds it to the operator when a snap first needs it.
#pragma once

#include <hyperelastic/assembly/energy_term.h>
#include <hyperelastic/base/linear_algebra.h>

namespace hyperelastic
{
  template <int dim>
  class SnapDamping : public EnergyTerm<dim>
  {
  public:
    /// The metric @p diagonal (owned entries; zero where nothing is
    /// damped). Inactive (c = 0) until set().
    explicit SnapDamping(const VectorType &diagonal);

    /// Damping @p c (0: none) centred at @p centre (owned entries).
    void
    set(double c, const VectorType &centre);

    /// Whether the damping acts (c > 0).
    bool
    active() const
    {
      return c > 0.;
    }

    /// The l2 norm of the damping force c D (@p u - w) (collective).
    double
    force_norm(const VectorType &u) const;

    /// The mean ratio of the @p matrix diagonal to D over the damped
    /// unknowns: the damping c at which c D matches the stiffness's
    /// diagonal on average (collective).
    double
    stiffness_ratio(const MatrixType &matrix) const;

    // EnergyTerm
    std::string
    name() const override
    {
      return "snap damping";
    }
    TermKind
    kind() const override
    {
      return TermKind::conservative;
    }
    double
    energy(const VectorType &u, double t) const override;
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

  private:
    /// c D (u - w) into @p force (owned entries).
    void
    damping_force(const VectorType &u, VectorType &force) const;

    VectorType diagonal;
    VectorType centre;
    double     c = 0.;
  };
} // namespace hyperelastic
