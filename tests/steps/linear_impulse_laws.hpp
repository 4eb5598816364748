#pragma once
// The laws chapter 3's steps are checked against, shared by the public step tests and the
// hidden tests so that a student reads the same law, statement and hint from both.
#include "feedback.hpp"

namespace workbook::linear_impulse_laws {

using workbook::testing::Law;

inline const Law normal_velocity{
    "relative normal velocity", "v12 . n = (v1 - v2) . n, negative when the bodies approach",
    "subtract in the order body 1 minus body 2, then dot with the normal: dot(body1.velocity - body2.velocity, normal); "
    "the normal points from body 2 to body 1, so an approaching pair gives a negative number"};
inline const Law separating{
    "a contact can only push", "when v12 . n >= 0 (separating, sliding or resting) both velocities stay exactly as they are",
    "return before changing anything when relative_normal_velocity(body1, body2, contact.normal) >= 0; an impulse on a "
    "separating pair would pull the bodies back together"};
inline const Law respond{
    "an approaching pair must be resolved", "when v12 . n < 0 resolve changes the velocities",
    "skip only pairs with v12 . n >= 0; check the comparison's direction (approaching is < 0) and that resolve applies "
    "the impulse when the pair approaches"};
inline const Law impulse{
    "the impulse that reverses the relative normal velocity", "J = -(1 + e) (v12 . n) / (|n|^2 (1/m1 + 1/m2))",
    "use the inverse masses w = body.inverse_mass in the denominator (w1 + w2, never m1 + m2), the factor 1 + e (not "
    "e - 1), and the relative normal velocity of step 1; with w1 + w2 == 0 return 0"};
inline const Law push{
    "contacts push, never pull", "J >= 0 for every approaching pair (v12 . n < 0)",
    "v12 . n is negative when the pair approaches, so -(1 + e) (v12 . n) is positive; a negative J means a sign is "
    "flipped: the order v1 - v2, the minus in front, or 1 + e"};
inline const Law normal_length{
    "the length of the normal cancels", "J n is the same impulse for n and k n: J(k n) = J(n) / k",
    "divide by |n|^2 = dot(n, n) as well as by the inverse masses: v12 . n grows with |n| and so does the J n you apply"};
inline const Law momentum{
    "conservation of linear momentum", "m1 v1 + m2 v2 is the same before and after, to rounding",
    "the impulses must be equal and opposite: body 1 gets +J n times w1, body 2 gets -J n times w2 (minus, and its own "
    "inverse mass)"};
inline const Law restitution{
    "Newton's law of restitution", "v12' . n = -e v12 . n, with e = combined_restitution(body1, body2)",
    "compute J once, before either velocity changes, from the relative velocity v1 - v2 (not from one body's own "
    "velocity), with e = combined_restitution(body1, body2), and apply it to both bodies"};
inline const Law tangential{
    "a frictionless impulse acts along the normal only", "the tangential relative velocity v12 - (v12 . n) n is unchanged",
    "change the velocities only by multiples of contact.normal; reversing the whole relative velocity (or its "
    "sliding part) is a different, wrong model"};
inline const Law energy{
    "kinetic energy lost to restitution", "E - E' = 1/2 mu (1 - e^2) (v12 . n)^2, mu = m1 m2 / (m1 + m2)",
    "the loss is set by the impulse alone: if it is wrong, J or the way it is applied is (equal and opposite, scaled by "
    "each body's inverse mass, once per contact however many points it has)"};
inline const Law immovable{
    "an immovable body (inverse mass 0) has infinite mass", "it keeps its velocity exactly, and nothing becomes NaN",
    "multiply the impulse by body.inverse_mass, which is 0 for an immovable body, rather than divide by body.mass(); "
    "with two immovable bodies return J = 0 rather than divide by w1 + w2 = 0"};

}  // namespace workbook::linear_impulse_laws
