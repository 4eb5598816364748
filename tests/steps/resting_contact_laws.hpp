#pragma once
// The laws chapter 5's steps are checked against, shared by the public step tests and the
// hidden tests so that a student reads the same law, statement and hint from both.
#include "feedback.hpp"

namespace workbook::resting_contact_laws {

using workbook::testing::Law;

inline const Law effective_mass{
    "the effective mass of a contact point",
    "m_eff = 1 / k with k = 1/m1 + 1/m2 + n . ((I1^-1 (r1 x n)) x r1 + (I2^-1 (r2 x n)) x r2); a cube's corner on the "
    "ground has m/4",
    "invert chapter 4's denominator, angular terms included (body.inverse_inertia_world, r from each body's own "
    "centre); return 0 when k is 0"};
inline const Law accumulated{
    "the accumulated impulse is clamped, not the increment",
    "after accumulate(J, dJ): J' = max(J + dJ, 0), and the returned impulse is J' - J (negative when a later pass "
    "takes back some of an earlier one)",
    "add first, then clamp the SUM at zero and return the difference; clamping dJ itself (max(dJ, 0)) can never "
    "take back an impulse that was too large"};
inline const Law bounce{
    "restitution only for a real impact",
    "bounce = -e u for a point approaching at u < -threshold, else 0: resting bodies do not bounce on gravity's own "
    "speed of one step",
    "u is the relative normal velocity at the point (body 1's point velocity minus body 2's, dotted with n); compare "
    "it with -settings.bounce_threshold"};
inline const Law bias{
    "the overlap to remove this step",
    "bias = fraction * max(depth - slop, 0) / dt (at most settings.max_push / dt): the pseudo-velocity that removes that "
    "share of the overlap in one step",
    "use the point's own depth (contact.points[i].penetration), subtract the slop, clamp at 0, scale by the fraction, "
    "cap at settings.max_push and divide by dt; set pseudo to 0 and leave normal alone"};
inline const Law warm{
    "warm starting applies the stored impulse",
    "body 1 gets +J and body 2 gets -J at the point, J = normal n, with the angular terms v += J / m, "
    "w += I^-1 (r x J)",
    "apply the accumulated impulse itself, not a new one; each body's lever arm from its own centre"};
inline const Law rest{
    "a resting point stops approaching",
    "after a pass, u = bounce at every point that still pushes (accumulated impulse > 0), and u >= bounce where it "
    "does not",
    "dJ = mass * (bounce - u) with u measured now, before the impulse; pass dJ through accumulate() and apply what it "
    "returns, + on body 1 and - on body 2, along n at the point"};
inline const Law no_pull{
    "a contact never pulls",
    "the accumulated impulse stays >= 0: a pair moving apart keeps its speed once its impulse is used up",
    "clamp the accumulated sum at zero (step 2), and apply only the returned difference"};
inline const Law stack{
    "a stack carries its own weight",
    "in a column of n resting balls, the contact under ball k carries the impulse of the (n - k + 1) balls above it, "
    "(n - k + 1) m g dt, and no ball moves",
    "the world calls your solve_velocity for every contact again and again: it must accumulate (step 2) and use the "
    "velocities as they are at that moment"};
inline const Law pseudo{
    "overlap is removed without changing velocities",
    "the position pass drives the relative normal pseudo-velocity to the bias, keeping its sum in `pseudo`, not in "
    "`normal`",
    "the same pass as step 5 with bias for bounce and pseudo for normal"};
}  // namespace workbook::resting_contact_laws
