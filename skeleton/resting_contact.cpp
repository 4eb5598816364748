// Chapter 5, resting contact: your contact solver's steps.
//
// Fill in the steps in order. After each one, run
//     ./workbook check resting-contact
// and it tells you which steps pass, and for a failing one which law your code breaks.
// The chapter text (chapters/resting-contact/chapter.md, or the built site) explains each step.
// The world calls these functions for every contact of a step, pass after pass
// (workbook/contact_solver.hpp); each works on one contact.
#include "resting-contact.hpp"

#include <algorithm>
#include <cmath>

#include "workbook/restitution.hpp"

namespace workbook::resting_contact {

//! [normal-mass]
double normal_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    // STEP 1: k = 1/m1 + 1/m2 + n . ((I1^-1 (r1 x n)) x r1 + (I2^-1 (r2 x n)) x r2), chapter 4's
    // denominator, with I^-1 = body.inverse_inertia_world and r the lever arm from each body's
    // own centre. Return 1 / k, or 0 when k == 0.
    (void)body1;
    (void)body2;
    (void)point;
    (void)normal;
    return 0.0;
}
//! [normal-mass]

//! [accumulate]
double accumulate(double& accumulated, double increment) {
    // STEP 2: add the increment to the running sum, keep the SUM >= 0 (not the increment),
    // store it in `accumulated` and return what changed: new sum - old sum.
    (void)accumulated;
    (void)increment;
    return 0.0;
}
//! [accumulate]

//! [prepare]
void prepare(const RigidBody& body1, const RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
             const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt) {
    // STEP 3: for each of the contact.point_count points, fill impulses.points[i]:
    //   mass   = normal_mass(...) at the point;
    //   bounce = -e u when the point approaches at u < -settings.bounce_threshold, else 0
    //            (u = relative normal velocity at the point, e = combined_restitution(body1, body2));
    //   bias   = knobs.fraction * max(depth - knobs.slop, 0) / dt;
    //   pseudo = 0. Leave `normal` alone: the world set it.
    (void)body1;
    (void)body2;
    (void)contact;
    (void)impulses;
    (void)settings;
    (void)knobs;
    (void)dt;
}
//! [prepare]

//! [warm-start]
void warm_start(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses) {
    // STEP 4: at each point apply J = p.normal n to body 1 and -J to body 2, with the angular
    // terms (v += J/m, w += I^-1 (r x J) for body 1).
    (void)body1;
    (void)body2;
    (void)contact;
    (void)impulses;
}
//! [warm-start]

//! [solve-velocity]
double solve_velocity(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    // STEP 5: for each point in order: u = relative normal velocity at the point now;
    // applied = accumulate(p.normal, p.mass * (p.bounce - u)); apply `applied` along n at the
    // point. Return the largest |applied| / p.mass (skip points whose mass is 0).
    (void)body1;
    (void)body2;
    (void)contact;
    (void)impulses;
    return 0.0;
}
//! [solve-velocity]

//! [solve-position]
double solve_position(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    // STEP 6: the same pass as step 5 with p.bias for the target and p.pseudo for the sum; the
    // bodies' velocities are the pseudo-velocities here.
    (void)body1;
    (void)body2;
    (void)contact;
    (void)impulses;
    return 0.0;
}
//! [solve-position]

}  // namespace workbook::resting_contact
