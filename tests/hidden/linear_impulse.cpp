// Hidden step tests for chapter 3, linear impulses with restitution. Broader than the public
// ones: seeded random pairs in 3D with normals off the axes and of any length, mass ratios
// from 1e-12 to 1e12, an immovable body on either side, e = 0 and e = 1, sliding contacts,
// equal velocities, touching pairs that separate. Tolerances are a few ulps of the speeds (or
// momenta, energies) that go in, so every correct algebraic form of the formulas passes.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <string>

#include "../steps/linear_impulse_laws.hpp"
#include "feedback.hpp"
#include "sent_values.hpp"
#include "linear-impulse.hpp"
#include "seeded_random.hpp"
#include "workbook/probes.hpp"

using namespace workbook;
namespace laws = workbook::linear_impulse_laws;
using workbook::testing::describe;
using workbook::testing::format;
using workbook::testing::rounding_tolerance;
using workbook::testing::SeededRandom;

namespace {

constexpr int random_cases = 2000;
constexpr double ulps = 64.0;

struct Pair {
    RigidBody body1;
    RigidBody body2;
    Contact contact;
};

void make_immovable(RigidBody& body, SeededRandom& random, bool moving) {
    body.inverse_mass = 0.0;
    body.inertia_body = Matrix3::zero();
    body.update_world_inertia();
    body.velocity = moving ? random.vector(5.0) : Vector3{};  // a moving platform, or a wall
}

/// A random pair: masses over twelve decades either way, 3D velocities, a unit normal off the
/// axes, restitutions in [0, 1] with e = 0 and e = 1 among them; `immovable` 1 or 2 pins that body.
Pair random_pair(SeededRandom& random, bool approaching, int immovable = 0, double ratio_decades = 12.0) {
    const double scale = random.log_uniform(-2.0, 2.0);
    const double ratio = random.log_uniform(-ratio_decades, ratio_decades);
    Pair p{make_sphere(scale, 0.5, {}, random.vector(50.0)), make_sphere(scale * ratio, 0.5, {}, random.vector(50.0)), {}};
    const double pick = random.uniform(0.0, 1.0);
    p.body1.restitution = pick < 0.1 ? 0.0 : pick < 0.2 ? 1.0 : random.uniform(0.0, 1.0);
    p.body2.restitution = random.uniform(0.0, 1.0) < 0.5 ? 1.0 : random.uniform(0.0, 1.0);
    if (immovable == 1) make_immovable(p.body1, random, random.uniform(0.0, 1.0) < 0.5);
    if (immovable == 2) make_immovable(p.body2, random, random.uniform(0.0, 1.0) < 0.5);
    p.contact.normal = random.direction();
    const double vn = dot(p.body1.velocity - p.body2.velocity, p.contact.normal);
    if ((vn < 0.0) != approaching) p.contact.normal = -p.contact.normal;
    p.body2.position = p.body1.position - p.contact.normal * 0.99;
    p.contact.add_point(p.body1.position - p.contact.normal * 0.495, 0.01);
    return p;
}

std::string body_text(const RigidBody& b) { return describe(b) + ", e = " + format(b.restitution); }

std::string case_text(const Pair& p, int index, std::uint64_t seed) {
    return "random case " + std::to_string(index) + " of seed " + std::to_string(seed) + ": body 1: " + body_text(p.body1) +
           "; body 2: " + body_text(p.body2) + "; normal " + format(p.contact.normal);
}

double speed_scale(const Pair& p) { return length(p.body1.velocity) + length(p.body2.velocity); }

bool close(double a, double b, double tolerance) { return std::isfinite(a) && std::isfinite(b) && std::abs(a - b) <= tolerance; }

bool close(const Vector3& a, const Vector3& b, double tolerance) {
    return close(a.x, b.x, tolerance) && close(a.y, b.y, tolerance) && close(a.z, b.z, tolerance);
}

bool same_bits(const Vector3& a, const Vector3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

Vector3 momentum(const RigidBody& a, const RigidBody& b) { return a.mass() * a.velocity + b.mass() * b.velocity; }

/// 1/2 m |v - frame|^2, and 0 for an immovable body.
double kinetic_energy_in_frame(const RigidBody& body, const Vector3& frame) {
    return body.is_immovable() ? 0.0 : 0.5 * body.mass() * length_squared(body.velocity - frame);
}

Vector3 tangential(const Vector3& v, const Vector3& unit_normal) { return v - dot(v, unit_normal) * unit_normal; }

/// Every law of a whole response on one pair; reports the first broken one and returns false.
bool full_response_holds(const Pair& before, const std::string& situation) {
    Pair p = before;
    linear_impulse::resolve(p.body1, p.body2, p.contact);
    const Vector3 n = before.contact.normal;
    const double e = combined_restitution(before.body1, before.body2);
    const Vector3 v12 = before.body1.velocity - before.body2.velocity;
    const Vector3 v12_after = p.body1.velocity - p.body2.velocity;
    const double speed = speed_scale(before);
    for (int side = 1; side <= 2; ++side) {
        const RigidBody& was = side == 1 ? before.body1 : before.body2;
        const RigidBody& is = side == 1 ? p.body1 : p.body2;
        if (was.is_immovable() && !same_bits(was.velocity, is.velocity)) {
            workbook::testing::expect_close(laws::immovable, was.velocity, is.velocity, 0.0, "m/s",
                                            situation + " (the immovable body " + std::to_string(side) + " after)");
            return false;
        }
    }
    if (!close(-e * dot(v12, n), dot(v12_after, n), rounding_tolerance(speed, ulps))) {
        workbook::testing::expect_close(laws::restitution, -e * dot(v12, n), dot(v12_after, n), rounding_tolerance(speed, ulps), "m/s",
                                        situation + " (v12' . n after)");
        return false;
    }
    if (!close(tangential(v12, n), tangential(v12_after, n), rounding_tolerance(speed, ulps))) {
        workbook::testing::expect_close(laws::tangential, tangential(v12, n), tangential(v12_after, n), rounding_tolerance(speed, ulps),
                                        "m/s", situation + " (tangential relative velocity after)");
        return false;
    }
    if (!before.body1.is_immovable() && !before.body2.is_immovable()) {
        const double scale = before.body1.mass() * length(before.body1.velocity) + before.body2.mass() * length(before.body2.velocity);
        const Vector3 p0 = momentum(before.body1, before.body2);
        const Vector3 p1 = momentum(workbook::testing::judged(before.body1, p.body1), workbook::testing::judged(before.body2, p.body2));
        if (!close(p0, p1, rounding_tolerance(scale, ulps))) {
            workbook::testing::expect_close(laws::momentum, p0, p1, rounding_tolerance(scale, ulps), "kg m/s",
                                            situation + " (total momentum after)");
            return false;
        }
    }
    const double mu = 1.0 / (before.body1.inverse_mass + before.body2.inverse_mass);
    const double vn = dot(v12, n);
    // Measured in the frame of an immovable body (a moving platform does work in any other frame).
    const Vector3 frame = before.body1.is_immovable()   ? before.body1.velocity
                          : before.body2.is_immovable() ? before.body2.velocity
                                                        : Vector3{};
    const double energy_before = kinetic_energy_in_frame(before.body1, frame) + kinetic_energy_in_frame(before.body2, frame);
    const double energy_after = kinetic_energy_in_frame(workbook::testing::judged(before.body1, p.body1), frame) +
                                kinetic_energy_in_frame(workbook::testing::judged(before.body2, p.body2), frame);
    const double expected = 0.5 * mu * (1.0 - e * e) * vn * vn;
    const double tolerance = rounding_tolerance(energy_before + energy_after, ulps);
    if (!close(expected, energy_before - energy_after, tolerance)) {
        workbook::testing::expect_close(laws::energy, expected, energy_before - energy_after, tolerance, "J",
                                        situation + " (kinetic energy lost)");
        return false;
    }
    return true;
}

}  // namespace

// ----- Step 1 -----------------------------------------------------------------------------

TEST_CASE("random pairs and normals of any length: v12 . n", "[linear-impulse][step:1:relative-normal-velocity][points:3]") {
    const std::uint64_t seed = workbook::testing::run_seed() + 30;
    SeededRandom random(seed);
    for (int i = 0; i < random_cases; ++i) {
        const bool approaching = random.uniform(0.0, 1.0) < 0.5;
        Pair p = random_pair(random, approaching);
        p.contact.normal = p.contact.normal * random.log_uniform(-3.0, 3.0);
        const Vector3& n = p.contact.normal;
        const double expected = dot(p.body1.velocity - p.body2.velocity, n);
        const double actual = linear_impulse::relative_normal_velocity(p.body1, p.body2, n);
        const double tolerance = rounding_tolerance(speed_scale(p) * length(n), ulps);
        if (!close(expected, actual, tolerance)) {
            workbook::testing::expect_close(laws::normal_velocity, expected, actual, tolerance, "m/s", case_text(p, i, seed));
            return;
        }
    }
    SUCCEED();
}

// ----- Step 2 -----------------------------------------------------------------------------

TEST_CASE("random separating pairs keep their velocities exactly, approaching ones do not",
          "[linear-impulse][step:2:separating-contacts][points:3]") {
    const std::uint64_t seed = workbook::testing::run_seed() + 31;
    SeededRandom random(seed);
    for (int i = 0; i < random_cases; ++i) {
        Pair apart = random_pair(random, false, i % 3);
        const Pair before = apart;
        linear_impulse::resolve(apart.body1, apart.body2, apart.contact);
        if (!same_bits(apart.body1.velocity, before.body1.velocity) || !same_bits(apart.body2.velocity, before.body2.velocity)) {
            workbook::testing::expect_close(laws::separating, before.body1.velocity - before.body2.velocity,
                                            apart.body1.velocity - apart.body2.velocity, 0.0, "m/s",
                                            case_text(before, i, seed) + " (separating: relative velocity after)");
            return;
        }
    }
    for (int i = 0; i < 200; ++i) {
        // Moderate masses and e = 0.5: whether the pair is resolved at all is this step's question,
        // how well is step 4's (a wrong J that rounds away against a 1e12 mass ratio is not a skip).
        Pair towards = random_pair(random, true, i % 3, 2.0);
        towards.body1.restitution = towards.body2.restitution = 0.5;
        const Pair before = towards;
        linear_impulse::resolve(towards.body1, towards.body2, towards.contact);
        const double change = length(towards.body1.velocity - before.body1.velocity) + length(towards.body2.velocity - before.body2.velocity);
        if (!(change > 0.0)) {
            workbook::testing::expect_at_least(laws::respond, 1e-6 * speed_scale(before), change, 0.0, "m/s",
                                               case_text(before, i, seed) + " (approaching: |v1' - v1| + |v2' - v2|)");
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("sliding contacts (v12 . n = 0) and equal velocities get no impulse", "[linear-impulse][step:2:separating-contacts][points:2]") {
    const std::uint64_t seed = workbook::testing::run_seed() + 32;
    SeededRandom random(seed);
    // Normals along an axis, so that v12 . n is exactly 0 when the velocities share that component.
    const Vector3 axes[] = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}};
    for (int i = 0; i < 300; ++i) {
        Pair p = random_pair(random, true, i % 3);
        p.contact.normal = axes[i % 3];
        if (i % 2 == 0) {
            p.body2.velocity = p.body1.velocity;  // equal velocities
            if (p.body2.is_immovable() || p.body1.is_immovable()) continue;
        } else {
            Vector3 v = p.body1.velocity;  // body 1 slides along body 2: the same normal component
            const Vector3 n = p.contact.normal;
            v = v - dot(v, n) * n + dot(p.body2.velocity, n) * n;
            p.body1.velocity = v;
            if (dot(p.body1.velocity - p.body2.velocity, n) != 0.0) continue;
        }
        const Pair before = p;
        linear_impulse::resolve(p.body1, p.body2, p.contact);
        if (!same_bits(p.body1.velocity, before.body1.velocity) || !same_bits(p.body2.velocity, before.body2.velocity)) {
            workbook::testing::expect_close(laws::separating, before.body1.velocity - before.body2.velocity,
                                            p.body1.velocity - p.body2.velocity, 0.0, "m/s",
                                            case_text(before, i, seed) + (i % 2 == 0 ? " (equal velocities" : " (sliding") +
                                                ", v12 . n = 0: relative velocity after)");
            return;
        }
    }
    Pair towards = random_pair(random, true, 0, 2.0);
    towards.body1.restitution = towards.body2.restitution = 0.5;
    const Pair before = towards;
    linear_impulse::resolve(towards.body1, towards.body2, towards.contact);
    workbook::testing::expect_at_least(laws::respond, 1e-6 * speed_scale(before),
                                       length(towards.body1.velocity - before.body1.velocity) +
                                           length(towards.body2.velocity - before.body2.velocity),
                                       0.0, "m/s", case_text(before, 0, seed) + " (approaching: |v1' - v1| + |v2' - v2|)");
}

// ----- Step 3 -----------------------------------------------------------------------------

TEST_CASE("random approaching pairs over 24 decades of mass ratio, normals of any length: J", "[linear-impulse][step:3:impulse-size][points:3]") {
    const std::uint64_t seed = workbook::testing::run_seed() + 33;
    SeededRandom random(seed);
    for (int i = 0; i < random_cases; ++i) {
        Pair p = random_pair(random, true, i % 4 == 3 ? 1 + (i / 4) % 2 : 0);
        const double k = random.log_uniform(-3.0, 3.0);
        const Vector3 n = p.contact.normal * k;
        const double e = random.uniform(0.0, 1.0) < 0.2 ? (i % 2 == 0 ? 0.0 : 1.0) : random.uniform(0.0, 1.0);
        const double w = p.body1.inverse_mass + p.body2.inverse_mass;
        const double vn = dot(p.body1.velocity - p.body2.velocity, p.contact.normal);
        const double expected = -(1.0 + e) * vn / (k * w);
        const double actual = linear_impulse::impulse_magnitude(p.body1, p.body2, n, e);
        const double tolerance = rounding_tolerance((1.0 + e) * speed_scale(p) / (k * w), ulps);
        const std::string situation = case_text(p, i, seed) + ", normal passed " + format(n) + " (length " + format(k) +
                                      "), restitution argument " + format(e);
        if (!(actual >= 0.0)) {
            workbook::testing::expect_at_least(laws::push, 0.0, actual, 0.0, "N s", situation);
            return;
        }
        if (!close(expected, actual, tolerance)) {
            // A value off by the factor k^2 or k is the length of the normal, not the formula.
            const bool length_only = close(expected * k, actual, tolerance * k) || close(expected * k * k, actual, tolerance * k * k);
            workbook::testing::expect_close(length_only ? laws::normal_length : laws::impulse, expected, actual, tolerance, "N s", situation);
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("an immovable body on either side: J = (1 + e) m |v12 . n|; two of them: J = 0", "[linear-impulse][step:3:impulse-size][points:2]") {
    const std::uint64_t seed = workbook::testing::run_seed() + 34;
    SeededRandom random(seed);
    for (int i = 0; i < 500; ++i) {
        Pair p = random_pair(random, true, 1 + i % 2);
        if (dot(p.body1.velocity - p.body2.velocity, p.contact.normal) >= 0.0) p.contact.normal = -p.contact.normal;
        const RigidBody& movable = p.body1.is_immovable() ? p.body2 : p.body1;
        const double e = i % 5 == 0 ? 1.0 : random.uniform(0.0, 1.0);
        const double vn = dot(p.body1.velocity - p.body2.velocity, p.contact.normal);
        const double expected = -(1.0 + e) * vn * movable.mass();
        const double actual = linear_impulse::impulse_magnitude(p.body1, p.body2, p.contact.normal, e);
        const double tolerance = rounding_tolerance((1.0 + e) * speed_scale(p) * movable.mass(), ulps);
        if (!close(expected, actual, tolerance)) {
            workbook::testing::expect_close(laws::immovable, expected, actual, tolerance, "N s",
                                            case_text(p, i, seed) + ", restitution argument " + format(e));
            return;
        }
    }
    RigidBody wall1 = make_immovable_sphere(1.0, {0, 0, 0});
    RigidBody wall2 = make_immovable_sphere(1.0, {1.5, 0, 0});
    wall2.velocity = {-1, 0.5, 0};
    const double j = linear_impulse::impulse_magnitude(wall2, wall1, {1, 0, 0}, 0.5);
    workbook::testing::expect_close(laws::immovable, 0.0, j, 0.0, "N s",
                                    "two immovable bodies approaching: body 1: " + describe(wall2) + "; body 2: " + describe(wall1));
}

// ----- Step 4 -----------------------------------------------------------------------------

TEST_CASE("random approaching pairs: momentum, restitution, tangential velocity and energy", "[linear-impulse][step:4:apply-impulse][points:3]") {
    const std::uint64_t seed = workbook::testing::run_seed() + 35;
    SeededRandom random(seed);
    for (int i = 0; i < random_cases; ++i) {
        Pair p = random_pair(random, true);
        // Some contacts have several points (a face on a face): still one impulse.
        for (int extra = 0; extra < i % 4; ++extra) p.contact.add_point(p.contact.points[0].position + random.vector(0.1), 0.005);
        if (!full_response_holds(p, case_text(p, i, seed) + ", " + std::to_string(p.contact.point_count) + " contact points")) return;
    }
    SUCCEED();
}

TEST_CASE("an immovable body on either side, at rest or moving", "[linear-impulse][step:4:apply-impulse][points:2]") {
    const std::uint64_t seed = workbook::testing::run_seed() + 36;
    SeededRandom random(seed);
    for (int i = 0; i < 500; ++i) {
        const Pair p = random_pair(random, true, 1 + i % 2);
        if (!full_response_holds(p, case_text(p, i, seed) + (i % 2 == 0 ? " (body 1 immovable)" : " (body 2 immovable)"))) return;
    }
    SUCCEED();
}

TEST_CASE("e = 0 and e = 1 on equal masses: the pair moves on together, or swaps normal velocities", "[linear-impulse][step:4:apply-impulse][points:2]") {
    const std::uint64_t seed = workbook::testing::run_seed() + 37;
    SeededRandom random(seed);
    for (int i = 0; i < 200; ++i) {
        Pair p = random_pair(random, true);
        p.body2.inverse_mass = p.body1.inverse_mass;
        p.body1.restitution = p.body2.restitution = (i % 2 == 0) ? 0.0 : 1.0;
        if (!full_response_holds(p, case_text(p, i, seed))) return;
    }
    SUCCEED();
}
