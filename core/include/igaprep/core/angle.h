#pragma once
// The angle between two vectors, by atan2(|a x b|, a . b) rather than acos:
// exact for nearly parallel (and nearly opposite) vectors, where acos's
// round-off near 1 alone is about 1e-6 degrees.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace igaprep {

inline double angle_radians(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

inline double angle_degrees(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return angle_radians(a, b) * 180.0 / M_PI;
}

}  // namespace igaprep
