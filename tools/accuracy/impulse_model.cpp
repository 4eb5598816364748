#include "impulse_model.hpp"

#include <algorithm>

namespace workbook::accuracy {

void restitution_impulse(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const double approach = dot(body1.velocity - body2.velocity, contact.normal);
    const double inverse_masses = body1.inverse_mass + body2.inverse_mass;
    if (approach >= 0.0 || inverse_masses == 0.0) return;
    const double e = std::min(body1.restitution, body2.restitution);
    const double impulse = -(1.0 + e) * approach / inverse_masses;
    body1.velocity += contact.normal * (impulse * body1.inverse_mass);
    body2.velocity -= contact.normal * (impulse * body2.inverse_mass);
}

void split_projection(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double inverse_masses = body1.inverse_mass + body2.inverse_mass;
    const double depth = std::max(contact.penetration - knobs.slop, 0.0) * knobs.fraction;
    if (depth == 0.0 || inverse_masses == 0.0) return;
    body1.position += contact.normal * (depth * body1.inverse_mass / inverse_masses);
    body2.position -= contact.normal * (depth * body2.inverse_mass / inverse_masses);
}

const ResponseModel& model_for_benchmarks() {
    if (const ResponseModel* chapter = find_response_model(chapter_impulse_model)) return *chapter;
    return own_impulse_model;
}

}  // namespace workbook::accuracy
