#pragma once
/// \file
/// Chapter 5, resting contact: the functions the student writes.
///
/// Shared by skeleton/resting_contact.cpp (the student's copy) and the reference solution, so
/// the two can never disagree on a signature. The world's contact solver
/// (workbook/contact_solver.hpp) calls them for every contact of a step, pass after pass.

#include "workbook/contact.hpp"
#include "workbook/contact_solver.hpp"
#include "workbook/response_model.hpp"
#include "workbook/rigid_body.hpp"

/// Chapter 5, resting contact (\ref chapter_resting_contact): every contact of a step is
/// solved together by sequential impulses. Each point keeps the impulse it has accumulated
/// within the step, only that sum has to stay non-negative, and the passes go on until no
/// point approaches; overlap is removed on pseudo-velocities that are thrown away afterwards.
///
/// The contact's legal domain, for every function: `contact.normal` is a unit vector from
/// body 2 towards body 1, `contact.point_count` is 1 to 4, every point's penetration is >= 0,
/// at least one body is movable, masses and inertias are positive and finite.
namespace workbook::resting_contact {

/// Step 1. The effective mass of the contact at `point` along `normal`, in kg: the impulse
/// that changes the relative normal velocity at the point by 1 m/s. It is 1 / k with k
/// chapter 4's denominator (angular_impulse::impulse_denominator(), angular terms included);
/// 0 when k is 0 (two immovable bodies: no impulse moves anything).
[[nodiscard]] double normal_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point,
                                 const Vector3& normal);

/// Step 2. Adds `increment` (kg m/s, either sign) to the impulse `accumulated` so far at one
/// point within this step, keeps the sum non-negative (a contact can push, never pull), and
/// returns the impulse to apply now: the new sum minus the old. A negative increment may take
/// back impulse given by an earlier pass, but never more than was given.
double accumulate(double& accumulated, double increment);

/// Step 3. Fills, for every point i of `contact`, `impulses.points[i]`:
///  - `mass`: normal_mass() at the point;
///  - `bounce`: the normal relative velocity the velocity passes aim for, -e u where the point
///    approaches at u < -settings.bounce_threshold (e = workbook::combined_restitution()), else 0;
///  - `bias`: knobs.fraction * max(depth - knobs.slop, 0) / dt, the separating pseudo-velocity
///    that would remove that share of the point's overlap in one step;
///  - `pseudo` = 0. `normal` is left as it is: the world has set it (0, or the last step's
///    impulse at the same point when warm starting).
void prepare(const RigidBody& body1, const RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
             const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt);

/// Step 4. Warm start: applies the impulse already accumulated at every point on body 1 (and
/// its opposite on body 2) at the point, with angular terms (as chapter 4's
/// angular_impulse::apply_impulse()): `normal` along the contact normal plus `friction[0]`
/// and `friction[1]` along the two workbook::friction_tangents() of the normal.
void warm_start(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses);

/// Step 5. One pass over the points of one contact: at each, in order, the impulse
/// `mass * (bounce - u)`, with u the current relative normal velocity at the point (body 1's
/// point velocity minus body 2's, dotted with the normal), goes through accumulate() into
/// `normal`, and what accumulate() returns is applied at the point. Returns the largest
/// change of a point's normal velocity this pass made, |applied| / mass, m/s (0 when none).
double solve_velocity(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses);

/// Step 7 (friction). One pass over the points of one contact for Coulomb friction with
/// coefficient `friction`: at each point, the tangential relative velocity along the two
/// workbook::friction_tangents() t1, t2 is brought to zero by impulses of size
/// -(v . t) / k_t (k_t: step 1's k with t for n), added to `friction`, and the sum is kept
/// within the disc of radius `friction` x `normal` (scaled back onto its rim when outside);
/// what changed is applied. Returns the largest change of a point's tangent velocity, m/s.
double solve_friction(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
                      double friction);

/// Step 6. The same pass for the overlap: the bodies' velocities are the pseudo-velocities
/// (the world swaps them in, starting from zero), the target is `bias` and the sum is kept in
/// `pseudo`. Returns the largest change of a point's normal pseudo-velocity, m/s.
double solve_position(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses);

/// The functions above as the world's contact solver calls them (response model
/// `resting-contact`), without friction: chapter 6 (response model `friction`) adds it.
inline constexpr ContactSolverHooks hooks{&prepare, &warm_start, &solve_velocity, nullptr, &solve_position};

}  // namespace workbook::resting_contact
