#pragma once
/// \file
/// Chapter 4, angular impulses: the functions the student writes.
///
/// Shared by skeleton/angular_impulse.cpp (the student's copy) and the reference solution, so the two
/// can never disagree on a signature.

#include "workbook/contact.hpp"
#include "workbook/matrix3.hpp"
#include "workbook/rigid_body.hpp"

/// Chapter 4, angular impulses (\ref chapter_angular_impulse): an impulse J n applied at a
/// contact point away from the centre of mass changes both the velocity and the angular
/// velocity of each body, and a contact with several points is resolved as one.
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
/// Here also: angular velocities of any direction, an immovable body may spin (kinematic); a
/// movable body's inertia is about its mass times a size from 1 cm to 10 m squared, kept within
/// 1e-90 to 1e90 kg m^2 (its determinant a normal double), principal axes turned any way in
/// the body. `point` anywhere near the bodies, its lever arms not along the normal. A contact
/// of several points is a face, an edge or a few corners of body 1 within a few of its sizes,
/// where some points may approach while others rest or move away (a rocking box).
/// apply_impulse() and resolve() change velocities and angular velocities only.
namespace workbook::angular_impulse {

/// Step 1. The inverse inertia tensor in the world frame, R I^-1 R^T, where I is
/// `body.inertia_body` (body frame) and R = to_matrix(body.orientation). It turns an angular
/// momentum into the angular velocity it causes: w = I_world^-1 L. The zero matrix for an
/// immovable body (no torque turns it).
[[nodiscard]] Matrix3 world_inverse_inertia(const RigidBody& body);

/// Step 2. The velocity of the material point of `body` that is at `point` (world, m) now:
/// v + w x r, with the lever arm r = point - body.position. The term w x r is the point's
/// velocity due to the rotation. For a kinematic body (immovable but moving) it is its
/// prescribed motion, the same formula.
[[nodiscard]] Vector3 point_velocity(const RigidBody& body, const Vector3& point);

/// Step 3. How much the relative normal velocity at `point` changes per unit of impulse +n on
/// body 1 and -n on body 2, in 1/kg (the tutorial's denominator, with |n| = 1):
///
///     k = 1/m1 + 1/m2 + n . ((I1^-1 (r1 x n)) x r1 + (I2^-1 (r2 x n)) x r2)
///
/// The first two terms move the centres, the angular term turns the bodies; k >= 1/m1 + 1/m2.
/// 0 when both bodies are immovable.
[[nodiscard]] double impulse_denominator(const RigidBody& body1, const RigidBody& body2, const Vector3& point,
                                         const Vector3& normal);

/// Step 3. The size J of the impulse +J n on body 1 and -J n on body 2, applied at `point`,
/// that turns the relative normal velocity at the point, u = (vp1 - vp2) . n with vp the
/// point_velocity() of each body, into -e u:  J = -(1 + e) u / k with k the impulse_denominator().
/// Positive for an approaching point (u < 0); 0 when both bodies are immovable.
[[nodiscard]] double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& point,
                                       const Vector3& normal, double restitution);

/// Step 4. Applies `impulse` (a vector, kg m/s) to body 1 at `point` and its opposite to body 2:
/// v1 += impulse / m1, w1 += I1^-1 (r1 x impulse), v2 -= impulse / m2, w2 -= I2^-1 (r2 x impulse),
/// with the world-frame inverse inertia of step 1. Keeps the total linear momentum and the total
/// angular momentum about any fixed point; an immovable body is not changed.
void apply_impulse(RigidBody& body1, RigidBody& body2, const Vector3& point, const Vector3& impulse);

/// Steps 5 and 6. Responds to `contact` with impulses along its normal at its points, with
/// e = workbook::combined_restitution() of the two bodies. When no point approaches, nothing
/// changes. One point: one impulse of step 3's size. Several points (a face or an edge on the
/// ground) are resolved together, not one after another: every point that was approaching at
/// u leaves at no less than -e u, every point's total impulse is >= 0, and a point that pushes
/// leaves at exactly -e u. A box landing flat then bounces straight up without spinning.
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact);

}  // namespace workbook::angular_impulse
