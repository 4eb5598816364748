// Chapter 1 on the grader's wire (see remote.hpp and docs/adding-a-chapter.md): every
// function of chapters/inelastic/inelastic.hpp, once in the list and once as a stand-in.
#include "inelastic.hpp"
#include "remote.hpp"

namespace workbook::inelastic {

using Remote = remote::Functions<&common_velocity, &resolve, &energy_lost>;

#if WORKBOOK_REMOTE_CHECKER
Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) { return Remote::call<&common_velocity>(body1, body2); }
void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) { Remote::call<&resolve>(body1, body2, contact); }
double energy_lost(const RigidBody& body1, const RigidBody& body2) { return Remote::call<&energy_lost>(body1, body2); }
#endif

}  // namespace workbook::inelastic

WORKBOOK_REMOTE_SERVE(workbook::inelastic::Remote)
