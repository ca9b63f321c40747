// Any model with multiplicative growth or prestrain, F = Fe Fg (issue 59;
// Fg from materials/growth.h). With W the model's energy per unit volume of
// the grown (intermediate) configuration and Jg = det Fg:
//   psi(F) = Jg W(Fe),   Fe = F Fg^-1,
//   P(F)   = Jg P_e(Fe) Fg^-T,
//   dP/dF_iJkL = Jg sum_MN A_e,iMkN(Fe) Fg^-1_JM Fg^-1_LN,
// the chain rule of the model's own P and dP/dF, whatever the model. The
// Cauchy stress P F^T / J = P_e Fe^T / det Fe is that of Fe (residual
// stress), and the stored energy is the elastic one.
//
// Fg is the 3D tensor in 2D too: a plane-strain scene evaluates the model's
// 3D twin at Fe = diag(F, 1) Fg^-1 and keeps the in-plane block of P and of
// dP/dF (growth out of the plane is held by the plane-strain constraint).
//
// Fg varies with the reference position and the load factor t: the scene's
// model hands out a point copy per quadrature point (at_position()), all of
// them sharing one load factor (GrowingMaterial::set_load_factor, set by the
// assemblers before each evaluation); a point copy evaluates Fg once per
// load factor.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <hyperelastic/materials/growth.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/materials/material_registry.h>
#include <hyperelastic/materials/model_capabilities.h>

#include <limits>
#include <memory>
#include <string>

namespace hyperelastic
{
  /// What Grown is built from: the model, the growth entries and the
  /// subsection they are in ('Material', 'Region 2/Material') for messages.
  struct GrowthConstants
  {
    MaterialFactory  elastic;
    GrowthParameters growth;
    std::string      path = "Material";
  };

  template <int dim>
  class Grown : public Material<dim>, public GrowingMaterial
  {
  public:
    using Constants = GrowthConstants;

    /// The scene's model (before at_position()).
    explicit Grown(const GrowthConstants &constants)
        : Grown(std::shared_ptr<const Material<dim>>(
                  constants.elastic.template create<dim>()),
                nullptr,
                std::make_shared<const GrowthLaw>(constants.growth,
                                                  constants.path),
                std::make_shared<double>(0.),
                dealii::Point<3>())
    {
    }

    /// @p elastic (and its 3D twin @p elastic3, made from it if null) grown
    /// by @p law at @p X, at the load factor @p clock.
    Grown(std::shared_ptr<const Material<dim>> elastic,
          std::shared_ptr<const Material<3>>   elastic3,
          std::shared_ptr<const GrowthLaw>     law,
          std::shared_ptr<double>              clock,
          const dealii::Point<3>              &X)
        : elastic(std::move(elastic))
        , elastic3(elastic3 ? std::move(elastic3) : twin_of(*this->elastic))
        , law(std::move(law))
        , clock(std::move(clock))
        , X(X)
    {
      if (const auto *fibres =
            dynamic_cast<const FibreFamilies *>(this->elastic3.get()))
        {
          const auto directions = fibres->fibre_directions();
          if (!directions.empty())
            {
              model_fibre     = directions[0];
              has_model_fibre = true;
            }
        }
    }

    std::string
    name() const override
    {
      return elastic->name() + " with growth";
    }

    double
    energy_density(const Tensor<2, dim> &F) const override
    {
      const State &g = growth();
      return g.J * elastic3->energy_density(embed(F) * g.inverse);
    }

    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override
    {
      const State &g = growth();
      return restrict(g.J *
                      elastic3->first_piola_kirchhoff(embed(F) * g.inverse) *
                      transpose(g.inverse));
    }

    StressTangent<dim>
    stress_tangent(const Tensor<2, dim> &F) const override
    {
      const State &g = growth();
      return pulled_back(elastic3->stress_tangent(embed(F) * g.inverse), g);
    }

    void
    stress_and_tangent(const Tensor<2, dim> &F,
                       Tensor<2, dim>       &P,
                       StressTangent<dim>   &A) const override
    {
      const State  &g = growth();
      Tensor<2, 3>  P3;
      Tensor<4, 3>  A3;
      elastic3->stress_and_tangent(embed(F) * g.inverse, P3, A3);
      P = restrict(g.J * P3 * transpose(g.inverse));
      A = pulled_back(A3, g);
    }

    bool
    defined_for_inverted_elements() const override
    {
      return elastic->defined_for_inverted_elements();
    }

    /// The model's own (at Fg = I).
    LameParameters
    small_strain_moduli() const override
    {
      return elastic->small_strain_moduli();
    }

    std::unique_ptr<Material<3>>
    three_dimensional_twin() const override
    {
      return std::make_unique<Grown<3>>(
        elastic3, elastic3, law, clock, X);
    }

    bool
    depends_on_position() const override
    {
      return true;
    }

    std::unique_ptr<Material<dim>>
    at_position(const dealii::Point<dim> &position) const override
    {
      dealii::Point<3> X3;
      for (unsigned int d = 0; d < dim; ++d)
        X3[d] = position[d];
      if (!elastic->depends_on_position())
        return std::make_unique<Grown<dim>>(
          elastic, elastic3, law, clock, X3);
      return std::make_unique<Grown<dim>>(
        std::shared_ptr<const Material<dim>>(elastic->at_position(position)),
        nullptr,
        law,
        clock,
        X3);
    }

    void
    set_load_factor(const double t) const override
    {
      *clock = t;
    }

    dealii::Tensor<2, 3>
    growth_tensor() const override
    {
      return growth().Fg;
    }

  private:
    /// Fg, its inverse and determinant at one load factor.
    struct State
    {
      double       t = std::numeric_limits<double>::quiet_NaN();
      Tensor<2, 3> Fg, inverse;
      double       J = 1.;
    };

    static std::shared_ptr<const Material<3>>
    twin_of(const Material<dim> &model)
    {
      return std::shared_ptr<const Material<3>>(model.three_dimensional_twin());
    }

    /// Fg at the load factor set (evaluated once per load factor).
    const State &
    growth() const
    {
      if (!(state.t == *clock))
        {
          const dealii::Tensor<1, 3> a =
            law->kind() != GrowthParameters::Kind::fibre || has_model_fibre ?
              model_fibre :
              law->direction(X, *clock);
          state.Fg      = law->at(X, *clock, a);
          state.inverse = invert(state.Fg);
          state.J       = determinant(state.Fg);
          state.t       = *clock;
        }
      return state;
    }

    /// Plane strain: diag(F, 1).
    static Tensor<2, 3>
    embed(const Tensor<2, dim> &F)
    {
      Tensor<2, 3> F3;
      F3[2][2] = 1.;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F3[i][j] = F[i][j];
      return F3;
    }

    static Tensor<2, dim>
    restrict(const Tensor<2, 3> &P3)
    {
      Tensor<2, dim> P;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          P[i][j] = P3[i][j];
      return P;
    }

    /// Jg sum_MN A3_iMkN G_JM G_LN, G = Fg^-1, on the in-plane indices.
    static StressTangent<dim>
    pulled_back(const Tensor<4, 3> &A3, const State &g)
    {
      const Tensor<2, 3> &G = g.inverse;
      StressTangent<dim>  A;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int k = 0; k < dim; ++k)
          {
            // B_ML = sum_N A3_iMkN G_LN.
            Tensor<2, 3> B;
            for (unsigned int M = 0; M < 3; ++M)
              for (unsigned int L = 0; L < 3; ++L)
                for (unsigned int N = 0; N < 3; ++N)
                  B[M][L] += A3[i][M][k][N] * G[L][N];
            for (unsigned int J = 0; J < dim; ++J)
              for (unsigned int L = 0; L < dim; ++L)
                {
                  double sum = 0.;
                  for (unsigned int M = 0; M < 3; ++M)
                    sum += G[J][M] * B[M][L];
                  A[i][J][k][L] = g.J * sum;
                }
          }
      return A;
    }

    std::shared_ptr<const Material<dim>> elastic;
    std::shared_ptr<const Material<3>>   elastic3;
    std::shared_ptr<const GrowthLaw>     law;
    /// The load factor, shared by the scene's model, its point copies and
    /// twins.
    std::shared_ptr<double> clock;
    /// The reference position (the origin for the scene's model).
    dealii::Point<3> X;
    /// The model's fibre family 1 (FibreFamilies), where it has one here.
    dealii::Tensor<1, 3> model_fibre;
    bool                 has_model_fibre = false;
    mutable State        state;
  };
} // namespace hyperelastic
