// Multiplicative growth and prestrain, F = Fe Fg (issue 59): the entries of
// Material/Growth and the growth tensor Fg(X, t) they define.
//
//   none       Fg = I;
//   isotropic  Fg = g I, g = 'Growth stretch';
//   fibre      Fg = g_t I + (g_f - g_t) a (x) a, g_f = 'Growth along fibre',
//              g_t = 'Growth across fibre', a the unit direction of the
//              model's fibre family 1 (Holzapfel-Gasser-Ogden), or of
//              'Growth direction' for a model without fibres;
//   tensor     Fg = 'Growth tensor', nine expressions row by row. A
//              prestrain F0 (the stretch a body carries before it is loaded)
//              is Fg = F0^-1.
// Every value is an expression of the reference position x, y, z (z = 0 in
// 2D) and of the load factor t: growth is a load path. Fg is the full 3D
// tensor also in plane strain (Fg_zz = g: growth out of the plane is held
// by the plane-strain constraint).
#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>

namespace hyperelastic
{
  struct GrowthParameters
  {
    enum class Kind
    {
      none,
      isotropic,
      fibre,
      tensor
    };
    Kind        kind      = Kind::none;
    std::string stretch   = "1";
    std::string along     = "1";
    std::string across    = "1";
    std::string direction = "1; 0; 0";
    std::string tensor    = "1; 0; 0; 0; 1; 0; 0; 0; 1";

    /// Declares the entries in the current subsection (Material).
    static void
    declare(dealii::ParameterHandler &prm);

    /// Reads them from the current subsection (Material).
    void
    parse(dealii::ParameterHandler &prm);
  };

  /// Fg(X, t) of a GrowthParameters, its expressions parsed.
  class GrowthLaw
  {
  public:
    /// @p path names the subsection in messages ('Material', 'Region 2/
    /// Material'). InputError naming the entry if an expression does not
    /// parse or a list has the wrong length.
    GrowthLaw(const GrowthParameters &parameters, const std::string &path);

    GrowthParameters::Kind
    kind() const
    {
      return growth_kind;
    }

    /// Fg at the reference point @p X and load factor @p t; @p fibre is the
    /// unit fibre direction there (used by Kind::fibre only). InputError
    /// naming the entry, the place and t if det Fg <= 0 or an entry is not
    /// finite there.
    dealii::Tensor<2, 3>
    at(const dealii::Point<3>     &X,
       double                      t,
       const dealii::Tensor<1, 3> &fibre) const;

    /// The unit 'Growth direction' at @p X and @p t (Kind::fibre for a model
    /// without fibre families). InputError if it vanishes there.
    dealii::Tensor<1, 3>
    direction(const dealii::Point<3> &X, double t) const;

  private:
    GrowthParameters::Kind growth_kind;
    std::string            path;
    /// The entry of 'values' for messages.
    std::string entry;
    /// The kind's values (1 stretch, 2 fibre stretches or 9 entries).
    std::shared_ptr<dealii::Function<3>> values;
    /// 'Growth direction' (Kind::fibre).
    std::shared_ptr<dealii::Function<3>> growth_direction;
  };
} // namespace hyperelastic
