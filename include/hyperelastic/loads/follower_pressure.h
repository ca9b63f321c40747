// A follower pressure: p(X, t) acting on the deformed surface along its
// deformed normal. By Nanson's formula n da = cof(F) N dA (cof F = J F^-T),
// so node a receives
//   g_a = - int p N_a cof(F) N dA            (reference faces, normal N),
// and the load stiffness is
//   -dg_a/du_b = int p N_a M(b) dA,   M_ik = e_ikm w_m,   w = F (N x grad N_b)
// (the derivative of cof(F) N along grad N_b; plane strain is the 3D formula
// at F = diag(F, 1), N = (N, 0), where M is c [[0, 1], [-1, 0]] with
// c = N x grad N_b). The stiffness is not symmetric in general.
//
// If the loaded faces form a closed surface and p is uniform on it, the load
// is conservative with the potential
//   V(u) = p / dim int x . cof(F) N dA,   x = X + u,
// which is p times the enclosed volume (minus it for a cavity), and the
// assembled stiffness is symmetric: Newton can then use the energy line
// search and CG. Both conditions are checked once, on the mesh and on the
// values of p at the quadrature points for a few load factors.
#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/assembly/energy_term.h>
#include <hyperelastic/loads/loading_parameters.h>

namespace hyperelastic
{
  template <int dim>
  class FollowerPressure : public EnergyTerm<dim>
  {
  public:
    /// @p subsection: the scene section, for messages ("Pressure 1").
    FollowerPressure(dealii::Function<dim>         &pressure,
                     dealii::types::boundary_id     boundary_id,
                     const std::string             &subsection,
                     const dealii::DoFHandler<dim> &dof_handler,
                     const dealii::Mapping<dim>    &mapping);

    /// The scene sections "Pressure 1" ... "Pressure 4".
    static BoundaryLoadKind
    scene_kind()
    {
      BoundaryLoadKind kind;
      kind.name          = "Pressure";
      kind.max_sections  = 4;
      kind.vector_valued = false;
      kind.default_value = "0";
      kind.id_documentation =
        "Boundary id loaded by this pressure; -1 leaves this slot unused.";
      kind.value_documentation =
        "Pressure p (force per unit deformed area, positive pushes into the "
        "body): one expression of the reference position x, y, (z,) and t. "
        "A follower load: it acts along the deformed normal on the deformed "
        "area, p J F^-T N dA, and adds a load stiffness to the tangent "
        "(non-symmetric unless the loaded surface is closed and p uniform, "
        "when the load has the potential p times the enclosed volume).";
      return kind;
    }

    std::string
    name() const override
    {
      return subsection + "/Pressure";
    }

    /// Conservative on a closed loaded surface with uniform p.
    TermKind
    kind() const override
    {
      return conservative ? TermKind::conservative : TermKind::non_conservative;
    }

    ForceSize
    add_forces(const VectorType &u,
               double            t,
               VectorType       &forces) const override;

    void
    add_stiffness(const VectorType                        &u,
                  double                                   t,
                  TangentProjection                        projection,
                  const dealii::AffineConstraints<double> &constraints,
                  MatrixType                              &matrix,
                  VectorType                              &rhs) const override;

    double
    energy(const VectorType &u, double t) const override;

  private:
    struct FaceData;

    /// Calls @p worker(data) for each loaded face of the owned cells, with
    /// F, cof(F) N and p at its quadrature points in data; then checks
    /// (collectively) that p was finite.
    template <typename FaceWorker>
    void
    for_each_face(const VectorType &u, double t, FaceWorker &&worker) const;

    /// Whether every ridge (vertex in 2D, edge in 3D) of the loaded faces is
    /// shared by exactly two of them, over all ranks.
    bool
    surface_is_closed() const;

    /// Whether p takes one value on the whole surface at a few load factors.
    bool
    pressure_is_uniform() const;

    dealii::Function<dim>            &pressure;
    const dealii::types::boundary_id  boundary_id;
    const std::string                 subsection;
    const dealii::DoFHandler<dim>    &dof_handler;
    const dealii::Mapping<dim>       &mapping;
    const dealii::Quadrature<dim - 1> quadrature;
    bool                              conservative = false;
  };
} // namespace hyperelastic
