#include "workbook/guards.hpp"

#include <cmath>
#include <sstream>

namespace workbook {

namespace {

bool finite(const Vector3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool finite(const Quaternion& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

std::string describe(const std::string& body, std::size_t index, const std::string& name) {
    std::string text = body + " " + std::to_string(index);
    if (!name.empty()) text += " (\"" + name + "\")";
    return text;
}

std::string value_of(const RigidBody& body, const std::string& quantity) {
    std::ostringstream out;
    const auto put = [&out](const Vector3& v) { out << "(" << v.x << ", " << v.y << ", " << v.z << ")"; };
    if (quantity == "position") put(body.position);
    else if (quantity == "velocity") put(body.velocity);
    else if (quantity == "angular_velocity") put(body.angular_velocity);
    else out << "(" << body.orientation.w << ", " << body.orientation.x << ", " << body.orientation.y << ", "
             << body.orientation.z << ")";
    return out.str();
}

}  // namespace

NonFiniteState::NonFiniteState(std::size_t body, std::string body_name, std::string quantity, std::uint64_t step,
                               std::string stage, const std::string& value)
    : std::runtime_error("step " + std::to_string(step) + ", stage " + stage + ": " +
                         describe("body", body, body_name) + ": " + quantity + " is not finite: " + value),
      body_(body),
      body_name_(std::move(body_name)),
      quantity_(std::move(quantity)),
      step_(step),
      stage_(std::move(stage)) {}

std::optional<std::string> first_non_finite(const RigidBody& body) {
    if (!finite(body.position)) return "position";
    if (!finite(body.velocity)) return "velocity";
    if (!finite(body.orientation)) return "orientation";
    if (!finite(body.angular_velocity)) return "angular_velocity";
    return std::nullopt;
}

void check_finite(std::span<const RigidBody> bodies, std::span<const std::string> names, std::uint64_t step,
                  const char* stage) {
    // Fast path: x * 0 is 0 for every finite x and NaN for a NaN or an infinity (so the compiler
    // may not fold it), and a sum of such products says whether a search is needed at all. Huge
    // finite values whose sum overflows only send it to the search, which then finds nothing.
    double poison = 0.0;
    for (const RigidBody& b : bodies) {
        poison += (b.position.x + b.position.y + b.position.z + b.velocity.x + b.velocity.y + b.velocity.z) * 0.0;
        poison += (b.orientation.w + b.orientation.x + b.orientation.y + b.orientation.z + b.angular_velocity.x +
                   b.angular_velocity.y + b.angular_velocity.z) * 0.0;
    }
    if (poison == 0.0) return;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        // The common case is one pass of isfinite over the numbers; the message is built only on failure.
        if (auto quantity = first_non_finite(bodies[i])) {
            const std::string name = i < names.size() ? names[i] : std::string();
            throw NonFiniteState(i, name, *quantity, step, stage, value_of(bodies[i], *quantity));
        }
    }
}

}  // namespace workbook
