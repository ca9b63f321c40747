// Rigid motions of the unheld bodies: the tangent's regularization and the
// removal of the unresisted motions from Newton's updates.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/constraints/unheld_rigid_motions.h>
#include <hyperelastic/materials/tangent_projection.h>
#include <hyperelastic/mesh/bodies.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// Modified Gram-Schmidt with global dot products (collective); a
    /// vector of zero norm stays zero.
    void
    orthonormalize(std::vector<VectorType> &vectors)
    {
      for (unsigned int i = 0; i < vectors.size(); ++i)
        {
          for (unsigned int j = 0; j < i; ++j)
            vectors[i].add(-(vectors[i] * vectors[j]), vectors[j]);
          const double norm = vectors[i].l2_norm();
          if (norm > 0.)
            vectors[i] /= norm;
        }
    }
  } // namespace

  template <int dim>
  UnheldRigidMotions<dim>::UnheldRigidMotions(
    const Mapping<dim>                 &mapping,
    const DoFHandler<dim>              &dof_handler,
    const std::set<types::boundary_id> &dirichlet_ids,
    const bool                          frictional)
      : frictional(frictional)
      , comm(dof_handler.get_communicator())
      , owned(dof_handler.locally_owned_dofs())
  {
    std::vector<unsigned int>    body_of_cell;
    const std::vector<Body<dim>> all =
      find_bodies(dof_handler, dirichlet_ids, &body_of_cell);
    std::vector<int> unheld_index(all.size(), -1);
    for (unsigned int b = 0; b < all.size(); ++b)
      if (!all[b].held)
        {
          unheld_index[b] = bodies.size();
          bodies.emplace_back();
        }
    if (bodies.empty())
      return;

    // The displacement nodes: support point j of the first base element,
    // its dim unknowns component_to_system_index(c, j).
    const FiniteElement<dim> &fe      = dof_handler.get_fe();
    const unsigned int        n_nodes = fe.base_element(0).n_dofs_per_cell();
    FEValues<dim>             fe_values(mapping,
                            fe,
                            Quadrature<dim>(fe.get_unit_support_points()),
                            update_quadrature_points);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::set<types::global_dof_index>    seen;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          unheld_index[body_of_cell[cell->active_cell_index()]] >= 0)
        {
          UnheldBody &body =
            bodies[unheld_index[body_of_cell[cell->active_cell_index()]]];
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int j = 0; j < n_nodes; ++j)
            {
              Node node;
              for (unsigned int c = 0; c < dim; ++c)
                node.dofs[c] = dofs[fe.component_to_system_index(c, j)];
              if (!owned.is_element(node.dofs[0]) ||
                  !seen.insert(node.dofs[0]).second)
                continue;
              node.X =
                fe_values.quadrature_point(fe.component_to_system_index(0, j));
              body.nodes.push_back(node);
            }
        }
  }

  template <int dim>
  void
  UnheldRigidMotions<dim>::regularize(MatrixType &tangent)
  {
    for (UnheldBody &body : bodies)
      {
        double sum = 0., count = 0.;
        for (const Node &node : body.nodes)
          for (const auto i : node.dofs)
            sum += std::abs(tangent.diag_element(i)), count += 1.;
        sum        = Utilities::MPI::sum(sum, comm);
        count      = Utilities::MPI::sum(count, comm);
        body.scale = count > 0. ? sum / count : 0.;
        body.beta  = 1e-8 * body.scale;
        for (const Node &node : body.nodes)
          for (const auto i : node.dofs)
            tangent.add(i, i, body.beta);
      }
    tangent.compress(VectorOperation::add);
  }

  template <int dim>
  std::vector<VectorType>
  UnheldRigidMotions<dim>::motions(const UnheldBody &body,
                                   const VectorType &u) const
  {
    // About the body's centre (better conditioned than the origin).
    Tensor<1, dim> centre;
    for (const Node &node : body.nodes)
      for (unsigned int c = 0; c < dim; ++c)
        centre[c] += node.X[c] + u(node.dofs[c]);
    const double n = Utilities::MPI::sum(double(body.nodes.size()), comm);
    centre         = Utilities::MPI::sum(centre, comm) / std::max(n, 1.);

    std::vector<VectorType> r(n_modes);
    for (VectorType &v : r)
      v.reinit(owned, comm);
    for (const Node &node : body.nodes)
      {
        Tensor<1, dim> x;
        for (unsigned int c = 0; c < dim; ++c)
          x[c] = node.X[c] + u(node.dofs[c]) - centre[c];
        for (unsigned int c = 0; c < dim; ++c)
          r[c](node.dofs[c]) = 1.;
        if constexpr (dim == 2)
          {
            r[2](node.dofs[0]) = -x[1];
            r[2](node.dofs[1]) = x[0];
          }
        else
          // Rotations about x, y, z: e_k x (x - centre).
          for (unsigned int k = 0; k < 3; ++k)
            {
              const unsigned int a = (k + 1) % 3, b = (k + 2) % 3;
              r[3 + k](node.dofs[a]) = -x[b];
              r[3 + k](node.dofs[b]) = x[a];
            }
      }
    for (VectorType &v : r)
      v.compress(VectorOperation::insert);
    orthonormalize(r);
    return r;
  }

  template <int dim>
  unsigned int
  UnheldRigidMotions<dim>::pin_unresisted(const VectorType &u,
                                          const MatrixType &tangent,
                                          const VectorType &rhs,
                                          const double      force_scale)
  {
    unsigned int pinned = 0;
    for (UnheldBody &body : bodies)
      {
        body.pinned.clear();
        const std::vector<VectorType> r = motions(body, u);
        // The tangent (without beta) restricted to the rigid motions.
        SmallMatrix<n_modes> S{};
        VectorType           Kr(owned, comm);
        for (unsigned int j = 0; j < n_modes; ++j)
          {
            tangent.vmult(Kr, r[j]);
            for (unsigned int i = 0; i <= j; ++i)
              S[i][j] = r[i] * Kr - (i == j ? body.beta : 0.);
          }
        std::array<double, n_modes> values;
        SmallMatrix<n_modes>        vectors;
        jacobi_eigen_decomposition<n_modes>(S, values, vectors);
        const double largest = *std::max_element(values.begin(), values.end());
        // Resisted: an eigenvalue of the order of the supports' stiffness
        // (the largest one: a plate pressing along its normal). A support
        // that only nearly resists counts as none.
        const double resisted = frictional
                                  ? 1e-6 * body.scale
                                  : std::max(1e-6 * body.scale, 1e-2 * largest);
        for (unsigned int k = 0; k < n_modes; ++k)
          {
            if (!(values[k] <= resisted) ||
                (frictional && !(std::abs(values[k]) <= resisted)))
              continue;
            VectorType v(owned, comm);
            for (unsigned int i = 0; i < n_modes; ++i)
              v.add(vectors[i][k], r[i]);
            // A net force of the size of the loads along the motion (the
            // body pushed along a tilted support) moves the body by
            // Newton's step instead.
            if (!(std::abs(v * rhs) <=
                  (frictional ? 1e-10 : 1e-4) * force_scale))
              continue;
            std::array<double, n_modes> c;
            for (unsigned int i = 0; i < n_modes; ++i)
              c[i] = vectors[i][k];
            body.pinned.push_back(c);
          }
        if (!frictional)
          snap_to_axes(body, r, rhs, force_scale);
        pinned += body.pinned.size();
      }
    return pinned;
  }

  template <int dim>
  void
  UnheldRigidMotions<dim>::snap_to_axes(UnheldBody                    &body,
                                        const std::vector<VectorType> &r,
                                        const VectorType              &rhs,
                                        const double force_scale) const
  {
    const unsigned int m = body.pinned.size();
    if (m == 0 || m == n_modes)
      return;
    // w_i = |P e_i|^2, e_i the i-th orthonormal rigid motion, P the
    // projector on the pinned ones.
    std::array<double, n_modes>       w{};
    std::array<unsigned int, n_modes> order;
    for (unsigned int i = 0; i < n_modes; ++i)
      {
        order[i] = i;
        for (const auto &c : body.pinned)
          w[i] += c[i] * c[i];
      }
    std::sort(order.begin(), order.end(), [&](const auto a, const auto b) {
      return w[a] > w[b];
    });
    // Each of the m motions most inside the pinned span almost wholly in
    // it (supports along the axes): those pure motions are pinned instead.
    for (unsigned int j = 0; j < m; ++j)
      if (!(w[order[j]] >= 0.99) ||
          !(std::abs(r[order[j]] * rhs) <= 1e-4 * force_scale))
        return;
    body.pinned.clear();
    for (unsigned int j = 0; j < m; ++j)
      {
        std::array<double, n_modes> c{};
        c[order[j]] = 1.;
        body.pinned.push_back(c);
      }
  }

  template <int dim>
  unsigned int
  UnheldRigidMotions<dim>::n_pinned() const
  {
    unsigned int n = 0;
    for (const UnheldBody &body : bodies)
      n += body.pinned.size();
    return n;
  }

  template <int dim>
  std::vector<VectorType>
  UnheldRigidMotions<dim>::pinned_motions(const VectorType &u) const
  {
    std::vector<VectorType> V;
    for (const UnheldBody &body : bodies)
      {
        if (body.pinned.empty())
          continue;
        const std::vector<VectorType> r = motions(body, u);
        for (const auto &c : body.pinned)
          {
            VectorType v(owned, comm);
            for (unsigned int i = 0; i < n_modes; ++i)
              v.add(c[i], r[i]);
            V.push_back(std::move(v));
          }
      }
    // Orthonormal (those of one body are, up to round-off; different
    // bodies have disjoint unknowns).
    orthonormalize(V);
    return V;
  }

  template <int dim>
  double
  UnheldRigidMotions<dim>::project_out_pinned(const VectorType &u,
                                              VectorType       &v) const
  {
    double removed = 0.;
    for (const VectorType &p : pinned_motions(u))
      {
        const double c = p * v;
        v.add(-c, p);
        removed += c * c;
      }
    return std::sqrt(removed);
  }

  template <int dim>
  void
  UnheldRigidMotions<dim>::constrain_update(
    const VectorType                                            &u,
    const std::function<void(const VectorType &, VectorType &)> &solve,
    VectorType                                                  &update) const
  {
    const std::vector<VectorType> V = pinned_motions(u);
    const unsigned int            k = V.size();
    if (k == 0)
      return;
    // Nothing along the pinned motions: the update is the constrained one
    // already (a support flat to round-off, the body's energy invariant).
    Vector<double> Vd(k);
    double         along = 0.;
    for (unsigned int i = 0; i < k; ++i)
      Vd[i] = V[i] * update, along += Vd[i] * Vd[i];
    if (std::sqrt(along) <= 1e-12 * update.l2_norm())
      return;
    // Z = K^{-1} V, M = V^T Z; the constrained minimizer of the quadratic
    // model is update - Z M^{-1} V^T update (its residual lies in span V).
    std::vector<VectorType> Z(k, VectorType(owned, comm));
    FullMatrix<double>      M(k, k);
    for (unsigned int j = 0; j < k; ++j)
      {
        solve(V[j], Z[j]);
        for (unsigned int i = 0; i < k; ++i)
          M(i, j) = V[i] * Z[j];
      }
    // M is symmetric positive definite for a tangent positive definite;
    // where it is not invertible, the components are only removed.
    bool invertible = true;
    try
      {
        M.gauss_jordan();
      }
    catch (...)
      {
        invertible = false;
      }
    if (invertible)
      {
        Vector<double> mu(k);
        M.vmult(mu, Vd);
        for (unsigned int j = 0; j < k; ++j)
          if (std::isfinite(mu[j]))
            update.add(-mu[j], Z[j]);
      }
    // Exactly without components along them (the solves are inexact).
    project_out_pinned(u, update);
  }

  template class UnheldRigidMotions<2>;
  template class UnheldRigidMotions<3>;
} // namespace hyperelastic
