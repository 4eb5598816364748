#pragma once
/// \file
/// Chapter 1, perfectly inelastic collision: the functions the student writes.
///
/// This one declaration is shared by skeleton/inelastic.cpp (the student's copy) and the
/// reference solution, so the two can never disagree on a signature.

#include "workbook/contact.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook::inelastic {

/// Step 1. The single velocity two bodies share after a perfectly inelastic collision:
/// the one that keeps their total linear momentum, (m1 v1 + m2 v2) / (m1 + m2).
/// Written with inverse masses so that an immovable body (inverse mass 0) needs no special case.
[[nodiscard]] Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2);

/// Steps 2-4. Makes the two bodies of `contact` leave with the common velocity: the whole
/// velocity, both bodies, an immovable body never moved, and a pair that is already
/// separating along `contact.normal` left alone.
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact);

/// Step 5. The kinetic energy the collision turns into heat and deformation,
/// 1/2 mu |v1 - v2|^2 with the reduced mass mu = m1 m2 / (m1 + m2), in joules.
[[nodiscard]] double energy_lost(const RigidBody& body1, const RigidBody& body2);

}  // namespace workbook::inelastic
