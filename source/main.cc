// hyperelastic: command line handling; everything else lives in the library.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/commands/fit_command.h>
#include <hyperelastic/scene/parameters.h>
#include <hyperelastic/problem/problem.h>

#include <iostream>
#include <string>

namespace
{
  const char *usage =
    "Usage: mpirun -np N hyperelastic SCENE.prm\n"
    "       mpirun -np N hyperelastic --restart CHECKPOINT SCENE.prm\n"
    "                                          continue a run from the\n"
    "                                          checkpoint its scene wrote\n"
    "                                          (Output/Checkpoint every),\n"
    "                                          on as many ranks\n"
    "       mpirun -np N hyperelastic --fit FIT.prm\n"
    "                                          fit a model's constants to test\n"
    "                                          curves (doc/calibration.md)\n"
    "       hyperelastic --print-parameters    every scene parameter with its\n"
    "                                          default and documentation\n"
    "       hyperelastic --help\n"
    "\n"
    "Solves a hyperelastic problem on a simplex mesh with Newton's method,\n"
    "quasi-static (load steps) or in time (Time integration/Scheme), writing\n"
    "ParaView files and a CSV summary per load or time step.\n"
    "Exit status: 0 success, 1 input error, 2 internal error, 3 convergence\n"
    "failure.\n";
} // namespace

int
main(int argc, char *argv[])
{
  using namespace hyperelastic;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;

  const std::string argument = argc == 2 ? argv[1] : "";
  if (argument == "--help" || argument == "-h")
    {
      if (root)
        std::cout << usage;
      return success;
    }
  if (argument == "--print-parameters")
    {
      if (root)
        {
          dealii::ParameterHandler prm;
          Parameters::declare(prm);
          prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
        }
      return success;
    }
  if (argc == 3 && std::string(argv[1]) == "--fit")
    return run_and_report(
      [&]() { run_fit_command(argv[2], comm); }, comm);
  const bool        restart = argc == 4 && std::string(argv[1]) == "--restart";
  const std::string scene   = restart ? argv[3] : argument;
  if (!(argc == 2 || restart) || scene.empty() || scene[0] == '-')
    {
      if (root)
        std::cerr << usage;
      return input_error;
    }

  return run_and_report(
    [&]() {
      Parameters parameters;
      parameters.read(scene);
      if (restart)
        parameters.restart_checkpoint = argv[2];
      run_scene(parameters, comm);
    },
    comm);
}
