// The table of response models a scene can name in its "responder" field. It is compiled
// once against the reference solutions and once against the student's skeleton, so the
// same scene runs with either.
#include <algorithm>
#include <array>

#include "inelastic.hpp"
#include "workbook/response_model.hpp"

namespace workbook {

namespace {
constexpr std::array models{
    ResponseModel{"none", nullptr, nullptr},
    ResponseModel{"inelastic", &inelastic::resolve, nullptr},
};
}  // namespace

std::span<const ResponseModel> response_models() { return models; }

const ResponseModel* find_response_model(std::string_view name) {
    const auto* found = std::ranges::find(models, name, &ResponseModel::name);
    return found == models.end() ? nullptr : found;
}

}  // namespace workbook
