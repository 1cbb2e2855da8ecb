#pragma once
// The periodic image of a coordinate: one rule for every place that wraps positions into a
// periodic box (the cell list, particle generation).
#include <cmath>

namespace curvsph {

// v moved by a whole number of periods into [lo, lo + length); a value already there is
// returned unchanged, and one that round-off puts on the upper edge goes to lo.
template <class T>
T wrap_periodic(T v, T lo, T length) {
  const T rel = v - lo;
  if (rel >= 0 && rel < length) return v;
  const T w = lo + rel - length * std::floor(rel / length);
  return w >= lo + length ? lo : w;
}

}  // namespace curvsph
