// The damping energy of a damped snap step: forces, energy, tangent.
#include <deal.II/base/mpi.h>

#include <hyperelastic/solvers/snap_damping.h>

namespace hyperelastic
{
  using namespace dealii;

  void
  SnapDamping::initialize(const VectorType &metric)
  {
    diagonal = metric;
    centre   = metric;
    centre   = 0.;
    c        = 0.;
  }

  void
  SnapDamping::set(const double factor, const VectorType &at)
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

  void
  SnapDamping::damping_force(const VectorType &u, VectorType &force) const
  {
    force = centre;
    for (const auto i : force.locally_owned_elements())
      force[i] = c * diagonal[i] * (u[i] - centre[i]);
    force.compress(VectorOperation::insert);
  }

  void
  SnapDamping::add_forces(const VectorType &u, VectorType &forces) const
  {
    VectorType force;
    damping_force(u, force);
    forces += force;
  }

  double
  SnapDamping::energy(const VectorType &u) const
  {
    double sum = 0.;
    for (const auto i : centre.locally_owned_elements())
      {
        const double d = u[i] - centre[i];
        sum += 0.5 * c * diagonal[i] * d * d;
      }
    return Utilities::MPI::sum(sum, centre.get_mpi_communicator());
  }

  double
  SnapDamping::force_norm(const VectorType &u) const
  {
    VectorType force;
    damping_force(u, force);
    return force.l2_norm();
  }

  void
  SnapDamping::add_to_system(const VectorType &u,
                             MatrixType       &matrix,
                             VectorType       &rhs) const
  {
    VectorType force;
    damping_force(u, force);
    rhs -= force;
    for (const auto i : diagonal.locally_owned_elements())
      if (diagonal[i] != 0.)
        matrix.add(i, i, c * diagonal[i]);
    matrix.compress(VectorOperation::add);
  }

  double
  SnapDamping::stiffness_ratio(const MatrixType &matrix) const
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
} // namespace hyperelastic
