// gmsh's global state, opened and closed in one place (gmsh_session.h).
#include <hyperelastic/mesh/gmsh_session.h>

#include <gmsh.h>

namespace hyperelastic
{
  GmshSession::GmshSession()
  {
    gmsh::initialize(0, nullptr, false);
    // No messages on the terminal (errors arrive as exceptions) and one
    // thread: the program's parallelism is MPI's.
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);
  }

  GmshSession::~GmshSession()
  {
    gmsh::finalize();
  }
} // namespace hyperelastic
