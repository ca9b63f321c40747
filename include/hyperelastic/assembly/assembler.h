// The material part of the discrete problem: what an assembler computes for a
// displacement field u (internal forces, tangent, stored energy, smallest J).
// Two implementations: the P1 kernel (assembly/p1_assembler.h) and the
// generic FEValues loops (assembly/generic_assembler.h). Loads are not here:
// they are EnergyTerms (assembly/energy_term.h), added by ElasticityOperator.
#pragma once

#include <deal.II/lac/affine_constraints.h>

#include <hyperelastic/assembly/assembly_tools.h>
#include <hyperelastic/assembly/point_materials.h>
#include <hyperelastic/base/tangent_projection_mode.h>

namespace hyperelastic
{
  template <int dim>
  class Assembler
  {
  public:
    virtual ~Assembler() = default;

    /// Internal forces f_int(u) = int P(F) grad N_a dV on the owned rows
    /// (u with ghost entries). Returns the round-off level of their l2 norm
    /// (collective).
    virtual double
    internal_forces(const VectorType &u, VectorType &internal) const = 0;

    /// Tangent K = d f_int / du and right-hand side -f_int, condensed with
    /// @p constraints (their inhomogeneities imposed: a constrained row reads
    /// d du_r = d g_r). With @p project_tangent, dP/dF is projected to
    /// positive semi-definite first. Returns false, having written nothing,
    /// if this assembler cannot handle @p constraints or @p matrix (the same
    /// answer on all ranks). Collective.
    virtual bool
    system(const VectorType                        &u,
           const dealii::AffineConstraints<double> &constraints,
           TangentProjection                        project_tangent,
           MatrixType                              &matrix,
           VectorType                              &rhs) const = 0;

    /// Stored energy int psi(F) dV (if @p with_energy) with its round-off
    /// level, and the smallest J at the quadrature points. Collective.
    virtual EnergyEvaluation
    stored_energy(const VectorType &u, bool with_energy) const = 0;

    /// The stored energy int psi(F) dV of each region (0: the top-level
    /// Material, then the scene's regions), summed over the ranks; empty if
    /// the material part has no regions to tell apart. Collective.
    virtual std::vector<double>
    region_energies(const VectorType &u) const
    {
      (void)u;
      return {};
    }

    /// Whether the internal forces are the gradient of the stored energy
    /// (then the tangent is symmetric). Not so for stiffness warping.
    virtual bool
    is_conservative() const
    {
      return true;
    }

    /// A model with history (Material::has_history()): the next step
    /// (each attempt of it) lasts @p dt from the last accepted state.
    void
    begin_step(const double dt)
    {
      if (const PointMaterials<dim> *points = point_materials())
        points->begin_step(dt);
    }

    /// A growing model (materials/grown.h): the evaluations to come are at
    /// the load factor @p t (PointMaterials::set_load_factor). Collective.
    void
    set_load_factor(const double t) const
    {
      if (const PointMaterials<dim> *points = point_materials())
        points->set_load_factor(t);
    }

    /// A model with history: the step ended at @p u (ghosted); every
    /// quadrature point writes its new state (each assembler computes F
    /// its own way).
    virtual void
    accept_step(const VectorType &u)
    {
      (void)u;
    }

    /// A model with history: appends the quadrature points' history to
    /// @p state (a checkpoint); load_history() reads it back.
    void
    save_history(std::vector<double> &state) const
    {
      if (const PointMaterials<dim> *points = point_materials())
        points->save_history(state);
    }

    void
    load_history(const std::vector<double> &state, std::size_t &position)
    {
      if (const PointMaterials<dim> *points = point_materials())
        points->load_history(state, position);
    }

  protected:
    /// The model at each quadrature point, where the assembler keeps one
    /// (null: the scene's model everywhere, no history).
    virtual const PointMaterials<dim> *
    point_materials() const
    {
      return nullptr;
    }
  };
} // namespace hyperelastic
