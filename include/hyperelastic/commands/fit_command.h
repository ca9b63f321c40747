// 'hyperelastic --fit FIT.prm': a fit to homogeneous test curves
// (calibration/run_fit.h) or, with Fit/Scene, through a whole scene
// (scene_fit.h). Above the concerns: a scene fit runs the Problem.
#pragma once

#include <mpi.h>
#include <string>

namespace hyperelastic
{
  void
  run_fit_command(const std::string &fit_file, MPI_Comm comm);
} // namespace hyperelastic
