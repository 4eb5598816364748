// Chapter 2 on the grader's wire (see remote.hpp and docs/adding-a-chapter.md): every
// function of chapters/projection/projection.hpp, once in the list and once as a stand-in.
#include "projection.hpp"
#include "remote.hpp"

namespace workbook::projection {

using Remote = remote::Functions<&depth_to_remove, &correct>;

#if WORKBOOK_REMOTE_CHECKER
double depth_to_remove(double depth, const PositionCorrection& knobs) { return Remote::call<&depth_to_remove>(depth, knobs); }
void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    Remote::call<&correct>(body1, body2, contact, knobs);
}
#endif

}  // namespace workbook::projection

WORKBOOK_REMOTE_SERVE(workbook::projection::Remote)
