// The equilibrium system's part of a checkpoint: the last two converged
// states, the driver's state and the materials' history.
#include <hyperelastic/equilibrium_system/equilibrium_system.h>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  void
  EquilibriumSystem<dim>::save_state(StateBlob &blob) const
  {
    for (const ConvergedState *state : {&converged, &previous})
      {
        blob.put(state->valid ? 1. : 0.);
        blob.put(state->load_factor);
        blob.put(state->force_scale);
        blob.put(state->solution_size);
        if (state->valid)
          blob.put_owned(state->u);
      }
    stepping->save_state(blob);
    blob.put(elasticity->material_history());
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::load_state(StateBlob &blob)
  {
    for (ConvergedState *state : {&converged, &previous})
      {
        state->valid         = blob.get_double() != 0.;
        state->load_factor   = blob.get_double();
        state->force_scale   = blob.get_double();
        state->solution_size = blob.get_double();
        if (state->valid)
          {
            state->u.reinit(owned_dofs, comm);
            blob.get_owned(state->u);
          }
      }
    current_load_factor = converged.load_factor;
    restore_converged_state();
    stepping->load_state(blob);
    elasticity->restore_material_history(blob.get_doubles());
  }

  template void
  EquilibriumSystem<2>::save_state(StateBlob &) const;
  template void
  EquilibriumSystem<2>::load_state(StateBlob &);
  template void
  EquilibriumSystem<3>::save_state(StateBlob &) const;
  template void
  EquilibriumSystem<3>::load_state(StateBlob &);
} // namespace hyperelastic
