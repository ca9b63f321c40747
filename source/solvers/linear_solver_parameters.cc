// The scene's Linear solver subsection: declaration, documentation and
// validation of its entries.
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/solvers/linear_solver_parameters.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  using namespace entry_patterns;

  void
  LinearSolverParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Type",
                      "CG with AMG",
                      Selection("CG with AMG|direct"),
                      "'CG with AMG': conjugate gradients preconditioned by "
                      "Trilinos ML algebraic multigrid with all rigid-body "
                      "modes (scales to large meshes); GMRES when the "
                      "tangent is not symmetric, and with 'Problem/"
                      "Formulation = mixed' GMRES with a block "
                      "preconditioner (the AMG on the displacement block, "
                      "a diagonal Schur complement). 'direct': sparse LU "
                      "(robust, for small problems).");
    prm.declare_entry("Relative tolerance",
                      "1e-8",
                      Double(0, 1),
                      "CG stops when the residual is reduced by this factor.");
    prm.declare_entry(
      "Max iterations",
      "1000",
      Integer(1),
      "CG iterations before a linear-solver failure is reported.");
    prm.declare_entry(
      "Direct solver",
      "Amesos_Klu",
      Selection("Amesos_Klu|Amesos_Umfpack|Amesos_Mumps|Amesos_Superludist"),
      "Amesos solver used by Type = direct. Not every Trilinos build has "
      "all of them (Debian 12's: Amesos_Klu and Amesos_Mumps); one that is "
      "missing is rejected at start, with the list of those available.");
    prm.declare_entry("AMG aggregation threshold",
                      "1e-4",
                      Double(0, 1),
                      "ML drops matrix entries below this (relative) when "
                      "forming aggregates.");
    prm.declare_entry(
      "AMG smoother sweeps",
      "1",
      Integer(1, 10),
      "Degree of the Chebyshev smoother on each level (pre- and "
      "post-smoothing). 1 costs more CG iterations than 2 but makes each "
      "one much cheaper: measured on the twisted bar 0.72x the run time at "
      "6e5 unknowns, 0.80x at 1.8e5, 0.89x at 2.5e4 (benchmarks/README.md, "
      "'ML settings tried').");
    prm.declare_entry(
      "AMG smoothed aggregation",
      "true",
      Bool(),
      "true: ML's smoothed aggregation (prolongators smoothed by one damped "
      "Jacobi step, damping 4/3). false: plain aggregation (ML's "
      "'aggregation: damping factor' 0): sparser coarse operators, a "
      "several times cheaper setup, two to three times the CG "
      "iterations, growing with the problem. Measured on the twisted bar "
      "(benchmarks/README.md, 'ML settings tried'): 0.88x the run time at "
      "1.8e5 unknowns, the same at 2.5e4, 1.30x at 1.1e6.");
    prm.declare_entry(
      "AMG rebuild growth",
      "1.5",
      Double(0),
      "The AMG hierarchy (the expensive part of a CG solve) is kept across "
      "Newton iterations and load steps, and rebuilt from the current "
      "tangent once CG needs more than this factor times the iterations per "
      "decade of residual reduction of the first solve with the hierarchy "
      "(and at least 5 more), or when CG fails with an old hierarchy. 0: "
      "rebuild for every solve.");
    prm.declare_entry(
      "AMG reuse aggregates",
      "false",
      Bool(),
      "true: a rebuild for a new tangent (see AMG rebuild growth) keeps the "
      "aggregates of the hierarchy's first build and recomputes only the "
      "prolongators, coarse operators and smoothers from the new matrix "
      "(ML's ReComputePreconditioner); if CG then fails, the hierarchy is "
      "built anew once. false: every rebuild aggregates anew. Measured on "
      "the twisted bar (1.8e5 unknowns, doc/performance.md): the refresh was "
      "only 11 % cheaper than a new build and its hierarchy took 5 to 9 "
      "times the CG iterations, hence false by default.");
    prm.declare_entry(
      "P2 preconditioner",
      "two-level",
      Selection("two-level|AMG"),
      "With Problem/Finite element degree = 2 and Type = CG with AMG (the "
      "displacement formulation): 'two-level': a V-cycle of Chebyshev "
      "smoothing (degree 2, Jacobi-preconditioned) on the P2 tangent and ML "
      "AMG (as configured here, rigid-body modes) on its Galerkin projection "
      "onto the P1 field of the same mesh; 'AMG': ML on the P2 tangent "
      "directly. Measured on the twisted bar's last tangent, 7e3 to 1.6e5 "
      "unknowns (benchmarks/setup/p2_preconditioner.csv): 'two-level' "
      "builds in a fifth to a tenth of ML's time and needs about a third "
      "of its CG iterations (3-7x faster in all), hence the default. If CG "
      "fails with it for a tangent, that solve is repeated with ML on the "
      "whole tangent. The mixed formulation keeps its own block "
      "preconditioner.");
    prm.declare_entry(
      "AMG for contrast",
      "auto",
      Selection("auto|true|false"),
      "ML settings for parts of very different stiffness (steel bonded to "
      "rubber): energy-minimizing prolongators (ML's 'energy minimization', "
      "type 2) instead of damped-Jacobi smoothing, and an 'AMG aggregation "
      "threshold' of at least 0.01, so that aggregates do not straddle a "
      "stiff and a soft part. 'auto': on when the scene's regions (with "
      "cells) differ in small-strain stiffness lambda + 2 mu by more than a "
      "factor 10. Measured on a twisted rubber bar with a bonded steel "
      "band, E 1e4 apart (benchmarks/regions): CG iterations per Newton "
      "step 2.8x the one-material bar's without, 1.5x with, and 0.4x the "
      "run time. Only for the P1 preconditioner and the mixed formulation's "
      "displacement block (the two-level P2 preconditioner keeps its "
      "settings).");
    prm.declare_entry(
      "Exact solve on stiff couplings",
      "false",
      Bool(),
      "Where a term's stiffness is far above the elastic one on a few "
      "unknowns (contact: the barrier and friction between touching "
      "surfaces, up to 1e4 times the elastic stiffness), CG's "
      "preconditioner solves on those unknowns exactly (UMFPACK on their "
      "block of the tangent, gathered on every rank) before and after the "
      "AMG cycle: a symmetric positive definite preconditioner that takes "
      "the stiff modes off the AMG, which its rigid-body aggregates cannot "
      "represent. Costs two more matrix products per CG iteration; nothing "
      "in scenes without such terms. Measured on a TetWild bunny squeezed "
      "between plates (benchmarks/bunny_squeeze): CG iterations per "
      "Newton iteration 120 -> 55, run time 0.59x. Off by default for now: "
      "it moves the stored example scenes' Newton paths (their answers "
      "within Newton's tolerance).");
    prm.leave_subsection();
  }

  void
  LinearSolverParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    type               = prm.get("Type") == "direct" ? LinearSolverType::direct
                                                     : LinearSolverType::cg_amg;
    relative_tolerance = prm.get_double("Relative tolerance");
    if (!(relative_tolerance > 0.))
      reject("Linear solver/Relative tolerance",
             prm.get("Relative tolerance"),
             "must be positive");
    max_iterations             = prm.get_integer("Max iterations");
    direct_solver              = prm.get("Direct solver");
    aggregation_threshold      = prm.get_double("AMG aggregation threshold");
    smoother_sweeps            = prm.get_integer("AMG smoother sweeps");
    smoothed_aggregation       = prm.get_bool("AMG smoothed aggregation");
    amg_rebuild_growth         = prm.get_double("AMG rebuild growth");
    amg_reuse_aggregates       = prm.get_bool("AMG reuse aggregates");
    p2_two_level               = prm.get("P2 preconditioner") == "two-level";
    stiff_couplings_solve      = prm.get_bool("Exact solve on stiff couplings");
    const std::string contrast = prm.get("AMG for contrast");
    amg_for_contrast           = contrast == "auto"   ? Contrast::automatic
                                 : contrast == "true" ? Contrast::on
                                                      : Contrast::off;
    prm.leave_subsection();
  }
} // namespace hyperelastic
