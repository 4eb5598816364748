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
namespace workbook::projection {

/// Step 4. The depth one pass removes from a contact `depth` metres deep:
/// knobs.fraction * max(depth - knobs.slop, 0), in metres. A depth within the slop gives 0,
/// never a negative value (projection pushes bodies apart; it never pulls them together).
[[nodiscard]] double depth_to_remove(double depth, const PositionCorrection& knobs);

/// Steps 1-4. Moves the two bodies of `contact` apart along `contact.normal` (which points
/// from body 2 to body 1): body 1 by +d' w1/(w1+w2) n and body 2 by -d' w2/(w1+w2) n, where
/// w is the inverse mass and d' = depth_to_remove(contact.penetration, knobs).
///
/// The depth used is `contact.penetration`, the deepest of the contact's points: one push
/// of the whole body along n that clears the deepest point clears every other point too.
///
/// The centre of mass of the pair stays where it was (m1 dx1 + m2 dx2 = 0); an immovable body
/// (w = 0) never moves, and two immovable bodies are left alone; a contact within the slop
/// moves nothing. No velocity, angular velocity or orientation changes: momentum and kinetic
/// energy are exactly what they were.
void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs);

}  // namespace workbook::projection
