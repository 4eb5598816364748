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
/// A body that turns by more than max_turn_per_substep in `dt` (|w| dt) is advanced in equal sub-steps
/// (at most max_substeps; the scene loader refuses spins that would need more, see
/// scene_limits.hpp), so energy stays constant at any turn per step a scene may have.
int advance_free_rotation(RigidBody& body, double dt);

/// The most a sub-step of advance_free_rotation() turns a body, rad: well inside the 3 rad up
/// to which its Newton iteration was measured to converge.
inline constexpr double max_turn_per_substep = 1.0;
/// The most sub-steps one step of advance_free_rotation() takes. The loader refuses a spin
/// that would need more at the start; a collision that spins a body up further makes it
/// lose exact energy conservation instead of stalling the run.
inline constexpr int max_substeps = 1024;

/// An upper bound on how fast a free body can spin while its energy E is constant, rad/s:
/// sqrt(2 E |I^-1|_F), at least the largest |w| its precession ever reaches.
double largest_spin(const RigidBody& body);

/// True when `inertia` has the same moment about every axis (a sphere, a cube): such a body
/// keeps its w and turns exactly, at any speed, with no solver.
bool is_isotropic(const Matrix3& inertia);

/// Moves a kinematic body (immovable, but given a velocity) along its constant velocity and
/// turns it at its constant angular velocity; an immovable body at rest is left bit for bit.
void advance_kinematic(RigidBody& body, double dt);

}  // namespace workbook
