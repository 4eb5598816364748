// The table of response models a scene can name in its "responder" field. It is compiled
// once against the reference solutions and once against the student's skeleton, so the
// same scene runs with either.
#include <algorithm>
#include <array>

#include "inelastic.hpp"
#include "linear-impulse.hpp"
#include "projection.hpp"
#include "angular-impulse.hpp"
#include "resting-contact.hpp"
#include "friction.hpp"
#include "workbook/restitution.hpp"
#include "workbook/response_model.hpp"

namespace workbook {

namespace {

/// Chapter 4's counter-example, built from the chapter's own steps: each point of a contact
/// gets one impulse in turn and is never revisited. A box landing flat then spins; the page
/// shows it beside angular_impulse::resolve, which resolves the points together.
void resolve_points_one_by_one(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const double e = combined_restitution(body1, body2);
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        const Vector3& p = contact.points[i].position;
        const double j = angular_impulse::impulse_magnitude(body1, body2, p, contact.normal, e);
        if (j > 0.0) angular_impulse::apply_impulse(body1, body2, p, j * contact.normal);
    }
}

constexpr std::array models{
    ResponseModel{"none", nullptr, nullptr},
    ResponseModel{"inelastic", &inelastic::resolve, nullptr},
    ResponseModel{"projection", nullptr, &projection::correct},
    // The impulse fixes the velocities, then chapter 2's projection removes the overlap.
    ResponseModel{"linear-impulse", &linear_impulse::resolve, &projection::correct},
    ResponseModel{"angular-impulse", &angular_impulse::resolve, &projection::correct},
    ResponseModel{"angular-impulse-one-by-one", &resolve_points_one_by_one, &projection::correct},
    // Every contact of a step solved together (the world's contact solver calls the steps).
    ResponseModel{"resting-contact", nullptr, nullptr, &resting_contact::hooks},
    // Chapter 5's solver with chapter 6's Coulomb friction pass after each normal pass.
    ResponseModel{"friction", nullptr, nullptr, &friction::hooks},
};
}  // namespace

std::span<const ResponseModel> response_models() { return models; }

const ResponseModel* find_response_model(std::string_view name) {
    const auto found = std::find_if(models.begin(), models.end(), [name](const ResponseModel& m) { return m.name == name; });
    return found == models.end() ? nullptr : &*found;
}

}  // namespace workbook
