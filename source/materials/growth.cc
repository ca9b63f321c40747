// The entries of Material/Growth and the growth tensor they define
// (materials/growth.h).
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/expressions.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/materials/growth.h>

#include <cmath>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;
  using namespace entry_patterns;

  void
  GrowthParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Growth",
      "none",
      Selection("none|isotropic|fibre|tensor"),
      "Multiplicative growth or prestrain, F = Fe Fg, the energy W(Fe) of "
      "the model per unit grown volume: P = det(Fg) P(F Fg^-1) Fg^-T. "
      "'isotropic': Fg = g I ('Growth stretch'); 'fibre': Fg = g_t I + "
      "(g_f - g_t) a a ('Growth along fibre', 'Growth across fibre'; a: the "
      "model's fibre family 1, or 'Growth direction' for a model without "
      "fibres); 'tensor': Fg = 'Growth tensor' (a prestretch F0 is Fg = "
      "F0^-1). Every value is an expression of x, y, z and the load factor "
      "t (growth is a load path); det Fg <= 0 anywhere is an input error. "
      "Not with the mixed formulation, viscoelasticity or stiffness "
      "warping.");
    prm.declare_entry("Growth stretch",
                      "1",
                      Anything(),
                      "g of 'Growth = isotropic': an expression of x, y, z, "
                      "t (> 0).");
    prm.declare_entry("Growth along fibre",
                      "1",
                      Anything(),
                      "g_f of 'Growth = fibre': the stretch of growth along "
                      "the fibre, an expression of x, y, z, t.");
    prm.declare_entry("Growth across fibre",
                      "1",
                      Anything(),
                      "g_t of 'Growth = fibre': the stretch of growth across "
                      "the fibre, an expression of x, y, z, t.");
    prm.declare_entry("Growth direction",
                      "1; 0; 0",
                      Anything(),
                      "The fibre direction of 'Growth = fibre' for a model "
                      "without fibre families: three expressions of x, y, z, "
                      "t separated by ';' (normalised where evaluated).");
    prm.declare_entry("Growth tensor",
                      "1; 0; 0; 0; 1; 0; 0; 0; 1",
                      Anything(),
                      "Fg of 'Growth = tensor': nine expressions of x, y, z, "
                      "t, row by row, separated by ';' (the 3D tensor also "
                      "in 2D).");
  }

  void
  GrowthParameters::parse(ParameterHandler &prm)
  {
    const std::string k = prm.get("Growth");
    kind = k == "isotropic" ? Kind::isotropic :
           k == "fibre"     ? Kind::fibre :
           k == "tensor"    ? Kind::tensor :
                              Kind::none;
    stretch   = prm.get("Growth stretch");
    along     = prm.get("Growth along fibre");
    across    = prm.get("Growth across fibre");
    direction = prm.get("Growth direction");
    tensor    = prm.get("Growth tensor");
  }

  namespace
  {
    /// The expressions of @p text as a function of (x, y, z, t) with
    /// @p n components; InputError naming @p entry otherwise.
    std::shared_ptr<Function<3>>
    parse(const std::string &text, const unsigned int n, const std::string &entry)
    {
      const std::vector<std::string> expressions = split_expressions(text);
      if (expressions.size() != n)
        reject(entry,
               text,
               "needs " + std::to_string(n) + (n == 1 ? " expression" : " expressions separated by ';'") +
                 " of x, y, z, t");
      return parse_vector_function<3>(expressions, {}, entry);
    }

    std::string
    place(const Point<3> &X, const double t)
    {
      std::ostringstream out;
      out << "at (x, y, z) = (" << X[0] << ", " << X[1] << ", " << X[2]
          << "), t = " << t;
      return out.str();
    }
  } // namespace

  GrowthLaw::GrowthLaw(const GrowthParameters &p, const std::string &path)
      : growth_kind(p.kind)
      , path(path)
  {
    using Kind = GrowthParameters::Kind;
    if (growth_kind == Kind::isotropic)
      {
        entry  = path + "/Growth stretch";
        values = parse(p.stretch, 1, entry);
      }
    else if (growth_kind == Kind::fibre)
      {
        entry  = path + "/Growth along fibre";
        values = parse(p.along + "; " + p.across, 2, entry);
        growth_direction =
          parse(p.direction, 3, path + "/Growth direction");
      }
    else if (growth_kind == Kind::tensor)
      {
        entry  = path + "/Growth tensor";
        values = parse(p.tensor, 9, entry);
      }
  }

  Tensor<1, 3>
  GrowthLaw::direction(const Point<3> &X, const double t) const
  {
    Vector<double> v(3);
    growth_direction->set_time(t);
    growth_direction->vector_value(X, v);
    Tensor<1, 3> a;
    for (unsigned int d = 0; d < 3; ++d)
      a[d] = v[d];
    const double length = a.norm();
    if (!(length > 0.) || !std::isfinite(length))
      throw InputError("scene entry '" + path +
                       "/Growth direction': the direction has no length " +
                       place(X, t));
    return a / length;
  }

  Tensor<2, 3>
  GrowthLaw::at(const Point<3> &X, const double t, const Tensor<1, 3> &fibre) const
  {
    using Kind = GrowthParameters::Kind;
    Tensor<2, 3> Fg;
    if (growth_kind == Kind::none)
      {
        for (unsigned int d = 0; d < 3; ++d)
          Fg[d][d] = 1.;
        return Fg;
      }
    Vector<double> v(values->n_components);
    values->set_time(t);
    values->vector_value(X, v);
    if (growth_kind == Kind::isotropic)
      for (unsigned int d = 0; d < 3; ++d)
        Fg[d][d] = v[0];
    else if (growth_kind == Kind::fibre)
      Fg = v[1] * unit_symmetric_tensor<3>() +
           (v[0] - v[1]) * outer_product(fibre, fibre);
    else
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          Fg[i][j] = v[3 * i + j];
    const double J = determinant(Fg);
    if (!(J > 0.) || !std::isfinite(J))
      {
        std::ostringstream why;
        why << "the growth tensor has det Fg = " << J << " " << place(X, t)
            << " (it must be positive)";
        throw InputError("scene entry '" + entry + "': " + why.str());
      }
    return Fg;
  }
} // namespace hyperelastic
