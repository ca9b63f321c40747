// The contact terms of a scene and their one reporter.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/contact/contact_layer.h>
#include <hyperelastic/contact/mesh_obstacle_pairs.h>
#include <hyperelastic/contact/obstacle_contact.h>
#include <hyperelastic/contact/self_contact.h>

#include <algorithm>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// Reports for the obstacles (with the meshed obstacles' corner and
    /// edge pairs) and the self contact together: each column is written
    /// once, from all terms' measures.
    template <int dim>
    class ContactReport : public StepReporter<dim>
    {
    public:
      ContactReport(const ObstacleContact<dim>   *obstacles,
                    const MeshObstaclePairs<dim> *corners,
                    const SelfContact<dim>       *self,
                    const ContactSetup<dim>      &setup)
          : obstacles(obstacles)
          , corners(corners)
          , self(self)
          , n_obstacles(setup.parameters.obstacles.size())
          , dynamic(setup.dynamic)
          , owned_dofs(setup.dof_handler.locally_owned_dofs())
          , comm(setup.dof_handler.get_communicator())
      {}

      void
      print_header(std::ostream &out) const override
      {
        if (obstacles)
          out << "contact: " << n_obstacles << " obstacle(s), barrier distance "
              << barrier_distance_text(obstacles->settings())
              << ", barrier stiffness kappa = "
              << barrier_stiffness_text(obstacles->settings(),
                                        obstacles->barrier_stiffness())
              << (obstacles->has_friction()
                    ? (dynamic ? ", friction smoothing eps_v = "
                               : ", friction smoothing eps = ") +
                        std::to_string(obstacles->friction_smoothing(1.))
                    : std::string())
              << std::endl;
        if (corners)
          out << "meshed obstacles: " << corners->n_features()[0]
              << " sharp vertices against the body's boundary faces"
              << (dim == 3 ? ", " + std::to_string(corners->n_features()[1]) +
                               " sharp edges against its edges"
                           : std::string())
              << std::endl;
        if (self)
          {
            const auto size = self->boundary_size();
            out << "self contact: " << size[0] << " boundary vertices, "
                << size[1] << (dim == 2 ? " segments" : " triangles");
            if (dim == 3)
              out << ", " << size[2] << " edges";
            out << " (connectivity on every rank; positions exchanged with "
                   "the ranks within reach), barrier distance "
                << barrier_distance_text(self->settings())
                << ", barrier stiffness kappa = "
                << barrier_stiffness_text(self->settings(),
                                          self->barrier_stiffness())
                << std::endl;
          }
      }

      /// contact_force_<k>_<axis> of each obstacle, then their
      /// contact_moment_<k>_<axis>, then the smallest distance and the
      /// active pairs of obstacles and self contact.
      void
      add_columns(const ReportedState &state, StepSummary<dim> &s) override
      {
        ContactMeasures all;
        if (obstacles)
          all = obstacles->measure(state.u, state.t);
        if (corners)
          {
            const ContactMeasures m = corners->measure(state.u, state.t);
            for (const auto &[mine, totals] :
                 {std::pair(&m.forces, &all.forces),
                  std::pair(&m.moments, &all.moments)})
              for (const SummaryColumn &c : *mine)
                for (SummaryColumn &total : *totals)
                  if (total.name == c.name)
                    total.value += c.value;
            all.min_distance = std::min(all.min_distance, m.min_distance);
            all.active_pairs += m.active_pairs;
          }
        if (self)
          {
            const ContactMeasures m = self->measure(state.u);
            all.min_distance = std::min(all.min_distance, m.min_distance);
            all.active_pairs += m.active_pairs;
          }
        s.more.insert(s.more.end(), all.forces.begin(), all.forces.end());
        s.more.insert(s.more.end(), all.moments.begin(), all.moments.end());
        s.more.push_back({"contact_min_distance", all.min_distance});
        s.more.push_back({"contact_active_pairs", all.active_pairs});
      }

      /// The force the obstacles and the rest of the boundary exert on the
      /// body, per boundary vertex.
      void
      add_nodal_fields(const ReportedState     &state,
                       std::vector<NodalField> &fields) override
      {
        VectorType owned(owned_dofs, comm);
        if (obstacles)
          obstacles->contact_forces(state.u, state.t, owned);
        if (corners)
          corners->contact_forces(state.u, state.t, owned);
        if (self)
          self->contact_forces(state.u, state.t, owned);
        owned.compress(VectorOperation::add);
        contact_force.reinit(state.u);
        contact_force = owned;
        fields.push_back({"contact_force", &contact_force});
      }

      /// Where self contact's time went (rank 0's; the timing table holds
      /// all contact work in its section "contact").
      void
      print_cost(std::ostream &out) const override
      {
        // The barrier's operating point (BarrierStiffness): kappa at the
        // start and at the end, and the smallest distance over d_hat of
        // the converged states the steps started from.
        const auto operating_point = [&](const char             *what,
                                         const BarrierStiffness &k) {
          out << "\n" << what << ": barrier stiffness kappa = " << k.value();
          if (k.adaptive())
            out << " (automatic, re-targeted " << k.n_retargets()
                << " times between steps)";
          if (k.largest_ratio() > 0.)
            out << "; smallest distance over d_hat at the steps' starts "
                << k.smallest_ratio() << " to " << k.largest_ratio();
          out << std::endl;
        };
        if (obstacles)
          operating_point("obstacle contact", obstacles->stiffness_control());
        if (corners)
          operating_point("meshed obstacles' corners",
                          corners->stiffness_control());
        if (self)
          operating_point("self contact", self->stiffness_control());
        if (!self)
          return;
        const auto &c = self->cost();
        out << "\nself contact: " << c.evaluations
            << " evaluations; wall time: exchange " << c.exchange
            << " s, broad phase " << c.broad << " s, narrow phase "
            << c.narrow << " s, CCD " << c.ccd << " s; "
            << c.sparsity_rebuilds << " sparsity rebuilds; "
            << c.received / std::max(c.evaluations, 1u)
            << " doubles received per evaluation" << std::endl;
      }

    private:
      const ObstacleContact<dim> *const   obstacles;
      const MeshObstaclePairs<dim> *const corners;
      const SelfContact<dim> *const     self;
      const std::size_t                 n_obstacles;
      const bool                        dynamic;
      const IndexSet                    owned_dofs;
      const MPI_Comm                    comm;
      /// The last contact_force field (kept until the frame is written).
      VectorType contact_force;
    };
  } // namespace

  template <int dim>
  std::unique_ptr<StepReporter<dim>>
  add_contact_terms(const ContactSetup<dim> &setup,
                    ElasticityOperator<dim> &elasticity)
  {
    const ContactParameters &parameters = setup.parameters;
    // A term timed in the section "contact", owned by the operator.
    const auto add = [&](auto term) {
      term->set_timer(setup.timer);
      auto *const added = term.get();
      elasticity.add_term(std::move(term));
      return added;
    };
    // Self contact first: its reference gaps may make the automatic d_hat
    // smaller, and the obstacles take the same settings. (The operator
    // holds the obstacles' term first.)
    std::unique_ptr<SelfContact<dim>> self_term;
    if (parameters.self_contact)
      {
        if (setup.has_pressure_unknowns)
          throw InputError(
            "'Contact/Self contact = true' needs 'Problem/Formulation = "
            "displacement' (the mixed formulation's block preconditioner "
            "keeps the tangent's sparsity, which self-contact pairs grow)");
        self_term = std::make_unique<SelfContact<dim>>(parameters,
                                                       setup.dof_handler,
                                                       setup.moduli,
                                                       setup.dynamic);
      }
    ObstacleContact<dim> *obstacles = nullptr;
    SelfContact<dim>     *self      = nullptr;
    if (!parameters.obstacles.empty())
      obstacles = add(std::make_unique<ObstacleContact<dim>>(
        parameters,
        setup.constants,
        setup.dof_handler,
        setup.moduli,
        setup.dynamic,
        self_term ? &self_term->settings() : nullptr));
    // A meshed obstacle's sharp corners and edges against the body's faces
    // and edges.
    // They use the obstacles' surfaces and barrier settings.
    MeshObstaclePairs<dim> *corners = nullptr;
    if (obstacles && MeshObstaclePairs<dim>::wanted(parameters))
      corners = add(
        std::make_unique<MeshObstaclePairs<dim>>(parameters,
                                                 setup.constants,
                                                 setup.dof_handler,
                                                 obstacles->obstacle_surfaces(),
                                                 obstacles->settings()));
    if (self_term)
      self = add(std::move(self_term));
    if (!obstacles && !self)
      return nullptr;
    return std::make_unique<ContactReport<dim>>(obstacles, corners, self, setup);
  }

  template std::unique_ptr<StepReporter<2>>
  add_contact_terms(const ContactSetup<2> &, ElasticityOperator<2> &);
  template std::unique_ptr<StepReporter<3>>
  add_contact_terms(const ContactSetup<3> &, ElasticityOperator<3> &);
} // namespace hyperelastic
