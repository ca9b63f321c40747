// Problem/Reference = loaded (issue 59, item 3): the mesh is the deformed
// configuration x^ of the body under the scene's loads at t = 1, and the
// reference configuration X whose forward solution x(X) = X + u(X)
// reproduces it is sought (inverse elastostatics).
//
// Method: the backward-displacement fixed point (Sellier 2011; Bols et al.
// 2013), X_(k+1) = X_k + w_k (x^ - x(X_k)), each iterate a forward solve of
// the whole scene on the mesh moved to X_k, with Aitken's dynamic relaxation
// w_k = -w_(k-1) r_(k-1).(r_k - r_(k-1)) / |r_k - r_(k-1)|^2 (w_0 = 1),
// r_k = x^ - x(X_k). It stops when every vertex of x(X_k) lies within
// 'Problem/Reference tolerance' of the mesh's diagonal from its place in
// x^. Every formulation, model and load of the forward problem works as it
// does there (follower pressures on the deformed surface included); why
// this and not the inverse formulation of Govindjee and Mihalic:
// doc/manual.md, "The unloaded shape".
#pragma once

#include <hyperelastic/scene/parameters.h>
#include <hyperelastic/problem/problem.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  /// How the search for the unloaded shape went.
  struct UnloadedShape
  {
    /// Forward solves (the last one from the reference found).
    unsigned int iterations = 0;
    /// max_v |x(X) - x^| / diagonal after each forward solve.
    std::vector<double> distances;
    /// The relaxation factor w_k of each update.
    std::vector<double> relaxation;
    /// Wall time of the whole search and of its first forward solve, s.
    double seconds = 0., first_solve_seconds = 0.;
    /// The loaded mesh's vertex positions on their displacement dofs (0
    /// elsewhere), owned entries.
    VectorType loaded;
  };

  /// Moves @p problem's mesh (the loaded configuration, not yet run) to the
  /// reference configuration that deforms into it, by the iteration above;
  /// @p problem then holds the forward run from it (its summaries, solution
  /// and output). ConvergenceFailure if the tolerance is not reached within
  /// 'Problem/Reference iterations'. Collective.
  template <int dim>
  UnloadedShape
  find_unloaded_shape(Problem<dim>               &problem,
                      const ProblemParameters    &parameters,
                      dealii::ConditionalOStream &pcout);

  /// Writes @p problem's reference mesh as ASCII gmsh 4.1 to @p path: the
  /// mesh file @p mesh_file (the loaded configuration, whose vertices are
  /// at @p loaded: UnloadedShape::loaded) with each node at the reference
  /// position of the vertex that was there, tags and entities unchanged
  /// (the gmsh API). Collective; rank 0 writes.
  template <int dim>
  void
  write_reference_mesh(const Problem<dim> &problem,
                       const VectorType   &loaded,
                       const std::string  &mesh_file,
                       const std::string  &path);
} // namespace hyperelastic
