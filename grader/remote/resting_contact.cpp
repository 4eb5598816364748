// Chapter 5 on the grader's wire (see remote.hpp and docs/adding-a-chapter.md): every
// function of chapters/resting-contact/resting-contact.hpp, once in the list and once as a stand-in.
#include "resting-contact.hpp"
#include "remote.hpp"

namespace workbook::resting_contact {

using Remote = remote::Functions<&normal_mass, &accumulate, &prepare, &warm_start, &solve_velocity,
                                 &solve_position>;

#if WORKBOOK_REMOTE_CHECKER
double normal_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    return Remote::call<&normal_mass>(body1, body2, point, normal);
}
double accumulate(double& accumulated, double increment) { return Remote::call<&accumulate>(accumulated, increment); }
void prepare(const RigidBody& body1, const RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
             const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt) {
    Remote::call<&prepare>(body1, body2, contact, impulses, settings, knobs, dt);
}
void warm_start(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses) {
    Remote::call<&warm_start>(body1, body2, contact, impulses);
}
double solve_velocity(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    return Remote::call<&solve_velocity>(body1, body2, contact, impulses);
}
double solve_position(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    return Remote::call<&solve_position>(body1, body2, contact, impulses);
}
#endif

}  // namespace workbook::resting_contact

WORKBOOK_REMOTE_SERVE(workbook::resting_contact::Remote)
