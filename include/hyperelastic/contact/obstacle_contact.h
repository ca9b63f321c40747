// Contact of the body's boundary vertices with rigid obstacles (planes and
// spheres, moving as expressions of t) through the IPC barrier
//   V(u, t) = kappa sum over boundary vertices a and obstacles k of
//             A_a b(d_k(X_a + u_a, t), d_hat),
// A_a the vertex's share of the boundary's area (2D: length),
// as one load term: forces g = -dV/du, load stiffness d2V/du2 (each vertex's
// dim x dim block projected to positive semi-definite), potential V. Its
// largest feasible step keeps every distance above a tenth of its value along
// a Newton direction (closed form for planes and spheres), so no iterate
// crosses an obstacle.
//
// Distances: plane d = n . (x - p(t)), n the unit normal towards the body;
// sphere d = |x - c(t)| - R (the body outside). Every rank handles the
// boundary vertices whose dofs it owns (P2: the vertices only, not the
// mid-edge nodes); the answer does not depend on the number of ranks.
#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/contact/contact_parameters.h>
#include <hyperelastic/loads/load_term.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/output/step_summary.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class ObstacleContact : public LoadTerm<dim>
  {
  public:
    /// Finds the owned boundary vertices, sets d_hat and kappa (automatic
    /// where the scene gives 0) and checks the start: a vertex on the wrong
    /// side of an obstacle at t = 0 is an InputError naming the obstacle and
    /// the vertex. Collective.
    ObstacleContact(const ContactParameters             &parameters,
                    const std::map<std::string, double> &constants,
                    const dealii::DoFHandler<dim>       &dof_handler,
                    const dealii::Mapping<dim>          &mapping,
                    const LameParameters                &moduli);
    ~ObstacleContact() override;

    std::string
    name() const override
    {
      return "Contact (obstacles)";
    }

    bool
    depends_on_solution() const override
    {
      return true;
    }

    bool
    is_conservative() const override
    {
      return true;
    }

    /// Throws ConvergenceFailure on every rank if a vertex is on the wrong
    /// side of an obstacle (an obstacle moved into the body over the step).
    void
    add_forces(const VectorType &u,
               double            t,
               VectorType       &forces) const override;

    void
    add_load_stiffness(const VectorType                        &u,
                       double                                   t,
                       const dealii::AffineConstraints<double> &constraints,
                       MatrixType                              &matrix,
                       VectorType &rhs) const override;

    /// kappa sum b(d); +infinity if a distance is not positive.
    double
    potential(const VectorType &u, double t) const override;

    double
    largest_feasible_step(const VectorType &u,
                          const VectorType &direction,
                          double            t) const override;

    /// The CSV columns contact_force_<k>_<axis> (the force obstacle k
    /// exerts on the body), contact_min_distance and contact_active_pairs
    /// at @p u (ghosted). Collective.
    void
    summarize(const VectorType &u, double t, StepSummary<dim> &summary) const;

    /// The nodal contact forces on the body at @p u (owned entries).
    void
    contact_forces(const VectorType &u, double t, VectorType &forces) const;

    double
    barrier_distance() const
    {
      return d_hat_value;
    }

    double
    barrier_stiffness() const
    {
      return kappa;
    }

  private:
    /// One boundary vertex: its reference position and its dofs.
    struct Vertex
    {
      dealii::Point<dim>                               X;
      std::array<dealii::types::global_dof_index, dim> dofs;
      /// Its share of the boundary's measure (area in 3D, length in 2D):
      /// the weight of its barrier, so that a uniform contact pressure
      /// gives equal distances.
      double area = 0.;
    };

    /// Distance of @p x to obstacle @p k at @p t, its gradient and Hessian.
    double
    distance(unsigned int              k,
             const dealii::Point<dim> &x,
             double                    t,
             dealii::Tensor<1, dim>   *gradient = nullptr,
             dealii::Tensor<2, dim>   *hessian  = nullptr) const;

    dealii::Point<dim>
    position(const Vertex &v, const VectorType &u) const;

    /// The obstacle's displacement at t.
    dealii::Tensor<1, dim>
    offset(unsigned int k, double t) const;

    const std::vector<ObstacleParameters>               obstacles;
    std::vector<std::unique_ptr<dealii::Function<dim>>> motions;
    const MPI_Comm                                      comm;
    std::vector<Vertex>                                 vertices;
    double                                              d_hat_value = 0.;
    double                                              kappa       = 0.;
  };
} // namespace hyperelastic
