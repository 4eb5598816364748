#pragma once
/// \file
/// The response models the stress corpus and the accuracy bench run with: the chapters' own,
/// looked up by name in the response model table (chapters/response_models.cpp), so that what
/// is measured is what the chapters teach.

#include <string_view>

#include "workbook/response_model.hpp"

namespace workbook::accuracy {

/// The model `name` from the table of the linked chapter code. Throws std::invalid_argument
/// naming the model and the ones there are when the table has no such model.
const ResponseModel& chapter_model(std::string_view name);

/// What a reader has after chapter 2: chapter 1's inelastic responder with chapter 2's
/// projection, both taken from the table ("inelastic" has no corrector of its own).
ResponseModel inelastic_with_projection();

/// The model the stress corpus runs by default: chapter 3's linear-impulse.
inline constexpr std::string_view default_stress_model = "linear-impulse";

}  // namespace workbook::accuracy
