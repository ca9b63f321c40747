// The damping energy of snap sub-steps as an energy term (see the header).
#include <deal.II/base/mpi.h>

#include <hyperelastic/assembly/snap_damping.h>

#include <cmath>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  SnapDamping<dim>::SnapDamping(const VectorType &metric)
      : diagonal(metric)
      , centre(metric)
  {
    centre = 0.;
  }

  template <int dim>
  void
  SnapDamping<dim>::set(const double factor, const VectorType &at)
  {
    c = factor;
    if (c > 0.)
      {
        // Owned entries only (the centre may be given with ghosts).
        for (const auto i : centre.locally_owned_elements())
          centre[i] = at[i];
        centre.compress(VectorOperation::insert);
      }
  }

  template <int dim>
  void
  SnapDamping<dim>::damping_force(const VectorType &u, VectorType &force) const
  {
    force = centre;
    for (const auto i : force.locally_owned_elements())
      force[i] = c * diagonal[i] * (u[i] - centre[i]);
    force.compress(VectorOperation::insert);
  }

  template <int dim>
  double
  SnapDamping<dim>::energy(const VectorType &u, double) const
  {
    if (!active())
      return 0.;
    double sum = 0.;
    for (const auto i : centre.locally_owned_elements())
      {
        const double d = u[i] - centre[i];
        sum += 0.5 * c * diagonal[i] * d * d;
      }
    return Utilities::MPI::sum(sum, centre.get_mpi_communicator());
  }

  template <int dim>
  ForceSize
  SnapDamping<dim>::add_forces(const VectorType &u,
                               double,
                               VectorType &forces) const
  {
    // g = -c D (u - w): the residual f_int - f_ext gains c D (u - w).
    if (active())
      {
        VectorType force;
        damping_force(u, force);
        forces -= force;
      }
    return {};
  }

  template <int dim>
  void
  SnapDamping<dim>::add_stiffness(const VectorType &,
                                  double,
                                  TangentProjection,
                                  const AffineConstraints<double> &,
                                  MatrixType &matrix,
                                  VectorType &) const
  {
    // D is zero on constrained rows, which stay as they are.
    if (!active())
      return;
    for (const auto i : diagonal.locally_owned_elements())
      if (diagonal[i] != 0.)
        matrix.add(i, i, c * diagonal[i]);
  }

  template <int dim>
  double
  SnapDamping<dim>::force_norm(const VectorType &u) const
  {
    if (!active())
      return 0.;
    VectorType force;
    damping_force(u, force);
    return force.l2_norm();
  }

  template <int dim>
  double
  SnapDamping<dim>::stiffness_ratio(const MatrixType &matrix) const
  {
    double stiffness = 0., metric = 0.;
    for (const auto i : diagonal.locally_owned_elements())
      if (diagonal[i] != 0.)
        {
          stiffness += std::abs(matrix.diag_element(i));
          metric += diagonal[i];
        }
    const MPI_Comm comm = diagonal.get_mpi_communicator();
    stiffness           = Utilities::MPI::sum(stiffness, comm);
    metric              = Utilities::MPI::sum(metric, comm);
    return metric > 0. ? stiffness / metric : 0.;
  }

  template class SnapDamping<2>;
  template class SnapDamping<3>;
} // namespace hyperelastic
