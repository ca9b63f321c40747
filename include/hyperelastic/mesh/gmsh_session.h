// The one owner of the gmsh API's global state (gmsh::initialize and
// gmsh::finalize): the surface mesher and the reference-mesh writer of the
// unloaded shape each open one for the length of their work.
#pragma once

namespace hyperelastic
{
  /// gmsh initialized quiet and single-threaded for as long as the object
  /// lives, finalized however the scope ends (also on an exception). Not
  /// copyable; one at a time (gmsh's state is global).
  class GmshSession
  {
  public:
    GmshSession();
    ~GmshSession();
    GmshSession(const GmshSession &) = delete;
    GmshSession &
    operator=(const GmshSession &) = delete;
  };
} // namespace hyperelastic
