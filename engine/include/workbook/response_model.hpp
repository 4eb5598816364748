#pragma once
/// \file
/// How a scene answers contacts: the hook each chapter's responder plugs into.

#include <span>
#include <string_view>

#include "workbook/contact.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook {

struct ContactSolverHooks;  // workbook/contact_solver.hpp

/// Changes the velocities of the two bodies of one contact (an impulse, or a merge).
using VelocityResponder = void (*)(RigidBody& body1, RigidBody& body2, const Contact& contact);

/// The two knobs every position corrector takes (chapter 2, the projection method): per step
/// it removes `fraction` of the depth beyond `slop`, that is fraction * max(depth - slop, 0).
/// fraction 1 and slop 0 remove the whole overlap at once.
struct PositionCorrection {
    double fraction = 1.0;  ///< share of the depth (beyond the slop) removed per step; often called beta or percent
    double slop = 0.0;      ///< depth left alone, m, so that resting contacts do not jitter
};

/// Moves the two bodies of one contact apart (the projection method), by the knobs given.
using PositionCorrector = void (*)(RigidBody& body1, RigidBody& body2, const Contact& contact,
                                   const PositionCorrection& knobs);

/// A named pair of stages. Either may be null: the world then skips that stage entirely.
struct ResponseModel {
    std::string_view name;                 ///< what scene files write in "responder"
    VelocityResponder respond = nullptr;  ///< velocity stage, or null
    PositionCorrector correct = nullptr;  ///< position stage, or null
    /// When set, the world answers all contacts of a step together with the contact solver
    /// (workbook/contact_solver.hpp, chapter 5) calling these functions, instead of `respond`
    /// and `correct` once per contact.
    const ContactSolverHooks* contact_solver = nullptr;
};

/// Every response model the linked chapter code provides (the reference solutions or the
/// student's skeleton, whichever the executable was linked with).
std::span<const ResponseModel> response_models();

/// The model called `name`, or nullptr when there is none.
const ResponseModel* find_response_model(std::string_view name);

}  // namespace workbook
