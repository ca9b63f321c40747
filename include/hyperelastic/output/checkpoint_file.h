// The checkpoint file ('Output/Checkpoint every', `hyperelastic --restart
// FILE scene.prm`): one file holding a part common to all ranks and one
// part per rank, written by rank 0 after a gather, so that a run killed
// while writing never leaves a broken file in place of a good one:
//   - the new file is written beside the old one (FILE.partial) and renamed
//     over it after the old one has been renamed to FILE.previous;
//   - the file ends with its length and an FNV-1a checksum; a file that
//     fails them (truncated by a kill, a full disk) is rejected on reading
//     and FILE.previous is read instead, with a note saying so.
// What goes into the parts is the business of the classes that own the
// state (StateBlob: values appended and read back in the same order).
#pragma once

#include <deal.II/base/mpi.h>

#include <hyperelastic/base/linear_algebra.h>

#include <cstdint>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// Bytes of a state: values appended with put() and read back in the same
  /// order with the get functions, which throw InputError past the end.
  class StateBlob
  {
  public:
    StateBlob() = default;
    explicit StateBlob(std::string bytes)
        : bytes(std::move(bytes))
    {
    }

    void
    put(double x);
    void
    put_count(std::uint64_t n);
    void
    put(const std::string &text);
    void
    put(const std::vector<double> &values);
    /// The owned entries of @p v in the order of its index set.
    void
    put_owned(const VectorType &v);

    double
    get_double();
    std::uint64_t
    get_count();
    std::string
    get_string();
    std::vector<double>
    get_doubles();
    /// Fills the owned entries of @p v (a vector without ghosts, laid out
    /// like the one written) in the order put_owned() wrote them.
    void
    get_owned(VectorType &v);

    const std::string &
    data() const
    {
      return bytes;
    }

  private:
    void
    read(void *target, std::size_t size);

    std::string bytes;
    std::size_t position = 0;
  };

  /// Writes @p common (rank 0's is used) and every rank's @p own to
  /// @p file as described above. Collective; InputError on every rank if
  /// the file cannot be written.
  void
  write_checkpoint(const std::string &file,
                   const StateBlob   &common,
                   const StateBlob   &own,
                   MPI_Comm           comm);

  /// What read_checkpoint() found.
  struct CheckpointParts
  {
    StateBlob   common;
    StateBlob   own;
    std::string file; ///< the file read (FILE or FILE.previous)
    std::string note; ///< why FILE.previous was read (empty otherwise)
  };

  /// Reads @p file, or FILE.previous if @p file is missing or damaged.
  /// Collective; InputError naming the file if neither is whole or if it
  /// was written by another number of ranks.
  CheckpointParts
  read_checkpoint(const std::string &file, MPI_Comm comm);
} // namespace hyperelastic
