// Run under `mpirun -np N` (N >= 2) by ctest: only the last rank finds bad input; every rank
// must raise the same InputError (file, key, reason) and none may hang. Exit 0 when every
// rank got exactly that error, 1 otherwise.
#include <iostream>

#include "curvsph/parallel/agree.hpp"

int main(int argc, char** argv) {
  using namespace curvsph;
  mpi::Session session(argc, argv);
  const mpi::Comm comm = mpi::Comm::world();
  bool ok = false;
  try {
    mpi::agree_on_input(comm, [&] {
      if (comm.rank() == comm.size() - 1)
        throw InputError("case.yaml", "walls.1.radius",
                         "found on rank " + std::to_string(comm.rank()));
    });
  } catch (const InputError& e) {
    ok = e.file() == "case.yaml" && e.key() == "walls.1.radius" &&
         e.reason() == "found on rank " + std::to_string(comm.size() - 1);
  }
  // The instability path: the lowest failing rank's error reaches everyone.
  bool ok2 = false;
  try {
    std::optional<InstabilityError> e;
    if (comm.rank() >= 1) e.emplace("particle 7 on rank " + std::to_string(comm.rank()), 5, 7);
    mpi::raise_first(comm, e);
  } catch (const InstabilityError& e) {
    ok2 = std::string(e.what()) == "particle 7 on rank 1" && e.step() == 5 && e.particle() == 7;
  }
  const bool all = comm.min(static_cast<std::int64_t>(ok && ok2)) == 1 && comm.size() >= 2;
  if (comm.root())
    std::cout << (all ? "agree: every rank raised the same error\n" : "agree: FAILED\n");
  return all ? 0 : 1;
}
