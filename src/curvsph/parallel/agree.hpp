#pragma once
// Errors that every rank must raise together. A rank that finds bad input or an unstable
// particle must not simply throw: the other ranks would wait for it in the next collective
// call for ever. Each rank passes what it found (or nothing) to raise_first(); when any rank
// found something, every rank throws the error of the lowest such rank, with the same message,
// so all ranks stop with the same exit code (2 bad input, 3 unstable) and the same text.
#include <optional>

#include "curvsph/core/error.hpp"
#include "curvsph/parallel/communicator.hpp"

namespace curvsph::mpi {

void raise_first(const Comm& comm, const std::optional<InputError>& e);
void raise_first(const Comm& comm, const std::optional<InstabilityError>& e);

// Runs f; an InputError it throws is held back and raised on every rank by raise_first.
template <class F>
void agree_on_input(const Comm& comm, F&& f) {
  std::optional<InputError> err;
  try {
    f();
  } catch (const InputError& e) {
    err = e;
  }
  raise_first(comm, err);
}

}  // namespace curvsph::mpi
