// Chapter 3 on the grader's wire (see remote.hpp and docs/adding-a-chapter.md): every
// function of chapters/linear-impulse/linear-impulse.hpp, once in the list and once as a stand-in.
#include "linear-impulse.hpp"
#include "remote.hpp"

namespace workbook::linear_impulse {

using Remote = remote::Functions<&relative_normal_velocity, &impulse_magnitude, &resolve>;

#if WORKBOOK_REMOTE_CHECKER
double relative_normal_velocity(const RigidBody& body1, const RigidBody& body2, const Vector3& normal) {
    return Remote::call<&relative_normal_velocity>(body1, body2, normal);
}
double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& normal, double restitution) {
    return Remote::call<&impulse_magnitude>(body1, body2, normal, restitution);
}
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) { Remote::call<&resolve>(body1, body2, contact); }
#endif

}  // namespace workbook::linear_impulse

WORKBOOK_REMOTE_SERVE(workbook::linear_impulse::Remote)
