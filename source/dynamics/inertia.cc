// The inertia term of an implicit time step: cell mass matrices from the
// reference simplex's (the mapping is affine), forces, stiffness, potential.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/dynamics/inertia.h>
#include <hyperelastic/mesh/mesh_checks.h>

#include <cmath>
#include <limits>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  InertiaTerm<dim>::InertiaTerm(const DoFHandler<dim> &dof_handler,
                                const double           density,
                                const bool             lumped,
                                std::vector<double>    cell_density)
      : dof_handler(dof_handler)
      , density(density)
      , cell_density(std::move(cell_density))
      , lumped(lumped)
  {
    const FiniteElement<dim> &base = dof_handler.get_fe().base_element(0);
    const unsigned int        n    = base.dofs_per_cell;
    const QGaussSimplex<dim>  rule(base.degree + 1);
    reference_mass.reinit(n, n);
    for (unsigned int q = 0; q < rule.size(); ++q)
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < n; ++b)
          reference_mass(a, b) += base.shape_value(a, rule.point(q)) *
                                  base.shape_value(b, rule.point(q)) *
                                  rule.weight(q);
    if (lumped)
      {
        // HRZ: the diagonal scaled to the element's mass (for P1 the row
        // sums; for P2 it keeps every vertex mass positive).
        double diagonal = 0., total = 0.;
        for (unsigned int a = 0; a < n; ++a)
          {
            diagonal += reference_mass(a, a);
            for (unsigned int b = 0; b < n; ++b)
              total += reference_mass(a, b);
          }
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            reference_mass(a, b) =
              a == b ? reference_mass(a, a) * total / diagonal : 0.;
      }
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    target.reinit(dof_handler.locally_owned_dofs(),
                  relevant,
                  dof_handler.get_communicator());
    own_forces.reinit(dof_handler.locally_owned_dofs(),
                      dof_handler.get_communicator());
    own_round_off.reinit(own_forces);
  }

  template <int dim>
  template <typename Worker>
  void
  InertiaTerm<dim>::for_each_cell(Worker &&worker) const
  {
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    const unsigned int                   n  = fe.dofs_per_cell;
    std::vector<types::global_dof_index> dofs(n);
    FullMatrix<double>                   cell_mass(n, n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          const double scale =
            (cell_density.empty() ? density
                                  : cell_density[cell->active_cell_index()]) *
            std::abs(simplex_measure<dim>([&](const unsigned int k)
                                            -> const Point<dim> & {
                       return cell->vertex(k);
                     }).det);
          for (unsigned int i = 0; i < n; ++i)
            {
              const auto [ci, ki] = fe.system_to_component_index(i);
              for (unsigned int j = 0; j < n; ++j)
                {
                  const auto [cj, kj] = fe.system_to_component_index(j);
                  cell_mass(i, j)     = (ci == cj && ci < dim)
                                          ? scale * reference_mass(ki, kj)
                                          : 0.;
                }
            }
          worker(dofs, cell_mass);
        }
  }

  template <int dim>
  void
  InertiaTerm<dim>::set_step(const double c, const VectorType &w)
  {
    this->c = c;
    target  = w;
  }

  template <int dim>
  template <typename Worker>
  void
  InertiaTerm<dim>::for_each_cell_product(const VectorType &v,
                                          const VectorType *subtracted,
                                          Worker          &&worker) const
  {
    Vector<double> d, product;
    for_each_cell([&](const auto &dofs, const FullMatrix<double> &m) {
      d.reinit(dofs.size());
      product.reinit(dofs.size());
      for (unsigned int i = 0; i < dofs.size(); ++i)
        d[i] = v(dofs[i]) - (subtracted ? (*subtracted)(dofs[i]) : 0.);
      m.vmult(product, d);
      worker(dofs, d, product);
    });
  }

  template <int dim>
  ForceSize
  InertiaTerm<dim>::add_forces(const VectorType &u,
                               const double,
                               VectorType &forces) const
  {
    // The term's own forces -c M (u - w) and the bound c |M| (|u| + |w|) eps
    // of their round-off (the entries of u and w carry eps of their size,
    // and their difference is far smaller in a long rigid motion: a body
    // 50 units down keeps falling 0.0004 a step), each assembled on its own
    // for its norm, then added to @p forces.
    own_forces    = 0.;
    own_round_off = 0.;
    Vector<double> d, product, size;
    for_each_cell([&](const auto &dofs, const FullMatrix<double> &m) {
      const unsigned int n = dofs.size();
      d.reinit(n);
      product.reinit(n);
      size.reinit(n);
      for (unsigned int i = 0; i < n; ++i)
        d[i] = u(dofs[i]) - target(dofs[i]);
      m.vmult(product, d);
      product *= -c;
      own_forces.add(dofs, product);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          size[i] += std::abs(m(i, j)) *
                     (std::abs(u(dofs[j])) + std::abs(target(dofs[j])));
      size *= c * std::numeric_limits<double>::epsilon();
      own_round_off.add(dofs, size);
    });
    own_forces.compress(VectorOperation::add);
    own_round_off.compress(VectorOperation::add);
    std::vector<types::global_dof_index> rows;
    std::vector<double>                  values;
    for (const auto i : own_forces.locally_owned_elements())
      {
        rows.push_back(i);
        values.push_back(own_forces(i));
      }
    forces.add(rows, values);
    return {own_forces.l2_norm(), own_round_off.l2_norm()};
  }

  template <int dim>
  void
  InertiaTerm<dim>::add_stiffness(const VectorType &,
                                  const double,
                                  TangentProjection,
                                  const AffineConstraints<double> &constraints,
                                  MatrixType                      &matrix,
                                  VectorType                      &rhs) const
  {
    FullMatrix<double> scaled;
    for_each_cell([&](const auto &dofs, const FullMatrix<double> &m) {
      scaled.reinit(m.m(), m.n());
      scaled.add(c, m);
      add_condensed(scaled, dofs, constraints, matrix, rhs);
    });
  }

  template <int dim>
  double
  InertiaTerm<dim>::energy(const VectorType &u, const double) const
  {
    double sum = 0.;
    for_each_cell_product(u,
                          &target,
                          [&](const auto &,
                              const Vector<double> &d,
                              const Vector<double> &Md) {
                            sum += 0.5 * c * (d * Md);
                          });
    return Utilities::MPI::sum(sum, dof_handler.get_communicator());
  }

  template <int dim>
  void
  InertiaTerm<dim>::mass_product(const VectorType &v, VectorType &product) const
  {
    product = 0.;
    for_each_cell_product(v,
                          nullptr,
                          [&](const auto &dofs,
                              const auto &,
                              const Vector<double> &Mv) {
                            product.add(dofs, Mv);
                          });
    product.compress(VectorOperation::add);
  }

  template <int dim>
  void
  InertiaTerm<dim>::solve_mass(const VectorType                &b,
                               const AffineConstraints<double> &constraints,
                               VectorType                      &x) const
  {
    // Jacobi-preconditioned CG; the mass matrix is well conditioned (its
    // condition number does not grow with refinement), so a few tens of
    // iterations reach round-off.
    VectorType diagonal(b), r(b), z(b), p(b), q(b);
    VectorType ghosted(target);
    diagonal = 0.;
    for_each_cell([&](const auto &dofs, const FullMatrix<double> &m) {
      Vector<double> d(dofs.size());
      for (unsigned int i = 0; i < dofs.size(); ++i)
        d[i] = m(i, i);
      diagonal.add(dofs, d);
    });
    diagonal.compress(VectorOperation::add);
    const auto apply = [&](const VectorType &in, VectorType &out) {
      ghosted = in;
      mass_product(ghosted, out);
      constraints.set_zero(out);
    };
    const auto precondition = [&](const VectorType &in, VectorType &out) {
      out = in;
      for (const auto i : out.locally_owned_elements())
        out(i) = diagonal(i) > 0. ? in(i) / diagonal(i) : 0.;
      constraints.set_zero(out);
    };
    x = 0.;
    r = b;
    constraints.set_zero(r);
    const double target_norm = 1e-12 * r.l2_norm();
    precondition(r, z);
    p            = z;
    double rho_k = r * z;
    for (unsigned int k = 0; k < 1000 && r.l2_norm() > target_norm; ++k)
      {
        apply(p, q);
        const double alpha = rho_k / (p * q);
        x.add(alpha, p);
        r.add(-alpha, q);
        precondition(r, z);
        const double rho_next = r * z;
        p.sadd(rho_next / rho_k, 1., z);
        rho_k = rho_next;
      }
    AssertThrow(!(r.l2_norm() > target_norm),
                ExcMessage("the mass-matrix solve did not converge"));
  }

  template class InertiaTerm<2>;
  template class InertiaTerm<3>;
} // namespace hyperelastic
