// The material part assembled with FEValues for any degree: forces
// int P(F) grad N_a dV, tangent int grad N_a : dP/dF : grad N_b dV and
// stored energy by Gauss quadrature, condensed with AffineConstraints. The
// P1 kernel is tested against it.
#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/assembly/assembler.h>
#include <hyperelastic/assembly/constant_forces.h>
#include <hyperelastic/assembly/point_materials.h>

namespace hyperelastic
{
  template <int dim>
  class GenericAssembler : public Assembler<dim>, public ConstantForces<dim>
  {
  public:
    GenericAssembler(const dealii::DoFHandler<dim> &dof_handler,
                     const dealii::Mapping<dim>    &mapping,
                     const MaterialRegions<dim>    &material);

    double
    internal_forces(const VectorType &u, VectorType &internal) const override;

    /// Handles every kind of constraint and sparsity: always true.
    bool
    system(const VectorType                        &u,
           const dealii::AffineConstraints<double> &constraints,
           TangentProjection                        project_tangent,
           MatrixType                              &matrix,
           VectorType                              &rhs) const override;

    EnergyEvaluation
    stored_energy(const VectorType &u, bool with_energy) const override;

    std::vector<double>
    region_energies(const VectorType &u) const override;

    void
    accept_step(const VectorType &u) override;

    /// d f_int / dc_k = int dP/dc_k(F) grad N_a dV for each constant k of
    /// the model (materials/constant_derivatives.h).
    std::vector<VectorType>
    constant_forces(const VectorType &u,
                    const VectorType &like) const override;

  protected:
    const PointMaterials<dim> *
    point_materials() const override
    {
      return &materials;
    }

  private:
    struct CellData;

    /// Calls @p worker(cell, data) on every locally owned cell with F at the
    /// quadrature points in data; a failure on one cell (a model undefined
    /// at its F) is reported on every rank, naming the cell.
    template <typename CellWorker>
    void
    for_each_cell(const VectorType &u, CellWorker &&worker) const;

    const dealii::DoFHandler<dim> &dof_handler;
    const dealii::Mapping<dim>    &mapping;
    const MaterialRegions<dim>     material;
    /// Exact for P1 (one point) and for the linear-elastic stiffness of P2.
    const dealii::Quadrature<dim> quadrature;
    /// The model at each quadrature point.
    const PointMaterials<dim> materials;
  };
} // namespace hyperelastic
