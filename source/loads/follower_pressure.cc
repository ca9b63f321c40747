// The follower pressure: forces, load stiffness and potential on the loaded
// faces, and the one-off checks that decide whether it is conservative.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/loads/follower_pressure.h>
#include <hyperelastic/loads/load_terms.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// cof(F) = J F^-T, written without the inverse (defined for any F).
    template <int dim>
    Tensor<2, dim>
    cofactor(const Tensor<2, dim> &F)
    {
      Tensor<2, dim> C;
      if constexpr (dim == 2)
        {
          C[0][0] = F[1][1];
          C[0][1] = -F[1][0];
          C[1][0] = -F[0][1];
          C[1][1] = F[0][0];
        }
      else
        // Column J is the cross product of the next two columns of F.
        for (unsigned int J = 0; J < 3; ++J)
          {
            const unsigned int a = (J + 1) % 3, b = (J + 2) % 3;
            for (unsigned int i = 0; i < 3; ++i)
              {
                const unsigned int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
                C[i][J] = F[i1][a] * F[i2][b] - F[i2][a] * F[i1][b];
              }
          }
      return C;
    }

    /// M_ik: the derivative of cof(F) N along grad N_b (header comment).
    template <int dim>
    Tensor<2, dim>
    cofactor_normal_derivative(const Tensor<2, dim> &F,
                               const Tensor<1, dim> &N,
                               const Tensor<1, dim> &grad)
    {
      Tensor<2, dim> M;
      if constexpr (dim == 2)
        {
          const double c = N[0] * grad[1] - N[1] * grad[0];
          M[0][1]        = c;
          M[1][0]        = -c;
        }
      else
        {
          const Tensor<1, 3> w = F * cross_product_3d(N, grad);
          M[0][1]              = w[2];
          M[0][2]              = -w[1];
          M[1][0]              = -w[2];
          M[1][2]              = w[0];
          M[2][0]              = w[1];
          M[2][1]              = -w[0];
        }
      return M;
    }
  } // namespace

  template <int dim>
  struct FollowerPressure<dim>::FaceData
  {
    FaceData(const Mapping<dim>        &mapping,
             const FiniteElement<dim>  &fe,
             const Quadrature<dim - 1> &quadrature)
        : values(mapping,
                 fe,
                 quadrature,
                 update_values | update_gradients | update_normal_vectors |
                   update_quadrature_points | update_JxW_values)
        , dofs(fe.dofs_per_cell)
        , u(fe.dofs_per_cell)
        , component(fe.dofs_per_cell)
        , F(quadrature.size())
        , cofactor_normal(quadrature.size())
        , p(quadrature.size())
    {
      for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
        {
          component[i] = fe.system_to_component_index(i).first;
          if (component[i] < dim)
            displacement.push_back(i);
        }
    }

    FEFaceValues<dim>                    values;
    std::vector<types::global_dof_index> dofs;
    Vector<double>                       u;
    std::vector<unsigned int>            component;
    /// The displacement shape functions (all but a mixed pressure's).
    std::vector<unsigned int>   displacement;
    std::vector<Tensor<2, dim>> F;
    /// cof(F) N at the quadrature points.
    std::vector<Tensor<1, dim>> cofactor_normal;
    std::vector<double>         p;
  };

  template <int dim>
  FollowerPressure<dim>::FollowerPressure(Function<dim>           &pressure,
                                          const types::boundary_id boundary_id,
                                          const std::string       &subsection,
                                          const DoFHandler<dim>   &dof_handler,
                                          const Mapping<dim>      &mapping)
      : pressure(pressure)
      , boundary_id(boundary_id)
      , subsection(subsection)
      , dof_handler(dof_handler)
      , mapping(mapping)
      , quadrature(QGaussSimplex<dim - 1>(dof_handler.get_fe().degree + 1))
  {
    conservative = surface_is_closed() && pressure_is_uniform();
  }

  template <int dim>
  template <typename FaceWorker>
  void
  FollowerPressure<dim>::for_each_face(const VectorType &u,
                                       const double      t,
                                       FaceWorker      &&worker) const
  {
    FaceData data(mapping, dof_handler.get_fe(), quadrature);
    pressure.set_time(t);
    bool finite = true;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == boundary_id)
            {
              data.values.reinit(cell, f);
              cell->get_dof_indices(data.dofs);
              cell->get_dof_values(u, data.u);
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  Tensor<2, dim> F = unit_symmetric_tensor<dim>();
                  for (const unsigned int i : data.displacement)
                    F[data.component[i]] +=
                      data.u[i] *
                      data.values.shape_grad_component(i, q, data.component[i]);
                  data.F[q] = F;
                  data.cofactor_normal[q] =
                    cofactor(F) * data.values.normal_vector(q);
                  data.p[q] = pressure.value(data.values.quadrature_point(q));
                  finite    = finite && std::isfinite(data.p[q]);
                }
              worker(data);
            }
    throw_if_load_not_finite(!finite, name(), dof_handler.get_communicator());
  }

  template <int dim>
  ForceSize
  FollowerPressure<dim>::add_forces(const VectorType &u,
                                    const double      t,
                                    VectorType       &forces) const
  {
    Vector<double> cell_forces(dof_handler.get_fe().dofs_per_cell);
    for_each_face(u, t, [&](const FaceData &data) {
      cell_forces = 0.;
      for (unsigned int q = 0; q < data.p.size(); ++q)
        {
          const double pJxW = data.p[q] * data.values.JxW(q);
          for (const unsigned int i : data.displacement)
            cell_forces[i] -= pJxW * data.values.shape_value(i, q) *
                              data.cofactor_normal[q][data.component[i]];
        }
      forces.add(data.dofs, cell_forces);
    });
    return {};
  }

  template <int dim>
  void
  FollowerPressure<dim>::add_stiffness(
    const VectorType &u,
    const double      t,
    TangentProjection,
    const AffineConstraints<double> &constraints,
    MatrixType                      &matrix,
    VectorType                      &rhs) const
  {
    const unsigned int n = dof_handler.get_fe().dofs_per_cell;
    FullMatrix<double> cell_matrix(n, n);
    for_each_face(u, t, [&](const FaceData &data) {
      cell_matrix = 0.;
      for (unsigned int q = 0; q < data.p.size(); ++q)
        {
          const double          pJxW = data.p[q] * data.values.JxW(q);
          const Tensor<1, dim> &N    = data.values.normal_vector(q);
          for (const unsigned int j : data.displacement)
            {
              const Tensor<2, dim> M = cofactor_normal_derivative(
                data.F[q],
                N,
                data.values.shape_grad_component(j, q, data.component[j]));
              for (const unsigned int i : data.displacement)
                cell_matrix(i, j) += pJxW * data.values.shape_value(i, q) *
                                     M[data.component[i]][data.component[j]];
            }
        }
      add_condensed(cell_matrix, data.dofs, constraints, matrix, rhs);
    });
  }

  template <int dim>
  double
  FollowerPressure<dim>::energy(const VectorType &u, const double t) const
  {
    double sum = 0.;
    for_each_face(u, t, [&](const FaceData &data) {
      for (unsigned int q = 0; q < data.p.size(); ++q)
        {
          Tensor<1, dim> x = data.values.quadrature_point(q);
          for (const unsigned int i : data.displacement)
            x[data.component[i]] += data.u[i] * data.values.shape_value(i, q);
          sum += data.p[q] / dim * (x * data.cofactor_normal[q]) *
                 data.values.JxW(q);
        }
    });
    return Utilities::MPI::sum(sum, dof_handler.get_communicator());
  }

  template <int dim>
  bool
  FollowerPressure<dim>::surface_is_closed() const
  {
    // A ridge (vertex in 2D, edge in 3D) as its sorted vertex coordinates:
    // the same on every rank, since all cells come from one serial mesh.
    constexpr unsigned int n_values = dim * (dim - 1); // 2D: 1 point, 3D: 2
    std::vector<double>    local;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == boundary_id)
            {
              const auto face = cell->face(f);
              if constexpr (dim == 2)
                for (const unsigned int v : face->vertex_indices())
                  for (unsigned int d = 0; d < dim; ++d)
                    local.push_back(face->vertex(v)[d]);
              else
                for (unsigned int l = 0; l < face->n_lines(); ++l)
                  {
                    std::array<Point<dim>, 2> ends = {{face->line(l)->vertex(0),
                                                       face->line(l)->vertex(1)}};
                    const auto                less = [](const Point<dim> &a,
                                         const Point<dim> &b) {
                      return std::lexicographical_compare(a.begin_raw(),
                                                          a.end_raw(),
                                                          b.begin_raw(),
                                                          b.end_raw());
                    };
                    std::sort(ends.begin(), ends.end(), less);
                    for (const auto &p : ends)
                      for (unsigned int d = 0; d < dim; ++d)
                        local.push_back(p[d]);
                  }
            }
    const auto all =
      Utilities::MPI::all_gather(dof_handler.get_communicator(), local);
    std::map<std::vector<double>, unsigned int> count;
    for (const auto &part : all)
      for (unsigned int k = 0; k + n_values <= part.size(); k += n_values)
        ++count[std::vector<double>(part.begin() + k,
                                    part.begin() + k + n_values)];
    if (count.empty())
      return false;
    for (const auto &ridge : count)
      if (ridge.second != 2)
        return false;
    return true;
  }

  template <int dim>
  bool
  FollowerPressure<dim>::pressure_is_uniform() const
  {
    const MPI_Comm comm = dof_handler.get_communicator();
    // The displacement does not matter: only the points and p are used.
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    const VectorType zero(dof_handler.locally_owned_dofs(), relevant, comm);
    for (const double t : {0.25, 0.5, 1.})
      {
        double low = std::numeric_limits<double>::infinity(), high = -low;
        for_each_face(zero, t, [&](const FaceData &data) {
          for (const double p : data.p)
            {
              low  = std::min(low, p);
              high = std::max(high, p);
            }
        });
        if (Utilities::MPI::min(low, comm) != Utilities::MPI::max(high, comm))
          return false;
      }
    return true;
  }

  template class FollowerPressure<2>;
  template class FollowerPressure<3>;
} // namespace hyperelastic
