// Checkpoint and restart of a run ('Output/Checkpoint every', `hyperelastic
// --restart CHECKPOINT scene.prm`). The file's format and its atomic
// replacement live in output/checkpoint_file.h; here is what goes in:
//   common part: what must match the resuming scene (mesh, unknowns,
//     element, model, formulation, scheme, ranks), the stepper's state
//     after the step (t, next increment, step count, easy steps in a row),
//     the output frames, PVD and XDMF entries, the AMG set-up counts;
//   each rank's part: EquilibriumSystem::save_state() (the last converged
//     state and the one before it, velocity and acceleration, history).
// The AMG hierarchy cannot be stored: at each checkpoint the run forgets
// its hierarchy, so that it and a restart both build a new one at the next
// solve and go on alike.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/dynamics/time_stepping.h>
#include <hyperelastic/equilibrium_system/equilibrium_system.h>
#include <hyperelastic/output/checkpoint_file.h>
#include <hyperelastic/problem/problem.h>

#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  std::string
  Problem<dim>::checkpoint_description() const
  {
    std::ostringstream text;
    text << "dimension: " << dim << "\n"
         << "cells: " << model.triangulation->n_global_active_cells() << "\n"
         << "unknowns: " << model.dof_handler.n_dofs() << "\n"
         << "element: " << model.formulation->element_description() << "\n"
         << "model: " << model.material->name() << "\n"
         << "formulation: " << parameters.problem.formulation << "\n"
         << "time integration: "
         << (parameters.time_integration.dynamic()
               ? parameters.time_integration.scheme_name()
               : std::string("quasi-static"))
         << "\n"
         << "MPI ranks: " << Utilities::MPI::n_mpi_processes(comm) << "\n";
    for (unsigned int r = 0; r < parameters.regions.size(); ++r)
      text << parameters.regions[r].name() << ": "
           << model.region_models[r]->name() << ", "
           << model.cell_regions.n_cells[r + 1] << " cells\n";
    return text.str();
  }

  template <int dim>
  void
  Problem<dim>::write_checkpoint(const LoadStep &step)
  {
    TimerOutput::Scope scope(timer, "output");
    StateBlob          common, own;
    common.put(checkpoint_description());
    common.put(step.load_factor);
    common.put(step.next_increment);
    common.put_count(step.step);
    common.put_count(step.easy_steps);
    common.put_count(n_frames);
    common.put_count(writer->series().size());
    for (const auto &[t, file] : writer->series())
      {
        common.put(t);
        common.put(file);
      }
    common.put(writer->packed_xdmf_entries());
    common.put_count(linear_solver->n_preconditioner_setups());
    common.put_count(linear_solver->n_preconditioner_refreshes());
    system->save_state(own);
    const std::string file = parameters.output.checkpoint_file();
    hyperelastic::write_checkpoint(file, common, own, comm);
    linear_solver->forget_preconditioner();
    pcout << "   checkpoint: " << file << " (t = " << step.load_factor
          << ", step " << step.step << ")" << std::endl;
  }

  template <int dim>
  void
  Problem<dim>::read_checkpoint()
  {
    const std::string &file = parameters.restart_checkpoint;
    if (parameters.load_stepping.method == LoadControl::arc_length &&
        !parameters.time_integration.dynamic())
      throw InputError("--restart '" + file +
                       "': a restart continues load control or time "
                       "stepping; 'Load stepping/Method = arc length' is "
                       "not supported");
    if (parameters.problem.reference_loaded)
      throw InputError("--restart '" + file +
                       "': a checkpoint belongs to one reference "
                       "configuration; 'Problem/Reference = loaded' searches "
                       "one per iterate and is not restarted");
    CheckpointParts parts = hyperelastic::read_checkpoint(file, comm);
    if (!parts.note.empty())
      pcout << "warning: " << parts.note << std::endl;

    // Every line of the description must match.
    std::istringstream saved(parts.common.get_string());
    std::istringstream scene(checkpoint_description());
    for (std::string was, is; std::getline(scene, is);)
      {
        std::getline(saved, was);
        if (was != is)
          {
            const std::string name = is.substr(0, is.find(':'));
            throw InputError(
              "the checkpoint '" + parts.file +
              "' does not fit this scene: its " + name + " is '" +
              (was.size() > name.size() + 2 ? was.substr(name.size() + 2)
                                            : was) +
              "', the scene's '" + is.substr(name.size() + 2) + "'");
          }
      }

    resume_point             = std::make_unique<ResumePoint>();
    resume_point->t          = parts.common.get_double();
    resume_point->increment  = parts.common.get_double();
    resume_point->step       = parts.common.get_count();
    resume_point->easy_steps = parts.common.get_count();
    n_frames                 = parts.common.get_count();
    resumed_series.resize(parts.common.get_count());
    for (auto &[t, name] : resumed_series)
      {
        t    = parts.common.get_double();
        name = parts.common.get_string();
      }
    resumed_xdmf                 = parts.common.get_string();
    const unsigned int setups    = parts.common.get_count();
    const unsigned int refreshes = parts.common.get_count();
    linear_solver->set_setup_counts(setups, refreshes);
    system->load_state(parts.own);
    pcout << "restart from " << parts.file << ": t = " << resume_point->t
          << " after step " << resume_point->step << std::endl;
  }

  // The members defined here (the class itself is instantiated in
  // problem.cc).
  template std::string
  Problem<2>::checkpoint_description() const;
  template std::string
  Problem<3>::checkpoint_description() const;
  template void
  Problem<2>::write_checkpoint(const LoadStep &);
  template void
  Problem<3>::write_checkpoint(const LoadStep &);
  template void
  Problem<2>::read_checkpoint();
  template void
  Problem<3>::read_checkpoint();
} // namespace hyperelastic
