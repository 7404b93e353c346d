// SPDX-License-Identifier: BSD-3-Clause
// Basic types and physical constants shared by every layer.
#pragma once

#include <Eigen/Core>

namespace flexrock {

using Real = double;
using MatrixX = Eigen::MatrixXd;
using VectorX = Eigen::VectorXd;

// standard gravity [m/s^2]; a body may carry its own value
inline constexpr double kStandardGravity = 9.80665;

}  // namespace flexrock
