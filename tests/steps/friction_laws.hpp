#pragma once
// The laws chapter 6's steps are checked against, shared by the public step tests, the hidden
// tests and the domain-wide samples, so that a student reads the same law, statement and hint
// from all three.
#include "feedback.hpp"

namespace workbook::friction_laws {

using workbook::testing::Law;

inline const Law mix{
    "a pair's coefficient is the geometric mean of its bodies'",
    "mu = sqrt(mu1 mu2): two bodies of one material give that material's mu, ice (mu = 0) on anything gives 0, and the "
    "pair's mu is never above the larger of the two",
    "return std::sqrt(mu1 * mu2); not the arithmetic mean (mu1 + mu2) / 2, not sqrt(mu1^2 + mu2^2), not the smaller or "
    "the larger of the two"};
inline const Law frame{
    "the tangents and the normal make a right-handed orthonormal frame",
    "|t1| = |t2| = 1, t1 . n = t2 . n = t1 . t2 = 0 and t1 x t2 = n, for every unit normal, the world's axes included; "
    "the same normal always gives the same pair",
    "t1 = normalized(cross(n, a)) with a the world axis n is LEAST aligned with (smallest |component|): a fixed axis "
    "gives a zero cross product, and a NaN, for a normal along it; then t2 = cross(n, t1), in that order"};
inline const Law tangent_mass{
    "the tangential effective mass of a contact point",
    "m_t = 1 / k with k = 1/m1 + 1/m2 + t . ((I1^-1 (r1 x t)) x r1 + (I2^-1 (r2 x t)) x r2); a solid ball on the "
    "ground has 2/7 m along any tangent (its normal effective mass is m)",
    "chapter 4's denominator with the tangent in place of the normal, angular terms included (body.inverse_inertia_world, "
    "r from each body's own centre to the point); return 0 when k is 0"};
inline const Law stick{
    "a point sticks while friction within mu_s J_n can hold it",
    "the accumulated friction (old + increment) is kept as it is while its length is at most mu_s J_n, J_n the "
    "accumulated normal impulse; the returned change is new - old",
    "add the increment to `accumulated` first, then compare the LENGTH of the sum (std::hypot of its two components) "
    "with static_coefficient * normal_impulse; return the difference between the new and the old sum"};
inline const Law slide{
    "a sliding point gets exactly mu_d J_n of friction, in the direction of the sum",
    "when |old + increment| > mu_s J_n the sum is scaled, direction kept, to length mu_d J_n: a disc (cone) of radius "
    "mu_d J_n, not a square, and never pointing the other way",
    "scale BOTH components by dynamic_coefficient * normal_impulse / |sum| (a positive factor); clamping each component "
    "on its own to [-mu J_n, mu J_n] lets the pair reach sqrt(2) mu J_n diagonally"};
inline const Law no_push{
    "no push, no friction",
    "with an accumulated normal impulse of 0 (touching without pushing, or separating) the friction sum becomes 0, and "
    "nothing is divided by zero",
    "the cone has radius mu J_n = 0: the sum sticks only if it is 0 (compare with <=, not <), else it is scaled to length "
    "0; compute the scale only when the sum's length is not 0"};
inline const Law slip_stops{
    "friction stops the slip when the cone allows it",
    "after the pass, a point that sticks has no slip: its two material points move alike along every tangent; a ball "
    "sliding at v on the ground with friction to spare ends rolling at 5/7 v",
    "measure the slip s = (v1 + w1 x r1) - (v2 + w2 x r2) at the point just before its impulse; increment_d = "
    "-tangent_mass(t_d) (s . t_d), each tangent with its own tangential mass (not the normal mass p.mass)"};
inline const Law pass_cone{
    "each point's friction goes through the cone of its accumulated normal impulse",
    "after the pass every point's friction sum (friction[0] t1 + friction[1] t2) lies within mu_s p.normal, and a "
    "sliding point's is mu_d p.normal long; a point with p.normal = 0 ends with none",
    "pass the increments and the point's ACCUMULATED normal impulse impulses.points[i].normal through "
    "accumulate_friction(), with mu_s from the bodies' static_friction and mu_d from their friction (mix_coefficients())"};
inline const Law pass_apply{
    "the change of friction is applied at the point, to both bodies, with the angular terms",
    "J = applied[0] t1 + applied[1] t2: v1 += J/m1, w1 += I1^-1 (r1 x J), v2 -= J/m2, w2 -= I2^-1 (r2 x J), so momentum "
    "is kept and an immovable body never moves",
    "apply what accumulate_friction() RETURNS (the change), not the whole accumulated friction; + on body 1 and - on "
    "body 2, each lever arm from its own body's centre"};
inline const Law pass_change{
    "the pass reports how much it changed a slip",
    "the returned value is the largest, over the points, length of the tangential part of the change of the relative "
    "velocity at the point, m/s; 0 when nothing changed",
    "after applying a point's impulse measure its relative velocity again, subtract the slip before, drop the part "
    "along the normal and keep the largest length; a velocity, not an impulse"};
inline const Law slope{
    "a ball on a slope rolls while static friction can hold its contact point, and slides beyond",
    "on a slope of angle theta a solid ball rolls without slipping, accelerating at 5/7 g sin theta, while "
    "mu_s >= 2/7 tan theta; beyond that it slides, accelerating at g (sin theta - mu_d cos theta) and spinning up at "
    "5/2 mu_d g cos theta / r",
    "mu_s decides whether a point sticks (the sum within mu_s J_n), mu_d is the friction of a point that slides: "
    "mix_coefficients() of the bodies' static_friction for the first and of their friction for the second"};

}  // namespace workbook::friction_laws
