#pragma once
/// \file
/// Chapter 3, linear impulses with restitution: the functions the student writes.
///
/// Shared by skeleton/linear_impulse.cpp (the student's copy) and the reference solution, so the two
/// can never disagree on a signature.

#include "workbook/contact.hpp"
#include "workbook/restitution.hpp"
#include "workbook/rigid_body.hpp"

/// Chapter 3, linear impulses with restitution (\ref chapter_linear_impulse): one impulse
/// J n along the contact normal, sized so that the relative normal velocity is reversed and
/// scaled by the coefficient of restitution e.
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
/// relative_normal_velocity() and impulse_magnitude() take a `normal` of any length from 1e-3 to
/// 1e3 (not only a unit one), and impulse_magnitude() any `restitution` from 0 to 1 and any
/// motion, approaching or not. resolve() changes the two velocities only.
namespace workbook::linear_impulse {

/// Step 1. The relative normal velocity v12 . n = (v1 - v2) . n, in m/s when `normal` is a
/// unit vector. Negative when the bodies approach each other along `normal` (which points
/// from body 2 to body 1), positive when they separate, zero when they slide or rest.
[[nodiscard]] double relative_normal_velocity(const RigidBody& body1, const RigidBody& body2, const Vector3& normal);

/// Step 3. The size J of the impulse +J n on body 1 and -J n on body 2 that makes
/// v12' . n = -e v12 . n:
///
///     J = -(1 + e) (v12 . n) / (|n|^2 (1/m1 + 1/m2))
///
/// written with inverse masses, so an immovable body (inverse mass 0) needs no special case.
/// `normal` need not be unit length: J n, and so every velocity, is the same for n and 2 n.
/// With two immovable bodies there is nothing to push: 0. J >= 0 for an approaching pair.
[[nodiscard]] double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& normal,
                                       double restitution);

/// Steps 2 and 4. Responds to `contact` with one impulse along its normal: a pair that does
/// not approach (v12 . n >= 0) is left exactly as it is; otherwise body 1's velocity changes
/// by +J n / m1 and body 2's by -J n / m2, with e = workbook::combined_restitution() of the
/// two bodies. Momentum is kept, the tangential relative velocity is untouched, and the
/// kinetic energy falls by exactly 1/2 mu (1 - e^2) (v12 . n)^2.
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact);

}  // namespace workbook::linear_impulse
