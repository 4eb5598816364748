// Chapter 3, linear impulses with restitution: your responder.
//
// Fill in the steps in order. After each one, run
//     ./workbook check linear-impulse
// and it tells you which steps pass, and for a failing one which law your code breaks.
// The chapter text (chapters/linear-impulse/chapter.md, or the built site) explains each step.
#include "linear-impulse.hpp"

namespace workbook::linear_impulse {

//! [relative-normal-velocity]
double relative_normal_velocity(const RigidBody& body1, const RigidBody& body2, const Vector3& normal) {
    // STEP 1: return the component of v1 - v2 along the normal, dot(v1 - v2, normal).
    // Negative means the bodies approach: the normal points from body 2 towards body 1.
    (void)body1;
    (void)body2;
    (void)normal;
    return 0.0;
}
//! [relative-normal-velocity]

//! [impulse-magnitude]
double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& normal, double restitution) {
    // STEP 3: return J = -(1 + e) (v12 . n) / (|n|^2 (w1 + w2)), with w = body.inverse_mass
    //         and e = restitution. Return 0 when both bodies are immovable (w1 + w2 == 0).
    (void)body1;
    (void)body2;
    (void)normal;
    (void)restitution;
    return 0.0;
}
//! [impulse-magnitude]

//! [resolve]
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    // STEP 2: return without changing anything when the pair does not approach:
    //         relative_normal_velocity(body1, body2, contact.normal) >= 0.
    // STEP 4: otherwise compute J with e = combined_restitution(body1, body2) and apply it:
    //         body 1 gets +J n times its inverse mass, body 2 gets -J n times its inverse mass.
    (void)body1;
    (void)body2;
    (void)contact;
}
//! [resolve]

}  // namespace workbook::linear_impulse
