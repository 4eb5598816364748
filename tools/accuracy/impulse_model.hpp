#pragma once
/// \file
/// The response model the stress corpus and the accuracy bench run with.
///
/// They need impulses with restitution. Until chapter 3's `linear-impulse` is in the linked
/// chapter code, they use a frictionless impulse of their own along the contact normal
/// (restitution min(e1, e2)) with a projection that splits the overlap by inverse mass; once a
/// model called `linear-impulse` exists, model_for_benchmarks() returns it instead, by name.

#include <string_view>

#include "workbook/response_model.hpp"

namespace workbook::accuracy {

/// The name the chapter-3 model is looked up by.
inline constexpr std::string_view chapter_impulse_model = "linear-impulse";

/// The impulse J = -(1 + e) v_n / (1/m1 + 1/m2) along the normal, for approaching pairs only.
void restitution_impulse(RigidBody& body1, RigidBody& body2, const Contact& contact);

/// Removes the whole overlap beyond the slop, times the fraction, split by inverse mass.
void split_projection(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs);

/// The tools' own model: restitution_impulse and split_projection.
inline constexpr ResponseModel own_impulse_model{"restitution-impulse (bench's own)", &restitution_impulse,
                                                 &split_projection};

/// `linear-impulse` from the linked chapters when there is one, otherwise own_impulse_model.
const ResponseModel& model_for_benchmarks();

}  // namespace workbook::accuracy
