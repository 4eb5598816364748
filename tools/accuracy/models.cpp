#include "models.hpp"

#include <stdexcept>
#include <string>

namespace workbook::accuracy {

const ResponseModel& chapter_model(std::string_view name) {
    if (const ResponseModel* model = find_response_model(name)) return *model;
    std::string known;
    for (const ResponseModel& model : response_models()) known += (known.empty() ? "" : ", ") + std::string(model.name);
    throw std::invalid_argument("no response model called \"" + std::string(name) + "\" (there are: " + known + ")");
}

ResponseModel inelastic_with_projection() {
    return {"inelastic + projection", chapter_model("inelastic").respond, chapter_model("projection").correct};
}

}  // namespace workbook::accuracy
