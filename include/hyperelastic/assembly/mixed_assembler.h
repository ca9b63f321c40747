// The material part of the displacement-pressure (mixed) formulation
// (materials/volumetric_split.h):
//   Pi(u, p) = int psi_iso(F) + p (J - 1) - U*(p) dV [- stabilisation],
//   R_u = int (P_iso + p J F^-T) : grad du dV,
//   R_p = int (J - J*(p)) dp dV            (J*(p) - 1 = U*'(p)),
// with its exact tangent (symmetric, a saddle point):
//   K_uu = int grad du : (A_iso + p J (G (x) G - G [x] G)) : grad Du,
//   K_up = int J G : grad du Dp,   K_pp = -int U*''(p) dp Dp,
// G = F^-T, (G [x] G)_iJkL = G_iL G_kJ. The unknowns are one vector over a
// DoFHandler of dim displacement components and one pressure component.
//
// Elements (Problem/Mixed element):
//  - P1-bubble/P1 (MINI): P1 displacement enriched by a cell bubble
//    b = 27 l1 l2 l3 (2D), 256 l1 l2 l3 l4 (3D) per component. The bubble
//    couples only within its cell: its equations R_b = 0 are solved on the
//    cell (a small Newton iteration) for every state, and the cell's system
//    is condensed, K* = K_rr - K_rb K_bb^-1 K_br, which is the exact tangent
//    of the reduced residual (implicit function theorem). The global system
//    holds P1 u and P1 p only.
//  - P1/P1 stabilised (Dohrmann-Bochev 2004): equal-order P1 with
//    -1/mu int (p - Pi0 p)(q - Pi0 q) dV added to the p-p block (Pi0: cell
//    mean), i.e. -1/(2 mu) int (p - Pi0 p)^2 dV added to Pi.
//  - P2/P1 (Taylor-Hood).
#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/assembly/assembler.h>
#include <hyperelastic/assembly/constant_forces.h>
#include <hyperelastic/assembly/mixed_element.h>
#include <hyperelastic/assembly/point_materials.h>
#include <hyperelastic/materials/volumetric_split.h>

#include <memory>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class MixedAssembler : public Assembler<dim>, public ConstantForces<dim>
  {
  public:
    /// @p material must have a volumetric split (checked when the scene is
    /// read); the DoFHandler's element is (P_k)^dim x P1.
    MixedAssembler(const dealii::DoFHandler<dim> &dof_handler,
                   const dealii::Mapping<dim>    &mapping,
                   const MaterialRegions<dim>    &material,
                   MixedElement                   element);
    ~MixedAssembler();

    /// [R_u; R_p] (owned rows). Non-finite entries where a cell has J <= 0.
    double
    internal_forces(const VectorType &u, VectorType &internal) const override;

    bool
    system(const VectorType                        &u,
           const dealii::AffineConstraints<double> &constraints,
           TangentProjection                        project_tangent,
           MatrixType                              &matrix,
           VectorType                              &rhs) const override;

    /// Pi(u, p) without external work (a saddle value, not a minimum) and the
    /// smallest J.
    EnergyEvaluation
    stored_energy(const VectorType &u, bool with_energy) const override;

    /// Pi(u, p) of each region's cells.
    std::vector<double>
    region_energies(const VectorType &u) const override;

    /// Every owned cell's points write their state at @p u (ghosted), the
    /// bubble solved (MINI).
    void
    accept_step(const VectorType &u) override;

    /// [dR_u/dc_k; dR_p/dc_k] (source/assembly/mixed_constant_forces.cc):
    /// the isochoric stress's dP_iso/dc_k = dP/dc_k of the isochoric model
    /// minus dkappa/dc_k (J^2 - 1)/2 F^-T, the pressure rows'
    /// -dJ*(p)/dkappa dkappa/dc_k, the stabilisation's d(1/mu)/dc_k, and
    /// MINI's bubble condensed: dr/dc = dR_r/dc - K_rb K_bb^-1 dR_b/dc.
    /// Empty also where the model's bulk modulus is neither its entry
    /// 'Bulk modulus' nor lambda + 2 mu / 3 of its Lame pair.
    std::vector<VectorType>
    constant_forces(const VectorType &u,
                    const VectorType &like) const override;

  protected:
    /// The isochoric part at each point (with viscoelasticity it holds the
    /// overstresses).
    const PointMaterials<dim> *
    point_materials() const override
    {
      return &isochoric;
    }

  private:
    struct CellData;
    struct CellResult;

    /// Calls @p worker for every owned cell with its data, the bubble solved
    /// (MINI) and the residual, and the matrix if @p with_matrix.
    template <typename Worker>
    void
    for_each_cell(const VectorType &u,
                  bool              with_matrix,
                  TangentProjection project_tangent,
                  Worker          &&worker) const;

    /// What evaluate_cell() computes: the bubble's own block (residual
    /// rows and matrix of the bubble unknowns, for its cell solve), the
    /// residual and energy, or the residual, energy and whole matrix.
    enum class CellOutput
    {
      bubble_block,
      residual,
      residual_and_matrix
    };

    /// The cell's residual (and matrix) at its current values and bubble.
    void
    evaluate_cell(CellData         &data,
                  CellOutput        output,
                  TangentProjection project_tangent) const;

    /// The pressure-projection stabilisation of 'P1/P1 stabilized' added to
    /// the cell's energy, residual (and matrix, @p with_matrix): the
    /// pressure @p p_q at each quadrature point, its mean @p p_mean over the
    /// cell of measure @p volume.
    void
    add_stabilization(CellData                  &data,
                      const std::vector<double> &p_q,
                      double                     p_mean,
                      double                     volume,
                      bool                       with_matrix) const;

    enum class BubbleOutcome
    {
      converged,
      inadmissible, ///< a point with J <= 0 on the way
      not_converged
    };

    /// MINI: Newton on the cell's bubble equations from data.bubble.
    BubbleOutcome
    iterate_bubble(CellData &data, TangentProjection project_tangent) const;

    /// MINI: solve the cell's bubble equations (from the cell's last
    /// bubble, else from zero), then evaluate and condense.
    void
    solve_bubble(CellData         &data,
                 bool              with_matrix,
                 TangentProjection project_tangent) const;

    const dealii::DoFHandler<dim> &dof_handler;
    const dealii::Mapping<dim>    &mapping;
    const MaterialRegions<dim>     material;
    /// The split of each region's model.
    std::vector<std::unique_ptr<VolumetricSplit<dim>>> split;
    const MixedElement                                 element;
    const dealii::Quadrature<dim>                      quadrature;
    /// The isochoric part at each quadrature point.
    const PointMaterials<dim> isochoric;
    /// 1/mu of the stabilisation (P1/P1), of each region.
    std::vector<double> inverse_shear_modulus;
    /// MINI: the last converged bubble of each cell (dim values per active
    /// cell index), the start of its next cell solve: Newton and line-search
    /// states are close to each other, so one or two local iterations do.
    mutable std::vector<double> bubble_cache;
  };
} // namespace hyperelastic
