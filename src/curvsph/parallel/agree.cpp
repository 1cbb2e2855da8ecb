#include "curvsph/parallel/agree.hpp"

#include <sstream>

namespace curvsph::mpi {
namespace {

// The lowest rank that has an error, or comm.size() when none has.
int first_failing(const Comm& comm, bool failed) {
  return static_cast<int>(comm.min(static_cast<std::int64_t>(failed ? comm.rank() : comm.size())));
}

}  // namespace

void raise_first(const Comm& comm, const std::optional<InputError>& e) {
  if (comm.size() == 1) {
    if (e) throw *e;
    return;
  }
  const int first = first_failing(comm, e.has_value());
  if (first == comm.size()) return;
  // file, key and reason travel separated by NUL characters (none of them contains one).
  std::string packed;
  if (comm.rank() == first) packed = e->file() + '\0' + e->key() + '\0' + e->reason();
  packed = comm.broadcast(packed, first);
  const auto a = packed.find('\0'), b = packed.find('\0', a + 1);
  throw InputError(packed.substr(0, a), packed.substr(a + 1, b - a - 1), packed.substr(b + 1));
}

void raise_first(const Comm& comm, const std::optional<InstabilityError>& e) {
  if (comm.size() == 1) {
    if (e) throw *e;
    return;
  }
  const int first = first_failing(comm, e.has_value());
  if (first == comm.size()) return;
  std::string packed;
  if (comm.rank() == first) {
    std::ostringstream s;
    s << e->step() << ' ' << e->particle() << ' ' << static_cast<int>(e->kind()) << ' '
      << e->count() << ' ' << e->what();
    packed = s.str();
  }
  packed = comm.broadcast(packed, first);
  std::istringstream s(packed);
  long step = 0, particle = 0, count = 0;
  int kind = 0;
  s >> step >> particle >> kind >> count;
  s.get();
  std::string what;
  std::getline(s, what, '\0');
  throw InstabilityError(what, step, particle, static_cast<InstabilityError::Kind>(kind), count);
}

}  // namespace curvsph::mpi
