#pragma once
/// \file
/// Guards against non-finite state: a NaN or an infinity found after a stage stops the run
/// with a message that says where it came from, instead of spreading silently.

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include "workbook/rigid_body.hpp"

namespace workbook {

/// A body left a stage with a NaN or an infinity. what() reads, for example,
/// "step 12, stage respond: body 1 (\"ball\"): velocity is not finite: (nan, 0, 0)".
class NonFiniteState : public std::runtime_error {
public:
    /// The error for `quantity` of body `body` (named `body_name`, may be empty), found after
    /// `stage` of step `step`; `value` is the quantity as text.
    NonFiniteState(std::size_t body, std::string body_name, std::string quantity, std::uint64_t step,
                   std::string stage, const std::string& value);
    [[nodiscard]] std::size_t body() const { return body_; }                 ///< index in the world
    [[nodiscard]] const std::string& body_name() const { return body_name_; }  ///< empty when the scene gave none
    [[nodiscard]] const std::string& quantity() const { return quantity_; }   ///< "position", "velocity", ...
    [[nodiscard]] std::uint64_t step() const { return step_; }               ///< 1 for the first step
    [[nodiscard]] const std::string& stage() const { return stage_; }        ///< "integrate", "respond", ...

private:
    std::size_t body_;
    std::string body_name_;
    std::string quantity_;
    std::uint64_t step_;
    std::string stage_;
};

/// 0 when every number the guard checks in `body` is finite, NaN otherwise: x * 0 is 0 for a
/// finite x and NaN for a NaN or an infinity (and a sum too large to represent gives a NaN
/// as well, which only sends the guard to look at every body, where it finds nothing). A
/// stage sums it over the bodies it changed and calls check_finite() only when the sum is not 0.
inline double poison(const RigidBody& b) {
    return (b.position.x + b.position.y + b.position.z + b.velocity.x + b.velocity.y + b.velocity.z + b.orientation.w +
            b.orientation.x + b.orientation.y + b.orientation.z + b.angular_velocity.x + b.angular_velocity.y +
            b.angular_velocity.z) * 0.0;
}

/// The first non-finite quantity of `body` ("position", "velocity", "orientation",
/// "angular_velocity"), or nothing when every number is finite.
std::optional<std::string> first_non_finite(const RigidBody& body);

/// Throws NonFiniteState for the first body with a non-finite quantity. `names` may be empty
/// or parallel to `bodies`; `step` and `stage` are copied into the message.
void check_finite(std::span<const RigidBody> bodies, std::span<const std::string> names, std::uint64_t step,
                  const char* stage);

}  // namespace workbook
