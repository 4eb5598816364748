// Chapter 2, the projection method: your position corrector.
//
// Fill in the steps in order. After each one, run
//     ./workbook check projection
// and it tells you which steps pass, and for a failing one which law your code breaks.
// The chapter text (chapters/projection/chapter.md, or the built site) explains each step.
#include "projection.hpp"

namespace workbook::projection {

//! [depth-to-remove]
double depth_to_remove(double depth, const PositionCorrection& knobs) {
    // STEP 4: return the depth one pass removes: knobs.fraction times the part of `depth` beyond
    //         knobs.slop, and 0 (never a negative value) when depth is within the slop.
    (void)depth;
    (void)knobs;
    return 0.0;
}
//! [depth-to-remove]

//! [correct]
void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    // STEP 1: push body 1 along +contact.normal and body 2 along -contact.normal, sharing the
    //         depth contact.penetration in proportion to the inverse masses w1 and w2, so that
    //         the centre of mass of the pair does not move and the overlap is gone.
    // STEP 2: an immovable body (inverse_mass == 0) never moves and the other body takes the
    //         whole push; with two immovable bodies, change nothing (w1 + w2 is 0).
    // STEP 3: change positions only: leave every velocity and angular velocity as it is.
    // STEP 4: push by depth_to_remove(contact.penetration, knobs) instead of the whole depth.
    (void)body1;
    (void)body2;
    (void)contact;
    (void)knobs;
}
//! [correct]

}  // namespace workbook::projection
