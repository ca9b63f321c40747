// What a converged step measures for its summary: the force each support
// exerts on the body (per Dirichlet boundary id) and its moment about
// 'Output/Moment point', the bounding box of the deformed vertices, the
// displacement at the points of 'Output/Points' and the range of the
// pressure unknowns. Set up once per mesh.
#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/base/linear_algebra.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/output/output_parameters.h>
#include <hyperelastic/output/point_values.h>
#include <hyperelastic/output/step_reporter.h>
#include <hyperelastic/output/step_summary.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class StepPostprocessor : public StepReporter<dim>
  {
  public:
    /// Finds the dofs of each Dirichlet boundary id (with their nodes'
    /// reference positions, for the moments) and locates the output
    /// points (a point outside the mesh is an InputError now, not after the
    /// first step). @p pressure_dofs: the pressure unknowns (may be empty).
    /// Collective.
    StepPostprocessor(const dealii::DoFHandler<dim> &dof_handler,
                      const dealii::Mapping<dim>    &mapping,
                      const BoundaryConditions<dim> &boundary_conditions,
                      const OutputParameters        &output,
                      const dealii::IndexSet        &pressure_dofs);
    ~StepPostprocessor() override;

    /// Fills the reactions and their moments from @p residual = f_int -
    /// f_ext (owned entries) and @p u, the bounding box, the point
    /// displacements and the pressure range from @p u (ghosted). Collective.
    void
    measure(const VectorType &u,
            const VectorType &residual,
            StepSummary<dim> &summary) const;

    /// measure() at the converged @p state (its residual forces).
    void
    add_columns(const ReportedState &state, StepSummary<dim> &summary) override
    {
      measure(state.u, state.residual_forces, summary);
    }

  private:
    const dealii::DoFHandler<dim> &dof_handler;
    const dealii::IndexSet         pressure_dofs;
    /// Whether there are pressure unknowns (on any rank).
    const bool has_pressure;
    /// An owned dof on a support whose component is prescribed there: its
    /// component, its node's reference position (support point) and the
    /// dofs of all displacement components at that node (owned together).
    struct ReactionDof
    {
      dealii::types::global_dof_index                  dof;
      unsigned int                                     component;
      dealii::Point<dim>                               X;
      std::array<dealii::types::global_dof_index, dim> node;
    };
    /// The distinct Dirichlet boundary ids and, for each, its ReactionDofs.
    std::vector<dealii::types::boundary_id> reaction_ids;
    std::vector<std::vector<ReactionDof>>   reaction_dofs;
    /// 'Output/Moment point'.
    dealii::Point<dim> moment_point;
    /// The points of 'Output/Points' (null if there are none).
    std::unique_ptr<PointValues<dim>> point_values;
  };
} // namespace hyperelastic
