#pragma once
/// \file
/// Chapter 2, the projection method: the functions the student writes.
///
/// One declaration shared by skeleton/projection.cpp (the student's copy), the reference solution,
/// the tests and the table of response models, so they cannot disagree.

#include "workbook/contact.hpp"
#include "workbook/response_model.hpp"
#include "workbook/rigid_body.hpp"

/// Chapter 2, the projection method (\ref chapter_projection): a position-only response that
/// pushes overlapping bodies apart along the contact normal and never touches a velocity.
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
/// Knobs: `fraction` at least 0 (usually at most 1; above 1 overshoots, and is legal), `slop`
/// at least 0 m; a depth from 0 (exactly touching) to 1 m. correct() changes positions only:
/// velocities, angular velocities, orientations, masses, inertia and shapes come back as they were.
namespace workbook::projection {

/// Step 4. The depth one pass removes from a contact `depth` metres deep:
/// knobs.fraction * max(depth - knobs.slop, 0), in metres. A depth within the slop gives 0,
/// never a negative value (projection pushes bodies apart; it never pulls them together).
[[nodiscard]] double depth_to_remove(double depth, const PositionCorrection& knobs);

/// Steps 1-4. Moves the two bodies of `contact` apart along `contact.normal` (which points
/// from body 2 to body 1): body 1 by +d' w1/(w1+w2) n and body 2 by -d' w2/(w1+w2) n, where
/// w is the inverse mass and d' = depth_to_remove(contact.penetration, knobs).
///
/// The depth used is `contact.penetration`, at least the deepest of the contact's points (for
/// a box pair, the overlap of the two shadows, which may be more): one push of the whole body
/// along n that clears it clears every point too. A point may be exactly 0 deep.
///
/// The centre of mass of the pair stays where it was (m1 dx1 + m2 dx2 = 0); an immovable body
/// (w = 0) never moves, and two immovable bodies are left alone; a contact within the slop
/// moves nothing. No velocity, angular velocity or orientation changes: momentum and kinetic
/// energy are exactly what they were.
void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs);

}  // namespace workbook::projection
