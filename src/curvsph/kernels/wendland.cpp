#include "curvsph/kernels/wendland.hpp"
namespace curvsph {
template struct WendlandC2<2>;
template struct WendlandC2<3>;
}  // namespace curvsph
