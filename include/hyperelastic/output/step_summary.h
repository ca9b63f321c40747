// The summary of one converged load or time step, and its one ordered list
// of (column name, value): the CSV header, the CSV row and the tests all read
// columns(), so the names and their order are written in one place.
#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <hyperelastic/solvers/newton_result.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  /// One CSV column of a step: its name and value.
  struct SummaryColumn
  {
    std::string name;
    double      value;
  };

  /// The moment about a point of a force @p force applied at @p arm from
  /// that point, arm x force, as a 3D vector (2D: in the plane z = 0, so
  /// only its z component is non-zero).
  template <int dim>
  dealii::Tensor<1, 3>
  moment_of(const dealii::Tensor<1, dim> &arm,
            const dealii::Tensor<1, dim> &force)
  {
    dealii::Tensor<1, 3> a, f;
    for (unsigned int d = 0; d < dim; ++d)
      {
        a[d] = arm[d];
        f[d] = force[d];
      }
    return dealii::cross_product_3d(a, f);
  }

  template <int dim>
  struct StepSummary
  {
    unsigned int step              = 0;
    double       load_factor       = 0.;
    double       load_increment    = 0.;
    unsigned int cut_backs         = 0; ///< failed attempts before this step
    /// The index of the stop ('Load stepping/Stop at load factors') the
    /// step landed on, if any (LoadStep::stop; not a CSV column).
    std::optional<unsigned int> stop;
    unsigned int newton_iterations = 0;
    unsigned int linear_iterations = 0;
    unsigned int backtracks        = 0; ///< rejected line-search trials
    /// AMG hierarchies computed so far in the run (built or refreshed);
    /// a column only where the linear solver is CG with AMG.
    std::optional<unsigned int> amg_setups;
    std::vector<NewtonIteration> newton_history;
    double                       residual = 0.;
    /// Total potential energy; in dynamics the potential energy (strain
    /// energy minus the work of dead loads), without the step's inertia.
    double energy = 0.;
    double min_J  = 0.;
    /// Cells with J <= 0 at a quadrature point (accepted only with
    /// 'Newton/Inverted elements at equilibrium = warn').
    dealii::types::global_cell_index inverted_cells = 0;
    /// Force the supports exert on the body, per Dirichlet boundary id: the
    /// sum of f_int - f_ext over the dofs on that boundary, for the
    /// components the condition prescribes (the others are reported as 0).
    std::vector<std::pair<dealii::types::boundary_id, dealii::Tensor<1, dim>>>
      reactions;
    /// The moment of each support's nodal forces (those of reactions, in
    /// the same order) about 'Output/Moment point' p, at the deformed
    /// positions of their nodes: sum of (X + u - p) x f over the dofs on
    /// that boundary (2D: only z is a column).
    std::vector<std::pair<dealii::types::boundary_id, dealii::Tensor<1, 3>>>
                           reaction_moments;
    dealii::Tensor<1, dim> deformed_min; ///< bounding box of x = X + u
    dealii::Tensor<1, dim> deformed_max;
    /// The displacement at each point of 'Output/Points', in their order.
    std::vector<dealii::Tensor<1, dim>> point_displacements;
    /// The range of the pressure unknowns (mixed formulation only).
    bool   has_pressure = false;
    double pressure_min = 0.;
    double pressure_max = 0.;
    /// Implicit dynamics: kinetic energy 1/2 v.M v, linear and angular
    /// momentum (about the origin; 2D: z only).
    bool                 dynamic        = false;
    double               kinetic_energy = 0.;
    dealii::Tensor<1, 3> linear_momentum;
    dealii::Tensor<1, 3> angular_momentum;
    /// Columns of features that add their own, after all the above in the
    /// order they were added.
    std::vector<SummaryColumn> more;

    /// Every column of the CSV row, in order:
    /// step, load_factor, newton_iterations, linear_iterations, residual,
    /// energy, min_J, reaction_<id>_<x|y|z> per Dirichlet boundary id,
    /// reaction_moment_<id>_x, _y (3D only), _z per Dirichlet boundary id,
    /// deformed_min_<axis> and deformed_max_<axis> per axis, load_increment,
    /// cut_backs, line_search_backtracks, amg_setups (CG with AMG only),
    /// inverted_cells, point<k>_u<axis>
    /// per output point; then with a pressure pressure_min, pressure_max; in
    /// dynamics kinetic_energy, total_energy, momentum_<axis> per axis,
    /// angular_momentum_x, _y (3D only), _z; then the added ones.
    std::vector<SummaryColumn>
    columns() const
    {
      const char                 axes[3] = {'x', 'y', 'z'};
      std::vector<SummaryColumn> c;
      const auto add = [&c](std::string name, const double value) {
        c.push_back({std::move(name), value});
      };
      add("step", step);
      add("load_factor", load_factor);
      add("newton_iterations", newton_iterations);
      add("linear_iterations", linear_iterations);
      add("residual", residual);
      add("energy", energy);
      add("min_J", min_J);
      for (const auto &[id, force] : reactions)
        for (unsigned int d = 0; d < dim; ++d)
          add("reaction_" + std::to_string(id) + '_' + axes[d], force[d]);
      for (const auto &[id, moment] : reaction_moments)
        for (unsigned int d = (dim == 3 ? 0 : 2); d < 3; ++d)
          add("reaction_moment_" + std::to_string(id) + '_' + axes[d],
              moment[d]);
      for (unsigned int d = 0; d < dim; ++d)
        {
          add(std::string("deformed_min_") + axes[d], deformed_min[d]);
          add(std::string("deformed_max_") + axes[d], deformed_max[d]);
        }
      add("load_increment", load_increment);
      add("cut_backs", cut_backs);
      add("line_search_backtracks", backtracks);
      if (amg_setups)
        add("amg_setups", *amg_setups);
      add("inverted_cells", inverted_cells);
      for (unsigned int k = 0; k < point_displacements.size(); ++k)
        for (unsigned int d = 0; d < dim; ++d)
          add("point" + std::to_string(k + 1) + "_u" + axes[d],
              point_displacements[k][d]);
      if (has_pressure)
        {
          add("pressure_min", pressure_min);
          add("pressure_max", pressure_max);
        }
      if (dynamic)
        {
          add("kinetic_energy", kinetic_energy);
          add("total_energy", kinetic_energy + energy);
          for (unsigned int d = 0; d < dim; ++d)
            add(std::string("momentum_") + axes[d], linear_momentum[d]);
          for (unsigned int d = (dim == 3 ? 0 : 2); d < 3; ++d)
            add(std::string("angular_momentum_") + axes[d],
                angular_momentum[d]);
        }
      c.insert(c.end(), more.begin(), more.end());
      return c;
    }
  };
} // namespace hyperelastic
