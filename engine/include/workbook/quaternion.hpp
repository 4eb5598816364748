#pragma once
/// \file
/// Unit quaternions for orientation.

#include <cmath>

#include "workbook/matrix3.hpp"
#include "workbook/vector3.hpp"

namespace workbook {

/// Orientation as a quaternion w + xi + yj + zk; the identity is (1, 0, 0, 0).
struct Quaternion {
    double w = 1.0;  ///< scalar part
    double x = 0.0;  ///< i component
    double y = 0.0;  ///< j component
    double z = 0.0;  ///< k component

    /// Exact, component-wise equality.
    friend constexpr bool operator==(const Quaternion&, const Quaternion&) = default;
};

/// Hamilton product: the rotation b followed by a.
constexpr Quaternion operator*(const Quaternion& a, const Quaternion& b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

/// The conjugate, which is the inverse rotation for a unit quaternion.
constexpr Quaternion conjugate(const Quaternion& q) { return {q.w, -q.x, -q.y, -q.z}; }

/// The quaternion's length.
inline double norm(const Quaternion& q) { return std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z); }

/// The unit quaternion along q.
inline Quaternion normalized(const Quaternion& q) {
    const double n = norm(q);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

/// Rotation by `angle` radians about a unit `axis`.
inline Quaternion from_axis_angle(const Vector3& axis, double angle) {
    const double s = std::sin(angle / 2.0);
    return {std::cos(angle / 2.0), axis.x * s, axis.y * s, axis.z * s};
}

/// The rotation matrix of a unit quaternion.
constexpr Matrix3 to_matrix(const Quaternion& q) {
    const double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    const double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    const double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    return {{1 - 2 * (yy + zz), 2 * (xy - wz), 2 * (xz + wy),  //
             2 * (xy + wz), 1 - 2 * (xx + zz), 2 * (yz - wx),  //
             2 * (xz - wy), 2 * (yz + wx), 1 - 2 * (xx + yy)}};
}

/// Rotates v by the unit quaternion q.
constexpr Vector3 rotate(const Quaternion& q, const Vector3& v) { return to_matrix(q) * v; }

/// Advances an orientation by angular velocity `omega` (world frame) over `dt`, using the
/// exact rotation for a constant omega so that a spinning body keeps a unit quaternion.
inline Quaternion integrate(const Quaternion& q, const Vector3& omega, double dt) {
    const double speed = length(omega);
    if (speed * dt == 0.0) return q;
    return normalized(from_axis_angle(omega / speed, speed * dt) * q);
}

}  // namespace workbook
