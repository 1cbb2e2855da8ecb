#include "curvsph/kernels/boundary_kernel.hpp"
namespace curvsph {
template struct BoundaryKernel<2>;
template struct BoundaryKernel<3>;
}  // namespace curvsph
