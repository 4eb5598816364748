// Chapter 4 on the grader's wire (see remote.hpp and docs/adding-a-chapter.md): every
// function of chapters/angular-impulse/angular-impulse.hpp, once in the list and once as a stand-in.
#include "angular-impulse.hpp"
#include "remote.hpp"

namespace workbook::angular_impulse {

using Remote = remote::Functions<&world_inverse_inertia, &point_velocity, &impulse_denominator, &impulse_magnitude,
                                 &apply_impulse, &resolve>;

#if WORKBOOK_REMOTE_CHECKER
Matrix3 world_inverse_inertia(const RigidBody& body) { return Remote::call<&world_inverse_inertia>(body); }
Vector3 point_velocity(const RigidBody& body, const Vector3& point) { return Remote::call<&point_velocity>(body, point); }
double impulse_denominator(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    return Remote::call<&impulse_denominator>(body1, body2, point, normal);
}
double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal,
                         double restitution) {
    return Remote::call<&impulse_magnitude>(body1, body2, point, normal, restitution);
}
void apply_impulse(RigidBody& body1, RigidBody& body2, const Vector3& point, const Vector3& impulse) {
    Remote::call<&apply_impulse>(body1, body2, point, impulse);
}
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) { Remote::call<&resolve>(body1, body2, contact); }
#endif

}  // namespace workbook::angular_impulse

WORKBOOK_REMOTE_SERVE(workbook::angular_impulse::Remote)
