// The checkpoint file: layout, atomic replacement, checksum, fallback.
//
// Layout (binary, native byte order: restart on the machine kind that wrote
// it):
//   "hyperelastic checkpoint 1\n"
//   u64 ranks, then per part (common, rank 0, rank 1, ...): u64 size, bytes
//   u64 length of everything before this field, u64 FNV-1a of it
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/output/checkpoint_file.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace hyperelastic
{
  namespace
  {
    const std::string magic = "hyperelastic checkpoint 1\n";

    std::uint64_t
    fnv1a(const std::string &bytes, const std::size_t size)
    {
      std::uint64_t hash = 1469598103934665603ull;
      for (std::size_t i = 0; i < size; ++i)
        {
          hash ^= static_cast<unsigned char>(bytes[i]);
          hash *= 1099511628211ull;
        }
      return hash;
    }

    void
    append(std::string &out, const std::uint64_t n)
    {
      out.append(reinterpret_cast<const char *>(&n), sizeof(n));
    }

    /// The parts of @p file, or the reason it is not a whole checkpoint.
    bool
    parse(const std::string         &file,
          std::vector<std::string>  &parts,
          std::string               &why)
    {
      std::ifstream in(file, std::ios::binary);
      if (!in)
        {
          why = "cannot be read";
          return false;
        }
      const std::string bytes((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
      const std::size_t trailer = 2 * sizeof(std::uint64_t);
      if (bytes.size() < magic.size() + trailer ||
          bytes.compare(0, magic.size(), magic) != 0)
        {
          why = "is not a hyperelastic checkpoint";
          return false;
        }
      std::uint64_t length, checksum;
      std::memcpy(&length, bytes.data() + bytes.size() - trailer, 8);
      std::memcpy(&checksum, bytes.data() + bytes.size() - 8, 8);
      if (length != bytes.size() - trailer ||
          checksum != fnv1a(bytes, length))
        {
          why = "is damaged (truncated or altered: its length or checksum "
                "does not match)";
          return false;
        }
      StateBlob blob(bytes.substr(magic.size(), length - magic.size()));
      const std::uint64_t n_parts = blob.get_count() + 1;
      parts.clear();
      for (std::uint64_t p = 0; p < n_parts; ++p)
        parts.push_back(blob.get_string());
      return true;
    }
  } // namespace

  // ----------------------------------------------------------- StateBlob
  void
  StateBlob::put(const double x)
  {
    bytes.append(reinterpret_cast<const char *>(&x), sizeof(x));
  }

  void
  StateBlob::put_count(const std::uint64_t n)
  {
    append(bytes, n);
  }

  void
  StateBlob::put(const std::string &text)
  {
    put_count(text.size());
    bytes.append(text);
  }

  void
  StateBlob::put(const std::vector<double> &values)
  {
    put_count(values.size());
    bytes.append(reinterpret_cast<const char *>(values.data()),
                 values.size() * sizeof(double));
  }

  void
  StateBlob::put_owned(const VectorType &v)
  {
    std::vector<double> values;
    values.reserve(v.locally_owned_size());
    for (const auto i : v.locally_owned_elements())
      values.push_back(v[i]);
    put(values);
  }

  void
  StateBlob::read(void *target, const std::size_t size)
  {
    if (position + size > bytes.size())
      throw InputError("the checkpoint ends before its state does");
    std::memcpy(target, bytes.data() + position, size);
    position += size;
  }

  double
  StateBlob::get_double()
  {
    double x;
    read(&x, sizeof(x));
    return x;
  }

  std::uint64_t
  StateBlob::get_count()
  {
    std::uint64_t n;
    read(&n, sizeof(n));
    return n;
  }

  std::string
  StateBlob::get_string()
  {
    const std::uint64_t n = get_count();
    if (position + n > bytes.size())
      throw InputError("the checkpoint ends before its state does");
    std::string text = bytes.substr(position, n);
    position += n;
    return text;
  }

  std::vector<double>
  StateBlob::get_doubles()
  {
    std::vector<double> values(get_count());
    read(values.data(), values.size() * sizeof(double));
    return values;
  }

  void
  StateBlob::get_owned(VectorType &v)
  {
    const std::vector<double> values = get_doubles();
    if (values.size() != v.locally_owned_size())
      throw InputError("the checkpoint's vector has " +
                       std::to_string(values.size()) +
                       " entries on this rank, the scene's " +
                       std::to_string(v.locally_owned_size()));
    std::size_t k = 0;
    for (const auto i : v.locally_owned_elements())
      v[i] = values[k++];
    v.compress(dealii::VectorOperation::insert);
  }

  // ------------------------------------------------------------- writing
  void
  write_checkpoint(const std::string &file,
                   const StateBlob   &common,
                   const StateBlob   &own,
                   const MPI_Comm     comm)
  {
    const auto  parts = dealii::Utilities::MPI::gather(comm, own.data(), 0);
    std::string error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        StateBlob body;
        body.put_count(parts.size());
        body.put(common.data());
        for (const std::string &part : parts)
          body.put(part);
        std::string bytes = magic + body.data();
        const std::uint64_t length = bytes.size();
        const std::uint64_t sum    = fnv1a(bytes, bytes.size());
        append(bytes, length);
        append(bytes, sum);
        const std::string partial = file + ".partial";
        {
          std::ofstream out(partial, std::ios::binary | std::ios::trunc);
          out.write(bytes.data(), bytes.size());
          out.flush();
          if (!out)
            error = "cannot write the checkpoint '" + partial +
                    "' (Output/Directory)";
        }
        std::error_code ec;
        if (error.empty() && std::filesystem::exists(file))
          std::filesystem::rename(file, file + ".previous", ec);
        if (error.empty() && !ec)
          std::filesystem::rename(partial, file, ec);
        if (error.empty() && ec)
          error = "cannot replace the checkpoint '" + file +
                  "': " + ec.message();
      }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
  }

  // ------------------------------------------------------------- reading
  CheckpointParts
  read_checkpoint(const std::string &file, const MPI_Comm comm)
  {
    // Rank 0 reads and checks; each rank gets the common part and its own.
    std::vector<std::string> parts;
    std::string              error, read_file, note;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::string why;
        read_file = file;
        if (!parse(file, parts, why))
          {
            const std::string previous = file + ".previous";
            std::string       why_previous;
            if (parse(previous, parts, why_previous))
              {
                note = "the checkpoint '" + file + "' " + why +
                       "; restarting from the one before it, '" + previous +
                       "'";
                read_file = previous;
              }
            else
              error = "the checkpoint '" + file + "' " + why +
                      (std::filesystem::exists(previous)
                         ? " and '" + previous + "' " + why_previous
                         : "");
          }
        const unsigned int n_ranks =
          dealii::Utilities::MPI::n_mpi_processes(comm);
        if (error.empty() && parts.size() != n_ranks + 1)
          error = "the checkpoint '" + read_file + "' was written by " +
                  std::to_string(parts.size() - 1) +
                  " MPI rank(s); restart it with as many (this run has " +
                  std::to_string(n_ranks) + ")";
      }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
    CheckpointParts result;
    result.file = dealii::Utilities::MPI::broadcast(comm, read_file, 0);
    result.note = dealii::Utilities::MPI::broadcast(comm, note, 0);
    result.common =
      StateBlob(dealii::Utilities::MPI::broadcast(
        comm, parts.empty() ? std::string() : parts[0], 0));
    // Each rank's own part, sent from rank 0.
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
    if (rank == 0)
      {
        for (unsigned int r = 1; r < parts.size() - 1; ++r)
          {
            const std::uint64_t size = parts[r + 1].size();
            MPI_Send(&size, 1, MPI_UINT64_T, r, 71, comm);
            MPI_Send(parts[r + 1].data(),
                     static_cast<int>(size),
                     MPI_CHAR,
                     r,
                     72,
                     comm);
          }
        result.own = StateBlob(parts[1]);
      }
    else
      {
        std::uint64_t size = 0;
        MPI_Recv(&size, 1, MPI_UINT64_T, 0, 71, comm, MPI_STATUS_IGNORE);
        std::string bytes(size, '\0');
        MPI_Recv(bytes.data(),
                 static_cast<int>(size),
                 MPI_CHAR,
                 0,
                 72,
                 comm,
                 MPI_STATUS_IGNORE);
        result.own = StateBlob(std::move(bytes));
      }
    return result;
  }
} // namespace hyperelastic
