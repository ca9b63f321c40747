// The solver's verdict on the inverted cells of a converged state: the
// warning that accepts it or the ConvergenceFailure that rejects it.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/output/inverted_cell_policy.h>

#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  void
  judge_inverted_cells(const InvertedCells<dim> &inverted,
                       const NewtonParameters   &newton,
                       const std::string        &model,
                       const bool                defined,
                       const ConditionalOStream &pcout)
  {
    if (inverted.n_cells == 0)
      return;
    std::ostringstream where;
    where << inverted.n_cells << " inverted cell"
          << (inverted.n_cells == 1 ? "" : "s")
          << " (J <= 0; smallest J = " << inverted.min_J
          << " in the cell centred at (" << inverted.worst_cell_center << "))";
    if (newton.accepts_inverted_elements(defined))
      {
        pcout << "   warning: equilibrium with " << where.str()
              << ", accepted: the " << model
              << " model is defined there ('Newton/Inverted elements at "
                 "equilibrium = warn')"
              << std::endl;
        return;
      }
    std::ostringstream message;
    message << "Newton converged to an equilibrium with " << where.str();
    if (defined)
      message << ", rejected by 'Newton/Inverted elements at equilibrium = "
                 "reject'; the "
              << model
              << " model is defined for J <= 0 and this can be its correct "
                 "discrete answer: set that entry to 'warn' to accept it";
    else
      message << ", where the " << model
              << " model is not defined (infinite energy): not a solution; "
                 "keep 'Newton/Line search = true' (its J > 0 filter keeps "
                 "this model's iterates admissible) or use a model defined "
                 "for J <= 0 (stable neo-Hookean, corotational)";
    throw ConvergenceFailure(message.str());
  }

  template void
  judge_inverted_cells(const InvertedCells<2> &,
                       const NewtonParameters &,
                       const std::string &,
                       bool,
                       const ConditionalOStream &);
  template void
  judge_inverted_cells(const InvertedCells<3> &,
                       const NewtonParameters &,
                       const std::string &,
                       bool,
                       const ConditionalOStream &);
} // namespace hyperelastic
