// A built model's materials rebuilt with other constants (issue 56, item 5):
// what a calibration loop does. A 2D block of two regions (the half x > 1 a
// region of its own), clamped below and pressed by a plane obstacle (whose
// automatic barrier stiffness follows the materials), is run with one set
// of Young's moduli; then its materials are rebuilt three times with other
// moduli, each rebuilt run compared with a run of a scene written with
// those moduli: every column of every CSV row equal, to the bit. The
// rebuilt runs read no mesh (their set-up has no mesh stage).
// Usage: mpirun -np N rebuilt_materials
#include <deal.II/base/mpi.h>

#include "support/checker.h"
#include "support/scene_run.h"
#include "support/scene_text.h"

#include <cmath>
#include <string>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  /// The scene with Young's moduli @p young (top-level) and @p young_region
  /// (Region 1).
  std::string
  scene(const double young, const double young_region)
  {
    const auto material = [](const double e) {
      return subsection("Material",
                        entry("Model", "neo-Hookean") +
                          entry("Young's modulus", number(e)) +
                          entry("Poisson's ratio", "0.3"));
    };
    return subsection("Problem", entry("Dimension", "2")) +
           subsection("Mesh",
                      entry("Upper corner", "2, 1") +
                        entry("Subdivisions", "8, 4")) +
           material(young) +
           subsection("Region 1",
                      entry("Cells", "x > 1") + material(young_region)) +
           subsection("Loading", entry("Number of load steps", "3")) +
           subsection("Dirichlet 1", entry("Boundary id", "2")) +
           subsection("Contact",
                      subsection("Obstacle 1",
                                 entry("Type", "plane") +
                                   entry("Point", "0, 1.02") +
                                   entry("Normal", "0, -1") +
                                   entry("Motion", "0; -0.12*t"))) +
           subsection("Output",
                      entry("Write VTU", "false") + entry("Verbose", "false") +
                        entry("Directory", "rebuilt_materials_output"));
  }

  /// Whether every column of every row of @p a and @p b is the same (the
  /// first difference noted).
  bool
  same_rows(Checker                           &checker,
            const std::vector<StepSummary<2>> &a,
            const std::vector<StepSummary<2>> &b)
  {
    if (a.size() != b.size())
      {
        checker.note("rows: " + std::to_string(a.size()) + " against " +
                     std::to_string(b.size()));
        return false;
      }
    for (unsigned int k = 0; k < a.size(); ++k)
      {
        const auto ca = a[k].columns(), cb = b[k].columns();
        if (ca.size() != cb.size())
          return false;
        for (unsigned int c = 0; c < ca.size(); ++c)
          if (ca[c].name != cb[c].name ||
              !(ca[c].value == cb[c].value ||
                (std::isnan(ca[c].value) && std::isnan(cb[c].value))))
            {
              checker.note("row " + std::to_string(k + 1) + ", " + ca[c].name +
                           ": " + number(ca[c].value) + " against " +
                           number(cb[c].value));
              return false;
            }
      }
    return true;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Checker   checker(dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) ==
                  0);
  const int status = run_and_report(
    [&]() {
      Parameters first;
      first.read_from_string(scene(1., 3.));
      Problem<2> model(first, MPI_COMM_WORLD, false);
      model.run();
      checker.at_least("rows of the first run", model.summaries().size(), 3);
      const double moduli[3][2] = {{2., 1.}, {0.5, 4.}, {5., 5.}};
      for (const auto &e : moduli)
        {
          Parameters trial;
          trial.read_from_string(scene(e[0], e[1]));
          model.rebuild_materials(trial.material, trial.regions);
          model.run();
          const auto        separate = run_scene<2>(scene(e[0], e[1]));
          const std::string which =
            "E = " + number(e[0]) + ", " + number(e[1]) + ": ";
          checker.is_true(which + "rebuilt run equals a separate run",
                          same_rows(checker,
                                    model.summaries(),
                                    separate->summaries()));
          bool reads_mesh = false;
          for (const auto &stage : model.setup_stage_times())
            reads_mesh = reads_mesh || stage.first == "read";
          checker.is_true(which + "the rebuilt run read no mesh", !reads_mesh);
        }
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
