#pragma once
// Domain-wide samples for the hidden tests: draws legal inputs over the whole domain each
// chapter header writes down, judges a function's answer against the reference's answer
// (computed here, in the checker, from the checker's own copy of the input), and reduces a
// failing input to the simplest one that still fails before reporting it.
//
//   Case        every input any chapter function takes (two bodies, a contact, knobs, ...)
//   Verdict     what a judge says about one case: passed, or the law, quantity, expected,
//               actual and tolerance of the first thing that broke
//   sample()    draws cases, judges each, reduces and reports the first failure
//
// Magnitudes are drawn log-uniformly, directions and orientations uniformly, and every edge of
// a domain (zero, equal, exactly touching, sliding, resting, creeping, immovable, kinematic,
// extreme ratios, ...) is drawn on purpose with a fixed probability. Each random number is
// drawn in a statement of its own: the order of the arguments of one call is not fixed by
// C++, and a case must be the same with every compiler.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "feedback.hpp"
#include "seeded_random.hpp"
#include "workbook/contact.hpp"
#include "workbook/contact_solver.hpp"
#include "workbook/matrix3.hpp"
#include "workbook/quaternion.hpp"
#include "workbook/response_model.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook::domain {

using testing::Law;
using testing::SeededRandom;

// ----- Cases --------------------------------------------------------------------------------

/// Every input a chapter function can take. A judge uses the fields its function reads.
struct Case {
    RigidBody body1;
    RigidBody body2;
    Contact contact;
    PositionCorrection knobs;
    Vector3 point{};          ///< a point argument (chapter 4)
    Vector3 normal{1, 0, 0};  ///< a normal argument (chapters 3 and 4)
    Vector3 impulse{};        ///< an impulse argument (chapter 4)
    double restitution = 1.0; ///< a restitution argument
    double depth = 0.0;       ///< a depth argument (chapter 2)
    // Chapter 6's arguments.
    ContactImpulses impulses{};           ///< the solver's impulses of `contact`'s points
    Vector3 tangent{};                    ///< a tangent argument
    double mu1 = 0.0;                     ///< the two coefficients mix_coefficients() mixes
    double mu2 = 0.0;
    std::array<double, 2> accumulated{};  ///< accumulate_friction()'s accumulated pair
    std::array<double, 2> increment{};    ///< and its increment
    double normal_impulse = 0.0;          ///< and its normal impulse and coefficients
    double static_coefficient = 0.0;
    double dynamic_coefficient = 0.0;
};

/// A field of `after` that differs from `before`, in words, with its two values; empty when none.
struct Change {
    std::string field;
    double before = 0.0;
    double after = 0.0;
};

/// Which fields of a body a function may change.
struct MayChange {
    bool velocity = false;
    bool angular_velocity = false;
    bool position = false;
};

inline bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

/// The first field the function was not allowed to change that it changed (compared value by
/// value: the bytes between fields mean nothing).
inline Change first_change(const RigidBody& before, const RigidBody& after, MayChange may, const std::string& who) {
    auto vector = [&](const char* name, const Vector3& a, const Vector3& b) -> Change {
        if (!same(a.x, b.x)) return {who + "." + name + ".x", a.x, b.x};
        if (!same(a.y, b.y)) return {who + "." + name + ".y", a.y, b.y};
        if (!same(a.z, b.z)) return {who + "." + name + ".z", a.z, b.z};
        return {};
    };
    auto matrix = [&](const char* name, const Matrix3& a, const Matrix3& b) -> Change {
        for (int i = 0; i < 9; ++i)
            if (!same(a.m[static_cast<std::size_t>(i)], b.m[static_cast<std::size_t>(i)]))
                return {who + "." + name + "(" + std::to_string(i / 3) + ", " + std::to_string(i % 3) + ")",
                        a.m[static_cast<std::size_t>(i)], b.m[static_cast<std::size_t>(i)]};
        return {};
    };
    if (!same(before.inverse_mass, after.inverse_mass)) return {who + ".inverse_mass", before.inverse_mass, after.inverse_mass};
    if (!same(before.restitution, after.restitution)) return {who + ".restitution", before.restitution, after.restitution};
    if (!same(before.friction, after.friction)) return {who + ".friction", before.friction, after.friction};
    if (!same(before.static_friction, after.static_friction))
        return {who + ".static_friction", before.static_friction, after.static_friction};
    if (Change c = matrix("inertia_body", before.inertia_body, after.inertia_body); !c.field.empty()) return c;
    if (Change c = matrix("inverse_inertia_world", before.inverse_inertia_world, after.inverse_inertia_world); !c.field.empty())
        return c;
    const Quaternion& q0 = before.orientation;
    const Quaternion& q1 = after.orientation;
    if (!same(q0.w, q1.w) || !same(q0.x, q1.x) || !same(q0.y, q1.y) || !same(q0.z, q1.z))
        return {who + ".orientation", q0.w, q1.w == q0.w ? q1.x : q1.w};
    if (before.shape.kind != after.shape.kind) return {who + ".shape.kind", double(before.shape.kind), double(after.shape.kind)};
    if (!same(before.shape.radius, after.shape.radius)) return {who + ".shape.radius", before.shape.radius, after.shape.radius};
    if (Change c = vector("shape.normal", before.shape.normal, after.shape.normal); !c.field.empty()) return c;
    if (Change c = vector("shape.half_extents", before.shape.half_extents, after.shape.half_extents); !c.field.empty()) return c;
    if (!may.position)
        if (Change c = vector("position", before.position, after.position); !c.field.empty()) return c;
    if (!may.velocity)
        if (Change c = vector("velocity", before.velocity, after.velocity); !c.field.empty()) return c;
    if (!may.angular_velocity)
        if (Change c = vector("angular_velocity", before.angular_velocity, after.angular_velocity); !c.field.empty()) return c;
    return {};
}

// ----- Verdicts -----------------------------------------------------------------------------

/// What a judge found. `law == nullptr` means the case passed.
struct Verdict {
    const Law* law = nullptr;
    std::string quantity;  ///< what was compared, e.g. "body 1's velocity after resolve"
    std::string unit;
    bool is_vector = false;
    Vector3 expected{};
    Vector3 actual{};
    double tolerance = 0.0;

    [[nodiscard]] bool failed() const { return law != nullptr; }
};

inline bool within(double expected, double actual, double tolerance) {
    return std::isfinite(actual) && std::abs(actual - expected) <= tolerance;
}

inline bool within(const Vector3& expected, const Vector3& actual, double tolerance) {
    return within(expected.x, actual.x, tolerance) && within(expected.y, actual.y, tolerance) &&
           within(expected.z, actual.z, tolerance);
}

/// Passed when |actual - expected| <= tolerance (and actual is finite), else the failure. An
/// expected value that is not finite is a case the reference itself cannot answer: no student
/// is blamed for it (legal() keeps such cases out of the samples).
inline Verdict compare(const Law& law, std::string quantity, std::string unit, double expected, double actual, double tolerance) {
    if (!std::isfinite(expected) || within(expected, actual, tolerance)) return {};
    return {&law, std::move(quantity), std::move(unit), false, {expected, 0, 0}, {actual, 0, 0}, tolerance};
}

inline Verdict compare(const Law& law, std::string quantity, std::string unit, const Vector3& expected, const Vector3& actual,
                       double tolerance) {
    if (!is_finite(expected) || within(expected, actual, tolerance)) return {};
    return {&law, std::move(quantity), std::move(unit), true, expected, actual, tolerance};
}

/// Passed when actual >= minimum - tolerance.
inline Verdict at_least(const Law& law, std::string quantity, std::string unit, double minimum, double actual, double tolerance) {
    if (std::isfinite(actual) && actual >= minimum - tolerance) return {};
    return {&law, std::move(quantity), std::move(unit), false, {minimum, 0, 0}, {actual, 0, 0}, tolerance};
}

/// The law every unchanged-field check reports under.
inline const Law unchanged_law{"a function changes only what its contract lets it change",
                               "every other field of both bodies (masses, inertia, shape, restitution, and the motion "
                               "the step does not touch) must come back exactly as it was sent",
                               "assign only to the fields your step is about; read the others, never write them (not "
                               "even a value you think is the same)"};

/// The unchanged-field check of both bodies after a call.
inline Verdict unchanged(const Case& before, const RigidBody& body1, const RigidBody& body2, MayChange may,
                         const std::string& call) {
    for (int side = 1; side <= 2; ++side) {
        const Change c = first_change(side == 1 ? before.body1 : before.body2, side == 1 ? body1 : body2, may,
                                      side == 1 ? "body1" : "body2");
        if (!c.field.empty()) return compare(unchanged_law, c.field + " after " + call, "", c.before, c.after, 0.0);
    }
    return {};
}

// ----- Tolerances ---------------------------------------------------------------------------

/// A few ulps of `scale`, the sum of the magnitudes of the terms that make an answer: what any
/// correct algebraic form of the answer is within (testing::rounding_tolerance, at the smallest
/// normal double for a scale of 0, so that a zero answer must be zero).
inline double rounding(double scale, double ulps = 32.0) { return testing::rounding_tolerance(std::abs(scale), ulps); }

inline double frobenius(const Matrix3& a) {
    double s = 0.0;
    for (double x : a.m) s += x * x;
    return std::sqrt(s);
}

/// How much rounding an inverse of `inertia` amplifies: ||I|| ||I^-1|| (Frobenius), >= 3.
inline double condition(const Matrix3& inertia) { return frobenius(inertia) * frobenius(inverse(inertia)); }

/// The size of a body, m (its inertia is about m size^2).
inline double body_size(const RigidBody& b) {
    if (b.is_immovable()) return 1.0;
    return std::sqrt((b.inertia_body(0, 0) + b.inertia_body(1, 1) + b.inertia_body(2, 2)) * b.inverse_mass);
}

/// How far rounding in I^-1 can reach: cond(I) ||I^-1||, 0 for an immovable body.
inline double inverse_reach(const RigidBody& b) {
    if (b.is_immovable()) return 0.0;
    return condition(b.inertia_body) * frobenius(inverse(b.inertia_body));
}

/// The sum of the magnitudes of the terms of a point velocity v + w x (p - x).
inline double point_speed_terms(const RigidBody& b, const Vector3& point) {
    return length(b.velocity) + length(b.angular_velocity) * (length(point - b.position) + length(point) + length(b.position));
}

// ----- Drawing ------------------------------------------------------------------------------

inline bool chance(SeededRandom& random, double p) { return random.uniform(0.0, 1.0) < p; }

/// A magnitude 10^u, u uniform in [low, high).
inline double decades(SeededRandom& random, double low, double high) { return random.log_uniform(low, high); }

/// A sign, + or -.
inline double sign(SeededRandom& random) { return chance(random, 0.5) ? 1.0 : -1.0; }

/// An inverse mass (1/kg) of a movable body: mostly 1e-3 to 1e3 kg, often 1e-12 to 1e12, and
/// sometimes the ends of the domain, 1e-100 to 1e100 kg.
inline double inverse_mass(SeededRandom& random) {
    const double pick = random.uniform(0.0, 1.0);
    if (pick < 0.55) return decades(random, -3.0, 3.0);
    if (pick < 0.8) return decades(random, -12.0, 12.0);
    return decades(random, -100.0, 100.0);
}

/// A speed, m/s: mostly 1e-3 to 1e3, sometimes creeping (1e-12 to 1e-6) or fast (up to 1e6).
inline double speed(SeededRandom& random) {
    const double pick = random.uniform(0.0, 1.0);
    if (pick < 0.7) return decades(random, -3.0, 3.0);
    if (pick < 0.85) return decades(random, -12.0, -6.0);
    return decades(random, -6.0, 6.0);
}

/// A velocity: zero with probability 0.1, else a uniform direction times a speed().
inline Vector3 velocity(SeededRandom& random) {
    if (chance(random, 0.1)) return {};
    const Vector3 d = random.direction();
    const double s = speed(random);
    return d * s;
}

/// A position, m: the origin with probability 0.15, else up to 1 km away.
inline Vector3 position(SeededRandom& random) {
    if (chance(random, 0.15)) return {};
    const Vector3 d = random.direction();
    const double r = decades(random, -3.0, 3.0);
    return d * r;
}

/// A unit normal: uniform over the sphere, or an axis (either sign) with probability 0.15.
inline Vector3 unit_normal(SeededRandom& random) {
    if (chance(random, 0.15)) {
        const double s = sign(random);
        const double axis = random.uniform(0.0, 3.0);
        if (axis < 1.0) return {s, 0, 0};
        if (axis < 2.0) return {0, s, 0};
        return {0, 0, s};
    }
    return random.direction();
}

/// A rotation uniform over all orientations (a uniform point of the 4D unit sphere), or none
/// with probability 0.15.
inline Quaternion orientation(SeededRandom& random) {
    if (chance(random, 0.15)) return {};
    for (;;) {
        const double w = random.uniform(-1.0, 1.0);
        const double x = random.uniform(-1.0, 1.0);
        const double y = random.uniform(-1.0, 1.0);
        const double z = random.uniform(-1.0, 1.0);
        const double n2 = w * w + x * x + y * y + z * z;
        if (n2 > 1e-6 && n2 <= 1.0) return normalized(Quaternion{w, x, y, z});
    }
}

/// A body-frame inertia tensor for mass 1/`w`: principal moments m s^2 (a, b, c) with a size s
/// from 1 cm to 10 m (m s^2 kept within 1e-90 to 1e90) and a, b, c that a solid can have (each at most the sum of the other
/// two), about principal axes turned in the body with probability 0.5 (not diagonal).
inline Matrix3 inertia(SeededRandom& random, double w) {
    const double size = decades(random, -2.0, 1.0);
    const double a = random.uniform(0.2, 1.0);
    const double b = random.uniform(0.2, 1.0);
    const double c_low = std::abs(a - b) + 0.05;
    const double c = random.uniform(c_low, a + b);
    // Kept within 1e-90 to 1e90 kg m^2, where the determinant of I is a normal double.
    const double scale = std::clamp(size * size / w, 1e-90, 1e90);
    const Matrix3 principal = Matrix3::diagonal({a * scale, b * scale, c * scale});
    if (chance(random, 0.5)) return principal;
    const Quaternion axes = orientation(random);
    const Matrix3 r = to_matrix(axes);
    Matrix3 turned = r * principal * transpose(r);
    for (int i = 0; i < 3; ++i)  // exactly symmetric, as a tensor is
        for (int j = 0; j < i; ++j) turned(i, j) = turned(j, i);
    return turned;
}

/// A movable body with an inverse mass, an inertia, a random orientation and a shape.
inline RigidBody movable(SeededRandom& random, double w) {
    RigidBody body;
    body.inverse_mass = w;
    body.inertia_body = inertia(random, w);
    body.orientation = orientation(random);
    body.shape = Shape::sphere(decades(random, -2.0, 1.0));
    body.restitution = chance(random, 0.2) ? 1.0 : chance(random, 0.2) ? 0.0 : random.uniform(0.0, 1.0);
    body.update_world_inertia();
    return body;
}

/// Makes `body` immovable (inverse mass 0). The header defines immovable by the inverse mass
/// alone, so its inertia_body stays what it was (not zero) with probability 0.5; kinematic
/// (moving) with probability `moving`.
inline void pin(SeededRandom& random, RigidBody& body, double moving, bool spin) {
    body.inverse_mass = 0.0;
    if (chance(random, 0.5)) body.inertia_body = Matrix3::zero();
    body.velocity = chance(random, moving) ? velocity(random) : Vector3{};
    if (spin) body.angular_velocity = chance(random, moving) ? velocity(random) : Vector3{};
    body.update_world_inertia();
}

/// Two inverse masses with the pair edges on purpose: equal (0.1), both heavy or both light
/// at the ends of the domain (0.1), a ratio up to 1e200 (0.1), otherwise independent.
inline void pair_masses(SeededRandom& random, double& w1, double& w2) {
    const double pick = random.uniform(0.0, 1.0);
    if (pick < 0.1) {
        w1 = inverse_mass(random);
        w2 = w1;
    } else if (pick < 0.2) {
        const double end = chance(random, 0.5) ? 1.0 : -1.0;
        const double common = decades(random, 60.0, 97.0);
        w1 = std::pow(common, end);
        const double ratio = decades(random, -3.0, 3.0);
        w2 = w1 * ratio;
    } else if (pick < 0.3) {
        w1 = decades(random, -100.0, 100.0);
        const double ratio = decades(random, -100.0, 100.0);
        w2 = std::clamp(w1 * ratio, 1e-100, 1e100);
    } else {
        w1 = inverse_mass(random);
        w2 = inverse_mass(random);
    }
}

/// How many bodies of a pair are immovable, drawn with the given probabilities of 1 and 2.
inline int immovable_count(SeededRandom& random, double one, double two) {
    const double pick = random.uniform(0.0, 1.0);
    if (pick < two) return 2;
    if (pick < two + one) return 1;
    return 0;
}

/// How a pair moves along its normal.
enum class Approach { approaching, creeping, separating, sliding, equal, resting };

inline const char* approach_name(Approach a) {
    switch (a) {
        case Approach::approaching: return "approaching";
        case Approach::creeping: return "creeping together (1e-12 to 1e-6 m/s)";
        case Approach::separating: return "moving apart";
        case Approach::sliding: return "sliding (v12 . n = 0)";
        case Approach::equal: return "equal velocities";
        case Approach::resting: return "resting";
    }
    return "";
}

/// v12 . n as the laws define it (dot of the whole relative velocity with the normal).
inline double normal_velocity(const Case& c) { return dot(c.body1.velocity - c.body2.velocity, c.contact.normal); }

inline bool matches(const Case& c, Approach a) {
    const double vn = normal_velocity(c);
    switch (a) {
        case Approach::approaching: return vn < 0.0;
        case Approach::creeping: return vn < 0.0 && vn >= -2e-6;
        case Approach::separating: return vn > 0.0;
        case Approach::sliding: return vn == 0.0 && !(c.body1.velocity == c.body2.velocity);
        case Approach::equal: return c.body1.velocity == c.body2.velocity;
        case Approach::resting: return c.body1.velocity == Vector3{} && c.body2.velocity == Vector3{};
    }
    return false;
}

/// Sets the velocities of an already drawn pair so that it moves as `a` says along the
/// contact normal (which it may flip or set to an axis). False when the draw failed (the
/// caller draws again): rounding may leave a creeping pair at v12 . n = 0.
inline bool set_motion(SeededRandom& random, Case& c, Approach a) {
    RigidBody& b1 = c.body1;
    RigidBody& b2 = c.body2;
    // An immovable body keeps the velocity pin() gave it; only a movable one is set here.
    auto set = [](RigidBody& body, const Vector3& v) {
        if (!body.is_immovable()) body.velocity = v;
    };
    switch (a) {
        case Approach::approaching:
        case Approach::separating: {
            set(b1, velocity(random));
            set(b2, velocity(random));
            const double vn = normal_velocity(c);
            if (vn == 0.0) return false;
            if ((vn < 0.0) != (a == Approach::approaching)) c.contact.normal = -c.contact.normal;
            break;
        }
        case Approach::creeping: {
            // Small bodies meeting at small speeds: the whole motion is about as slow as the approach.
            const double approach = decades(random, -12.0, -6.0);
            const double drift = approach * decades(random, 0.0, 3.0);
            const Vector3 d = random.direction();
            const Vector3 along = d * drift;
            set(b2, b2.is_immovable() ? b2.velocity : along);
            const Vector3 sideways = cross(c.contact.normal, random.direction()) * drift;
            const Vector3 closing = c.contact.normal * approach;
            if (b1.is_immovable()) {
                set(b2, b1.velocity + closing + sideways);
            } else {
                set(b1, b2.velocity - closing + sideways);
            }
            break;
        }
        case Approach::sliding: {
            // Along an axis normal v12 . n is exactly the difference of one component, so any
            // way of writing v12 . n gives exactly 0.
            c.contact.normal = unit_normal(random);
            if (std::abs(c.contact.normal.x) + std::abs(c.contact.normal.y) + std::abs(c.contact.normal.z) != 1.0) {
                const double s = sign(random);
                c.contact.normal = {0, s, 0};
            }
            const Vector3 n = c.contact.normal;
            const Vector3 v = velocity(random);
            const Vector3 slide = velocity(random);
            const Vector3 across = slide - n * dot(slide, n);  // exact: n is an axis
            if (b1.is_immovable() && b2.is_immovable()) return false;
            if (b1.is_immovable()) {
                set(b2, b1.velocity - across);
            } else if (b2.is_immovable()) {
                set(b1, b2.velocity + across);
            } else {
                set(b2, v);
                set(b1, v + across);
            }
            break;
        }
        case Approach::equal: {
            const Vector3 v = velocity(random);
            if (b1.is_immovable() && b2.is_immovable()) return false;
            if (b1.is_immovable()) {
                set(b2, b1.velocity);
            } else if (b2.is_immovable()) {
                set(b1, b2.velocity);
            } else {
                set(b1, v);
                set(b2, v);
            }
            break;
        }
        case Approach::resting:
            if (b1.is_immovable() && !(b1.velocity == Vector3{})) return false;
            if (b2.is_immovable() && !(b2.velocity == Vector3{})) return false;
            set(b1, {});
            set(b2, {});
            break;
    }
    return matches(c, a);
}

/// Positions for a pair along the normal: exactly touching (the gap between the two spheres
/// is 0) with probability 0.3, else overlapping a little; one contact point between them, off
/// the line of centres with probability 0.5, and body 2's centre far to the side of the normal
/// (a plane's anchor, a box's centre) with probability 0.4.
inline void place_pair(SeededRandom& random, Case& c) {
    const Vector3 n = c.contact.normal;
    c.body1.position = position(random);
    const double r1 = c.body1.shape.radius;
    const double r2 = c.body2.shape.radius;
    const bool touching = chance(random, 0.3);
    const double overlap = touching ? 0.0 : (r1 + r2) * decades(random, -6.0, -1.0);
    c.body2.position = c.body1.position - n * (r1 + r2 - overlap);
    Vector3 point = c.body1.position - n * (r1 - overlap / 2);
    if (chance(random, 0.4)) {
        // Body 2 is a plane or a box face whose centre lies far to the side: the normal is not
        // the line through the centres.
        const Vector3 side = cross(n, random.direction());
        const double away = decades(random, -2.0, 2.0);
        c.body2.position = c.body2.position + side * away;
    }
    if (chance(random, 0.5)) {
        const Vector3 side = cross(n, random.direction());
        const double reach = decades(random, -3.0, 1.0);
        point = point + side * reach;
    }
    c.contact.point_count = 0;
    c.contact.penetration = 0.0;
    c.contact.add_point(point, overlap);
}

/// A pair of spheres along the contact normal for the chapters without spin (1 and 3): masses
/// with the pair edges (pair_masses()), `pinned` immovable bodies (1: either side, at rest or
/// kinematic), moving along the normal as `how` says (set_motion()), placed by place_pair(),
/// and each spinning with probability 0.5 (the angular velocity is not those chapters', and
/// must come back as it was). False when the motion could not be drawn.
inline bool draw_pair_moving(SeededRandom& random, Case& c, int pinned, Approach how) {
    double w1 = 1.0;
    double w2 = 1.0;
    pair_masses(random, w1, w2);
    c.body1 = movable(random, w1);
    c.body2 = movable(random, w2);
    c.contact.normal = unit_normal(random);
    const bool first = chance(random, 0.5);
    if (pinned >= 1) pin(random, first ? c.body1 : c.body2, 0.5, false);
    if (pinned == 2) pin(random, first ? c.body2 : c.body1, 0.5, false);
    if (!set_motion(random, c, how)) return false;
    place_pair(random, c);
    for (RigidBody* b : {&c.body1, &c.body2}) {
        const bool spins = chance(random, 0.5);
        if (spins) b->angular_velocity = velocity(random);
    }
    return true;
}

/// Any motion along the normal: approaching 0.4, creeping 0.15, separating 0.15, sliding 0.1,
/// equal velocities 0.1, resting 0.1.
inline Approach any_motion(SeededRandom& random) {
    const double pick = random.uniform(0.0, 1.0);
    if (pick < 0.4) return Approach::approaching;
    if (pick < 0.55) return Approach::creeping;
    if (pick < 0.7) return Approach::separating;
    if (pick < 0.8) return Approach::sliding;
    if (pick < 0.9) return Approach::equal;
    return Approach::resting;
}

/// A motion that does not approach: separating 0.5, sliding 0.2, equal velocities 0.2, resting 0.1.
inline Approach not_approaching(SeededRandom& random) {
    const double pick = random.uniform(0.0, 1.0);
    if (pick < 0.5) return Approach::separating;
    if (pick < 0.7) return Approach::sliding;
    if (pick < 0.9) return Approach::equal;
    return Approach::resting;
}

/// A restitution argument (chapters 3 and 4): 0 and 1 on purpose, else uniform.
inline double draw_restitution(SeededRandom& random) {
    const double pick = random.uniform(0.0, 1.0);
    if (pick < 0.15) return 0.0;
    if (pick < 0.3) return 1.0;
    return random.uniform(0.0, 1.0);
}

/// |v1| + |v2|: the scale of a velocity answer of the chapters without spin.
inline double speeds(const Case& c) { return length(c.body1.velocity) + length(c.body2.velocity); }

/// How many bodies of the case are immovable.
inline int pinned(const Case& c) { return int(c.body1.is_immovable()) + int(c.body2.is_immovable()); }

// ----- Reducing a failing case --------------------------------------------------------------

/// Simpler values than x, simplest first: 0, +-1, its power of ten, x to 1 and 3 digits.
inline std::vector<double> simpler_numbers(double x) {
    std::vector<double> out;
    auto add = [&](double y) {
        if (std::isfinite(y) && y != x && std::find(out.begin(), out.end(), y) == out.end()) out.push_back(y);
    };
    if (x == 0.0 || !std::isfinite(x)) return out;
    const double s = x < 0 ? -1.0 : 1.0;
    add(0.0);
    add(s);
    const double p = std::floor(std::log10(std::abs(x)));
    add(s * std::pow(10.0, p));
    for (double digits : {1.0, 3.0}) {
        const double unit = std::pow(10.0, p - digits + 1.0);
        add(std::round(x / unit) * unit);
    }
    return out;
}

/// The numbers of a case that reduction may simplify one at a time (normals and inertia are
/// simplified whole, see simpler_cases()).
inline std::vector<double*> numbers(Case& c) {
    std::vector<double*> out;
    auto vec = [&](Vector3& v) {
        out.push_back(&v.x);
        out.push_back(&v.y);
        out.push_back(&v.z);
    };
    for (RigidBody* b : {&c.body1, &c.body2}) {
        out.push_back(&b->inverse_mass);
        vec(b->velocity);
        vec(b->angular_velocity);
        vec(b->position);
        out.push_back(&b->restitution);
    }
    for (std::size_t i = 0; i < c.contact.point_count; ++i) {
        vec(c.contact.points[i].position);
        out.push_back(&c.contact.points[i].penetration);
    }
    out.push_back(&c.contact.penetration);
    out.push_back(&c.knobs.fraction);
    out.push_back(&c.knobs.slop);
    vec(c.point);
    vec(c.impulse);
    out.push_back(&c.restitution);
    out.push_back(&c.depth);
    // Chapter 6's (all 0 in the other chapters' cases, so nothing to simplify there).
    for (RigidBody* b : {&c.body1, &c.body2}) {
        out.push_back(&b->friction);
        out.push_back(&b->static_friction);
    }
    for (std::size_t i = 0; i < c.contact.point_count; ++i) {
        out.push_back(&c.impulses.points[i].normal);
        out.push_back(&c.impulses.points[i].friction[0]);
        out.push_back(&c.impulses.points[i].friction[1]);
    }
    for (double* x : {&c.mu1, &c.mu2, &c.accumulated[0], &c.accumulated[1], &c.increment[0], &c.increment[1], &c.normal_impulse,
                      &c.static_coefficient, &c.dynamic_coefficient})
        out.push_back(x);
    return out;
}

inline Vector3 nearest_axis(const Vector3& n) {
    const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
    const double l = std::abs(length(n) - 1.0) < 1e-12 ? 1.0 : length(n);
    if (ax >= ay && ax >= az) return {n.x < 0 ? -l : l, 0, 0};
    if (ay >= az) return {0, n.y < 0 ? -l : l, 0};
    return {0, 0, n.z < 0 ? -l : l};
}

/// Every case one simplification away from `c`: a point fewer, a whole vector zero, a body
/// unturned, a diagonal inertia, a normal along an axis, one number simpler.
inline std::vector<Case> simpler_cases(const Case& c) {
    std::vector<Case> out;
    auto fix = [](Case& k) {
        k.body1.update_world_inertia();
        k.body2.update_world_inertia();
        return k;
    };
    for (std::size_t drop = 0; c.contact.point_count > 1 && drop < c.contact.point_count; ++drop) {
        Case k = c;
        k.contact.point_count = 0;
        k.impulses = ContactImpulses{};
        for (std::size_t i = 0; i < c.contact.point_count; ++i)
            if (i != drop) {
                k.impulses.points[k.contact.point_count] = c.impulses.points[i];
                k.contact.points[k.contact.point_count++] = c.contact.points[i];
            }
        out.push_back(k);
    }
    for (int side = 0; side < 2; ++side) {
        const RigidBody& b = side == 0 ? c.body1 : c.body2;
        auto with = [&](auto change) {
            Case k = c;
            change(side == 0 ? k.body1 : k.body2);
            out.push_back(fix(k));
        };
        if (!(b.velocity == Vector3{})) with([](RigidBody& x) { x.velocity = {}; });
        if (!(b.angular_velocity == Vector3{})) with([](RigidBody& x) { x.angular_velocity = {}; });
        if (!(b.position == Vector3{})) with([](RigidBody& x) { x.position = {}; });
        const Quaternion q = b.orientation;
        if (q.w != 1.0 || q.x != 0.0 || q.y != 0.0 || q.z != 0.0) with([](RigidBody& x) { x.orientation = {}; });
        const Matrix3& i = b.inertia_body;
        const Matrix3 diag = Matrix3::diagonal({i(0, 0), i(1, 1), i(2, 2)});
        if (!(i.m == diag.m)) with([&](RigidBody& x) { x.inertia_body = diag; });
        const double mean = (i(0, 0) + i(1, 1) + i(2, 2)) / 3.0;
        const Matrix3 round = Matrix3::diagonal({mean, mean, mean});
        if (!(i.m == round.m)) with([&](RigidBody& x) { x.inertia_body = round; });
    }
    for (Vector3 Case::*field : {&Case::normal}) {
        const Vector3 axis = nearest_axis(c.*field);
        if (!(axis == c.*field)) {
            Case k = c;
            k.*field = axis;
            out.push_back(k);
        }
    }
    {
        const Vector3 axis = nearest_axis(c.contact.normal);
        if (!(axis == c.contact.normal)) {
            Case k = c;
            k.contact.normal = axis;
            out.push_back(k);
        }
    }
    Case copy = c;
    const std::size_t count = numbers(copy).size();
    for (std::size_t j = 0; j < count; ++j) {
        Case probe = c;
        const double x = *numbers(probe)[j];
        for (double y : simpler_numbers(x)) {
            Case k = c;
            *numbers(k)[j] = y;
            // A body's inertia follows its mass, so that a lighter body keeps its size.
            for (RigidBody* b : {&k.body1, &k.body2})
                if (numbers(k)[j] == &b->inverse_mass && x > 0.0 && y > 0.0) b->inertia_body = b->inertia_body * (x / y);
            out.push_back(fix(k));
        }
    }
    return out;
}

/// Legal for every chapter: non-negative inverse masses and depths, restitutions in [0, 1], a
/// movable body's inertia positive definite with a determinant of 1e-290 to 1e290, a
/// contact's depth at least each point's, unit normals, a fraction and a slop that are not negative.
inline bool legal(const Case& c) {
    for (const RigidBody* b : {&c.body1, &c.body2}) {
        if (!(b->inverse_mass >= 0.0) || !(b->restitution >= 0.0 && b->restitution <= 1.0)) return false;
        if (!(b->friction >= 0.0 && b->static_friction >= b->friction)) return false;
        if (!b->is_immovable()) {
            const Matrix3& i = b->inertia_body;
            const double d1 = i(0, 0);
            const double d2 = i(0, 0) * i(1, 1) - i(0, 1) * i(1, 0);
            // Positive definite, and a determinant double can hold, so that its inverse can be computed.
            if (!(d1 > 0.0 && d2 > 0.0 && determinant(i) >= 1e-290 && determinant(i) <= 1e290)) return false;
        }
    }
    for (std::size_t i = 0; i < c.contact.point_count; ++i) {
        const double d = c.contact.points[i].penetration;
        if (!(d >= 0.0) || d > c.contact.penetration) return false;
    }
    if (std::abs(length(c.contact.normal) - 1.0) > 1e-15) return false;
    for (std::size_t i = 0; i < c.contact.point_count; ++i)
        if (!(c.impulses.points[i].normal >= 0.0)) return false;
    if (!(c.mu1 >= 0.0 && c.mu2 >= 0.0 && c.normal_impulse >= 0.0)) return false;
    if (!(c.dynamic_coefficient >= 0.0 && c.static_coefficient >= c.dynamic_coefficient)) return false;
    return c.knobs.fraction >= 0.0 && c.knobs.slop >= 0.0 && c.depth >= 0.0 && c.restitution >= 0.0 && c.restitution <= 1.0;
}

// ----- Describing a case --------------------------------------------------------------------

inline std::string body_text(const RigidBody& b, bool spin) {
    using testing::format;
    std::string s = b.is_immovable() ? std::string("immovable (inverse mass 0)") : "m = " + format(b.mass()) + " kg";
    s += ", v = " + format(b.velocity) + " m/s";
    if (!(b.angular_velocity == Vector3{})) s += ", w = " + format(b.angular_velocity) + " rad/s";
    s += ", at " + format(b.position) + " m";
    if (b.restitution != 1.0) s += ", e = " + format(b.restitution);
    if (b.friction != 0.0 || b.static_friction != 0.0)
        s += ", friction " + format(b.friction) + " (static " + format(b.static_friction) + ")";
    if (!spin) return s;
    const Quaternion& q = b.orientation;
    if (q.w != 1.0 || q.x != 0.0 || q.y != 0.0 || q.z != 0.0)
        s += ", orientation (w, x, y, z) = (" + format(q.w) + ", " + format(q.x) + ", " + format(q.y) + ", " + format(q.z) + ")";
    const Matrix3& i = b.inertia_body;
    const bool diagonal = i(0, 1) == 0.0 && i(0, 2) == 0.0 && i(1, 2) == 0.0 && i(1, 0) == 0.0 && i(2, 0) == 0.0 && i(2, 1) == 0.0;
    if (diagonal) {
        s += ", inertia_body = diag" + format(Vector3{i(0, 0), i(1, 1), i(2, 2)}) + " kg m^2";
    } else {
        s += ", inertia_body rows " + format(i.row(0)) + " " + format(i.row(1)) + " " + format(i.row(2)) + " kg m^2";
    }
    return s;
}

inline std::string contact_text(const Contact& c) {
    using testing::format;
    std::string s = "normal " + format(c.normal) + ", depth " + format(c.penetration) + " m, points";
    for (std::size_t i = 0; i < c.point_count; ++i)
        s += (i ? "; " : " ") + format(c.points[i].position) + " (depth " + format(c.points[i].penetration) + ")";
    return s;
}

/// What a judge reads of a case, for the feedback: it prints only those parts.
struct Reads {
    bool body1 = true;  ///< false for a function that takes no body (chapter 6's steps 1, 2 and 4)
    bool body2 = true;
    bool contact = false;
    bool knobs = false;
    bool point = false;
    bool normal = false;
    bool impulse = false;
    bool restitution = false;
    bool depth = false;
    bool spin = false;  ///< orientation and inertia (chapter 4)
    bool impulses = false;     ///< the points' accumulated normal and friction impulses (chapter 6)
    bool tangent = false;      ///< a tangent argument (chapter 6)
    bool mix = false;          ///< mix_coefficients()'s two coefficients (chapter 6)
    bool accumulate = false;   ///< accumulate_friction()'s arguments (chapter 6)
};

inline std::string case_text(const Case& c, Reads reads) {
    using testing::format;
    std::string s = reads.body1 ? "body 1: " + body_text(c.body1, reads.spin) : std::string();
    if (reads.body2) s += "; body 2: " + body_text(c.body2, reads.spin);
    if (reads.contact) s += "; contact: " + contact_text(c.contact);
    if (reads.knobs) s += "; knobs: fraction " + format(c.knobs.fraction) + ", slop " + format(c.knobs.slop) + " m";
    if (reads.point) s += "; point " + format(c.point) + " m";
    if (reads.normal) s += "; normal " + format(c.normal);
    if (reads.impulse) s += "; impulse " + format(c.impulse) + " kg m/s";
    if (reads.restitution) s += "; e = " + format(c.restitution);
    if (reads.depth) s += "; depth " + format(c.depth) + " m";
    if (reads.impulses)
        for (std::size_t i = 0; i < c.contact.point_count; ++i) {
            const PointImpulse& p = c.impulses.points[i];
            s += "; point " + std::to_string(i + 1) + "'s accumulated normal impulse " + format(p.normal) + " kg m/s, friction (" +
                 format(p.friction[0]) + ", " + format(p.friction[1]) + "), normal effective mass " + format(p.mass) + " kg";
        }
    if (reads.tangent) s += "; tangent " + format(c.tangent);
    if (reads.mix) s += "; mu1 = " + format(c.mu1) + ", mu2 = " + format(c.mu2);
    if (reads.accumulate)
        s += "; accumulated (" + format(c.accumulated[0]) + ", " + format(c.accumulated[1]) + ") kg m/s, increment (" +
             format(c.increment[0]) + ", " + format(c.increment[1]) + "), normal impulse " + format(c.normal_impulse) +
             " kg m/s, mu_s = " + format(c.static_coefficient) + ", mu_d = " + format(c.dynamic_coefficient);
    return s.starts_with("; ") ? s.substr(2) : s;
}

// ----- The sampling loop --------------------------------------------------------------------

/// How many legal inputs each function meets per grading run, per test case.
inline constexpr int samples = 1000;

/// Draws `count` cases with `draw` (which may return false to draw again), judges each with
/// `judge`, and on the first failure reduces the case: while some simpler legal case that
/// `keep` still accepts (the same kind of case, so the same step) fails too, take it. The
/// reduced case is reported with its law, expected and actual values and hint.
template <class Draw, class Judge, class Keep>
void sample(std::uint64_t offset, Reads reads, Draw draw, Judge judge, Keep keep, int count = samples) {
    const std::uint64_t seed = testing::run_seed() + offset;
    SeededRandom random(seed);
    int drawn = 0;
    for (int attempts = 0; drawn < count && attempts < 20 * count; ++attempts) {
        Case c;
        if (!draw(random, c) || !legal(c) || !keep(c)) continue;
        ++drawn;
        Verdict verdict = judge(c);
        if (!verdict.failed()) continue;
        int tries = 0;
        for (bool reduced = true; reduced && tries < 3000;) {
            reduced = false;
            for (const Case& k : simpler_cases(c)) {
                if (!legal(k) || !keep(k)) continue;
                ++tries;
                Verdict v = judge(k);
                if (v.failed()) {
                    c = k;
                    verdict = std::move(v);
                    reduced = true;
                    break;
                }
            }
        }
        const std::string situation = case_text(c, reads) + " (" + verdict.quantity + "; sampled case " + std::to_string(drawn) +
                                      " of seed " + std::to_string(seed) + ", reduced to its simplest failing form)";
        if (verdict.is_vector) {
            testing::expect_close(*verdict.law, verdict.expected, verdict.actual, verdict.tolerance, verdict.unit, situation);
        } else {
            testing::expect_close(*verdict.law, verdict.expected.x, verdict.actual.x, verdict.tolerance, verdict.unit, situation);
        }
        return;
    }
    REQUIRE(drawn == count);  // the draws themselves must reach the count (a test bug otherwise)
}

}  // namespace workbook::domain
