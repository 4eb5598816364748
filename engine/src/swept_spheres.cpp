#include "workbook/swept_spheres.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "workbook/detection.hpp"
#include "workbook/event_timing.hpp"

namespace workbook {

namespace {

/// Where `body` started this step, undoing what integrate() did: x_end = x0 + v_end dt - c g dt^2
/// with c = 1 - k (0 for semi-implicit Euler, 1/2 for exact-under-gravity, 1 for explicit Euler).
Vector3 start_of_step(const RigidBody& body, const WorldSettings& settings) {
    if (body.is_immovable()) return body.position;
    const double dt = settings.time_step;
    const double c = 1.0 - gravity_position_factor(settings.integrator);
    return body.position - body.velocity * dt + settings.gravity * (c * dt * dt);
}

/// The fraction s in [0, 1) of the straight paths start -> end at which the pair first touches,
/// or nothing. Pairs that overlapped at the start are not swept.
std::optional<double> first_touch(const RigidBody& a, const Vector3& a0, const RigidBody& b, const Vector3& b0) {
    if (b.shape.kind == ShapeKind::plane) {
        const Vector3 normal = rotate(b.orientation, b.shape.normal);
        const double h0 = dot(a0 - b.position, normal) - a.shape.radius;
        const double h1 = dot(a.position - b.position, normal) - a.shape.radius;
        // Only a centre that crossed the plane is tunnelling; a shallower overlap is an ordinary
        // contact that detection has already found. A sphere already touching at the start is
        // stopped where it started.
        if (h0 + a.shape.radius < 0.0 || h1 + a.shape.radius >= 0.0) return std::nullopt;
        return h0 <= 0.0 ? 0.0 : h0 / (h0 - h1);
    }
    if (b.shape.kind != ShapeKind::sphere) return std::nullopt;
    const Vector3 d = a0 - b0;
    const Vector3 u = (a.position - a0) - (b.position - b0);
    const double radii = a.shape.radius + b.shape.radius;
    const double distance = length(d);
    const double gap = distance - radii;
    const double approach = dot(d, u);
    if (gap < 0.0 || approach >= 0.0) return std::nullopt;
    // A pair that overlaps at the end of the step was found by detection; only a pair that went
    // through each other and out again is tunnelling.
    if (length(a.position - b.position) < radii) return std::nullopt;
    const double uu = length_squared(u);
    const double c = gap * (distance + radii);
    const double discriminant = approach * approach - uu * c;
    if (discriminant < 0.0) return std::nullopt;
    const double s = c / (-approach + std::sqrt(discriminant));  // the smaller root, without cancellation
    return s < 1.0 ? std::optional<double>(s) : std::nullopt;
}

}  // namespace

void sweep_fast_spheres(World& world) {
    std::span<RigidBody> bodies = world.bodies_;
    double smallest_radius = std::numeric_limits<double>::infinity();
    for (const RigidBody& body : bodies)
        if (body.shape.kind == ShapeKind::sphere) smallest_radius = std::min(smallest_radius, body.shape.radius);

    const auto count = static_cast<std::uint32_t>(bodies.size());
    for (std::uint32_t i = 0; i < count; ++i) {
        RigidBody& fast = bodies[i];
        if (fast.is_immovable() || fast.shape.kind != ShapeKind::sphere) continue;
        const Vector3 fast_start = start_of_step(fast, world.settings_);
        if (!(length(fast.position - fast_start) > smallest_radius)) continue;

        double earliest = 1.0;
        std::uint32_t partner = count;
        for (std::uint32_t j = 0; j < count; ++j) {
            if (j == i) continue;
            if (auto s = first_touch(fast, fast_start, bodies[j], start_of_step(bodies[j], world.settings_))) {
                if (*s < earliest) {
                    earliest = *s;
                    partner = j;
                }
            }
        }
        if (partner == count) continue;

        // The fast sphere goes back to the moment of touching. Its partner keeps its place and
        // its other contacts (taking those away would let a resting body sink).
        const RigidBody& other = bodies[partner];
        const Vector3 other_start = start_of_step(other, world.settings_);
        fast.position = fast_start + (fast.position - fast_start) * earliest;
        const Vector3 other_then = other_start + (other.position - other_start) * earliest;
        // The contacts found for the fast sphere at the end of the step no longer hold; it is
        // detected again where it now is. In a dense pile that place overlaps other bodies, and
        // often the partner itself, which has moved on since the moment of touching; leaving
        // those overlaps out of this step's correction let them grow (to two thirds of a
        // diameter under 100 g in the stress corpus), and the projection of such overlaps then
        // pushed neighbours' centres through the walls of a box.
        std::erase_if(world.contacts_, [i](const Contact& c) { return c.body1 == i || c.body2 == i; });
        bool partner_overlaps = false;
        for (std::uint32_t j = 0; j < count; ++j) {
            if (j == i) continue;
            auto found = i < j ? collide(fast, i, bodies[j], j) : collide(bodies[j], j, fast, i);
            if (!found) continue;
            world.contacts_.push_back(*found);
            partner_overlaps = partner_overlaps || j == partner;
        }
        if (partner_overlaps) continue;
        // Otherwise the pair gets the touching contact of the moment they met, its normal taken
        // where both were then.
        Contact contact;
        const bool plane = other.shape.kind == ShapeKind::plane;
        contact.body1 = i;
        contact.body2 = partner;
        if (plane) {
            contact.normal = rotate(other.orientation, other.shape.normal);
        } else {
            const Vector3 offset = fast.position - other_then;
            const double distance = length(offset);
            contact.normal = distance > 0.0 ? offset / distance : coincident_centres_normal;
        }
        contact.add_point(fast.position - contact.normal * fast.shape.radius, 0.0);
        world.contacts_.push_back(contact);  // the pair was not among them: it did not overlap at the end
    }
}

}  // namespace workbook
