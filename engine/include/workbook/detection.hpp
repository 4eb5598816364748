#pragma once
/// \file
/// Narrow-phase collision detection: sphere-sphere and sphere-plane.

#include <optional>

#include "workbook/contact.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook {

/// The normal used when two sphere centres coincide and no direction can be derived from
/// the geometry. Any unit vector is a valid separating direction there; a fixed one keeps
/// the result reproducible and free of NaN.
inline constexpr Vector3 coincident_centres_normal{0.0, 1.0, 0.0};

/// The contact between two spheres, or nothing when they do not overlap. Touching without
/// overlap (distance == r1 + r2) is not a contact.
std::optional<Contact> collide_spheres(const RigidBody& sphere1, const RigidBody& sphere2);

/// The contact between a sphere (body 1) and a plane (body 2); the normal is the plane's normal.
std::optional<Contact> collide_sphere_plane(const RigidBody& sphere, const RigidBody& plane);

/// Dispatches on the two shapes. The indices are copied into the result; when the pair is
/// given plane-first the bodies are swapped so that the normal convention still holds.
std::optional<Contact> collide(const RigidBody& a, std::uint32_t index_a, const RigidBody& b, std::uint32_t index_b);

}  // namespace workbook
