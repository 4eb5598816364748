// The reference solution of chapter 6, compiled a second time for the hidden tests'
// domain-wide samples (see ../reference.hpp), and reached through workbook::reference_friction.
// It is linked into the checker and the workbook's own test binaries only, never into a
// student's process.
//
// The other chapters rename their namespace with a macro; this chapter's name, `friction`, is
// also a field of RigidBody and PointImpulse, which such a macro would rename too. So the
// solution is read inside a namespace of its own, whose `workbook` sees the real one: its
// `namespace workbook::friction` becomes copy::workbook::friction, its every other name is
// the engine's. Every header it includes is included first (a header read inside a namespace
// would put the standard library there); the chapter header's declarations are then skipped,
// so the copy must define each function before using it, as the solution does.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <utility>

#include "../reference.hpp"
#include "friction.hpp"
#include "workbook/contact.hpp"
#include "workbook/contact_solver.hpp"
#include "workbook/matrix3.hpp"
#include "workbook/restitution.hpp"
#include "workbook/rigid_body.hpp"
#include "workbook/vector3.hpp"

namespace workbook_reference_friction_copy {
namespace workbook {
using namespace ::workbook;  // NOLINT(google-build-using-namespace): the engine, as the solution sees it
}  // namespace workbook
#include "../../../solutions/friction.cpp"  // NOLINT(bugprone-suspicious-include)
}  // namespace workbook_reference_friction_copy

namespace workbook::reference_friction {

namespace copy = ::workbook_reference_friction_copy::workbook::friction;

double mix_coefficients(double mu1, double mu2) { return copy::mix_coefficients(mu1, mu2); }

std::array<Vector3, 2> tangent_basis(const Vector3& normal) { return copy::tangent_basis(normal); }

double tangent_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& tangent) {
    return copy::tangent_mass(body1, body2, point, tangent);
}

std::array<double, 2> accumulate_friction(std::array<double, 2>& accumulated, const std::array<double, 2>& increment,
                                          double normal_impulse, double static_coefficient, double dynamic_coefficient) {
    return copy::accumulate_friction(accumulated, increment, normal_impulse, static_coefficient, dynamic_coefficient);
}

double solve_friction(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    return copy::solve_friction(body1, body2, contact, impulses);
}

}  // namespace workbook::reference_friction
