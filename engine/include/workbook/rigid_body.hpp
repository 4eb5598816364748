#pragma once
/// \file
/// The rigid body every responder works on.

#include <limits>

#include "workbook/matrix3.hpp"
#include "workbook/quaternion.hpp"
#include "workbook/shape.hpp"
#include "workbook/vector3.hpp"

namespace workbook {

/// A rigid body. Mass is stored as its inverse so that an immovable body (a wall, the
/// ground) is simply `inverse_mass == 0`: every impulse formula then leaves it untouched
/// without a special case, and no infinity ever enters the arithmetic.
struct RigidBody {
    double inverse_mass = 1.0;                  ///< 1 / kg; 0 means immovable
    Matrix3 inertia_body = Matrix3::identity();  ///< inertia tensor in body space, kg m^2
    Matrix3 inverse_inertia_world = Matrix3::identity();  ///< (R I R^T)^-1, kept current by the world
    Vector3 position{};                          ///< centre of mass, m
    Quaternion orientation{};                    ///< body to world rotation
    Vector3 velocity{};                          ///< m/s
    Vector3 angular_velocity{};                  ///< rad/s, world frame
    double restitution = 1.0;                    ///< coefficient of restitution e in [0, 1]
    /// Coefficient of dynamic (sliding) friction, >= 0 (chapter 6); a pair's is the geometric
    /// mean of its bodies' (friction::mix_coefficients()). 0: frictionless.
    double friction = 0.0;
    /// Coefficient of static friction, >= `friction`: a point sticks while its friction
    /// impulse needs at most this times its normal impulse (chapter 6).
    double static_friction = 0.0;
    Shape shape{};                               ///< collision geometry, in body space

    /// True for an immovable body (infinite mass, inverse_mass == 0).
    [[nodiscard]] bool is_immovable() const { return inverse_mass == 0.0; }

    /// Mass in kg; infinity for an immovable body.
    [[nodiscard]] double mass() const {
        return is_immovable() ? std::numeric_limits<double>::infinity() : 1.0 / inverse_mass;
    }

    /// Inertia tensor in the world frame, R I R^T (zero for an immovable body).
    [[nodiscard]] Matrix3 inertia_world() const {
        if (is_immovable()) return Matrix3::zero();
        const Matrix3 r = to_matrix(orientation);
        return r * inertia_body * transpose(r);
    }

    /// Recomputes inverse_inertia_world from the orientation; call after changing either.
    void update_world_inertia() {
        if (is_immovable()) {
            inverse_inertia_world = Matrix3::zero();
            return;
        }
        const Matrix3 r = to_matrix(orientation);
        inverse_inertia_world = r * inverse(inertia_body) * transpose(r);
    }
};

/// Inertia tensor of a solid ball: 2/5 m r^2 on the diagonal.
inline Matrix3 solid_sphere_inertia(double mass, double radius) {
    const double i = 0.4 * mass * radius * radius;
    return Matrix3::diagonal({i, i, i});
}

/// Inertia tensor of a solid box with the given half extents.
inline Matrix3 solid_box_inertia(double mass, const Vector3& h) {
    const double k = mass / 3.0;  // m/12 * (2h)^2 = m/3 * h^2
    return Matrix3::diagonal({k * (h.y * h.y + h.z * h.z), k * (h.x * h.x + h.z * h.z), k * (h.x * h.x + h.y * h.y)});
}

/// A movable solid ball of the given mass (kg) and radius (m) at `position`.
RigidBody make_sphere(double mass, double radius, const Vector3& position, const Vector3& velocity = {});

/// An immovable plane through `point` whose solid side lies behind `unit_normal`.
RigidBody make_immovable_plane(const Vector3& unit_normal, const Vector3& point);

/// An immovable ball, for tests and scenes that pin one body in place.
RigidBody make_immovable_sphere(double radius, const Vector3& position);

/// A movable solid box of the given mass (kg) and half extents (m), turned by `orientation`.
RigidBody make_box(double mass, const Vector3& half_extents, const Vector3& position, const Quaternion& orientation = {},
                   const Vector3& velocity = {});

}  // namespace workbook
