// Chapter 4, angular impulses: your responder.
//
// Fill in the steps in order. After each one, run
//     ./workbook check angular-impulse
// and it tells you which steps pass, and for a failing one which law your code breaks.
// The chapter text (chapters/angular-impulse/chapter.md, or the built site) explains each step.
#include "angular-impulse.hpp"

#include "workbook/restitution.hpp"

namespace workbook::angular_impulse {

//! [world-inverse-inertia]
Matrix3 world_inverse_inertia(const RigidBody& body) {
    // STEP 1: return R I^-1 R^T, with R = to_matrix(body.orientation) and I = body.inertia_body
    // (inverse() and transpose() are in workbook/matrix3.hpp). An immovable body: Matrix3::zero().
    (void)body;
    return Matrix3::identity();
}
//! [world-inverse-inertia]

//! [point-velocity]
Vector3 point_velocity(const RigidBody& body, const Vector3& point) {
    // STEP 2: return v + w x r, with r = point - body.position (the lever arm from THIS body's centre).
    (void)point;
    return body.velocity;
}
//! [point-velocity]

//! [impulse-size]
double impulse_denominator(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    // STEP 3: return 1/m1 + 1/m2 + n . ((I1^-1 (r1 x n)) x r1 + (I2^-1 (r2 x n)) x r2),
    // with I^-1 from step 1 and r1, r2 the lever arms from each body's own centre.
    (void)body1;
    (void)body2;
    (void)point;
    (void)normal;
    return 1.0;
}

double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal,
                         double restitution) {
    // STEP 3: u = (point velocity of body 1 - point velocity of body 2) . n; return -(1 + e) u / k,
    // with k = impulse_denominator(...), and 0 when k == 0 (two immovable bodies).
    (void)body1;
    (void)body2;
    (void)point;
    (void)normal;
    (void)restitution;
    return 0.0;
}
//! [impulse-size]

//! [apply-impulse]
void apply_impulse(RigidBody& body1, RigidBody& body2, const Vector3& point, const Vector3& impulse) {
    // STEP 4: v1 += impulse / m1 and w1 += I1^-1 (r1 x impulse); body 2 gets the opposite impulse.
    // Use inverse_mass and world_inverse_inertia(), which are 0 for an immovable body.
    (void)body1;
    (void)body2;
    (void)point;
    (void)impulse;
}
//! [apply-impulse]

//! [resolve]
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    // STEP 5: one contact point: when it approaches (relative normal velocity u < 0), apply the
    //         impulse impulse_magnitude(...) * contact.normal there, with
    //         e = combined_restitution(body1, body2); otherwise change nothing.
    // STEP 6: several points (contact.point_count up to 4): resolve them together, so that every
    //         point that approached at u leaves at -e u if it pushes (and no slower otherwise),
    //         with every point's impulse >= 0. Either sweep over the points, giving each the
    //         impulse that brings its normal velocity to its target and keeping each point's
    //         accumulated impulse >= 0, until no impulse changes any more; or solve for all the
    //         impulses at once. The chapter explains both.
    (void)body1;
    (void)body2;
    (void)contact;
}
//! [resolve]

}  // namespace workbook::angular_impulse
