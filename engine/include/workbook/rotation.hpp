#pragma once
/// \file
/// Advancing orientations over one step: a free rigid body's rotation, and a kinematic body's.

#include "workbook/rigid_body.hpp"

namespace workbook {

/// Advances a movable body's orientation and angular velocity over `dt` with no torque
/// acting (gravity pulls at the centre of mass and exerts none).
///
/// Without torque the angular momentum L = I w is constant in the world frame, but w is not:
/// for a body whose three principal moments differ, w wanders in the body frame (Euler's
/// equations, the "gyroscopic term" w x I w). The step keeps L exact to rounding and the
/// kinetic energy exact to the solver's tolerance; see rotation.cpp for the method. A body
/// with the same moment about every axis (a sphere, a cube) keeps w and turns by the exact
/// rotation |w| dt about it, bit for bit as before boxes existed.
///
/// Updates `orientation` (renormalised), `angular_velocity` and `inverse_inertia_world`, and
/// returns the number of solver iterations it took (0 when none were needed).
int advance_free_rotation(RigidBody& body, double dt);

/// Moves a kinematic body (immovable, but given a velocity) along its constant velocity and
/// turns it at its constant angular velocity; an immovable body at rest is left bit for bit.
void advance_kinematic(RigidBody& body, double dt);

}  // namespace workbook
