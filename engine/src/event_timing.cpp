#include "workbook/event_timing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "workbook/detection.hpp"
#include "workbook/probes.hpp"
#include "workbook/rotation.hpp"

namespace workbook {

namespace {

/// Gaps within this share of the scene's length scale count as touching: what rounding
/// leaves after advancing exactly to a time of impact.
constexpr double touching_tolerance = 1e-12;

/// The smallest root in (0, limit] of a t^2 + b t + c with c > 0 (the pair is apart now), or
/// nothing. The root is taken in the form that does not cancel.
std::optional<double> first_positive_root(double a, double b, double c, double limit) {
    if (a == 0.0) {
        if (b >= 0.0) return std::nullopt;
        const double t = -c / b;
        return t <= limit ? std::optional<double>(t) : std::nullopt;
    }
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return std::nullopt;
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    double best = std::numeric_limits<double>::infinity();
    for (double t : {q / a, q != 0.0 ? c / q : std::numeric_limits<double>::infinity()})
        if (t > 0.0 && t < best) best = t;
    return best <= limit ? std::optional<double>(best) : std::nullopt;
}

Vector3 acceleration_of(const RigidBody& body, const Vector3& gravity) {
    return body.is_immovable() ? Vector3{} : gravity;
}

/// How far a sphere, or a box that does not spin, reaches from its centre towards the plane of
/// unit normal `normal`: its radius, or the box's support sum_k h_k |a_k . n|.
double reach_towards(const RigidBody& body, const Vector3& normal) {
    if (body.shape.kind == ShapeKind::sphere) return body.shape.radius;
    const Matrix3 axes = to_matrix(body.orientation);
    const Vector3& h = body.shape.half_extents;
    return h.x * std::abs(axes(0, 0) * normal.x + axes(1, 0) * normal.y + axes(2, 0) * normal.z) +
           h.y * std::abs(axes(0, 1) * normal.x + axes(1, 1) * normal.y + axes(2, 1) * normal.z) +
           h.z * std::abs(axes(0, 2) * normal.x + axes(1, 2) * normal.y + axes(2, 2) * normal.z);
}

/// A sphere, or a box that does not spin, against a plane: its lowest point towards the plane
/// moves with the centre, along the same parabola, so the gap is a quadratic in t.
std::optional<double> sphere_plane(const RigidBody& sphere, const RigidBody& plane, const Vector3& gravity, double k,
                                   double limit) {
    if (sphere.is_immovable()) return std::nullopt;
    const Vector3 normal = rotate(plane.orientation, plane.shape.normal);
    const double reach = reach_towards(sphere, normal);
    const double gap = dot(sphere.position - plane.position, normal) - reach;
    const double rate = dot(sphere.velocity, normal);
    const double curvature = k * dot(gravity, normal);  // gap(t) = gap + rate t + curvature t^2
    const double scale = std::abs(dot(sphere.position - plane.position, normal)) + reach;
    if (std::abs(gap) <= touching_tolerance * scale) {
        if (rate < 0.0) return 0.0;
        // Just bounced (or resting): the next touch is where the parabola comes back down.
        if (rate > 0.0 && curvature < 0.0) {
            const double t = -rate / curvature;
            return t <= limit ? std::optional<double>(t) : std::nullopt;
        }
        return std::nullopt;
    }
    if (gap < 0.0) return std::nullopt;
    // Over [0, limit] the gap is at least this; when it stays positive there is no root to look
    // for. Most steps of a falling or flying ball end here, without a square root or a division.
    if (gap + std::min(rate, 0.0) * limit + std::min(curvature, 0.0) * (limit * limit) > 0.0) return std::nullopt;
    return first_positive_root(curvature, rate, gap, limit);
}

/// |d + u t + A t^2|^2 - R^2 for the quartic case.
double squared_gap(const Vector3& d, const Vector3& u, const Vector3& a, double radii, double t) {
    return length_squared(d + u * t + a * (t * t)) - radii * radii;
}

std::optional<double> sphere_sphere(const RigidBody& s1, const RigidBody& s2, const Vector3& gravity, double k,
                                    double limit) {
    const Vector3 d = s1.position - s2.position;
    const Vector3 u = s1.velocity - s2.velocity;
    const Vector3 a = (acceleration_of(s1, gravity) - acceleration_of(s2, gravity)) * k;
    // Two cheap answers first, without a square root; most pairs of a step end here. A pair
    // that does not move relative to itself keeps its distance (a row of touching balls, two
    // balls falling together) ...
    if (u == Vector3{} && a == Vector3{}) return std::nullopt;
    const double radii = s1.shape.radius + s2.shape.radius;
    const double limit2 = limit * limit;
    // ... and the centres close by at most reach = |u| limit + |a| limit^2 over [0, limit], where
    // reach^2 <= 2 (|u|^2 limit^2 + |a|^2 limit^4); centres more than 2 max(radii, reach) apart
    // cannot come within the radii.
    const double reach_squared = 2.0 * (length_squared(u) * limit2 + length_squared(a) * (limit2 * limit2));
    if (length_squared(d) > 4.0 * std::max(radii * radii, reach_squared)) return std::nullopt;
    const double distance = length(d);
    const double gap = distance - radii;
    const double approach = dot(d, u);
    if (std::abs(gap) <= touching_tolerance * (distance + radii)) {
        if (approach < 0.0) return 0.0;
        if (a == Vector3{}) return std::nullopt;
    } else if (gap < 0.0) {
        return std::nullopt;
    } else if (gap * gap > reach_squared) {
        return std::nullopt;  // the gap is wider than the reach
    }
    if (a == Vector3{}) {
        // |d + u t|^2 = R^2 with c = (|d| - R)(|d| + R) written so that it does not cancel.
        return first_positive_root(length_squared(u), 2.0 * approach, gap * (distance + radii), limit);
    }
    // One body falls, the other is pinned: a quartic. Bracket the first sign change on a grid,
    // skipping the instant of touching itself, then bisect to rounding.
    constexpr int samples = 64;
    double previous_t = 0.0;
    double previous = std::max(squared_gap(d, u, a, radii, 0.0), 0.0);
    for (int i = 1; i <= samples; ++i) {
        const double t = limit * i / samples;
        const double value = squared_gap(d, u, a, radii, t);
        if (previous >= 0.0 && value < 0.0) {
            double lo = previous_t;
            double hi = t;
            for (int j = 0; j < 200 && lo < hi; ++j) {
                const double mid = 0.5 * (lo + hi);
                if (mid == lo || mid == hi) break;
                (squared_gap(d, u, a, radii, mid) < 0.0 ? hi : lo) = mid;
            }
            return lo;
        }
        previous_t = t;
        previous = value;
    }
    return std::nullopt;
}

void advance(std::span<RigidBody> bodies, const Vector3& gravity, double k, double tau) {
    if (tau <= 0.0) return;
    for (RigidBody& body : bodies) {
        if (body.is_immovable()) continue;
        body.position += body.velocity * tau + gravity * (k * tau * tau);
        body.velocity += gravity * tau;
        // Free rotation as in the discrete step: a box whose moments differ precesses (Euler's
        // equations), which turning it about a fixed w would miss.
        if (body.angular_velocity != Vector3{}) advance_free_rotation(body, tau);
    }
}

/// The corners of a box touching a plane: those within rounding of the lowest (one, two for an
/// edge, four for a face), each a point of the contact.
void add_touching_corners(const RigidBody& box, const Vector3& plane_point, const Vector3& normal, Contact& contact) {
    const Matrix3 axes = to_matrix(box.orientation);
    const Vector3& h = box.shape.half_extents;
    std::array<Vector3, 8> corners;
    std::array<double, 8> heights;
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < 8; ++c) {
        const Vector3 local{(c & 1) != 0 ? h.x : -h.x, (c & 2) != 0 ? h.y : -h.y, (c & 4) != 0 ? h.z : -h.z};
        corners[c] = box.position + axes * local;
        heights[c] = dot(corners[c] - plane_point, normal);
        lowest = std::min(lowest, heights[c]);
    }
    const double scale = std::abs(dot(box.position - plane_point, normal)) + length(h);
    for (std::size_t c = 0; c < 8; ++c)
        if (heights[c] - lowest <= touching_tolerance * scale) contact.add_point(corners[c], 0.0);
}

/// The contact of a touching pair (no overlap), normal from body 2 to body 1.
Contact touching_contact(const RigidBody& b1, std::uint32_t i1, const RigidBody& b2, std::uint32_t i2) {
    Contact contact;
    contact.body1 = i1;
    contact.body2 = i2;
    if (b1.shape.kind == ShapeKind::box) {
        contact.normal = rotate(b2.orientation, b2.shape.normal);
        add_touching_corners(b1, b2.position, contact.normal, contact);
    } else if (b2.shape.kind == ShapeKind::plane) {
        contact.normal = rotate(b2.orientation, b2.shape.normal);
        contact.add_point(b1.position - contact.normal * b1.shape.radius, 0.0);
    } else {
        const Vector3 offset = b1.position - b2.position;
        const double distance = length(offset);
        contact.normal = distance > 0.0 ? offset / distance : coincident_centres_normal;
        contact.add_point(b2.position + contact.normal * b2.shape.radius, 0.0);
    }
    return contact;
}

/// Spheres, planes, and boxes that do not spin (whose lowest point follows a parabola) take
/// part in the event loop; other bodies are left to the discrete back-stop.
bool takes_part(const RigidBody& body) {
    return body.shape.kind == ShapeKind::sphere || body.shape.kind == ShapeKind::plane ||
           (body.shape.kind == ShapeKind::box && body.angular_velocity == Vector3{});
}

/// How far any movable body can get over `limit`, |v| limit + k |g| limit^2 at most: one
/// number per scan that lets most pairs of spheres be passed over with one squared distance,
/// as cheap as the discrete loop's overlap test.
double largest_reach(std::span<const RigidBody> bodies, const Vector3& gravity, double k, double limit) {
    double fastest_squared = 0.0;
    for (const RigidBody& body : bodies)
        if (!body.is_immovable()) fastest_squared = std::max(fastest_squared, length_squared(body.velocity));
    return std::sqrt(fastest_squared) * limit + std::abs(k) * length(gravity) * limit * limit;
}

/// False only when spheres a and b are too far apart to touch within the reach of each.
bool may_meet(const RigidBody& a, const RigidBody& b, double reach) {
    if (a.shape.kind != ShapeKind::sphere || b.shape.kind != ShapeKind::sphere) return true;
    const double within = a.shape.radius + b.shape.radius + reach * ((a.is_immovable() ? 0 : 1) + (b.is_immovable() ? 0 : 1));
    return !(length_squared(a.position - b.position) > within * within);
}

}  // namespace

double gravity_position_factor(Integrator integrator) {
    switch (integrator) {
        case Integrator::semi_implicit_euler: return 1.0;
        case Integrator::explicit_euler: return 0.0;
        case Integrator::exact_under_gravity: return 0.5;
    }
    return 0.5;
}

std::optional<double> time_of_impact(const RigidBody& a, const RigidBody& b, const Vector3& gravity, double k,
                                     double limit) {
    if (a.is_immovable() && b.is_immovable()) return std::nullopt;
    const ShapeKind ka = a.shape.kind;
    const ShapeKind kb = b.shape.kind;
    if (ka == ShapeKind::sphere && kb == ShapeKind::sphere) return sphere_sphere(a, b, gravity, k, limit);
    if (ka == ShapeKind::sphere && kb == ShapeKind::plane) return sphere_plane(a, b, gravity, k, limit);
    if (ka == ShapeKind::plane && kb == ShapeKind::sphere) return sphere_plane(b, a, gravity, k, limit);
    // A box that does not spin meets a plane like a sphere whose radius is the box's reach.
    const auto still_box = [](const RigidBody& body) {
        return body.shape.kind == ShapeKind::box && body.angular_velocity == Vector3{};
    };
    if (still_box(a) && kb == ShapeKind::plane) return sphere_plane(a, b, gravity, k, limit);
    if (ka == ShapeKind::plane && still_box(b)) return sphere_plane(b, a, gravity, k, limit);
    return std::nullopt;
}

void step_with_event_timing(World& world) {
    const WorldSettings& settings = world.settings_;
    const double k = gravity_position_factor(settings.integrator);
    std::span<RigidBody> bodies = world.bodies_;
    const auto count = static_cast<std::uint32_t>(bodies.size());
    const std::size_t event_budget = std::min<std::size_t>(1024, 8 + 2 * std::size_t{count});

    world.contacts_.clear();
    world.response_energy_change_ = 0.0;
    double remaining = settings.time_step;
    std::size_t events = 0;
    while (remaining > 0.0 && events < event_budget) {
        double earliest = remaining;
        std::uint32_t first = count;
        std::uint32_t second = count;
        const double reach = largest_reach(bodies, settings.gravity, k, remaining);
        for (std::uint32_t i = 0; i < count; ++i) {
            if (!takes_part(bodies[i])) continue;
            for (std::uint32_t j = i + 1; j < count; ++j) {
                if (!takes_part(bodies[j]) || !may_meet(bodies[i], bodies[j], reach)) continue;
                if (auto t = time_of_impact(bodies[i], bodies[j], settings.gravity, k, earliest)) {
                    if (first == count || *t < earliest) {
                        earliest = *t;
                        first = i;
                        second = j;
                    }
                }
            }
        }
        advance(bodies, settings.gravity, k, earliest);
        world.guard("event: advance");
        remaining -= earliest;
        if (first == count) {
            remaining = 0.0;
            break;
        }
        // Body 2 of a pair with a plane is the plane, as everywhere else.
        if (bodies[first].shape.kind == ShapeKind::plane) std::swap(first, second);
        const Contact contact = touching_contact(bodies[first], first, bodies[second], second);
        if (world.model_.respond != nullptr) {
            const double before = kinetic_energy(bodies[first]) + kinetic_energy(bodies[second]);
            world.model_.respond(bodies[first], bodies[second], contact);
            world.response_energy_change_ += kinetic_energy(bodies[first]) + kinetic_energy(bodies[second]) - before;
        }
        // Kept for the probes (how many contacts this step answered). The world reserves room for
        // every pair; only a step with more events than pairs, which the event budget allows,
        // can make this grow.
        world.contacts_.push_back(contact);
        world.guard("event: respond");
        ++events;
        // Without a responder nothing changes at an impact, and the same pair would be found
        // again at once; let the bodies pass as the discrete loop would.
        if (world.model_.respond == nullptr) {
            advance(bodies, settings.gravity, k, remaining);
            remaining = 0.0;
        }
    }
    if (remaining > 0.0) advance(bodies, settings.gravity, k, remaining);  // the event budget ran out

    // The discrete back-stop: whatever still overlaps beyond rounding.
    const std::size_t first_overlap = world.contacts_.size();
    for (std::uint32_t i = 0; i < count; ++i)
        for (std::uint32_t j = i + 1; j < count; ++j) {
            if (bodies[i].is_immovable() && bodies[j].is_immovable()) continue;
            if (auto contact = collide(bodies[i], i, bodies[j], j)) world.contacts_.push_back(*contact);
        }
    const std::span<const Contact> overlaps = std::span<const Contact>(world.contacts_).subspan(first_overlap);
    if (world.model_.respond != nullptr)
        for (const Contact& contact : overlaps) {
            RigidBody& b1 = bodies[contact.body1];
            RigidBody& b2 = bodies[contact.body2];
            const double before = kinetic_energy(b1) + kinetic_energy(b2);
            world.model_.respond(b1, b2, contact);
            world.response_energy_change_ += kinetic_energy(b1) + kinetic_energy(b2) - before;
        }
    world.guard("respond");
    if (world.model_.correct != nullptr)
        for (const Contact& contact : overlaps)
            world.model_.correct(bodies[contact.body1], bodies[contact.body2], contact, settings.position_correction);
    world.guard("correct");
}

}  // namespace workbook
