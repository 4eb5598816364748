// Chapter 6, friction: your friction pass for chapter 5's contact solver.
//
// Fill in the steps in order. After each one, run
//     ./workbook check friction
// and it tells you which steps pass, and for a failing one which law your code breaks.
// The chapter text (chapters/friction/chapter.md, or the built site) explains each step.
// The world's contact solver calls solve_friction() for every contact right after chapter 5's
// normal pass, pass after pass; the other functions are its parts.
#include "friction.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace workbook::friction {

//! [mix-coefficients]
double mix_coefficients(double mu1, double mu2) {
    // STEP 1: the pair's coefficient is the geometric mean of the two bodies' coefficients,
    // sqrt(mu1 * mu2).
    (void)mu1;
    (void)mu2;
    return 0.0;
}
//! [mix-coefficients]

//! [tangent-basis]
std::array<Vector3, 2> tangent_basis(const Vector3& normal) {
    // STEP 2: two unit vectors t1, t2 at right angles to the normal and to each other, with
    // t1 x t2 = normal. Build t1 as the normalised cross product of the normal with a world
    // axis, chosen so that the cross product can never be (nearly) zero whatever the normal
    // is; then t2 = normal x t1.
    (void)normal;
    return {Vector3{}, Vector3{}};
}
//! [tangent-basis]

//! [tangent-mass]
double tangent_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& tangent) {
    // STEP 3: k = 1/m1 + 1/m2 + t . ((I1^-1 (r1 x t)) x r1 + (I2^-1 (r2 x t)) x r2), with
    // I^-1 = body.inverse_inertia_world and r the lever arm from each body's centre to the
    // point. Return 1 / k, or 0 when k == 0.
    (void)body1;
    (void)body2;
    (void)point;
    (void)tangent;
    return 0.0;
}
//! [tangent-mass]

//! [accumulate-friction]
std::array<double, 2> accumulate_friction(std::array<double, 2>& accumulated, const std::array<double, 2>& increment,
                                          double normal_impulse, double static_coefficient,
                                          double dynamic_coefficient) {
    // STEP 4: add the increment to the accumulated pair. If the new pair's length is at most
    // static_coefficient * normal_impulse, keep it (the point sticks); otherwise scale it, in
    // the same direction, to the length dynamic_coefficient * normal_impulse (it slides).
    // Store it in `accumulated` and return new pair - old pair. Never divide by zero.
    (void)accumulated;
    (void)increment;
    (void)normal_impulse;
    (void)static_coefficient;
    (void)dynamic_coefficient;
    return {0.0, 0.0};
}
//! [accumulate-friction]

//! [solve-friction]
double solve_friction(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    // STEP 5: mu_s = mix_coefficients of the bodies' static_friction, mu_d of their friction;
    // (t1, t2) = tangent_basis(contact.normal). For each point p = impulses.points[i]:
    //   s = velocity of body 1's material point there minus body 2's (v + w x r);
    //   increment[d] = -tangent_mass(body1, body2, point, t_d) * (s . t_d);
    //   applied = accumulate_friction(p.friction, increment, p.normal, mu_s, mu_d);
    //   apply J = applied[0] t1 + applied[1] t2 at the point: +J to body 1, -J to body 2, with
    //   the angular terms (v += J/m, w += I^-1 (r x J)).
    // Return the largest length of the tangential part of the change of a point's relative
    // velocity this pass made.
    (void)body1;
    (void)body2;
    (void)contact;
    (void)impulses;
    return 0.0;
}
//! [solve-friction]

}  // namespace workbook::friction
