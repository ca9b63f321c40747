// 'hyperelastic --fit' (see the header).
#include <hyperelastic/calibration/run_fit.h>
#include <hyperelastic/commands/fit_command.h>
#include <hyperelastic/inverse/scene_fit.h>

namespace hyperelastic
{
  void
  run_fit_command(const std::string &fit_file, const MPI_Comm comm)
  {
    dealii::ParameterHandler   prm;
    calibration::FitParameters parameters;
    calibration::read_fit_file(fit_file, prm, parameters);
    if (parameters.scene.empty())
      calibration::fit_tests(prm, parameters, fit_file, comm);
    else
      fit_through_scene(parameters, fit_file, comm);
  }
} // namespace hyperelastic
