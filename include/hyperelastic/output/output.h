// What a run writes: per load step one .vtu per rank plus a .pvtu, a .pvd for
// the whole series (open it in ParaView), and a CSV summary with one row per
// converged load step.
#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hyperelastic/output/cell_fields.h>
#include <hyperelastic/solvers/newton_solver.h>
#include <hyperelastic/output/output_parameters.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  /// The summary of one converged load step (one CSV row).
  template <int dim>
  struct StepSummary
  {
    unsigned int step              = 0;
    double       load_factor       = 0.;
    double       load_increment    = 0.;
    unsigned int cut_backs         = 0; ///< failed attempts before this step
    unsigned int newton_iterations = 0;
    unsigned int linear_iterations = 0;
    unsigned int backtracks        = 0; ///< rejected line-search trials
    std::vector<NewtonIteration> newton_history;
    double                       residual = 0.;
    double                       energy   = 0.;
    double                       min_J    = 0.;
    /// Cells with J <= 0 at a quadrature point (accepted only with
    /// 'Newton/Inverted elements at equilibrium = warn').
    dealii::types::global_cell_index inverted_cells = 0;
    /// Force the supports exert on the body, per Dirichlet boundary id: the
    /// sum of f_int - f_ext over the dofs on that boundary, for the
    /// components the condition prescribes (the others are reported as 0).
    std::vector<std::pair<dealii::types::boundary_id, dealii::Tensor<1, dim>>>
                           reactions;
    dealii::Tensor<1, dim> deformed_min; ///< bounding box of x = X + u
    dealii::Tensor<1, dim> deformed_max;
    /// The displacement at each point of 'Output/Points', in their order.
    std::vector<dealii::Tensor<1, dim>> point_displacements;
    /// Implicit dynamics: kinetic energy 1/2 v.M v, linear and angular
    /// momentum (about the origin; 2D: z only); energy is then the
    /// potential energy (strain energy minus the work of dead loads).
    bool                 dynamic        = false;
    double               kinetic_energy = 0.;
    dealii::Tensor<1, 3> linear_momentum;
    dealii::Tensor<1, 3> angular_momentum;
    /// The range of the pressure unknowns (mixed formulation only).
    bool   has_pressure = false;
    double pressure_min = 0.;
    double pressure_max = 0.;
  };

  template <int dim>
  class OutputWriter
  {
  public:
    /// Creates the output folder (collective; InputError if impossible).
    OutputWriter(const OutputParameters &parameters, MPI_Comm comm);

    /// Writes <base>_<step>.<rank>.vtu, <base>_<step>.pvtu and rewrites
    /// <base>.pvd. @p u (and @p velocity, written as the vector field
    /// "velocity" if not null: dynamics) must have ghost entries.
    void
    write_fields(unsigned int                                 step,
                 double                                       load_factor,
                 const dealii::DoFHandler<dim>               &dof_handler,
                 const dealii::Mapping<dim>                  &mapping,
                 const dealii::TrilinosWrappers::MPI::Vector &u,
                 const CellFields                            &fields,
                 const dealii::TrilinosWrappers::MPI::Vector *velocity = nullptr);

    /// Appends one row to <base>.csv (rank 0 writes).
    void
    write_summary(const StepSummary<dim> &summary);

    std::string
    csv_file() const;

    /// The .pvtu file of output step @p step.
    std::string
    pvtu_file(unsigned int step) const;

  private:
    const OutputParameters                      parameters;
    const MPI_Comm                              comm;
    std::vector<std::pair<double, std::string>> pvd_entries;
    std::ofstream                               csv;
  };
} // namespace hyperelastic
