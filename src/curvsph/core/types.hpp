#pragma once
// Scalar and vector types shared by every module. Fixed-size Eigen vectors keep the
// hot loops free of allocation and let the compiler unroll per dimension.
#include <Eigen/Core>
#include <cstddef>

namespace curvsph {

#ifdef CURVSPH_REAL_FLOAT
using Real = float;
#else
using Real = double;
#endif

template <int D>
using Vec = Eigen::Matrix<Real, D, 1>;
template <int D>
using Mat = Eigen::Matrix<Real, D, D>;

using Vec2 = Vec<2>;
using Vec3 = Vec<3>;

// Geometry (walls, NURBS, CAD) always works in double: closest-point Newton iterations and
// curvatures need the precision even when the particle fields are single precision.
template <int D>
using VecD = Eigen::Matrix<double, D, 1>;
using Vec2d = VecD<2>;
using Vec3d = VecD<3>;

using Index = std::ptrdiff_t;

}  // namespace curvsph
