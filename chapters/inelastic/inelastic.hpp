#pragma once
/// \file
/// Chapter 1, perfectly inelastic collision: the functions the student writes.
///
/// This one declaration is shared by skeleton/inelastic.cpp (the student's copy) and the
/// reference solution, so the two can never disagree on a signature.
///
/// **Legal inputs** (what the tests draw, and all a function must handle; the same for every
/// function below unless it says otherwise):
/// - a body's `inverse_mass` is 0 (immovable: a wall, the ground, or a kinematic platform that
///   moves with a velocity of its own) or a mass from 1e-100 to 1e100 kg; two bodies of a pair
///   may be both immovable, both very heavy or both very light, or a ratio up to 1e200 apart;
/// - velocities of any direction, 0 or from 1e-12 m/s (creeping) to 1e6 m/s; positions up
///   to 1 km from the origin;
/// - `contact.normal` a unit vector in any direction, from body 2 towards body 1, not
///   necessarily the line through the centres; one or more contact points anywhere near the
///   bodies, each at least 0 deep, and `contact.penetration` at least the deepest of them;
/// - `restitution` from 0 to 1; any orientation; `inertia_body` symmetric positive definite
///   and not necessarily diagonal, kept as it is on an immovable body (immovable is
///   `inverse_mass == 0` alone).
///
/// A pair approaches when dot(v1 - v2, contact.normal) < 0; it may also move apart, slide
/// (that dot exactly 0 with v1 != v2), have equal velocities or rest. A function changes only
/// what it says it changes: resolve() the two velocities, nothing else of either body.

#include "workbook/contact.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook::inelastic {

/// Step 1. The single velocity two bodies share after a perfectly inelastic collision:
/// the one that keeps their total linear momentum, (m1 v1 + m2 v2) / (m1 + m2).
/// Written with inverse masses so that an immovable body (inverse mass 0) needs no special case:
/// with one immovable body it is that body's velocity. With two immovable bodies any finite
/// value will do (resolve() changes nothing then).
[[nodiscard]] Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2);

/// Steps 2-4. Makes the two bodies of `contact` leave with the common velocity: the whole
/// velocity, both bodies, an immovable body never moved, and a pair that is already
/// separating along `contact.normal` left alone.
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact);

/// Step 5. The kinetic energy the collision turns into heat and deformation,
/// 1/2 mu |v1 - v2|^2 with the reduced mass mu = m1 m2 / (m1 + m2), in joules: the other
/// body's mass against an immovable one, 0 between two immovable bodies or equal velocities.
[[nodiscard]] double energy_lost(const RigidBody& body1, const RigidBody& body2);

}  // namespace workbook::inelastic
