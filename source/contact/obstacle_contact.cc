// The barrier contact of boundary vertices with rigid planes and spheres.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/full_matrix.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/contact/barrier.h>
#include <hyperelastic/contact/obstacle_contact.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/materials/tangent_projection.h>
#include <hyperelastic/mesh/mesh_distribution.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// A tenth of each distance is kept along a Newton direction.
    constexpr double feasible_fraction = 0.9;

    template <int dim>
    Point<dim>
    to_point(const std::vector<double> &values)
    {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = values[d];
      return p;
    }
  } // namespace

  template <int dim>
  ObstacleContact<dim>::ObstacleContact(
    const ContactParameters             &parameters,
    const std::map<std::string, double> &constants,
    const DoFHandler<dim>               &dof_handler,
    const Mapping<dim>                  &mapping,
    const LameParameters                &moduli)
      : obstacles(parameters.obstacles)
      , comm(dof_handler.get_communicator())
  {
    for (const auto &o : obstacles)
      motions.push_back(parse_vector_function<dim>(o.motion,
                                                   constants,
                                                   o.subsection + "/Motion"));

    // The boundary vertices whose dofs this rank owns (ghost cells too: an
    // owned vertex may lie only on a neighbour's boundary face); the faces
    // where the ghost layer ends are not the body's boundary.
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    std::map<types::global_dof_index, unsigned int>
               index; // first dof -> vertex
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::numeric_limits<double>::max();
        upper[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = std::min(lower[d], cell->vertex(v)[d]);
                upper[d] = std::max(upper[d], cell->vertex(v)[d]);
              }
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() ||
                face->boundary_id() == partition_edge_boundary_id)
              continue;
            // The face's measure, shared equally by its vertices (the
            // lumped weights of a uniform pressure on P1 faces).
            double measure = face->vertex(0).distance(face->vertex(1));
            if constexpr (dim == 3)
              measure =
                0.5 * cross_product_3d(face->vertex(1) - face->vertex(0),
                                       face->vertex(2) - face->vertex(0))
                        .norm();
            for (unsigned int v = 0; v < face->n_vertices(); ++v)
              {
                const types::global_dof_index first =
                  face->vertex_dof_index(v, 0);
                if (!owned.is_element(first))
                  continue;
                auto it = index.find(first);
                if (it == index.end())
                  {
                    Vertex vertex;
                    vertex.X = face->vertex(v);
                    for (unsigned int d = 0; d < dim; ++d)
                      vertex.dofs[d] = face->vertex_dof_index(v, d);
                    it = index.emplace(first, vertices.size()).first;
                    vertices.push_back(vertex);
                  }
                vertices[it->second].area += measure / face->n_vertices();
              }
          }
      }
    double diagonal = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double extent = Utilities::MPI::max(upper[d], comm) -
                              Utilities::MPI::min(lower[d], comm);
        diagonal += extent * extent;
      }
    diagonal    = std::sqrt(diagonal);
    d_hat_value = parameters.barrier_distance > 0. ? parameters.barrier_distance
                                                   : 1e-3 * diagonal;
    kappa       = parameters.barrier_stiffness > 0.
                    ? parameters.barrier_stiffness
                    : (moduli.lambda + 2. * moduli.mu) / d_hat_value;
    (void)mapping;

    // The start must be feasible.
    std::string problem;
    for (const Vertex &v : vertices)
      {
        for (unsigned int k = 0; k < obstacles.size() && problem.empty(); ++k)
          if (!(distance(k, v.X, 0.) > 0.))
            {
              std::ostringstream s;
              s << "the body starts on the wrong side of the obstacle of '"
                << obstacles[k].subsection << "': the boundary vertex at ("
                << v.X << ") has distance " << distance(k, v.X, 0.)
                << " (must be positive at t = 0)";
              problem = s.str();
            }
        if (!problem.empty())
          break;
      }
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int first   = Utilities::MPI::min(
      problem.empty() ? n_ranks : Utilities::MPI::this_mpi_process(comm), comm);
    if (first < n_ranks)
      throw InputError(Utilities::MPI::broadcast(comm, problem, first));
  }

  template <int dim>
  ObstacleContact<dim>::~ObstacleContact() = default;

  template <int dim>
  Tensor<1, dim>
  ObstacleContact<dim>::offset(const unsigned int k, const double t) const
  {
    motions[k]->set_time(t);
    Tensor<1, dim> w;
    for (unsigned int d = 0; d < dim; ++d)
      w[d] = motions[k]->value(Point<dim>(), d);
    return w;
  }

  template <int dim>
  double
  ObstacleContact<dim>::distance(const unsigned int k,
                                 const Point<dim>  &x,
                                 const double       t,
                                 Tensor<1, dim>    *gradient,
                                 Tensor<2, dim>    *hessian) const
  {
    const ObstacleParameters &o = obstacles[k];
    const Point<dim>          p = to_point<dim>(o.point) + offset(k, t);
    if (o.type == ObstacleType::plane)
      {
        const Tensor<1, dim> n = to_point<dim>(o.normal);
        if (gradient)
          *gradient = n;
        if (hessian)
          *hessian = Tensor<2, dim>();
        return n * (x - p);
      }
    // Sphere: d = |x - c| - R, grad d = e = (x - c)/r,
    // d2 d = (I - e e^T) / r.
    const Tensor<1, dim> r_vector = x - p;
    const double         r        = r_vector.norm();
    const Tensor<1, dim> e        = r_vector / r;
    if (gradient)
      *gradient = e;
    if (hessian)
      *hessian = (unit_symmetric_tensor<dim>() - outer_product(e, e)) / r;
    return r - o.radius;
  }

  template <int dim>
  Point<dim>
  ObstacleContact<dim>::position(const Vertex &v, const VectorType &u) const
  {
    Point<dim> x = v.X;
    for (unsigned int d = 0; d < dim; ++d)
      x[d] += u(v.dofs[d]);
    return x;
  }

  template <int dim>
  void
  ObstacleContact<dim>::contact_forces(const VectorType &u,
                                       const double      t,
                                       VectorType       &forces) const
  {
    bool                                 crossed = false;
    std::vector<types::global_dof_index> rows;
    std::vector<double>                  values;
    for (const Vertex &v : vertices)
      {
        const Point<dim> x = position(v, u);
        for (unsigned int k = 0; k < obstacles.size(); ++k)
          {
            Tensor<1, dim> n;
            const double   d = distance(k, x, t, &n);
            if (d >= d_hat_value)
              continue;
            if (!(d > 0.))
              {
                crossed = true;
                continue;
              }
            // g = -dV/dx = -kappa b'(d) grad d (b' < 0: away from it).
            const Tensor<1, dim> g =
              -kappa * v.area * barrier(d, d_hat_value).derivative * n;
            for (unsigned int c = 0; c < dim; ++c)
              {
                rows.push_back(v.dofs[c]);
                values.push_back(g[c]);
              }
          }
      }
    // On every rank, even without contact: the first add after an insert
    // makes Trilinos assemble the vector, a collective operation.
    forces.add(rows, values);
    if (Utilities::MPI::max(crossed ? 1 : 0, comm) != 0)
      throw ConvergenceFailure(
        "a boundary vertex is on the wrong side of an obstacle at t = " +
        std::to_string(t) +
        " (an obstacle moved into the body over the step; a shorter step "
        "lets the body follow it)");
  }

  template <int dim>
  void
  ObstacleContact<dim>::add_forces(const VectorType &u,
                                   const double      t,
                                   VectorType       &forces) const
  {
    contact_forces(u, t, forces);
  }

  template <int dim>
  void
  ObstacleContact<dim>::add_load_stiffness(
    const VectorType                &u,
    const double                     t,
    const AffineConstraints<double> &constraints,
    MatrixType                      &matrix,
    VectorType                      &rhs) const
  {
    FullMatrix<double>                   block(dim, dim);
    std::vector<types::global_dof_index> dofs(dim);
    // The right-hand side's switch to adding, on every rank (collective in
    // Trilinos); add_condensed then adds on the ranks with contact only.
    rhs.add(std::vector<types::global_dof_index>(), std::vector<double>());
    for (const Vertex &v : vertices)
      {
        const Point<dim> x = position(v, u);
        for (unsigned int k = 0; k < obstacles.size(); ++k)
          {
            Tensor<1, dim> n;
            Tensor<2, dim> H;
            const double   d = distance(k, x, t, &n, &H);
            if (!(d < d_hat_value) || !(d > 0.))
              continue;
            const Barrier b = barrier(d, d_hat_value);
            // d2V/dx2 = kappa (b'' n n^T + b' d2d), projected: b'' > 0
            // along n; the sphere's tangential curvature term b'/r < 0 is
            // dropped (its eigenvalue is negative).
            SymmetricTensor<2, dim> K;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                K[i][j] = kappa * v.area *
                          (b.second * n[i] * n[j] + b.derivative * H[i][j]);
            const auto              eigen = eigenvectors(K);
            SymmetricTensor<2, dim> P;
            for (const auto &[value, vector] : eigen)
              if (value > 0.)
                P += value * symmetrize(outer_product(vector, vector));
            for (unsigned int i = 0; i < dim; ++i)
              {
                dofs[i] = v.dofs[i];
                for (unsigned int j = 0; j < dim; ++j)
                  block(i, j) = P[i][j];
              }
            add_condensed(block, dofs, constraints, matrix, rhs);
          }
      }
  }

  template <int dim>
  double
  ObstacleContact<dim>::potential(const VectorType &u, const double t) const
  {
    double sum = 0.;
    for (const Vertex &v : vertices)
      {
        const Point<dim> x = position(v, u);
        for (unsigned int k = 0; k < obstacles.size(); ++k)
          {
            const double d = distance(k, x, t);
            if (d < d_hat_value)
              sum += kappa * v.area * barrier(d, d_hat_value).value;
          }
      }
    return Utilities::MPI::sum(sum, comm);
  }

  template <int dim>
  double
  ObstacleContact<dim>::largest_feasible_step(const VectorType &u,
                                              const VectorType &direction,
                                              const double      t) const
  {
    double alpha = 1.;
    for (const Vertex &v : vertices)
      {
        const Point<dim> x = position(v, u);
        Tensor<1, dim>   p;
        for (unsigned int c = 0; c < dim; ++c)
          p[c] = direction(v.dofs[c]);
        for (unsigned int k = 0; k < obstacles.size(); ++k)
          {
            const ObstacleParameters &o  = obstacles[k];
            const double              d0 = distance(k, x, t);
            if (!(d0 > 0.))
              continue; // the forces say so
            double hit = std::numeric_limits<double>::infinity();
            if (o.type == ObstacleType::plane)
              {
                const double approach = -(to_point<dim>(o.normal) * p);
                if (approach > 0.)
                  hit = d0 / approach;
              }
            else
              {
                // |x - c + s p| = R: a s^2 + 2 b s + c0 = 0, first root > 0.
                const Tensor<1, dim> r =
                  x - (to_point<dim>(o.point) + offset(k, t));
                const double a    = p * p;
                const double b    = r * p;
                const double c0   = r * r - o.radius * o.radius;
                const double disc = b * b - a * c0;
                if (a > 0. && b < 0. && disc >= 0.)
                  hit = c0 / (-b + std::sqrt(disc));
              }
            alpha = std::min(alpha, feasible_fraction * hit);
          }
      }
    return Utilities::MPI::min(alpha, comm);
  }

  template <int dim>
  void
  ObstacleContact<dim>::summarize(const VectorType &u,
                                  const double      t,
                                  StepSummary<dim> &s) const
  {
    const char                  axes[3] = {'x', 'y', 'z'};
    std::vector<Tensor<1, dim>> force(obstacles.size());
    double       min_distance = std::numeric_limits<double>::infinity();
    unsigned int active       = 0;
    for (const Vertex &v : vertices)
      {
        const Point<dim> x = position(v, u);
        for (unsigned int k = 0; k < obstacles.size(); ++k)
          {
            Tensor<1, dim> n;
            const double   d = distance(k, x, t, &n);
            min_distance     = std::min(min_distance, d);
            if (d < d_hat_value && d > 0.)
              {
                ++active;
                force[k] -=
                  kappa * v.area * barrier(d, d_hat_value).derivative * n;
              }
          }
      }
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      {
        const Tensor<1, dim> total = Utilities::MPI::sum(force[k], comm);
        for (unsigned int d = 0; d < dim; ++d)
          s.more.push_back({"contact_force_" +
                              std::to_string(obstacles[k].number) + "_" +
                              axes[d],
                            total[d]});
      }
    s.more.push_back(
      {"contact_min_distance", Utilities::MPI::min(min_distance, comm)});
    s.more.push_back({"contact_active_pairs",
                      static_cast<double>(Utilities::MPI::sum(active, comm))});
  }

  template class ObstacleContact<2>;
  template class ObstacleContact<3>;
} // namespace hyperelastic
