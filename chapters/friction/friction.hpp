#pragma once
/// \file
/// Chapter 6, friction: the functions the student writes.
///
/// Shared by skeleton/friction.cpp (the student's copy) and the reference solution, so the two
/// can never disagree on a signature. The world's contact solver (workbook/contact_solver.hpp)
/// calls solve_friction() for every contact of a step, right after chapter 5's normal pass,
/// pass after pass; the other functions are its parts.

#include <array>

#include "resting-contact.hpp"
#include "workbook/contact.hpp"
#include "workbook/contact_solver.hpp"
#include "workbook/rigid_body.hpp"
#include "workbook/vector3.hpp"

/// Chapter 6, friction (\ref chapter_friction): Coulomb friction on chapter 5's contact solver.
/// At every contact point a tangential impulse, accumulated within the step like the normal
/// one, tries to stop the slip (the tangential relative velocity of the two material points);
/// its length is kept within the friction cone, at most mu_s J_n while the point sticks and
/// exactly mu_d J_n once it slides, J_n being the normal impulse the point has accumulated.
/// The bodies' coefficients are `RigidBody::static_friction` and `RigidBody::friction`; a
/// pair's are the geometric means of its bodies' (as Box2D's).
///
/// **Legal inputs** (what the tests draw, and all a function must handle):
/// - a coefficient of friction is 0 or from 1e-6 to 10; a body's static coefficient is at
///   least its dynamic one;
/// - a body's `inverse_mass` is 0 (immovable: the ground, a wall, or a kinematic platform
///   that moves and spins at a velocity of its own) or a mass from 1e-6 to 1e6 kg; the
///   movable body's inertia about its mass times a size from 1 cm to 10 m squared, symmetric
///   positive definite, principal axes turned any way; at least one body of a pair movable;
/// - velocities and angular velocities of any direction, 0 or up to 1e3 m/s and 1e3 rad/s;
///   positions up to 1 km from the origin; any orientation;
/// - `normal` and `contact.normal` a unit vector (length 1 to rounding) in any direction,
///   the world's axes and their opposites included, from body 2 towards body 1;
///   `contact.point_count` 1 to 4, each point at least 0 deep, within a few of body 1's sizes
///   of its centre (a ball's point on the normal through its centre; a box's corners);
///   `tangent` a unit vector at right angles to some such normal;
/// - an impulse accumulated so far: `normal` 0 or from 1e-9 to 1e3 kg m/s; each component of
///   `friction` (and of accumulate_friction()'s `accumulated` and `increment`) 0 or up to
///   1e3 kg m/s of either sign, and the pair may lie outside the cone (the normal impulse may
///   have shrunk since it was clamped).
///
/// mix_coefficients(), tangent_basis() and tangent_mass() change nothing;
/// accumulate_friction() changes `accumulated` only; solve_friction() changes the two bodies'
/// velocities and angular velocities and the points' `friction`, nothing else.
namespace workbook::friction {

/// Step 1. The coefficient of friction of a pair of bodies whose own coefficients are `mu1`
/// and `mu2`: their geometric mean sqrt(mu1 mu2). Two bodies of one material give that
/// material's value, ice (0) on anything gives 0, and the result never exceeds the larger of
/// the two. Used for the static and the dynamic coefficient alike.
[[nodiscard]] double mix_coefficients(double mu1, double mu2);

/// Step 2. Two unit vectors t1, t2 that with the unit `normal` n make a right-handed
/// orthonormal frame (n, t1, t2): t1 . n = t2 . n = t1 . t2 = 0, |t1| = |t2| = 1 and
/// t1 x t2 = n, all to rounding. Defined (finite) for every unit normal, the world's axes
/// included: never normalise a vector that can be zero or nearly so. The same normal always
/// gives the same pair.
[[nodiscard]] std::array<Vector3, 2> tangent_basis(const Vector3& normal);

/// Step 3. The tangential effective mass at `point` along the unit `tangent`, in kg: the
/// impulse along the tangent that changes the relative velocity of the two material points
/// along it by 1 m/s. It is 1 / k with
///   k = 1/m1 + 1/m2 + t . ((I1^-1 (r1 x t)) x r1 + (I2^-1 (r2 x t)) x r2),
/// r the lever arm from each body's centre to the point and I^-1 the body's
/// `inverse_inertia_world`; 0 when k is 0 (two immovable bodies). For a ball on the ground
/// the angular terms make it 2/7 m, where the normal effective mass is m.
[[nodiscard]] double tangent_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point,
                                  const Vector3& tangent);

/// Step 4. Coulomb's law for one point, on impulses accumulated within the step. Adds
/// `increment` to `accumulated` (both as components along the point's two tangents, kg m/s)
/// and keeps the sum within the friction cone of the point's accumulated normal impulse
/// `normal_impulse` (>= 0):
///  - the point sticks when the sum's length is at most `static_coefficient` x
///    `normal_impulse`: the sum is kept as it is;
///  - otherwise it slides: the sum is scaled (same direction) to the length
///    `dynamic_coefficient` x `normal_impulse`.
/// Stores the new sum in `accumulated` and returns what changed, new sum minus old. With a
/// normal impulse of 0 the sum becomes 0 (no push, no friction), without dividing by zero.
std::array<double, 2> accumulate_friction(std::array<double, 2>& accumulated, const std::array<double, 2>& increment,
                                          double normal_impulse, double static_coefficient,
                                          double dynamic_coefficient);

/// Step 5. One friction pass over the points of one contact, run by the solver right after
/// chapter 5's normal pass (resting_contact::solve_velocity()). The contact's coefficients are
/// mix_coefficients() of the bodies' `static_friction` and of their `friction`. At each point
/// i, in order, with p = impulses.points[i] and (t1, t2) = tangent_basis(contact.normal):
///  - the slip s = body 1's point velocity minus body 2's at the point (before this point's
///    impulse);
///  - the increments -tangent_mass(t_d) (s . t_d) for d = 1, 2 (0 where the mass is 0) go
///    through accumulate_friction() into `p.friction`, against the accumulated `p.normal`;
///  - what it returns, applied[0] t1 + applied[1] t2, is applied at the point to body 1 and
///    its opposite to body 2, with the angular terms (as chapter 4's
///    angular_impulse::apply_impulse()).
/// A point whose accumulated normal impulse is 0 (touching without pushing, or separating)
/// ends with no friction. Returns the largest change this pass made to a point's slip, the
/// length of the tangential part of the change of its relative velocity, m/s (0 when none).
double solve_friction(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses);

/// Chapter 5's contact solver with this chapter's friction pass (response model `friction`).
/// The solver warm starts each point itself, the normal impulse and the friction impulses
/// along tangent_basis(), so that remembered friction is applied along the tangents it was
/// accumulated along (ContactSolverHooks::tangents).
inline constexpr ContactSolverHooks hooks{&resting_contact::prepare,        &resting_contact::warm_start,
                                          &resting_contact::solve_velocity, &solve_friction,
                                          &resting_contact::solve_position, &tangent_basis};

}  // namespace workbook::friction
