// The parameter file of 'hyperelastic --fit': the scene's Material
// subsection (the model, the starting constants, the fixed ones), Output's
// Directory and Base name, and the subsection Fit:
//   Free constants     entries of the model (default: all but the
//                      volumetric one; calibration/model_constants.h)
//   Incompressible     true: the tests are fitted with J = 1
//   Starts             how many starts the multi-start fit makes
//   Stability range    the stretches over which Drucker stability is checked
//   subsection Data k  (k = 1 ... 8) Test, File, Weight: one test each
//   Scene, Scene data  a fit through a whole scene instead (the scene's
//                      own Material, a measured CSV column at load factors)
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <hyperelastic/calibration/test_data.h>

#include <optional>
#include <string>
#include <vector>

namespace hyperelastic
{
  namespace calibration
  {
    /// A CSV column reaction_<id>_<x|y|z>: the support's boundary id and
    /// the component of its force.
    struct ReactionColumn
    {
      dealii::types::boundary_id boundary_id = 0;
      unsigned int               component   = 0;
    };

    /// @p column read as a reaction column; none for any other column.
    std::optional<ReactionColumn>
    reaction_column(const std::string &column);

    struct FitParameters
    {
      static constexpr unsigned int max_data_sets = 8;

      std::vector<std::string> free_constants;
      bool                     incompressible    = true;
      unsigned int             starts            = 8;
      double                   stability_lowest  = 0.1;
      double                   stability_highest = 10.;
      std::vector<TestData>    data;
      /// A fit through a scene: its file, and the data's column (read once
      /// into scene_reaction where it is a support's reaction).
      std::string                   scene, scene_column;
      std::optional<ReactionColumn> scene_reaction;
      std::string directory, base_name;

      /// Declares Material, Output (Directory, Base name) and Fit.
      static void
      declare(dealii::ParameterHandler &prm);

      /// Reads Fit and Output, and every Data k's file (relative paths are
      /// relative to @p folder, the parameter file's). InputErrors name the
      /// entry or the data file and line.
      void
      parse(dealii::ParameterHandler &prm, const std::string &folder);
    };
  } // namespace calibration
} // namespace hyperelastic
