#include "curvsph/parallel/agree.hpp"

#include <sstream>

namespace curvsph::mpi {
namespace {

// Every rank gets the error text packed by the lowest rank that has an error (nullopt when no
// rank has one): one reduction and one broadcast, shared by both error kinds.
template <class E, class Pack>
std::optional<std::string> from_first_failing(const Comm& comm, const std::optional<E>& e,
                                              Pack pack) {
  const int first = static_cast<int>(
      comm.min(static_cast<std::int64_t>(e.has_value() ? comm.rank() : comm.size())));
  if (first == comm.size()) return std::nullopt;
  return comm.broadcast(comm.rank() == first ? pack(*e) : std::string(), first);
}

}  // namespace

void raise_first(const Comm& comm, const std::optional<InputError>& e) {
  if (comm.size() == 1) {
    if (e) throw *e;
    return;
  }
  // file, key and reason travel separated by NUL characters (none of them contains one).
  const auto packed = from_first_failing(
      comm, e, [](const InputError& x) { return x.file() + '\0' + x.key() + '\0' + x.reason(); });
  if (!packed) return;
  const auto a = packed->find('\0'), b = packed->find('\0', a + 1);
  throw InputError(packed->substr(0, a), packed->substr(a + 1, b - a - 1), packed->substr(b + 1));
}

void raise_first(const Comm& comm, const std::optional<InstabilityError>& e) {
  if (comm.size() == 1) {
    if (e) throw *e;
    return;
  }
  const auto packed = from_first_failing(comm, e, [](const InstabilityError& x) {
    std::ostringstream s;
    s << x.step() << ' ' << x.particle() << ' ' << static_cast<int>(x.kind()) << ' ' << x.count()
      << ' ' << x.what();
    return s.str();
  });
  if (!packed) return;
  std::istringstream s(*packed);
  long step = 0, particle = 0, count = 0;
  int kind = 0;
  s >> step >> particle >> kind >> count;
  s.get();
  std::string what;
  std::getline(s, what, '\0');
  throw InstabilityError(what, step, particle, static_cast<InstabilityError::Kind>(kind), count);
}

}  // namespace curvsph::mpi
