#pragma once
/// \file
/// How a scene answers contacts: the hook each chapter's responder plugs into.

#include <span>
#include <string_view>

#include "workbook/contact.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook {

/// Changes the velocities of the two bodies of one contact (an impulse, or a merge).
using VelocityResponder = void (*)(RigidBody& body1, RigidBody& body2, const Contact& contact);

/// Moves the two bodies of one contact apart (the projection method).
using PositionCorrector = void (*)(RigidBody& body1, RigidBody& body2, const Contact& contact);

/// A named pair of stages. Either may be null: the world then skips that stage entirely.
struct ResponseModel {
    std::string_view name;                 ///< what scene files write in "responder"
    VelocityResponder respond = nullptr;  ///< velocity stage, or null
    PositionCorrector correct = nullptr;  ///< position stage, or null
};

/// Every response model the linked chapter code provides (the reference solutions or the
/// student's skeleton, whichever the executable was linked with).
std::span<const ResponseModel> response_models();

/// The model called `name`, or nullptr when there is none.
const ResponseModel* find_response_model(std::string_view name);

}  // namespace workbook
