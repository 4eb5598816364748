// Chapter 6 on the grader's wire (see remote.hpp and docs/adding-a-chapter.md): every
// function of chapters/friction/friction.hpp, once in the list and once as a stand-in.
#include "friction.hpp"
#include "remote.hpp"

namespace workbook::friction {

using Remote = remote::Functions<&mix_coefficients, &tangent_basis, &tangent_mass, &accumulate_friction, &solve_friction>;

#if WORKBOOK_REMOTE_CHECKER
double mix_coefficients(double mu1, double mu2) { return Remote::call<&mix_coefficients>(mu1, mu2); }
std::array<Vector3, 2> tangent_basis(const Vector3& normal) { return Remote::call<&tangent_basis>(normal); }
double tangent_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& tangent) {
    return Remote::call<&tangent_mass>(body1, body2, point, tangent);
}
std::array<double, 2> accumulate_friction(std::array<double, 2>& accumulated, const std::array<double, 2>& increment,
                                          double normal_impulse, double static_coefficient, double dynamic_coefficient) {
    return Remote::call<&accumulate_friction>(accumulated, increment, normal_impulse, static_coefficient, dynamic_coefficient);
}
double solve_friction(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    return Remote::call<&solve_friction>(body1, body2, contact, impulses);
}
#endif

}  // namespace workbook::friction

WORKBOOK_REMOTE_SERVE(workbook::friction::Remote)
