// Stiffness-proportional (Rayleigh) damping of an implicit time step as one
// more load term: the damping force b K0 v, with K0 the linear elastic
// stiffness at rest (the model's small-strain moduli) and v the end-of-step
// velocity, affine in the solved u for every scheme: v = kappa (u - d)
// (time_integrator.h). With s = b kappa,
//   g(u) = -s K0 (u - d),   load stiffness s K0,   potential s/2 |u - d|_K0^2,
// so the step still minimises an incremental potential. At small amplitude
// each mode of frequency omega is damped at the ratio b omega / 2. K0 is the
// stiffness at rest: it damps strain rates of small rotations only, and also
// resists the velocity of a large rigid rotation (use mass damping for
// spinning bodies).
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/assembly/energy_term.h>
#include <hyperelastic/assembly/material_regions.h>
#include <hyperelastic/materials/material.h>

namespace hyperelastic
{
  template <int dim>
  class StiffnessDampingTerm : public EnergyTerm<dim>
  {
  public:
    /// Assembles K0 with each cell's rest moduli (collective).
    StiffnessDampingTerm(const dealii::DoFHandler<dim> &dof_handler,
                         const dealii::Mapping<dim>    &mapping,
                         const MaterialRegions<dim>    &materials);

    std::string
    name() const override
    {
      return "Time integration (stiffness damping)";
    }

    TermKind
    kind() const override
    {
      return TermKind::conservative;
    }

    /// The step's scale s = b kappa >= 0 and the velocity's zero @p d
    /// (owned entries).
    void
    set_step(double s, const VectorType &d);

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

  private:
    /// K0 (u - d) into @p product and u - d into @p difference (owned).
    void
    apply(const VectorType &u,
          VectorType       &difference,
          VectorType       &product) const;

    MatrixType         stiffness;
    double             scale = 0.;
    VectorType         zero; ///< d
    mutable VectorType difference, product;
  };
} // namespace hyperelastic
