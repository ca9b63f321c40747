// Assembly of forces, tangent and energy with the generic FEValues path (any
// degree). Loads are integrated only when the scene defines them.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/lac/full_matrix.h>

#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/materials/tangent_projection.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  ElasticityOperator<dim>::ElasticityOperator(
    const DoFHandler<dim>         &dof_handler,
    const Mapping<dim>            &mapping,
    const Material<dim>           &material,
    const BoundaryConditions<dim> &boundary_conditions,
    const bool                     fast_p1)
      : dof_handler(dof_handler)
      , mapping(mapping)
      , material(material)
      , boundary_conditions(boundary_conditions)
      , stress_quadrature(QGaussSimplex<dim>(dof_handler.get_fe().degree))
      , load_quadrature(QGaussSimplex<dim>(dof_handler.get_fe().degree + 1))
      , face_quadrature(QGaussSimplex<dim - 1>(dof_handler.get_fe().degree + 1))
  {
    if (fast_p1 && dof_handler.get_fe().degree == 1)
      {
        p1 = std::make_unique<P1Assembler<dim>>(dof_handler, material);
        if (!p1->usable())
          p1.reset();
      }
  }

  namespace
  {
    /// Per-cell data shared by all assembly loops.
    template <int dim>
    struct CellData
    {
      CellData(const Mapping<dim>        &mapping,
               const FiniteElement<dim>  &fe,
               const Quadrature<dim>     &stress_quadrature,
               const Quadrature<dim>     &load_quadrature,
               const Quadrature<dim - 1> &face_quadrature)
          : stress_values(mapping,
                          fe,
                          stress_quadrature,
                          update_gradients | update_JxW_values)
          , load_values(mapping,
                        fe,
                        load_quadrature,
                        update_values | update_quadrature_points |
                          update_JxW_values)
          , face_values(mapping,
                        fe,
                        face_quadrature,
                        update_values | update_quadrature_points |
                          update_JxW_values)
          , dofs(fe.dofs_per_cell)
          , u(fe.dofs_per_cell)
          , F(stress_quadrature.size())
      {
      }

      FEValues<dim>                        stress_values;
      FEValues<dim>                        load_values;
      FEFaceValues<dim>                    face_values;
      std::vector<types::global_dof_index> dofs;
      Vector<double>                       u;
      std::vector<Tensor<2, dim>>          F;
      /// Which load gave a non-finite value: 0 none, 1 the body force,
      /// 2 + k traction k.
      int non_finite_load = 0;
    };

    /// F = I + grad u at the quadrature points of stress_values.
    template <int dim>
    void
    compute_deformation_gradients(CellData<dim> &data)
    {
      const FEValuesExtractors::Vector displacement(0);
      const FEValues<dim>             &fe_values = data.stress_values;
      for (unsigned int q = 0; q < data.F.size(); ++q)
        {
          Tensor<2, dim> F = unit_symmetric_tensor<dim>();
          for (unsigned int i = 0; i < data.u.size(); ++i)
            F += data.u[i] * fe_values[displacement].gradient(i, q);
          data.F[q] = F;
        }
    }

    template <typename Container>
    bool
    all_finite(const Container &v)
    {
      for (const double x : v)
        if (!std::isfinite(x))
          return false;
      return true;
    }

    template <int dim>
    std::string
    point_text(const Point<dim> &p)
    {
      std::ostringstream s;
      s << "(" << p << ")";
      return s.str();
    }

    /// Adds the body force and traction contributions (force vectors and
    /// their work on u) of one cell.
    template <int dim>
    void
    add_loads(CellData<dim>                                        &data,
              const typename DoFHandler<dim>::active_cell_iterator &cell,
              const BoundaryConditions<dim>                        &bc,
              const double                                          t,
              Vector<double>                                       *external,
              double                                               *work)
    {
      const FiniteElement<dim> &fe = cell->get_fe();
      Vector<double>            value(dim);
      if (bc.body_force)
        {
          bc.body_force->set_time(t);
          data.load_values.reinit(cell);
          for (unsigned int q = 0; q < data.load_values.n_quadrature_points;
               ++q)
            {
              bc.body_force->vector_value(data.load_values.quadrature_point(q),
                                          value);
              if (!all_finite(value))
                data.non_finite_load = 1;
              const double JxW = data.load_values.JxW(q);
              for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  const double       f =
                    value[c] * data.load_values.shape_value(i, q) * JxW;
                  if (external)
                    (*external)[i] += f;
                  if (work)
                    *work += f * data.u[i];
                }
            }
        }
      if (bc.tractions.empty() || !cell->at_boundary())
        return;
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          for (const auto &traction : bc.tractions)
            if (cell->face(f)->boundary_id() == traction.id)
              {
                traction.traction->set_time(t);
                data.face_values.reinit(cell, f);
                for (unsigned int q = 0;
                     q < data.face_values.n_quadrature_points;
                     ++q)
                  {
                    traction.traction->vector_value(
                      data.face_values.quadrature_point(q), value);
                    if (!all_finite(value))
                      data.non_finite_load =
                        2 + (&traction - bc.tractions.data());
                    const double JxW = data.face_values.JxW(q);
                    for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
                      {
                        const unsigned int c =
                          fe.system_to_component_index(i).first;
                        const double force =
                          value[c] * data.face_values.shape_value(i, q) * JxW;
                        if (external)
                          (*external)[i] += force;
                        if (work)
                          *work += force * data.u[i];
                      }
                  }
              }
    }
  } // namespace

  template <int dim>
  template <typename CellWorker>
  void
  ElasticityOperator<dim>::for_each_cell(const VectorType &u,
                                         CellWorker      &&worker) const
  {
    CellData<dim> data(mapping,
                       dof_handler.get_fe(),
                       stress_quadrature,
                       load_quadrature,
                       face_quadrature);
    // A failure on one cell (a model undefined at its F, an exception in a
    // material) may happen on one rank only: it is caught here and reported
    // on every rank, so that all of them cut back or stop together.
    std::string error;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          try
            {
              cell->get_dof_indices(data.dofs);
              cell->get_dof_values(u, data.u);
              data.stress_values.reinit(cell);
              compute_deformation_gradients(data);
              worker(cell, data);
            }
          catch (const std::exception &e)
            {
              error = "cell " + std::to_string(cell->active_cell_index()) +
                      " at " + point_text(cell->center()) + ": " +
                      exception_message(e);
              break;
            }
        }
    throw_convergence_failure_if_any(error, dof_handler.get_communicator());
    // Loads are evaluated on each rank's own cells: agree before throwing.
    throw_if_non_finite_load(data.non_finite_load);
  }

  template <int dim>
  void
  ElasticityOperator<dim>::throw_if_non_finite_load(const int non_finite) const
  {
    const int bad =
      Utilities::MPI::max(non_finite, dof_handler.get_communicator());
    if (bad != 0)
      throw InputError(
        "scene entry '" +
        (bad == 1
           ? std::string("Loading/Body force")
           : boundary_conditions.tractions[bad - 2].subsection + "/Traction") +
        "' is not a finite number somewhere on the mesh (a division by zero, "
        "the logarithm of a negative number or similar)");
  }

  template <int dim>
  const VectorType &
  ElasticityOperator<dim>::external_forces(const double t) const
  {
    if (t == external_cache_time)
      return external_cache;
    external_cache.reinit(dof_handler.locally_owned_dofs(),
                          dof_handler.get_communicator());
    if (boundary_conditions.body_force || !boundary_conditions.tractions.empty())
      {
        CellData<dim>  data(mapping,
                           dof_handler.get_fe(),
                           stress_quadrature,
                           load_quadrature,
                           face_quadrature);
        Vector<double> cell_external(dof_handler.get_fe().dofs_per_cell);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() &&
              (boundary_conditions.body_force || cell->at_boundary()))
            {
              cell->get_dof_indices(data.dofs);
              cell_external = 0.;
              add_loads(
                data, cell, boundary_conditions, t, &cell_external, nullptr);
              external_cache.add(data.dofs, cell_external);
            }
        throw_if_non_finite_load(data.non_finite_load);
        external_cache.compress(VectorOperation::add);
      }
    external_cache_time = t;
    return external_cache;
  }

  template <int dim>
  double
  ElasticityOperator<dim>::assemble_forces(const VectorType &u,
                                           const double      t,
                                           VectorType       &internal,
                                           VectorType       &external) const
  {
    if (p1)
      {
        const double magnitude_squared = p1->internal_forces(u, internal);
        external                       = external_forces(t);
        return std::numeric_limits<double>::epsilon() *
               std::sqrt(Utilities::MPI::sum(magnitude_squared,
                                             dof_handler.get_communicator()));
      }
    internal                     = 0.;
    external                     = 0.;
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    Vector<double>            cell_internal(fe.dofs_per_cell);
    Vector<double>            cell_external(fe.dofs_per_cell);
    const double              modulus_scale =
      std::abs(material.small_strain_moduli().mu) +
      std::abs(material.small_strain_moduli().lambda);
    // Round-off of the internal forces: each stress entry carries an error of
    // about eps (|mu| + |lambda|)(1 + |F|^2) (lambda ln J cancels mu F at
    // small strain), spread by the shape gradients; cells add up randomly.
    double magnitude_squared = 0.;
    for_each_cell(u, [&](const auto &cell, CellData<dim> &data) {
      cell_internal                  = 0.;
      cell_external                  = 0.;
      double               magnitude = 0.;
      const FEValues<dim> &fe_values = data.stress_values;
      for (unsigned int q = 0; q < data.F.size(); ++q)
        {
          const Tensor<2, dim> P   = material.first_piola_kirchhoff(data.F[q]);
          const double         JxW = fe_values.JxW(q);
          double               gradient_sum = 0.;
          for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
            {
              const unsigned int c    = fe.system_to_component_index(i).first;
              const auto         grad = fe_values.shape_grad_component(i, q, c);
              cell_internal[i] += (P[c] * grad) * JxW;
              gradient_sum += grad.norm();
            }
          magnitude +=
            modulus_scale * (1. + data.F[q].norm_square()) * gradient_sum * JxW;
        }
      magnitude_squared += magnitude * magnitude;
      add_loads(data, cell, boundary_conditions, t, &cell_external, nullptr);
      if (data.non_finite_load != 0)
        return; // reported collectively by for_each_cell
      internal.add(data.dofs, cell_internal);
      external.add(data.dofs, cell_external);
    });
    internal.compress(VectorOperation::add);
    external.compress(VectorOperation::add);
    return std::numeric_limits<double>::epsilon() *
           std::sqrt(Utilities::MPI::sum(magnitude_squared,
                                         dof_handler.get_communicator()));
  }

  template <int dim>
  void
  ElasticityOperator<dim>::assemble_system(
    const VectorType                &u,
    const double                     t,
    const AffineConstraints<double> &constraints,
    MatrixType                      &matrix,
    VectorType                      &rhs,
    const bool                       project_tangent) const
  {
    // The kernel declines (on all ranks) constraints other than Dirichlet
    // and matrices without its node-block sparsity.
    if (p1 && p1->system(u,
                         external_forces(t),
                         constraints,
                         project_tangent,
                         matrix,
                         rhs))
      return;
    matrix                       = 0.;
    rhs                          = 0.;
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    const unsigned int        n  = fe.dofs_per_cell;
    FullMatrix<double>        cell_matrix(n, n);
    Vector<double>            cell_rhs(n);
    Vector<double>            cell_external(n);
    std::vector<unsigned int> component(n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = fe.system_to_component_index(i).first;
    std::vector<Tensor<1, dim>> grad(n);
    Tensor<2, dim>              P;
    StressTangent<dim>          A;

    for_each_cell(u, [&](const auto &cell, CellData<dim> &data) {
      cell_matrix                    = 0.;
      cell_rhs                       = 0.;
      const FEValues<dim> &fe_values = data.stress_values;
      for (unsigned int q = 0; q < data.F.size(); ++q)
        {
          material.stress_and_tangent(data.F[q], P, A);
          if (project_tangent)
            project_to_positive_semidefinite(A);
          const double JxW = fe_values.JxW(q);
          for (unsigned int i = 0; i < n; ++i)
            grad[i] = fe_values.shape_grad_component(i, q, component[i]);
          for (unsigned int i = 0; i < n; ++i)
            {
              cell_rhs[i] -= (P[component[i]] * grad[i]) * JxW;
              // A[ci][J][cj][L] grad_i[J] grad_j[L]
              const Tensor<3, dim> &A_i = A[component[i]];
              for (unsigned int j = 0; j < n; ++j)
                {
                  double k = 0.;
                  for (unsigned int J = 0; J < dim; ++J)
                    k += grad[i][J] * (A_i[J][component[j]] * grad[j]);
                  cell_matrix(i, j) += k * JxW;
                }
            }
        }
      cell_external = 0.;
      add_loads(data, cell, boundary_conditions, t, &cell_external, nullptr);
      if (data.non_finite_load != 0)
        return; // reported collectively by for_each_cell
      cell_rhs += cell_external;
      // Checked before deal.II sees them (its debug build aborts on NaN).
      if (!all_finite(cell_rhs) || !all_finite(cell_matrix))
        throw std::domain_error(
          "non-finite stress or tangent (the model may be undefined for "
          "this element's deformation, e.g. J <= 0)");
      constraints.distribute_local_to_global(
        cell_matrix, cell_rhs, data.dofs, matrix, rhs, true);
    });
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
  }

  template <int dim>
  EnergyEvaluation
  ElasticityOperator<dim>::evaluate(const VectorType &u,
                                    const double      t,
                                    const bool        with_energy) const
  {
    // The energy density is computed from terms of the size of the moduli
    // (mu (I1 - 3): I1 is about 3), so its round-off is eps times them, not
    // eps times psi; the same holds for the work of the loads.
    const double modulus_scale =
      std::abs(material.small_strain_moduli().mu) +
      std::abs(material.small_strain_moduli().lambda);
    constexpr double round_off = 1e-13;
    double           energy = 0., magnitude = 0.;
    double           min_J = std::numeric_limits<double>::infinity();
    if (p1)
      {
        p1->stored_energy(u, with_energy, energy, magnitude, min_J);
        if (with_energy && (boundary_conditions.body_force ||
                            !boundary_conditions.tractions.empty()))
          {
            // Dead loads: their work is f_ext . u.
            const double work = p1->local_dot(u, external_forces(t));
            energy -= work;
            magnitude += std::abs(work);
          }
      }
    else
      for_each_cell(u, [&](const auto &cell, CellData<dim> &data) {
      for (unsigned int q = 0; q < data.F.size(); ++q)
        {
          min_J = std::min(min_J, static_cast<double>(determinant(data.F[q])));
          if (!with_energy)
            continue;
          const double JxW = data.stress_values.JxW(q);
          const double psi = material.energy_density(data.F[q]);
          energy += psi * JxW;
          magnitude +=
            (std::abs(psi) + modulus_scale * (1. + data.F[q].norm_square())) *
            JxW;
        }
      if (!with_energy)
        return;
      double work = 0.;
      add_loads(data, cell, boundary_conditions, t, nullptr, &work);
      energy -= work;
      magnitude += std::abs(work);
    });
    const MPI_Comm   comm = dof_handler.get_communicator();
    EnergyEvaluation result;
    result.min_J = Utilities::MPI::min(min_J, comm);
    if (with_energy)
      {
        result.energy = Utilities::MPI::sum(energy, comm);
        result.noise  = round_off * Utilities::MPI::sum(magnitude, comm);
      }
    return result;
  }

  namespace
  {
    /// Cauchy stress sigma = P F^T / J as a full 3x3 tensor; in 2D the
    /// plane-strain out-of-plane stress comes from the 3D model at F33 = 1.
    Tensor<2, 3>
    cauchy_stress_3d(const Material<3> &material3d, const Tensor<2, 3> &F)
    {
      return material3d.first_piola_kirchhoff(F) * transpose(F) /
             determinant(F);
    }
  } // namespace

  template <int dim>
  CellFields
  ElasticityOperator<dim>::cell_fields(const VectorType &u, double &min_J) const
  {
    const auto         material3d = material.three_dimensional_twin();
    const unsigned int n_cells =
      dof_handler.get_triangulation().n_active_cells();
    CellFields fields;
    fields.J.reinit(n_cells);
    fields.energy_density.reinit(n_cells);
    fields.von_mises.reinit(n_cells);
    for (auto &c : fields.cauchy)
      c.reinit(n_cells);

    min_J = std::numeric_limits<double>::max();
    for_each_cell(u, [&](const auto &cell, CellData<dim> &data) {
      const unsigned int index  = cell->active_cell_index();
      double             volume = 0.;
      Tensor<2, 3>       sigma;
      for (unsigned int q = 0; q < data.F.size(); ++q)
        {
          const double JxW = data.stress_values.JxW(q);
          Tensor<2, 3> F3  = unit_symmetric_tensor<3>();
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              F3[i][j] = data.F[q][i][j];
          const double J = determinant(data.F[q]);
          min_J          = std::min(min_J, J);
          fields.J[index] += J * JxW;
          fields.energy_density[index] +=
            material.energy_density(data.F[q]) * JxW;
          sigma += cauchy_stress_3d(*material3d, F3) * JxW;
          volume += JxW;
        }
      fields.J[index] /= volume;
      fields.energy_density[index] /= volume;
      sigma /= volume;
      const unsigned int pairs[6][2] = {
        {0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
      for (unsigned int c = 0; c < 6; ++c)
        fields.cauchy[c][index] = sigma[pairs[c][0]][pairs[c][1]];
      const Tensor<2, 3> dev =
        sigma - trace(sigma) / 3. * Tensor<2, 3>(unit_symmetric_tensor<3>());
      fields.von_mises[index] = std::sqrt(1.5 * scalar_product(dev, dev));
    });
    min_J = Utilities::MPI::min(min_J, dof_handler.get_communicator());
    return fields;
  }

  template class ElasticityOperator<2>;
  template class ElasticityOperator<3>;
} // namespace hyperelastic
