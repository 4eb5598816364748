// Reference solution for chapter 2, the projection method.
#include "projection.hpp"

#include <algorithm>

namespace workbook::projection {

double depth_to_remove(double depth, const PositionCorrection& knobs) {
    // The slop is subtracted once; what lies within it is left alone, never pulled back.
    return knobs.fraction * std::max(depth - knobs.slop, 0.0);
}

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    const double inverse_mass_sum = w1 + w2;
    // Two immovable bodies: nothing can move, and w1 + w2 = 0 must not be divided by.
    if (inverse_mass_sum == 0.0) return;
    const double depth = depth_to_remove(contact.penetration, knobs);
    if (depth <= 0.0) return;
    // Split by inverse mass so that m1 dx1 + m2 dx2 = 0: the centre of mass stays put, and an
    // immovable body (w = 0) gets a displacement of exactly zero without a special case.
    const Vector3 push = contact.normal * (depth / inverse_mass_sum);
    body1.position += push * w1;
    body2.position -= push * w2;
}

}  // namespace workbook::projection
