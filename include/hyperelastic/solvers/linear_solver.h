// Linear solves with Trilinos: CG (GMRES when the tangent is not symmetric)
// preconditioned by ML smoothed-aggregation AMG (with the rigid-body modes as
// near-null space), or a direct Amesos solver. Failures become
// ConvergenceFailure on every rank.
#pragma once

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hyperelastic/solvers/linear_solver_parameters.h>
#include <hyperelastic/solvers/saddle_point_preconditioner.h>
#include <hyperelastic/solvers/stiff_subspace_correction.h>
#include <hyperelastic/solvers/tangent_preconditioner.h>

#include <memory>
#include <string>
#include <vector>

namespace hyperelastic
{
  class LinearSolver
  {
  public:
    explicit LinearSolver(const LinearSolverParameters &parameters);

    /// The near-null space for AMG (column-major on the owned rows), and the
    /// number of unknowns per node ("PDE equations" for ML).
    void
    set_near_null_space(std::vector<double> modes,
                        unsigned int        n_modes,
                        unsigned int        n_components);

    /// The ratio of the largest to the smallest stiffness of the scene's
    /// parts (1 for one material): with 'AMG for contrast = auto', above
    /// LinearSolverParameters::contrast_threshold the AMG is built for
    /// contrast. Call before the first prepare().
    void
    set_stiffness_contrast(double ratio);

    /// Whether the AMG is built for contrast ('AMG for contrast').
    bool
    amg_for_contrast() const;

    /// The mixed formulation: the matrices to come are saddle points,
    /// solved with GMRES and @p preconditioner (AMG on their displacement
    /// block, built as below).
    void
    set_saddle_point(std::unique_ptr<SaddlePointPreconditioner> preconditioner)
    {
      saddle_point = std::move(preconditioner);
      symmetric    = false;
    }

    /// The owned unknowns whose couplings in the tangents to come are far
    /// stiffer than the rest (set before each prepare(); empty: none). The
    /// preconditioner then solves on them exactly around the AMG (see
    /// StiffSubspaceCorrection).
    void
    set_stiff_unknowns(const dealii::IndexSet &unknowns)
    {
      stiff_unknowns = unknowns;
    }

    /// Makes the preconditioner ready for @p A: builds the AMG hierarchy the
    /// first time and when the last solve asked for a rebuild; otherwise
    /// keeps the one built for an earlier tangent (see "AMG rebuild
    /// growth"). Nothing for a direct solver, which factorizes in solve().
    void
    prepare(const dealii::TrilinosWrappers::SparseMatrix &A);

    /// Solves A x = b with CG to @p relative_tolerance (the caller chooses
    /// it; inexact Newton loosens it). If CG fails with a reused hierarchy,
    /// rebuilds it and tries once more. Returns the number of Krylov iterations
    /// (0 for a direct solve).
    ///
    /// With @p negative_curvature (CG only: supports_trust_region()), CG
    /// stops where it meets a direction p with p^T A p <= 0 (A is
    /// indefinite) or a residual with r^T M^-1 r <= 0 (the preconditioner
    /// is not positive: built on an indefinite tangent); x is left as CG
    /// had it, and *negative_curvature is set to true (false otherwise).
    unsigned int
    solve(const dealii::TrilinosWrappers::SparseMatrix &A,
          dealii::TrilinosWrappers::MPI::Vector        &x,
          const dealii::TrilinosWrappers::MPI::Vector  &b,
          double                                        relative_tolerance,
          bool *negative_curvature = nullptr);

    /// How solve_in_trust_region() ended.
    struct TrustRegionSolve
    {
      /// Krylov iterations.
      unsigned int iterations = 0;
      /// CG met a direction p with p^T A p <= 0 (A is indefinite) and
      /// followed it to the boundary.
      bool negative_curvature = false;
      /// The step ends on the trust region's boundary (|x| = radius).
      bool on_boundary = false;
    };

    /// Steihaug-Toint truncated CG: x approximately minimizes
    /// q(x) = x^T A x / 2 - b^T x with |x| <= @p radius (Euclidean norm),
    /// preconditioned with the current hierarchy (prepare()). Unlike
    /// solve(), it does not fail on an indefinite A: the first direction of
    /// non-positive curvature, or the first iterate beyond the radius, is
    /// followed to the boundary. Inside it stops at @p relative_tolerance
    /// as solve() does. An infinite @p radius probes A: x is left where CG
    /// met negative curvature. Only for iterative solves of a symmetric
    /// matrix (supports_trust_region()).
    TrustRegionSolve
    solve_in_trust_region(const dealii::TrilinosWrappers::SparseMatrix &A,
                          dealii::TrilinosWrappers::MPI::Vector        &x,
                          const dealii::TrilinosWrappers::MPI::Vector  &b,
                          double relative_tolerance,
                          double radius) const;

    /// Whether solve_in_trust_region() can be used: CG (iterative, a
    /// symmetric tangent, not a saddle point).
    bool
    supports_trust_region() const
    {
      return parameters.type != LinearSolverType::direct && symmetric &&
             !saddle_point;
    }

    /// Krylov solves use @p preconditioner instead of ML AMG on the whole
    /// tangent (the two-level P2 one); it is built when the AMG hierarchy
    /// would be, and counts as an AMG set-up.
    void
    set_preconditioner(std::unique_ptr<TangentPreconditioner> preconditioner)
    {
      replacement = std::move(preconditioner);
    }

    /// Whether the matrices to come are symmetric (CG) or not (GMRES);
    /// symmetric by default.
    void
    set_symmetric(const bool is_symmetric)
    {
      symmetric = is_symmetric;
    }

    /// "CG" or "GMRES": the Krylov method of the iterative solves.
    std::string
    krylov_name() const
    {
      return symmetric ? "CG" : "GMRES";
    }

    /// One line saying which solver runs, for the run header.
    std::string
    description() const;

    /// How often the AMG hierarchy has been computed (built anew or
    /// refreshed on its aggregates).
    unsigned int
    n_preconditioner_setups() const
    {
      return n_setups;
    }

    /// How many of those setups were refreshes on the aggregates of an
    /// earlier build ("AMG reuse aggregates").
    unsigned int
    n_preconditioner_refreshes() const
    {
      return n_refreshes;
    }

    /// Forgets the hierarchy: the next prepare() builds one anew. At a
    /// checkpoint, so that the run and a restart from it solve alike.
    void
    forget_preconditioner()
    {
      amg_built = false;
    }

    /// The counts above, as a checkpoint recorded them.
    void
    set_setup_counts(const unsigned int setups, const unsigned int refreshes)
    {
      n_setups    = setups;
      n_refreshes = refreshes;
    }

  private:
    const LinearSolverParameters               parameters;
    std::vector<double>                        null_space;
    unsigned int                               n_modes      = 0;
    unsigned int                               n_components = 1;
    dealii::TrilinosWrappers::PreconditionAMG  amg;
    std::unique_ptr<SaddlePointPreconditioner> saddle_point;
    std::unique_ptr<TangentPreconditioner>     replacement;
    /// Whether the current hierarchy is the replacement's (false after it
    /// failed for a tangent, until the next rebuild).
    bool replacement_in_use = false;
    /// The displacement rows of null_space (saddle point only).
    std::vector<double> block_null_space;
    /// set_stiffness_contrast().
    double stiffness_contrast = 1.;
    /// set_stiff_unknowns() and the correction built on them.
    dealii::IndexSet        stiff_unknowns;
    StiffSubspaceCorrection stiff_correction;

    /// Computes the hierarchy for @p A now: the replacement preconditioner
    /// if there is one and @p may_use_replacement; else ML, refreshed on
    /// the aggregates of the last full build if @p may_reuse_aggregates
    /// (the caller's verdict, the same on every rank: the matrix is the
    /// object the hierarchy was built on) and the parameters allow it;
    /// otherwise built anew.
    void
    build_amg(const dealii::TrilinosWrappers::SparseMatrix &A,
              bool may_reuse_aggregates,
              bool may_use_replacement);

    /// CG with the current hierarchy; the control tells how it ended.
    dealii::SolverControl
    run_cg(const dealii::TrilinosWrappers::SparseMatrix &A,
           dealii::TrilinosWrappers::MPI::Vector        &x,
           const dealii::TrilinosWrappers::MPI::Vector  &b,
           double                                        tolerance,
           unsigned int                                  max_iterations,
           bool *negative_curvature = nullptr) const;

    /// z = B r: the stiff-subspace correction around
    /// whole_tangent_preconditioner() where there are stiff unknowns,
    /// else that alone.
    void
    precondition(dealii::TrilinosWrappers::MPI::Vector       &z,
                 const dealii::TrilinosWrappers::MPI::Vector &r) const;

    /// z = M^-1 r with the current hierarchy (AMG or the replacement).
    void
    whole_tangent_preconditioner(
      dealii::TrilinosWrappers::MPI::Vector       &z,
      const dealii::TrilinosWrappers::MPI::Vector &r) const;

    /// precondition() for deal.II's Krylov solvers.
    struct Preconditioning
    {
      const LinearSolver &solver;
      void
      vmult(dealii::TrilinosWrappers::MPI::Vector       &z,
            const dealii::TrilinosWrappers::MPI::Vector &r) const
      {
        solver.precondition(z, r);
      }
    };

    /// CG (GMRES if not symmetric) with @p preconditioner.
    template <typename Preconditioner>
    void
    krylov(const dealii::TrilinosWrappers::SparseMatrix &A,
           dealii::TrilinosWrappers::MPI::Vector        &x,
           const dealii::TrilinosWrappers::MPI::Vector  &b,
           const Preconditioner                         &preconditioner,
           dealii::SolverControl                        &control) const;

    bool         amg_built         = false;
    bool         rebuild_requested = false;
    unsigned int n_setups          = 0;
    unsigned int n_refreshes       = 0;
    /// The matrix the hierarchy was last built anew for (a refresh needs
    /// the same Epetra object, with new values).
    const void *amg_matrix = nullptr;
    bool        symmetric  = true;
    /// Iterations per decade of the first solve with the current hierarchy
    /// (negative until it has run).
    double baseline_rate = -1.;
  };
} // namespace hyperelastic
