#pragma once
/// \file
/// The one rule that turns two bodies' coefficients of restitution into the contact's.
///
/// Restitution is a property of a *pair* of materials (steel on steel, rubber on wood), but
/// scene files give each body one number, so every engine needs a combining rule. This is the
/// workbook's, in one place, so that every chapter with restitution (linear impulses,
/// angular impulses) bounces the same way.

#include <algorithm>

#include "workbook/rigid_body.hpp"

namespace workbook {

/// The coefficient of restitution of a contact between `body1` and `body2`: the **smaller**
/// of the two bodies' values.
///
/// Why the minimum (chapter 3 compares it with the rules other engines use):
/// - two bodies of one material give that material's value, e = combined(e, e); the product
///   (Bullet, Chipmunk) would give e^2, so five cradle balls of e = 0.9 would collide at 0.81;
/// - a body of e = 0 (clay) sticks to anything, as it does on a table, where the maximum
///   (Box2D) would let a superball bounce off clay;
/// - the ground's default e = 1 leaves a ball's own value in charge, so a scene sets the
///   bounce on the ball alone;
/// - the result stays in [0, 1] whatever the inputs are.
[[nodiscard]] inline double combined_restitution(const RigidBody& body1, const RigidBody& body2) {
    return std::min(body1.restitution, body2.restitution);
}

}  // namespace workbook
