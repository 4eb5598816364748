#pragma once
// A responder for the engine's own tests, which must not depend on the chapters' (those are
// the exercises): an elastic, frictionless impulse along the normal, only while the pair
// approaches. Each contact sees the velocities the previous ones left, so the order in which
// contacts come shows in the result.

#include "workbook/contact.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook::testing {

inline void elastic_impulse(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const double approach = dot(body1.velocity - body2.velocity, contact.normal);
    const double inverse_masses = body1.inverse_mass + body2.inverse_mass;
    if (approach >= 0.0 || inverse_masses == 0.0) return;
    const double impulse = -2.0 * approach / inverse_masses;
    body1.velocity += contact.normal * (impulse * body1.inverse_mass);
    body2.velocity -= contact.normal * (impulse * body2.inverse_mass);
}

}  // namespace workbook::testing
