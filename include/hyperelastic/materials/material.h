// The constitutive interface: a hyperelastic material is a pure function of the
// deformation gradient F giving the energy density psi(F) per unit reference
// volume, the first Piola-Kirchhoff stress P = dpsi/dF and its derivative
// dP/dF. Each model holds its own constants; the base class only knows the
// small-strain moduli every model reduces to at F = I. Nothing here knows
// about meshes, quadrature or MPI. Which models exist, and how a scene names
// and parametrises them, is material_registry.h.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <hyperelastic/materials/constant_derivatives.h>
#include <hyperelastic/materials/volumetric_split.h>

#include <limits>
#include <memory>
#include <vector>
#include <string>

namespace hyperelastic
{
  using dealii::Tensor;

  /// The two Lame parameters, and conversion from engineering constants.
  struct LameParameters
  {
    double mu     = 0.;
    double lambda = 0.;

    /// From Young's modulus E and Poisson's ratio nu (3D formulas; plane
    /// strain uses the same lambda).
    static LameParameters
    from_young_poisson(const double E, const double nu);

    double
    young_modulus() const;
    double
    poisson_ratio() const;
  };

  /// dP/dF stored as A[i][J][k][L] = d P_iJ / d F_kL.
  template <int dim>
  using StressTangent = Tensor<4, dim>;

  template <int dim>
  class Material
  {
  public:
    virtual ~Material() = default;

    virtual std::string
    name() const = 0;

    /// Strain energy density psi(F) per unit reference volume. +infinity where
    /// the model is undefined (for example J <= 0 for log-based energies).
    virtual double
    energy_density(const Tensor<2, dim> &F) const = 0;

    /// First Piola-Kirchhoff stress P = dpsi/dF.
    virtual Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const = 0;

    /// Exact derivative dP/dF.
    virtual StressTangent<dim>
    stress_tangent(const Tensor<2, dim> &F) const = 0;

    /// P and dP/dF together; models sharing work between both override this.
    virtual void
    stress_and_tangent(const Tensor<2, dim> &F,
                       Tensor<2, dim>       &P,
                       StressTangent<dim>   &A) const
    {
      P = first_piola_kirchhoff(F);
      A = stress_tangent(F);
    }

    /// True if psi, P and dP/dF are finite for every F with J <= 0.
    virtual bool
    defined_for_inverted_elements() const = 0;

    /// True if P is linear in F (dP/dF constant): one linear solve is the
    /// whole answer.
    virtual bool
    is_linear() const
    {
      return false;
    }

    /// The rest-state (small-strain) moduli: the (mu, lambda) whose tensor
    /// linear_elastic_tangent(mu, lambda) equals dP/dF at F = I. Code that
    /// needs a modulus scale (round-off estimates, the locking warning, the
    /// run header) asks this, whatever the model's own constants are.
    virtual LameParameters
    small_strain_moduli() const = 0;

    /// The same model with the same constants in 3D. For dim = 2 this is the
    /// model whose restriction to F = diag(F, 1) the plane-strain model is,
    /// which gives the out-of-plane stress; for dim = 3 a copy.
    virtual std::unique_ptr<Material<3>>
    three_dimensional_twin() const = 0;

    /// The model's volumetric-isochoric split psi = psi_iso(F) + U(J)
    /// (materials/volumetric_split.h), for the mixed displacement-pressure
    /// formulation; null for a model without one.
    virtual std::unique_ptr<VolumetricSplit<dim>>
    volumetric_split() const
    {
      return nullptr;
    }

    /// True for a model whose constants vary with the reference position
    /// (Holzapfel-Gasser-Ogden with fibre directions given as expressions
    /// of x, y, z). The assemblers then build at_position() once per
    /// quadrature point (assembly/point_materials.h); the other models cost
    /// nothing extra.
    virtual bool
    depends_on_position() const
    {
      return false;
    }

    /// The model with its constants evaluated at the reference point @p X:
    /// a pure function of F again. Only for depends_on_position() models;
    /// the others return a null pointer.
    virtual std::unique_ptr<Material<dim>>
    at_position(const dealii::Point<dim> & /*X*/) const
    {
      return nullptr;
    }

    /// True for a model with history (viscoelasticity): each quadrature
    /// point then holds its own copy (at_position()), whose state is
    /// frozen during a step and written only when the step is accepted.
    virtual bool
    has_history() const
    {
      return false;
    }

    /// A point copy with history: the next step (every attempt of it) has
    /// length @p dt from the last accepted state; a rejected attempt thus
    /// leaves no trace. Within the step the model is a pure function of F.
    virtual void
    begin_step(const double /*dt*/)
    {
    }

    /// A point copy with history: the step ended at @p F; its state
    /// becomes the last accepted one.
    virtual void
    accept_step(const Tensor<2, dim> & /*F*/)
    {
    }

    /// A point copy with history: appends its last accepted state to
    /// @p state (a checkpoint).
    virtual void
    save_history(std::vector<double> & /*state*/) const
    {
    }

    /// A point copy with history: its last accepted state from
    /// @p state at @p position (moved past it), as save_history() wrote it.
    virtual void
    load_history(const std::vector<double> & /*state*/,
                 std::size_t & /*position*/)
    {
    }

  protected:
    /// A tensor of NaNs: P (and each block of dP/dF) where a model is
    /// undefined.
    static Tensor<2, dim>
    not_a_number_tensor()
    {
      Tensor<2, dim> T;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          T[i][j] = std::numeric_limits<double>::quiet_NaN();
      return T;
    }
  };

  /// Base of the models whose constants are the Lame pair (mu, lambda) of
  /// the scene's shared elastic-constant entries (E and nu, Lame, or shear
  /// and bulk modulus): it stores the pair exactly as parsed, so that
  /// small_strain_moduli() returns it bit for bit, and creates the 3D twin.
  /// Every such model's P is linear in (mu, lambda), so the derivatives
  /// with respect to them are the stresses of the model with (1, 0) and
  /// (0, 1) (constant_derivatives.h).
  /// @p Model is the derived class template (curiously recurring).
  template <int dim, template <int> class Model>
  class LameBasedMaterial : public Material<dim>,
                            public ConstantDerivatives<dim>
  {
  public:
    /// The constants a model of this kind is built from.
    using Constants = LameParameters;

    explicit LameBasedMaterial(const LameParameters &lame)
        : lame(lame)
    {
    }

    /// The Lame pair the model was built from (for the models that derive
    /// their own constants from it, their rest-state tangent equals it).
    LameParameters
    small_strain_moduli() const override
    {
      return lame;
    }

    std::unique_ptr<Material<3>>
    three_dimensional_twin() const override
    {
      return std::make_unique<Model<3>>(lame);
    }

    std::vector<std::string>
    constant_names() const override
    {
      return {"mu", "lambda"};
    }

    std::vector<Tensor<2, dim>>
    stress_derivatives(const Tensor<2, dim> &F) const override
    {
      LameParameters unit_mu, unit_lambda;
      unit_mu.mu         = 1.;
      unit_lambda.lambda = 1.;
      return {Model<dim>(unit_mu).first_piola_kirchhoff(F),
              Model<dim>(unit_lambda).first_piola_kirchhoff(F)};
    }

  protected:
    const LameParameters lame;
  };

  /// The registered model names (material_registry.h) in registration
  /// order, separated by '|' (a parameter pattern).
  std::string
  material_model_names();

  /// Create the registered model called @p name with the small-strain moduli
  /// @p small_strain (its tangent at F = I is linear_elastic_tangent of
  /// them). The Lame-based models take the pair as their constants; a model
  /// with constants of its own derives them by the split its registration
  /// documents (Mooney-Rivlin: C1 = 3 mu / 8, C2 = mu / 8, kappa = lambda +
  /// 2 mu / 3). For tests and tools; scenes go through MaterialParameters.
  /// An unknown name throws, listing the registered ones.
  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const std::string &name, const LameParameters &small_strain);

  /// The small-strain elasticity tensor lambda I x I + 2 mu I^sym written as a
  /// dP/dF tensor; every model's tangent equals it at F = I.
  template <int dim>
  StressTangent<dim>
  linear_elastic_tangent(const LameParameters &lame);
} // namespace hyperelastic
