// Chapter 1, perfectly inelastic collision: your responder.
//
// Fill in the steps in order. After each one, run
//     ./workbook check inelastic
// and it tells you which steps pass, and for a failing one which law your code breaks.
// The chapter text (chapters/inelastic/chapter.md, or the built site) explains each step.
#include "inelastic.hpp"

namespace workbook::inelastic {

//! [common-velocity]
Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    // STEP 1: return the velocity that keeps m1 v1 + m2 v2 unchanged when both bodies share it.
    // Use body.inverse_mass rather than body.mass(): an immovable body has inverse_mass 0.
    (void)body1;
    (void)body2;
    return {};
}
//! [common-velocity]

//! [resolve]
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    // STEP 2: give both bodies the common velocity (every component, not only the normal one).
    // STEP 3: an immovable body (inverse_mass == 0) keeps its velocity exactly and the other body
    //         takes that velocity; with two immovable bodies, change nothing.
    // STEP 4: leave the pair alone when it is already separating: dot(v1 - v2, contact.normal) >= 0.
    (void)body1;
    (void)body2;
    (void)contact;
}
//! [resolve]

//! [energy-lost]
double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    // STEP 5: return 1/2 mu |v1 - v2|^2, with the reduced mass mu = 1 / (1/m1 + 1/m2).
    (void)body1;
    (void)body2;
    return 0.0;
}
//! [energy-lost]

}  // namespace workbook::inelastic
