#pragma once
/// \file
/// Laws are judged on what the checker sent, never on what a student's function hands back.
///
/// In the grader a chapter function runs in the student's process, and every body it takes by
/// reference comes back over the wire whole: masses, inertia and restitution included. A
/// momentum computed with the masses that came back would let a resolve() that rewrites them
/// pass its own law. judged() keeps the velocities the function returned (its answer, in a
/// velocity step) and takes every property the function may not change from the
/// checker's copy of what it sent; the domain-wide hidden tests check that those properties
/// came back unchanged, and a change costs the step.

#include "workbook/rigid_body.hpp"

namespace workbook::testing {

/// `sent` with the velocity and angular velocity of `returned`: what a law about a velocity
/// step's answer may read (a position step's answer is the returned position itself).
inline RigidBody judged(const RigidBody& sent, const RigidBody& returned) {
    RigidBody body = sent;
    body.velocity = returned.velocity;
    body.angular_velocity = returned.angular_velocity;
    return body;
}

}  // namespace workbook::testing
