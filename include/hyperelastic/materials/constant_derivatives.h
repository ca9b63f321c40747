// A capability of a model (opt-in, like the assembly's term capabilities):
// the exact derivatives of its first Piola-Kirchhoff stress with respect to
// its constants, dP/dc_k at F. Calibration (calibration/) fits constants
// with them; a model without this interface cannot be fitted.
//
// Most constants enter P linearly (the moduli: P = sum_k c_k G_k(F) with the
// other constants fixed), so dP/dc_k is the stress of the same model with
// that constant 1 and the other linear ones 0: exact, not a difference.
// The others (Gent's Jm, Arruda-Boyce's locking stretch, Ogden's alpha_p)
// are differentiated analytically by their models.
#pragma once

#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class ConstantDerivatives
  {
  public:
    virtual ~ConstantDerivatives() = default;

    /// The constants, in the order of stress_derivatives(): the entries of
    /// the model's own subsection (Material/<model>) by their names, or
    /// "mu" and "lambda" for a model built from the Lame pair (the scene's
    /// shared elastic constants are converted by the caller).
    virtual std::vector<std::string>
    constant_names() const = 0;

    /// dP/dc_k at @p F for every constant of constant_names().
    virtual std::vector<dealii::Tensor<2, dim>>
    stress_derivatives(const dealii::Tensor<2, dim> &F) const = 0;
  };
} // namespace hyperelastic
