#pragma once
// The laws chapter 4's steps are checked against, shared by the public step tests and the
// hidden tests so that a student reads the same law, statement and hint from both.
#include "feedback.hpp"

namespace workbook::angular_impulse_laws {

using workbook::testing::Law;

inline const Law world_inertia{
    "the inverse inertia in the world frame", "I_world^-1 = R I^-1 R^T, the inverse of R I R^T, so that w = I_world^-1 L",
    "body.inertia_body is given in the body frame: invert it (inverse()), then rotate it on both sides, "
    "R * inverse(I) * transpose(R) with R = to_matrix(body.orientation); not I itself, and not R^T I^-1 R"};
inline const Law immovable{
    "an immovable body (inverse mass 0) cannot be moved or turned",
    "its inverse inertia is the zero matrix, and an impulse changes neither its velocity nor its angular velocity",
    "return Matrix3::zero() when body.is_immovable(); multiply by inverse_mass and the inverse inertia rather than "
    "divide by a mass"};
inline const Law point_velocity{
    "the velocity of a point of a rigid body", "v_p = v + w x r with r = p - x, the lever arm from the body's own centre",
    "add the rotation's share w x r to the centre's velocity: cross(body.angular_velocity, point - body.position), in "
    "that order (r x w points the other way)"};
inline const Law rigid{
    "a rigid body keeps its shape", "two points p and q move so that (v_p - v_q) . (p - q) = 0: their distance is fixed",
    "the rotation's share of a point's velocity, w x r, is perpendicular to r; use cross(w, r) with r measured from "
    "the body's centre"};
inline const Law rod{
    "the tilted rod's impulse", "J = (1 + e) m u / (1 + 3 cos^2 theta) for a thin rod of mass m falling at u onto one end",
    "the denominator needs the angular term n . ((I^-1 (r x n)) x r) for each body, with I^-1 the world inverse inertia "
    "of step 1 and r from each body's own centre; without it J = (1 + e) m u, too large"};
inline const Law central{
    "an impulse through the centres turns nothing", "with r x n = 0, J = -(1 + e) (v12 . n) / (1/m1 + 1/m2), chapter 3's",
    "the angular term vanishes when r x n = 0; if the result differs, the linear part is wrong: 1/m1 + 1/m2 with "
    "inverse masses, and -(1 + e) times the relative normal velocity"};
inline const Law restitution{
    "Newton's law of restitution at the contact point",
    "u' = -e u, where u = (v_p1 - v_p2) . n is the relative normal velocity of the contact point itself",
    "take u from the point velocities of step 2 (not the centres' velocities), J = -(1 + e) u / k with k including the "
    "angular term, and apply J n at the point to both bodies, + on body 1 and - on body 2"};
inline const Law push{
    "contacts push, never pull", "J >= 0 for an approaching point (u < 0)",
    "u is negative when the point approaches, so -(1 + e) u / k is positive; k is a sum of positive terms"};
inline const Law momentum{
    "conservation of linear momentum", "m1 v1 + m2 v2 is the same before and after, to rounding",
    "the impulse changes v, not only w: v1 += impulse * inverse_mass1, v2 -= impulse * inverse_mass2"};
inline const Law angular_momentum{
    "conservation of angular momentum about a fixed point",
    "the sum over both bodies of x cross m v + I w is the same before and after, to rounding",
    "body 1 gets w1 += I1^-1 (r1 x impulse) and body 2 w2 -= I2^-1 (r2 x impulse): r x F (torque), not F x r, each r "
    "from its own body's centre, and the world inverse inertia of step 1"};
inline const Law impulse_response{
    "an impulse changes velocity and angular velocity", "dv = impulse / m and dw = I^-1 (r x impulse)",
    "apply the impulse to both v (divided by the mass) and w (the torque r x impulse through the world inverse inertia)"};
inline const Law energy{
    "kinetic energy never rises in a collision",
    "1/2 m v^2 + 1/2 w . I w, summed over both bodies, is not larger after; at e = 1 with one point it is unchanged",
    "the impulse must have the size of step 3 (angular term included) and be applied where it acts, r from each "
    "centre; a rising energy means an impulse too large or turning the wrong way"};
inline const Law separating{
    "only approaching contacts get an impulse", "when no contact point approaches, u >= 0, nothing changes",
    "compute u at the contact point from the point velocities and return before changing anything when u >= 0"};
inline const Law contact_point{
    "the contact point decides, not the centres",
    "a point that approaches (u < 0) is pushed even while the centres move apart, and a receding point is left "
    "alone even while the centres approach",
    "decide \"approaching\" from u at the contact point, (point_velocity(body1, p) - point_velocity(body2, p)) . n "
    "with the spin's w x r (step 2), not from the centres' velocities v1 - v2: a spinning body's point moves "
    "otherwise than its centre"};
inline const Law flat{
    "a box landing flat bounces straight", "v' = -e v, and the box does not start to spin: |w'| <= 1e-9 rad/s",
    "impulses applied corner after corner, each once, make the box spin; resolve the points together: sweep over "
    "them until no accumulated impulse changes (keeping each >= 0, and without a low cap on the sweeps), or solve for "
    "all the impulses at once"};
inline const Law every_point{
    "every contact point leaves as restitution says", "each point that approached at u leaves at u' >= -e u, and "
    "a point that pushes leaves at exactly -e u",
    "one pass over the points is not enough: a later point's impulse changes the velocity of the earlier ones. Repeat the "
    "sweeps, each time giving a point (target - u) / k with the accumulated impulse clamped at 0, until nothing changes; "
    "or solve the points' equations together"};
inline const Law edge{
    "a box landing on an edge", "J = (1 + e) u / (1/m + d^2 / I_axis) in total, w = J d / I_axis, d the edge's "
    "horizontal distance from the centre",
    "the two corners of the edge share one impulse; resolve them together so that both leave at -e u: sweeps "
    "repeated until no accumulated impulse changes (no low cap on their number), or one solve for both"};

}  // namespace workbook::angular_impulse_laws
