// The reference directions of up to two fibre families, each given in the
// scene as three expressions of the reference position x, y, z
// ("a_x; a_y; a_z", constant "pi"), normalised where they are evaluated.
// Parsed once with the scene (an unparsable expression is an InputError
// naming the entry); evaluated by a fibre model at a point (once per
// quadrature point, at set-up: assembly/point_materials.h), or once if no
// expression uses x, y or z.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim>
  class FunctionParser;
}

namespace hyperelastic
{
  class FibreDirections
  {
  public:
    /// No family.
    FibreDirections() = default;

    /// One family per nonempty text of @p texts; @p entries name the texts'
    /// scene entries in error messages.
    FibreDirections(const std::vector<std::string> &texts,
                    const std::vector<std::string> &entries);

    unsigned int
    n_families() const
    {
      return families.size();
    }

    /// True if an expression uses x, y or z.
    bool
    depends_on_position() const;

    /// The unit direction of every family at the reference point @p X (a
    /// 2D scene passes z = 0, and its directions must lie in the x-y plane:
    /// @p dim = 2 checks that). An InputError naming the entry if a
    /// direction has zero length (or a z component in 2D) there, or is not
    /// finite.
    std::vector<dealii::Tensor<1, 3>>
    at(const dealii::Point<3> &X, int dim) const;

  private:
    struct Family
    {
      std::string                                      entry;
      std::string                                      text;
      std::shared_ptr<const dealii::FunctionParser<3>> expression;
      bool                                             uses_position = false;
    };
    std::vector<Family> families;
  };
} // namespace hyperelastic
