// The scene's Loading subsection and its Dirichlet and Traction subsections.
// Declared with pattern, default and documentation; parsed with the values
// checked (an invalid value is an InputError naming the entry).
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <map>
#include <string>
#include <vector>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  /// A displacement prescribed on one boundary id for some components.
  struct DirichletCondition
  {
    dealii::types::boundary_id boundary_id = 0;
    std::vector<unsigned int>  components;  ///< 0 = x, 1 = y, 2 = z
    std::vector<std::string>   expressions; ///< one per entry of components
    std::string                subsection;  ///< for error messages
  };

  /// A traction (force per unit reference area) on one boundary id.
  struct TractionCondition
  {
    dealii::types::boundary_id boundary_id = 0;
    std::vector<std::string>   expressions; ///< one per space dimension
    std::string                subsection;
  };

  /// A follower pressure (force per unit deformed area along the deformed
  /// normal) on one boundary id.
  struct PressureCondition
  {
    dealii::types::boundary_id boundary_id = 0;
    std::string                expression; ///< p(x, y, (z,) t)
    std::string                subsection;
  };

  struct LoadingParameters
  {
    unsigned int                    n_load_steps = 10;
    std::vector<std::string>        body_force; ///< empty: no body force
    std::map<std::string, double>   constants;
    std::vector<DirichletCondition> dirichlet;
    std::vector<TractionCondition>  tractions;
    std::vector<PressureCondition>  pressures;

    static constexpr unsigned int max_dirichlet = 8;
    static constexpr unsigned int max_tractions = 4;
    static constexpr unsigned int max_pressures = 4;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };
} // namespace hyperelastic
