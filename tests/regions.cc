// Regions (a material per part of the mesh): two materials in series in
// confined tension or compression, and one region equal to the whole mesh.
//
// Series: the bar [0,2] x [0,1] (x [0,1]) with every lateral face on rollers
// and x = 0 held in x is pulled (or pushed) by a dead traction T on x = 2.
// The half x < 1 has the top-level Material, the half x > 1 is Region 1
// (selected by 'Cells = x > 1' on a generated box, or by the gmsh physical
// tag 2 of meshes/two_regions_<dim>d.msh). Each half deforms homogeneously,
// F = diag(l_k, 1, 1), and each stretch satisfies its own model's
// P11(l_k) = T: checked to 1e-10 with the stretches measured at reference
// points (also the mid-points of each half: homogeneity), and each region's
// energy (CSV column energy_region_<k>) against psi_k(l_k) times its volume.
// With the mixed formulation Region 1 is exactly incompressible (bulk
// modulus inf) next to a compressible top-level material, in confined
// compression: its stretch stays 1, the other half follows its model.
//
// Whole: 'Region 1' selecting every cell with the material of a run without
// regions (the top-level Material then softer and unused) gives that run's
// summary columns exactly, bit for bit; also with stiffness warping (each
// region's rest stiffness), and in dynamics with stiffness damping and the
// region's own density.
//
// Contrast: 'Linear solver/AMG for contrast' on a twisted rubber bar with a
// bonded steel band (E 1e4 apart) takes at most 0.8 of the Krylov
// iterations per Newton step without it, and leaves a one-material run
// unchanged (the 2x bound against one material is asserted in
// benchmarks/regions/run.py, at four times the cells).
//
// Usage: regions DIM DEGREE box|gmsh displacement|mixed
//        regions DIM whole [warping|dynamic]
//        regions 3 contrast
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/scene_run.h"
#include "support/scene_text.h"

#include <cmath>
#include <iostream>
#include <map>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  constexpr double tolerance = 1e-10;

  std::string
  series_scene(const int          dim,
               const int          degree,
               const bool         gmsh,
               const bool         mixed,
               const double       traction,
               const unsigned int refine = 1)
  {
    const std::string n1 = std::to_string(refine),
                      n2 = std::to_string(2 * refine),
                      n4 = std::to_string(4 * refine);
    const bool  three    = dim == 3;
    std::string text =
      subsection("Problem",
                 entry("Dimension", std::to_string(dim)) +
                   entry("Finite element degree", std::to_string(degree)) +
                   (mixed ? entry("Formulation", "mixed") +
                              entry("Mixed element",
                                    degree == 2 ? "P2/P1" : "P1-bubble/P1")
                          : ""));
    if (gmsh)
      text +=
        subsection("Mesh",
                   entry("Source", "file") +
                     entry("File",
                           std::string(SOURCE_DIR) + "/meshes/two_regions_" +
                             std::to_string(dim) + "d.msh"));
    else
      text += subsection("Mesh",
                         entry("Source", "box") +
                           entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                           entry("Upper corner", three ? "2, 1, 1" : "2, 1") +
                           entry("Subdivisions",
                                 three ? n4 + ", " + n1 + ", " + n1
                                       : n4 + ", " + n2));
    // Displacement formulation: neo-Hookean next to Mooney-Rivlin. Mixed:
    // a compressible Mooney-Rivlin next to an incompressible decoupled
    // neo-Hookean.
    if (mixed)
      text += subsection("Material",
                         entry("Model", "Mooney-Rivlin") +
                           subsection("Mooney-Rivlin",
                                      entry("C1", "0.3") + entry("C2", "0.1") +
                                        entry("Bulk modulus", "5")));
    else
      text +=
        subsection("Material",
                   entry("Model", "neo-Hookean") +
                     entry("Elastic constants", "Lame") +
                     entry("Shear modulus", "1") + entry("Lame lambda", "2"));
    const std::string region_material =
      mixed
        ? subsection("Material",
                     entry("Model", "decoupled neo-Hookean") +
                       entry("Elastic constants", "shear and bulk modulus") +
                       entry("Shear modulus", "10") +
                       entry("Bulk modulus", "inf"))
        : subsection("Material",
                     entry("Model", "Mooney-Rivlin") +
                       subsection("Mooney-Rivlin",
                                  entry("C1", "2") + entry("C2", "0.5") +
                                    entry("Bulk modulus", "20")));
    text +=
      subsection("Region 1",
                 (gmsh ? entry("Material id", "2") : entry("Cells", "x > 1")) +
                   region_material);
    // Boundary ids: the box's 0 ... 5, the gmsh file's 1 ... 6.
    const int off = gmsh ? 1 : 0;
    text += subsection("Loading", entry("Number of load steps", "3"));
    text += dirichlet(1, 0 + off, "x", "0") + dirichlet(2, 2 + off, "y", "0") +
            dirichlet(3, 3 + off, "y", "0");
    if (three)
      text += dirichlet(4, 4 + off, "z", "0") + dirichlet(5, 5 + off, "z", "0");
    text +=
      subsection("Traction 1",
                 entry("Boundary id", std::to_string(1 + off)) +
                   entry("Traction",
                         number(traction) + "*t; 0" + (three ? "; 0" : "")));
    text += tight_solver("direct");
    const std::string mid = three ? ", 0.5, 0.5" : ", 0.5";
    text += subsection("Output",
                       entry("Write VTU", "false") + entry("Verbose", "false") +
                         entry("Directory", "regions_output") +
                         entry("Points",
                               "0.5" + mid + "; 1" + mid + "; 1.5" + mid +
                                 "; 2" + mid));
    return text;
  }

  /// F = diag(l, 1, 1).
  Tensor<2, 3>
  confined(const double l)
  {
    Tensor<2, 3> F;
    F[0][0] = l;
    F[1][1] = F[2][2] = 1.;
    return F;
  }

  /// The CSV column @p name of @p s (NaN if missing).
  template <int dim>
  double
  column(const StepSummary<dim> &s, const std::string &name)
  {
    for (const auto &[n, value] : s.columns())
      if (n == name)
        return value;
    return std::numeric_limits<double>::quiet_NaN();
  }

  /// The errors of a mixed run against the exact series solution: the
  /// compressible half's P11 (relative to T) and the incompressible half's
  /// stretch.
  struct MixedErrors
  {
    double p11     = 0.;
    double stretch = 0.;
  };

  template <int dim>
  MixedErrors
  run_series(Checker           &checker,
             const int          degree,
             const bool         gmsh,
             const bool         mixed,
             const unsigned int refine = 1)
  {
    const double      traction = mixed ? -0.3 : 0.5;
    const std::string text =
      series_scene(dim, degree, gmsh, mixed, traction, refine);
    Parameters parameters;
    parameters.read_from_string(text);
    Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
    problem.run();
    const StepSummary<dim> &s = problem.summaries().back();
    checker.section(
      std::to_string(dim) + "D P" + std::to_string(degree) +
      (gmsh ? ", gmsh tags" : ", box split by Cells") +
      (mixed ? ", mixed (Region 1 incompressible)" : "") + ", " +
      std::to_string(
        problem.get_dof_handler().get_triangulation().n_global_active_cells()) +
      " cells, " +
      std::to_string(dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)) +
      " rank(s)");
    const auto u = [&](const unsigned int k) {
      return double(s.point_displacements[k][0]);
    };
    const double              l[2]      = {1. + u(1), 1. + (u(3) - u(1))};
    const MaterialParameters *models[2] = {&parameters.material,
                                           &parameters.regions[0].material};
    if (mixed)
      {
        // The pressure jumps at the interface (p = T in the incompressible
        // half, T - P_iso11(l) in the other), which a continuous pressure
        // cannot hold: the error is the interface layer's, and falls with
        // the mesh size.
        const auto  model = create_material<3>(*models[0]);
        MixedErrors errors;
        errors.p11 =
          std::abs(model->first_piola_kirchhoff(confined(l[0]))[0][0] -
                   traction) /
          std::abs(traction);
        errors.stretch = std::abs(l[1] - 1.);
        checker.note("top-level (" + model->name() + ") P11(l = " +
                     number(l[0]) + ") - T: relative " + number(errors.p11) +
                     "; incompressible stretch - 1: " + number(errors.stretch));
        checker.at_most("incompressible Region 1: |stretch - 1|",
                        errors.stretch,
                        1e-3);
        checker.at_most("compressible top-level half: |P11(l) - T| / |T|",
                        errors.p11,
                        1e-2);
        checker.at_most("energy_region_1 of the incompressible half / "
                        "energy_region_0",
                        column(s, "energy_region_1") /
                          column(s, "energy_region_0"),
                        1e-2);
        return errors;
      }
    checker.close("homogeneous top-level half: u(0.5) = u(1) / 2",
                  u(0),
                  u(1) / 2.,
                  std::abs(u(3)),
                  tolerance);
    checker.close("homogeneous Region 1: u(1.5) = (u(1) + u(2)) / 2",
                  u(2),
                  (u(1) + u(3)) / 2.,
                  std::abs(u(3)),
                  tolerance);
    // Each half's own model at its stretch (the scene's models themselves).
    for (unsigned int k = 0; k < 2; ++k)
      {
        const auto        model = create_material<3>(*models[k]);
        const std::string name  = k == 0 ? "top-level" : "Region 1";
        checker.close(name + " (" + model->name() +
                        ") P11(l = " + number(l[k]) + ") = T",
                      model->first_piola_kirchhoff(confined(l[k]))[0][0],
                      traction,
                      std::abs(traction),
                      tolerance);
        // Each half has unit volume (unit thickness in 2D).
        checker.close(name + " energy_region_" + std::to_string(k) +
                        " = psi(l) |half|",
                      column(s, "energy_region_" + std::to_string(k)),
                      model->energy_density(confined(l[k])),
                      std::abs(traction) * std::abs(l[0] - 1.),
                      1e-9);
      }
    return {};
  }

  template <int dim>
  void
  run_whole(Checker &checker, const std::string &variant)
  {
    const bool three   = dim == 3;
    const bool warping = variant == "warping";
    const bool dynamic = variant == "dynamic";
    // Dynamics: Newmark with stiffness damping; the density 2 is the
    // top-level one without regions, Region 1's with them.
    const auto time_integration = [&](const std::string &density) {
      return dynamic ? subsection("Time integration",
                                  entry("Scheme", "Newmark") +
                                    entry("Time step", "0.1") +
                                    entry("End time", "0.3") +
                                    entry("Density", density) +
                                    entry("Stiffness damping", "0.05"))
                     : std::string();
    };
    const auto scene = [&](const std::string &material,
                           const std::string &region) {
      return subsection("Problem", entry("Dimension", std::to_string(dim))) +
             subsection("Mesh",
                        entry("Source", "box") +
                          entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                          entry("Upper corner", three ? "3, 1, 1" : "3, 1") +
                          entry("Subdivisions", three ? "6, 2, 2" : "12, 4")) +
             material + region +
             subsection("Loading",
                        entry("Number of load steps", "3") +
                          entry("Body force",
                                three ? "0; 0; -0.02*t" : "0; -0.02*t")) +
             dirichlet(1,
                       0,
                       three ? "x, y, z" : "x, y",
                       three ? "0; 0; 0" : "0; 0") +
             dirichlet(2,
                       1,
                       three ? "x, y, z" : "x, y",
                       three ? "0.6*t; 0.1*t; 0" : "0.6*t; 0.1*t") +
             subsection("Output",
                        entry("Write VTU", "false") +
                          entry("Directory", "regions_output"));
    };
    const auto elastic = [&](const std::string &E) {
      return subsection("Material",
                        entry("Model",
                              warping ? "stiffness warping" : "neo-Hookean") +
                          entry("Young's modulus", E) +
                          entry("Poisson's ratio", "0.3"));
    };
    const auto one =
      run_scene<dim>(scene(elastic("1"), "") + time_integration("2"));
    const auto region =
      run_scene<dim>(scene(elastic("0.5"),
                           subsection("Region 1",
                                      entry("Cells", "x > -1") +
                                        (dynamic ? entry("Density", "2") : "") +
                                        elastic("1"))) +
                     time_integration("1"));
    checker.section(std::to_string(dim) +
                    "D: Region 1 = the whole mesh against one material" +
                    (warping ? ", stiffness warping" : "") +
                    (dynamic ? ", Newmark with stiffness damping and the "
                               "region's density"
                             : ""));
    checker.is_true("the same number of steps",
                    one->summaries().size() == region->summaries().size());
    unsigned int compared = 0, different = 0;
    for (unsigned int k = 0;
         k < one->summaries().size() && k < region->summaries().size();
         ++k)
      {
        std::map<std::string, double> with_region;
        for (const auto &[name, value] : region->summaries()[k].columns())
          with_region[name] = value;
        for (const auto &[name, value] : one->summaries()[k].columns())
          {
            ++compared;
            const auto it = with_region.find(name);
            if (it == with_region.end() ||
                !(it->second == value ||
                  (std::isnan(it->second) && std::isnan(value))))
              {
                ++different;
                checker.note(
                  "step " + std::to_string(k + 1) + ", " + name + ": " +
                  number(value) + " vs " +
                  (it == with_region.end() ? "missing" : number(it->second)));
              }
          }
      }
    checker.is_true("every column of every step identical (" +
                      std::to_string(compared) + " values)",
                    compared > 0 && different == 0);
    const StepSummary<dim> &last = region->summaries().back();
    checker.is_true("energy_region_0 = 0 (no cell left), energy_region_1 > 0",
                    column(last, "energy_region_0") == 0. &&
                      column(last, "energy_region_1") > 0.);
  }

  /// 'AMG for contrast': the bar of benchmarks/regions/contrast.prm at a
  /// quarter of its cells (24 x 6 x 6 boxes, rubber E = 1, nu = 0.45,
  /// twisted by 60 degrees and pulled, 4 load steps, CG + AMG), alone and
  /// with a bonded steel band (E = 1e4) for 1.5 < x < 2.5. The band with
  /// 'auto' (on) takes at most 0.8 of the Krylov iterations per Newton step
  /// of the band with 'false' (measured 26.3 against 38.8); on the
  /// one-material bar 'auto' is off: the run equals 'false' exactly.
  void
  run_contrast(Checker &checker)
  {
    const auto scene = [](const bool band, const std::string &contrast) {
      return subsection("Problem", entry("Dimension", "3")) +
             subsection("Mesh",
                        entry("Upper corner", "4, 1, 1") +
                          entry("Subdivisions", "24, 6, 6")) +
             subsection("Material",
                        entry("Model", "neo-Hookean") +
                          entry("Young's modulus", "1") +
                          entry("Poisson's ratio", "0.45")) +
             (band ? subsection("Region 1",
                                entry("Cells", "x > 1.5 && x < 2.5") +
                                  subsection("Material",
                                             entry("Model", "neo-Hookean") +
                                               entry("Young's modulus",
                                                     "1e4") +
                                               entry("Poisson's ratio",
                                                     "0.3")))
                   : "") +
             subsection("Loading",
                        entry("Number of load steps", "4") +
                          entry("Constants", "a = 1.0471975511965976")) +
             dirichlet(1, 0, "x, y, z", "0; 0; 0") +
             twisted_end("0.2*t", "a*t") +
             subsection("Linear solver", entry("AMG for contrast", contrast)) +
             subsection("Output",
                        entry("Write VTU", "false") +
                          entry("Directory", "regions_output"));
    };
    /// Krylov iterations per Newton iteration over the run.
    const auto per_newton = [](const Problem<3> &problem) {
      double newton = 0., krylov = 0.;
      for (const StepSummary<3> &s : problem.summaries())
        {
          newton += s.newton_iterations;
          krylov += s.linear_iterations;
        }
      return krylov / newton;
    };
    checker.section("AMG for contrast: a rubber bar with a bonded steel "
                    "band (E 1e4 apart), CG + AMG");
    const double off = per_newton(*run_scene<3>(scene(true, "false")));
    const double on  = per_newton(*run_scene<3>(scene(true, "auto")));
    checker.at_most("Krylov iterations per Newton step, on / off", on / off,
                    0.8);
    const double one_auto  = per_newton(*run_scene<3>(scene(false, "auto")));
    const double one_false = per_newton(*run_scene<3>(scene(false, "false")));
    checker.is_true("one material: 'auto' is 'false' (" + number(one_auto) +
                      " and " + number(one_false) + " per Newton step)",
                    one_auto == one_false);
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               whole =
    (argc == 3 || argc == 4) && std::string(argv[2]) == "whole";
  const bool contrast = argc == 3 && std::string(argv[2]) == "contrast";
  if (argc != 5 && !whole && !contrast)
    {
      std::cerr << "usage: regions DIM DEGREE box|gmsh displacement|mixed\n"
                   "       regions DIM whole [warping|dynamic]\n"
                   "       regions 3 contrast\n";
      return 2;
    }
  const std::string variant = whole && argc == 4 ? argv[3] : "";
  const int         dim     = std::stoi(argv[1]);
  Checker   checker(dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) ==
                  0);
  const int status = run_and_report(
    [&]() {
      if (contrast)
        {
          run_contrast(checker);
          return;
        }
      if (whole)
        {
          if (dim == 2)
            run_whole<2>(checker, variant);
          else
            run_whole<3>(checker, variant);
          return;
        }
      const int  degree  = std::stoi(argv[2]);
      const bool gmsh    = std::string(argv[3]) == "gmsh";
      const bool mixed   = std::string(argv[4]) == "mixed";
      const bool refined = mixed && !gmsh;
      const auto coarse  = dim == 2
                             ? run_series<2>(checker, degree, gmsh, mixed)
                             : run_series<3>(checker, degree, gmsh, mixed);
      if (!refined)
        return;
      // Mixed on the box: the interface layer's error falls with h.
      const auto fine = dim == 2
                          ? run_series<2>(checker, degree, gmsh, mixed, 2)
                          : run_series<3>(checker, degree, gmsh, mixed, 2);
      checker.at_most("P11 error ratio, h/2 against h",
                      fine.p11 / coarse.p11,
                      0.8);
      checker.at_most("stretch error ratio, h/2 against h",
                      fine.stretch / coarse.stretch,
                      0.8);
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
