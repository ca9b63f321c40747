// Finite-strain viscoelasticity (Simo 1987; Holzapfel, "Nonlinear Solid
// Mechanics", section 6.10) on any model with a volumetric-isochoric split:
// the second Piola-Kirchhoff stress
//   S = S_eq(F) + sum_j Q_j,
// with one internal stress Q_j per relaxation process (weight beta_j, time
// tau_j, up to three: a Prony series) driven by the isochoric stress
// S_iso = F^-1 P_iso of the equilibrium model:
//   dQ_j/dt + Q_j / tau_j = beta_j dS_iso/dt.
// The recursive update over a step dt (second order in the smooth part,
// unconditionally stable), with g_j = exp(-dt / (2 tau_j)):
//   H_j   = exp(-dt / tau_j) Q_j^n - g_j beta_j S_iso^n      (frozen),
//   Q_j^n+1 = H_j + g_j beta_j S_iso(F^n+1).
// Within a step the stress is therefore a pure function of F,
//   P(F) = P_eq(F) + c P_iso(F) + F H,   c = sum_j g_j beta_j,
//   H = sum_j H_j,
// the derivative of the step's energy
//   psi_step(F) = psi_eq(F) + c psi_iso(F) + H : (C - I) / 2,
// so Newton, its line search and the energy output work unchanged; the
// tangent is dP/dF = A_eq + c A_iso + delta_ik H_JL (consistent).
//
// A held stretch applied in one step relaxes the overstress exactly as
// exp(-t/tau_j) at the discrete times after that step; the jump itself is
// taken with the factor g_j instead of 1 (the integrator's error,
// O(dt / tau_j)).
//
// The scene's model (and its 3D twin, used by the output) is the
// equilibrium part: the long-term response. The model at each quadrature
// point (at_position(), built by the assemblers: assembly/point_materials.h)
// holds Q_j^n and S_iso^n of the last accepted step; begin_step(dt) freezes
// H for every attempt of a step, accept_step(F) writes the new state, so a
// rejected attempt changes nothing. Plane strain: the in-plane components
// of Q_j (the out-of-plane overstress does not enter the in-plane
// equations). The mixed formulation takes the volumetric energy of the
// equilibrium model as its own and this model around the equilibrium's
// isochoric part as the isochoric one (volumetric_split()): its quadrature
// points hold the history there.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/materials/material.h>
#include <hyperelastic/materials/material_registry.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// The Prony series and the time of a quasi-static scene (the entries of
  /// the subsection Material/Viscoelasticity).
  struct ViscoelasticParameters
  {
    std::vector<double> weights;          ///< beta_j >= 0; empty: elastic
    std::vector<double> relaxation_times; ///< tau_j > 0
    std::string         weights_text;     ///< the entry, for messages
    /// The physical time a quasi-static scene's load factor takes from 0
    /// to 1 (a load step of increment dt lasts duration * dt).
    double quasi_static_duration = 1.;

    bool
    active() const
    {
      return !weights.empty();
    }

    static void
    declare(dealii::ParameterHandler &prm);
    /// Inside the subsection Material/Viscoelasticity.
    void
    parse(dealii::ParameterHandler &prm);
  };

  /// The equilibrium model and the series.
  struct ViscoelasticConstants
  {
    MaterialFactory        equilibrium;
    ViscoelasticParameters prony;
  };

  template <int dim>
  class Viscoelastic : public Material<dim>
  {
  public:
    using Constants = ViscoelasticConstants;

    /// The scene's model: the equilibrium part (no history).
    explicit Viscoelastic(const Constants &constants)
        : Viscoelastic(constants, constants.equilibrium.template create<dim>())
    {
    }

    /// With the equilibrium model @p eq (at a point); @p isochoric_only:
    /// @p eq is the isochoric part of the scene's model (the mixed
    /// formulation's, see volumetric_split()).
    Viscoelastic(const Constants               &constants,
                 std::unique_ptr<Material<dim>> eq,
                 const bool                     isochoric_only = false)
        : constants(constants)
        , isochoric_only(isochoric_only)
        , equilibrium(std::move(eq))
        , split(equilibrium->volumetric_split())
        , n_processes(constants.prony.weights.size())
    {
      if (!split)
        throw std::logic_error("viscoelasticity needs a model with a "
                               "volumetric-isochoric split");
    }

    std::string
    name() const override
    {
      return equilibrium->name() + " with viscoelasticity";
    }

    double
    energy_density(const Tensor<2, dim> &F) const override
    {
      double psi = equilibrium->energy_density(F);
      if (!step_active || !std::isfinite(psi))
        return psi;
      const Tensor<2, dim> C = transpose(F) * F;
      return psi + c * split->isochoric->energy_density(F) +
             0.5 * (scalar_product(H, C) - trace(H));
    }

    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override
    {
      Tensor<2, dim> P = equilibrium->first_piola_kirchhoff(F);
      if (step_active)
        P += c * split->isochoric->first_piola_kirchhoff(F) + F * H;
      return P;
    }

    StressTangent<dim>
    stress_tangent(const Tensor<2, dim> &F) const override
    {
      Tensor<2, dim>     P;
      StressTangent<dim> A;
      stress_and_tangent(F, P, A);
      return A;
    }

    void
    stress_and_tangent(const Tensor<2, dim> &F,
                       Tensor<2, dim>       &P,
                       StressTangent<dim>   &A) const override
    {
      equilibrium->stress_and_tangent(F, P, A);
      if (!step_active)
        return;
      Tensor<2, dim>     P_iso;
      StressTangent<dim> A_iso;
      split->isochoric->stress_and_tangent(F, P_iso, A_iso);
      P += c * P_iso + F * H;
      A += c * A_iso;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int J = 0; J < dim; ++J)
          for (unsigned int L = 0; L < dim; ++L)
            A[i][J][i][L] += H[J][L];
    }

    /// The mixed formulation's split: the volumetric energy of the
    /// equilibrium model, and as isochoric part the same viscoelastic model
    /// around the equilibrium's isochoric part (the overstresses, driven by
    /// the isochoric stress, belong to it). P_iso + U'(J) J F^-T is then
    /// this model's P.
    std::unique_ptr<VolumetricSplit<dim>>
    volumetric_split() const override
    {
      return std::make_unique<VolumetricSplit<dim>>(VolumetricSplit<dim>{
        std::make_unique<Viscoelastic<dim>>(
          constants, std::move(equilibrium->volumetric_split()->isochoric), true),
        split->volumetric});
    }

    bool
    defined_for_inverted_elements() const override
    {
      return equilibrium->defined_for_inverted_elements();
    }

    /// The equilibrium (long-term) moduli.
    LameParameters
    small_strain_moduli() const override
    {
      return equilibrium->small_strain_moduli();
    }

    /// The equilibrium part in 3D (output: the long-term stress).
    std::unique_ptr<Material<3>>
    three_dimensional_twin() const override
    {
      return equilibrium->three_dimensional_twin();
    }

    bool
    depends_on_position() const override
    {
      return equilibrium->depends_on_position();
    }

    bool
    has_history() const override
    {
      return true;
    }

    /// A point copy with its own (zero) history.
    std::unique_ptr<Material<dim>>
    at_position(const dealii::Point<dim> &X) const override
    {
      std::unique_ptr<Material<dim>> eq;
      if (equilibrium->depends_on_position())
        eq = equilibrium->at_position(X);
      else if (isochoric_only)
        eq = std::move(
          constants.equilibrium.template create<dim>()->volumetric_split()->isochoric);
      else
        eq = constants.equilibrium.template create<dim>();
      return std::make_unique<Viscoelastic<dim>>(constants,
                                                 std::move(eq),
                                                 isochoric_only);
    }

    void
    begin_step(const double dt) override
    {
      step_active = true;
      c           = 0.;
      H           = Tensor<2, dim>();
      step_H.resize(n_processes);
      step_g.resize(n_processes);
      Q.resize(n_processes);
      for (unsigned int j = 0; j < n_processes; ++j)
        {
          const double beta = constants.prony.weights[j];
          const double tau  = constants.prony.relaxation_times[j];
          step_g[j]         = std::exp(-0.5 * dt / tau);
          step_H[j] = step_g[j] * step_g[j] * Q[j] - step_g[j] * beta * S_iso;
          c += step_g[j] * beta;
          H += step_H[j];
        }
    }

    void
    accept_step(const Tensor<2, dim> &F) override
    {
      const Tensor<2, dim> S =
        invert(F) * split->isochoric->first_piola_kirchhoff(F);
      if (step_active)
        for (unsigned int j = 0; j < n_processes; ++j)
          Q[j] = step_H[j] + step_g[j] * constants.prony.weights[j] * S;
      S_iso = S;
    }

    /// Q_j and S_iso of the last accepted step.
    void
    save_history(std::vector<double> &state) const override
    {
      const auto append = [&](const Tensor<2, dim> &T) {
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            state.push_back(T[i][j]);
      };
      for (unsigned int j = 0; j < n_processes; ++j)
        append(j < Q.size() ? Q[j] : Tensor<2, dim>());
      append(S_iso);
    }

    void
    load_history(const std::vector<double> &state,
                 std::size_t               &position) override
    {
      const auto take = [&](Tensor<2, dim> &T) {
        if (position + dim * dim > state.size())
          throw std::runtime_error("the checkpoint's history ends early");
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            T[i][j] = state[position++];
      };
      Q.resize(n_processes);
      for (unsigned int j = 0; j < n_processes; ++j)
        take(Q[j]);
      take(S_iso);
    }

  private:
    const Constants                       constants;
    const bool                            isochoric_only;
    const std::unique_ptr<Material<dim>>  equilibrium;
    std::unique_ptr<VolumetricSplit<dim>> split;
    const unsigned int                    n_processes;

    // The last accepted state of a point copy.
    std::vector<Tensor<2, dim>> Q;
    Tensor<2, dim>              S_iso;
    // The step's frozen part (after begin_step()).
    bool                        step_active = false;
    double                      c           = 0.;
    Tensor<2, dim>              H;
    std::vector<Tensor<2, dim>> step_H;
    std::vector<double>         step_g;
  };
} // namespace hyperelastic
