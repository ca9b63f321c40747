// Kinetic energy, linear and angular momentum of the discrete motion
// (u, v) with the mass matrix of an InertiaTerm:
//   T = 1/2 v.M v,   p = sum_a (M v)_a,   L = sum_a x_a x (M v)_a,
// x_a = X_a + u_a the current position of node a (its support point). For a
// consistent mass these are the exact momenta of the interpolated motion.
#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/dynamics/inertia.h>

#include <array>
#include <vector>

namespace hyperelastic
{
  struct MotionMeasures
  {
    double                 kinetic_energy = 0.;
    dealii::Tensor<1, 3>   linear_momentum; ///< z = 0 in 2D
    dealii::Tensor<1, 3>   angular_momentum; ///< about the origin; 2D: z only
  };

  template <int dim>
  class Motion
  {
  public:
    /// Finds the owned nodes (support points) once.
    Motion(const dealii::DoFHandler<dim> &dof_handler,
           const dealii::Mapping<dim>    &mapping,
           const InertiaTerm<dim>        &inertia);

    /// @p u and @p v with ghost entries (collective).
    MotionMeasures
    measure(const VectorType &u, const VectorType &v) const;

  private:
    struct Node
    {
      dealii::Point<dim>                                   X;
      std::array<dealii::types::global_dof_index, dim> dofs;
    };
    const dealii::DoFHandler<dim> &dof_handler;
    const InertiaTerm<dim>        &inertia;
    std::vector<Node>              nodes;
    mutable VectorType             momentum; ///< M v, owned entries
  };
} // namespace hyperelastic
