// Checkpoint and restart (issue 31; problem/checkpoint.cc,
// output/checkpoint_file.h). A run is "killed" by a step observer that
// throws after a given step (the CSV then holds rows past the checkpoint,
// as after a real kill), restarted from its checkpoint, and its CSV and PVD
// compared with those of the same scene run without interruption.
//   restart DIM dynamic        a cantilever under gravity, Newmark, 20 time
//       steps of 0.05 with 'Checkpoint every = 5' and CG with AMG: killed
//       after step 12 (checkpoint of step 10), restarted from a scene that
//       extends End time from 0.6 to 1: every CSV row equal to the
//       uninterrupted run's (1e-12 relative, each value), the same PVD
//       entries;
//   restart DIM quasi_static   a viscoelastic (Yeoh + two Prony terms) bar
//       stretched in 4 load steps with Newton limited to 4 iterations, so
//       that the first step is cut back before the checkpoint (every 2
//       steps): killed after step 3, restarted: equal rows (1e-12), the same
//       cut-backs;
//   restart DIM mixed          the same with the mixed formulation (P1/P1
//       stabilized; the pressures are part of the state): equal rows
//       (1e-12). (P1-bubble/P1 keeps per-cell bubble guesses that the
//       checkpoint does not hold: its restart is not bit-identical.)
//   restart DIM regions        the viscous bar with two regions of their own
//       models (one viscoelastic with its own Prony series, one elastic):
//       equal rows (1e-12), energy_region_<k> included;
//   restart DIM mismatch       a checkpoint restarted with another model and
//       with another mesh: the input error naming what differs;
//   restart DIM truncated      the checkpoint cut to half its size (a kill
//       while writing): the restart reads <base>.checkpoint.previous and
//       still ends with the uninterrupted run's rows; without a previous
//       one, the input error saying it is damaged.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/scene_run.h"
#include "support/scene_text.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using namespace hyperelastic;
  using namespace hyperelastic::testing;

  /// Thrown by the step observer: the run stops as if killed.
  struct Killed
  {
  };

  /// Runs @p text (from @p checkpoint if not empty); with @p kill_after > 0
  /// the run stops after that step.
  template <int dim>
  void
  run(const std::string &text,
      const std::string &checkpoint = "",
      const unsigned int kill_after = 0)
  {
    Parameters parameters;
    parameters.read_from_string(text);
    parameters.restart_checkpoint = checkpoint;
    Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
    if (kill_after > 0)
      problem.set_step_observer([&](const StepSummary<dim> &s) {
        if (s.step == kill_after)
          throw Killed();
      });
    try
      {
        problem.run();
      }
    catch (const Killed &)
      {
      }
    // Rank 0 writes the files the checks read on every rank.
    MPI_Barrier(MPI_COMM_WORLD);
  }

  std::vector<std::string>
  lines_of(const std::string &file)
  {
    std::ifstream            in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    return lines;
  }

  /// Compares the CSV files @p a and @p b value by value: the largest
  /// relative difference (1 if the headers or row counts differ).
  double
  csv_difference(const std::string &a, const std::string &b)
  {
    const auto rows_a = lines_of(a), rows_b = lines_of(b);
    if (rows_a.size() != rows_b.size() || rows_a.empty() ||
        rows_a[0] != rows_b[0])
      return 1.;
    double worst = 0.;
    for (unsigned int r = 1; r < rows_a.size(); ++r)
      {
        std::istringstream x(rows_a[r]), y(rows_b[r]);
        for (std::string u, v; std::getline(x, u, ',');)
          {
            if (!std::getline(y, v, ','))
              return 1.;
            const double p = std::stod(u), q = std::stod(v);
            if (p != q)
              worst =
                std::max(worst,
                         std::abs(p - q) / std::max(std::abs(p), std::abs(q)));
          }
      }
    return worst;
  }

  std::string
  output(const std::string &dir, const std::string &extra = "")
  {
    return subsection("Output",
                      entry("Directory", dir) + entry("Base name", "run") +
                        extra);
  }

  std::string
  folder(const int dim, const std::string &name)
  {
    return "restart_" + std::to_string(dim) + "d_" + name + "_np" +
           std::to_string(Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
  }

  /// The cantilever [0,2] x [0,0.5] (x [0,0.5]) clamped at x = 0 under
  /// gravity, Newmark up to @p end.
  std::string
  cantilever(const int dim, const std::string &end)
  {
    const bool three = dim == 3;
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh",
                      entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                        entry("Upper corner",
                              three ? "2, 0.5, 0.5" : "2, 0.5") +
                        entry("Subdivisions", three ? "8, 2, 2" : "16, 4")) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "100") +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading",
                      entry("Body force", three ? "0; -2; 0" : "0; -2")) +
           dirichlet(1,
                     0,
                     three ? "x, y, z" : "x, y",
                     three ? "0; 0; 0" : "0; 0") +
           subsection("Time integration",
                      entry("Scheme", "Newmark") + entry("Time step", "0.05") +
                        entry("End time", end));
  }

  /// A viscoelastic bar (lateral faces free, the end stretched to 1.6 over
  /// t in [0, 0.3] and held), Newton limited to 4 iterations: the first
  /// step is cut back.
  std::string
  viscous_bar(const int          dim,
              const std::string &model        = "Yeoh",
              const std::string &subdivisions = "")
  {
    const bool three = dim == 3;
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh",
                      entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                        entry("Upper corner", three ? "3, 1, 1" : "3, 1") +
                        entry("Subdivisions",
                              !subdivisions.empty() ? subdivisions
                              : three               ? "3, 1, 1"
                                                    : "6, 2")) +
           subsection(
             "Material",
             entry("Model", model) +
               subsection(model,
                          entry(model == "Yeoh" ? "C10" : "Shear modulus",
                                model == "Yeoh" ? "0.5" : "1") +
                            entry(model == "Yeoh" ? "Bulk modulus" : "Jm",
                                  "5")) +
               subsection("Viscoelasticity",
                          entry("Weights", "1, 0.5") +
                            entry("Relaxation times", "0.1, 0.8"))) +
           subsection("Loading", entry("Number of load steps", "4")) +
           subsection("Newton", entry("Max iterations", "4")) +
           dirichlet(1, 0, "x", "0") +
           dirichlet(2, 1, "x", "1.8*min(1, t/0.3)") +
           dirichlet(3, 2, "y", "0") + (three ? dirichlet(5, 4, "z", "0") : "");
  }

  template <int dim>
  void
  dynamic(Checker &checker)
  {
    const std::string tag   = std::to_string(dim) + "D dynamic: ";
    const std::string whole = folder(dim, "dynamic_whole");
    const std::string split = folder(dim, "dynamic_split");
    const std::string every = entry("Checkpoint every", "5");
    run<dim>(cantilever(dim, "1") + output(whole, every));
    run<dim>(cantilever(dim, "0.6") + output(split, every), "", 12);
    checker.is_true(tag + "the killed run wrote 12 rows",
                    lines_of(split + "/run.csv").size() == 13);
    run<dim>(cantilever(dim, "1") + output(split, every),
             split + "/run.checkpoint");
    checker.is_true(tag + "20 rows", lines_of(whole + "/run.csv").size() == 21);
    checker.at_most(tag + "every CSV value as without the interruption",
                    csv_difference(whole + "/run.csv", split + "/run.csv"),
                    1e-12);
    // The PVD files without deal.II's line with the time of writing.
    const auto entries = [](const std::string &file) {
      std::vector<std::string> kept;
      for (const std::string &line : lines_of(file))
        if (line.find("generated by the deal.II library") == std::string::npos)
          kept.push_back(line);
      return kept;
    };
    const auto pvd_whole = entries(whole + "/run.pvd"),
               pvd_split = entries(split + "/run.pvd");
    checker.is_true(tag + "the same PVD entries (" +
                      std::to_string(pvd_whole.size()) + " lines)",
                    pvd_whole == pvd_split && pvd_whole.size() > 20);
  }

  template <int dim>
  void
  quasi_static(Checker &checker)
  {
    const std::string tag   = std::to_string(dim) + "D quasi-static, viscous: ";
    const std::string whole = folder(dim, "static_whole");
    const std::string split = folder(dim, "static_split");
    const std::string every =
      entry("Checkpoint every", "2") + entry("Write VTU", "false");
    run<dim>(viscous_bar(dim) + output(whole, every));
    const auto rows = lines_of(whole + "/run.csv");
    // The cut-backs: the column cut_backs of the rows.
    const auto   header = rows.at(0);
    unsigned int index  = 0;
    {
      std::istringstream names(header);
      unsigned int       k = 0;
      for (std::string name; std::getline(names, name, ','); ++k)
        if (name == "cut_backs")
          index = k;
    }
    double cut_backs = 0.;
    for (unsigned int r = 1; r < rows.size(); ++r)
      {
        std::istringstream values(rows[r]);
        std::string        value;
        for (unsigned int k = 0; k <= index; ++k)
          std::getline(values, value, ',');
        cut_backs += std::stod(value);
      }
    checker.note(tag + std::to_string(rows.size() - 1) + " steps, " +
                 std::to_string(int(cut_backs)) + " cut-backs");
    checker.at_least(tag + "cut-backs", cut_backs, 1.);
    checker.at_least(tag + "steps", rows.size() - 1., 5.);
    // Killed one step after its first checkpoint (step 2).
    run<dim>(viscous_bar(dim) + output(split, every), "", 3);
    run<dim>(viscous_bar(dim) + output(split, every),
             split + "/run.checkpoint");
    checker.at_most(tag + "every CSV value as without the interruption",
                    csv_difference(whole + "/run.csv", split + "/run.csv"),
                    1e-12);
  }

  /// @p scene run to its end in the folder "<name>_whole", and again in
  /// "<name>_split", killed after its third step (checkpoints every 2
  /// steps) and resumed from its checkpoint: at least 4 steps, and every
  /// CSV value (@p what) as without the interruption (1e-12).
  template <int dim>
  void
  check_resumed(Checker           &checker,
                const std::string &tag,
                const std::string &scene,
                const std::string &name,
                const std::string &what)
  {
    const std::string whole = folder(dim, name + "_whole");
    const std::string split = folder(dim, name + "_split");
    const std::string every =
      entry("Checkpoint every", "2") + entry("Write VTU", "false");
    run<dim>(scene + output(whole, every));
    run<dim>(scene + output(split, every), "", 3);
    run<dim>(scene + output(split, every), split + "/run.checkpoint");
    checker.at_least(tag + "steps",
                     lines_of(whole + "/run.csv").size() - 1.,
                     4.);
    checker.at_most(tag + what + " as without the interruption",
                    csv_difference(whole + "/run.csv", split + "/run.csv"),
                    1e-12);
  }

  /// The viscous bar with the mixed formulation (P1/P1 stabilized): the
  /// pressures are part of the state.
  template <int dim>
  void
  mixed(Checker &checker)
  {
    check_resumed<dim>(checker,
                       std::to_string(dim) + "D mixed, viscous: ",
                       viscous_bar(dim) +
                         subsection("Problem",
                                    entry("Formulation", "mixed") +
                                      entry("Mixed element",
                                            "P1/P1 stabilized")),
                       "mixed",
                       "every CSV value");
  }

  /// The viscous bar with regions: x < 1 a viscoelastic Gent of its own
  /// Prony series (Region 1), x > 2 an elastic neo-Hookean without history
  /// (Region 2), the viscous Yeoh between: each region's history is part
  /// of the state, and points without history write none.
  template <int dim>
  void
  regions(Checker &checker)
  {
    const std::string scene =
      viscous_bar(dim) +
      subsection("Region 1",
                 entry("Cells", "x < 1") +
                   subsection("Material",
                              entry("Model", "Gent") +
                                subsection("Gent",
                                           entry("Shear modulus", "2") +
                                             entry("Jm", "5")) +
                                subsection("Viscoelasticity",
                                           entry("Weights", "2") +
                                             entry("Relaxation times",
                                                   "0.3")))) +
      subsection("Region 2",
                 entry("Cells", "x > 2") +
                   subsection("Material",
                              entry("Model", "neo-Hookean") +
                                entry("Young's modulus", "3")));
    check_resumed<dim>(checker,
                       std::to_string(dim) + "D regions, viscous: ",
                       scene,
                       "regions",
                       "every CSV value (energy_region_<k> included)");
  }

  /// The message of the input error @p text restarted from @p checkpoint
  /// raises (empty if none).
  template <int dim>
  std::string
  restart_error(const std::string &text, const std::string &checkpoint)
  {
    try
      {
        run<dim>(text, checkpoint);
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }

  template <int dim>
  void
  mismatch(Checker &checker)
  {
    const std::string tag = std::to_string(dim) + "D mismatch: ";
    const std::string dir = folder(dim, "mismatch");
    const std::string every =
      entry("Checkpoint every", "1") + entry("Write VTU", "false");
    run<dim>(viscous_bar(dim) + output(dir, every), "", 1);
    const std::string model =
      restart_error<dim>(viscous_bar(dim, "Gent") + output(dir, every),
                         dir + "/run.checkpoint");
    checker.note(model);
    checker.is_true(tag + "another model is an input error naming the model",
                    model.find("does not fit this scene: its model is 'Yeoh "
                               "with viscoelasticity', the scene's 'Gent "
                               "with viscoelasticity'") != std::string::npos);
    const std::string mesh = restart_error<dim>(
      viscous_bar(dim, "Yeoh", dim == 3 ? "3, 2, 1" : "6, 3") +
        output(dir, every),
      dir + "/run.checkpoint");
    checker.note(mesh);
    checker.is_true(tag + "another mesh is an input error naming the cells",
                    mesh.find("does not fit this scene: its cells is") !=
                      std::string::npos);
  }

  template <int dim>
  void
  truncated(Checker &checker)
  {
    const std::string tag   = std::to_string(dim) + "D truncated: ";
    const std::string whole = folder(dim, "truncated_whole");
    const std::string split = folder(dim, "truncated_split");
    const std::string every =
      entry("Checkpoint every", "1") + entry("Write VTU", "false");
    run<dim>(viscous_bar(dim) + output(whole, every));
    run<dim>(viscous_bar(dim) + output(split, every), "", 4);
    const std::string file = split + "/run.checkpoint";
    MPI_Barrier(MPI_COMM_WORLD);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
    MPI_Barrier(MPI_COMM_WORLD);
    run<dim>(viscous_bar(dim) + output(split, every), file);
    checker.at_most(tag + "restarted from the previous checkpoint: every "
                          "CSV value as without the interruption",
                    csv_difference(whole + "/run.csv", split + "/run.csv"),
                    1e-12);
    // No previous one to fall back on.
    MPI_Barrier(MPI_COMM_WORLD);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::filesystem::remove(file + ".previous");
        std::filesystem::resize_file(file,
                                     std::filesystem::file_size(file) - 3);
      }
    MPI_Barrier(MPI_COMM_WORLD);
    const std::string message =
      restart_error<dim>(viscous_bar(dim) + output(split, every), file);
    checker.note(message);
    checker.is_true(tag + "a damaged checkpoint without a previous one is an "
                          "input error saying so",
                    message.find("is damaged") != std::string::npos);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_for_dimension(
    argc, argv, 1, [&](const int dim, Checker &checker, bool) {
      const std::string name = argc > 2 ? argv[2] : "";
      if (name == "dynamic")
        dim == 2 ? dynamic<2>(checker) : dynamic<3>(checker);
      else if (name == "quasi_static")
        dim == 2 ? quasi_static<2>(checker) : quasi_static<3>(checker);
      else if (name == "mixed")
        dim == 2 ? mixed<2>(checker) : mixed<3>(checker);
      else if (name == "regions")
        dim == 2 ? regions<2>(checker) : regions<3>(checker);
      else if (name == "mismatch")
        dim == 2 ? mismatch<2>(checker) : mismatch<3>(checker);
      else if (name == "truncated")
        dim == 2 ? truncated<2>(checker) : truncated<3>(checker);
      else
        throw InputError("unknown case '" + name + "'");
    });
}
