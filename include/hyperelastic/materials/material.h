// The constitutive interface: a hyperelastic material is a pure function of the
// deformation gradient F giving the energy density psi(F) per unit reference
// volume, the first Piola-Kirchhoff stress P = dpsi/dF and its derivative
// dP/dF. Nothing here knows about meshes, quadrature or MPI.
#pragma once

#include <deal.II/base/tensor.h>

#include <limits>
#include <memory>
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
    explicit Material(const LameParameters &lame)
        : lame(lame)
    {
    }
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

    const LameParameters &
    parameters() const
    {
      return lame;
    }

    /// The rest-state (small-strain) moduli: dP/dF at F = I is their
    /// tensor. For round-off scales, warnings and the run header.
    const LameParameters &
    small_strain_moduli() const
    {
      return lame;
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

    const LameParameters lame;
  };

  /// The model names accepted in a scene, separated by '|' (a parameter
  /// pattern).
  std::string
  material_model_names();

  /// Create the model called @p name (one of material_model_names()).
  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const std::string &name, const LameParameters &lame);

  /// The small-strain elasticity tensor lambda I x I + 2 mu I^sym written as a
  /// dP/dF tensor; every model's tangent equals it at F = I.
  template <int dim>
  StressTangent<dim>
  linear_elastic_tangent(const LameParameters &lame);
} // namespace hyperelastic
