// Hidden step tests for chapter 1, perfectly inelastic collision. Broader than the public
// ones: seeded random pairs in 3D with mass ratios from 1e-6 to 1e6, immovable bodies on
// either side, two immovable bodies, equal velocities, pairs already moving apart.
// Momentum must hold to rounding: a few ulps of the total mass times the incoming speeds
// (what any correct algebraic form achieves), not a loose 1e-3. Extremes of mass and speed,
// a body at rest, equal masses and exactly touching bodies are among the cases.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "feedback.hpp"
#include "sent_values.hpp"
#include "inelastic.hpp"
#include "../steps/inelastic_laws.hpp"
#include "seeded_random.hpp"
#include "workbook/probes.hpp"

using namespace workbook;
namespace laws = workbook::inelastic_laws;
using workbook::testing::describe;
using workbook::testing::rounding_tolerance;
using workbook::testing::SeededRandom;

namespace {

constexpr int random_cases = 2000;

/// A random pair: masses spread over twelve decades around a random scale, 3D velocities.
struct Pair {
    RigidBody body1;
    RigidBody body2;
    Contact contact;
};

Pair random_pair(SeededRandom& random, bool approaching) {
    const double scale = random.log_uniform(-2.0, 2.0);
    const double ratio = random.log_uniform(-6.0, 6.0);
    Pair p{make_sphere(scale, 0.5, {}, random.vector(50.0)), make_sphere(scale * ratio, 0.5, {}, random.vector(50.0)), {}};
    p.contact.normal = random.direction();
    const bool is_approaching = dot(p.body1.velocity - p.body2.velocity, p.contact.normal) < 0.0;
    if (is_approaching != approaching) p.contact.normal = -p.contact.normal;
    p.body2.position = p.body1.position - p.contact.normal * 0.99;
    p.contact.add_point(p.body1.position - p.contact.normal * 0.495, 0.01);
    return p;
}

std::string case_text(const Pair& p, int index) {
    return "random case " + std::to_string(index) + " of seed " + std::to_string(workbook::testing::run_seed()) +
           ": body 1: " + describe(p.body1) + "; body 2: " + describe(p.body2) +
           "; normal " + workbook::testing::format(p.contact.normal);
}

Vector3 momentum(const RigidBody& a, const RigidBody& b) { return a.mass() * a.velocity + b.mass() * b.velocity; }

/// How exact a momentum can be: rounding of the total mass times the incoming speeds. Any
/// correct algebraic form of the common velocity is within a few ulps of this (the relative
/// form v1 + (v2 - v1) w1 / (w1 + w2) rounds at |v1 - v2|, not at each momentum).
double momentum_rounding(const RigidBody& a, const RigidBody& b) {
    return rounding_tolerance((a.mass() + b.mass()) * (length(a.velocity) + length(b.velocity)));
}

bool vectors_within(const Vector3& a, const Vector3& b, double tolerance) {
    return is_finite(a) && is_finite(b) && std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance &&
           std::abs(a.z - b.z) <= tolerance;
}

bool same_bits(const Vector3& a, const Vector3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/// The approaching half of step 4, judged by step 4's own law (the pair stops approaching),
/// so that a step 2 mistake is not reported a second time here. It also keeps an empty
/// resolve() from passing step 4.
void expect_no_longer_approaching(SeededRandom& random, int index) {
    Pair towards = random_pair(random, true);
    const Pair before = towards;
    inelastic::resolve(towards.body1, towards.body2, towards.contact);
    const double speed = length(before.body1.velocity) + length(before.body2.velocity);
    workbook::testing::expect_at_least(laws::approach, 0.0, dot(towards.body1.velocity - towards.body2.velocity, towards.contact.normal),
                                       rounding_tolerance(speed), "m/s",
                                       case_text(before, index) + " (approaching: normal relative velocity after)");
}

}  // namespace

TEST_CASE("random pairs over twelve decades of mass ratio: the common velocity keeps the momentum to rounding",
          "[inelastic][step:1:common-velocity][points:3]") {
    SeededRandom random(workbook::testing::run_seed());
    for (int i = 0; i < random_cases; ++i) {
        const Pair p = random_pair(random, true);
        const Vector3 shared = inelastic::common_velocity(p.body1, p.body2);
        const Vector3 after = (p.body1.mass() + p.body2.mass()) * shared;
        const double tolerance = momentum_rounding(p.body1, p.body2);
        if (!vectors_within(momentum(p.body1, p.body2), after, tolerance)) {
            workbook::testing::expect_close(laws::momentum, momentum(p.body1, p.body2), after, tolerance, "kg m/s", case_text(p, i));
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("extremes of mass and speed: one body at rest, equal masses, speeds over eight decades",
          "[inelastic][step:1:common-velocity][points:1]") {
    SeededRandom random(workbook::testing::run_seed() + 7);
    for (int i = 0; i < random_cases; ++i) {
        // Masses from a gram to a thousand tonnes, speeds from 0.1 mm/s to 10 km/s, and the
        // degenerate but legal corners: a body at rest, equal masses, equal speeds.
        const double m1 = random.log_uniform(-3.0, 6.0);
        const double m2 = (i % 5 == 0) ? m1 : random.log_uniform(-3.0, 6.0);
        // One draw a statement: the same pairs on every compiler.
        const Vector3 direction1 = random.direction();
        const Vector3 v1 = direction1 * random.log_uniform(-4.0, 4.0);
        Vector3 v2{};
        if (i % 7 != 0) {
            const Vector3 direction2 = random.direction();
            v2 = direction2 * random.log_uniform(-4.0, 4.0);
        }
        Pair p{make_sphere(m1, 0.5, {}, v1), make_sphere(m2, 0.5, {}, v2), {}};
        p.contact.normal = random.direction();
        p.body2.position = p.body1.position - p.contact.normal;  // exactly touching
        const Vector3 shared = inelastic::common_velocity(p.body1, p.body2);
        const Vector3 after = (p.body1.mass() + p.body2.mass()) * shared;
        const double tolerance = momentum_rounding(p.body1, p.body2);
        if (!vectors_within(momentum(p.body1, p.body2), after, tolerance)) {
            workbook::testing::expect_close(laws::momentum, momentum(p.body1, p.body2), after, tolerance, "kg m/s",
                                            case_text(p, i));
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("equal velocities have that velocity as their common velocity", "[inelastic][step:1:common-velocity][points:1]") {
    SeededRandom random(workbook::testing::run_seed() + 1);
    for (int i = 0; i < 200; ++i) {
        Pair p = random_pair(random, true);
        p.body2.velocity = p.body1.velocity;
        const Vector3 shared = inelastic::common_velocity(p.body1, p.body2);
        const double tolerance = rounding_tolerance(length(p.body1.velocity));
        if (!vectors_within(p.body1.velocity, shared, tolerance)) {
            workbook::testing::expect_close(laws::momentum, p.body1.velocity, shared, tolerance, "m/s", case_text(p, i));
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("random approaching pairs leave together with their momentum", "[inelastic][step:2:stick-together][points:3]") {
    SeededRandom random(workbook::testing::run_seed() + 2);
    for (int i = 0; i < random_cases; ++i) {
        Pair p = random_pair(random, true);
        const Pair before = p;
        inelastic::resolve(p.body1, p.body2, p.contact);
        const double speed = std::max(length(before.body1.velocity), length(before.body2.velocity));
        if (!vectors_within(p.body1.velocity, p.body2.velocity, rounding_tolerance(speed))) {
            const bool unchanged = laws::untouched(before.body1, before.body2, p.body1, p.body2);
            workbook::testing::expect_close(laws::stick_after(unchanged), Vector3{}, p.body1.velocity - p.body2.velocity, rounding_tolerance(speed),
                                            "m/s", case_text(before, i) + " (relative velocity after)");
            return;
        }
        const double tolerance = momentum_rounding(before.body1, before.body2);
        const Vector3 after = momentum(workbook::testing::judged(before.body1, p.body1), workbook::testing::judged(before.body2, p.body2));
        if (!vectors_within(momentum(before.body1, before.body2), after, tolerance)) {
            workbook::testing::expect_close(laws::momentum, momentum(before.body1, before.body2), after,
                                            tolerance, "kg m/s", case_text(before, i) + " (total momentum after resolve)");
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("an immovable body on either side, moving or at rest, sets the common velocity",
          "[inelastic][step:3:immovable-bodies][points:3]") {
    SeededRandom random(workbook::testing::run_seed() + 3);
    for (int i = 0; i < 500; ++i) {
        Pair p = random_pair(random, true);
        RigidBody& fixed = (i % 2 == 0) ? p.body1 : p.body2;
        fixed.inverse_mass = 0.0;
        fixed.inertia_body = Matrix3::zero();
        fixed.update_world_inertia();
        fixed.velocity = (i % 4 < 2) ? Vector3{} : random.vector(5.0);  // a wall, or a moving platform
        if (dot(p.body1.velocity - p.body2.velocity, p.contact.normal) >= 0.0) p.contact.normal = -p.contact.normal;
        const Pair before = p;
        const Vector3 platform = fixed.velocity;
        inelastic::resolve(p.body1, p.body2, p.contact);
        const RigidBody& fixed_after = (i % 2 == 0) ? p.body1 : p.body2;
        const RigidBody& free_after = (i % 2 == 0) ? p.body2 : p.body1;
        const std::string side = (i % 2 == 0) ? " (body 1 immovable)" : " (body 2 immovable)";
        if (!same_bits(fixed_after.velocity, platform)) {
            workbook::testing::expect_close(laws::immovable, platform, fixed_after.velocity, 0.0, "m/s",
                                            case_text(before, i) + side + ": the immovable body's velocity after");
            return;
        }
        // Any correct form rounds at the speeds that go in (the impulse form v + (v_wall - v) leaves
        // an ulp of the incoming speed), so the tolerance scales with both, not with the platform alone.
        const double incoming = length(platform) + length(((i % 2 == 0) ? before.body2 : before.body1).velocity);
        if (!vectors_within(free_after.velocity, platform, rounding_tolerance(incoming))) {
            const bool unchanged = laws::untouched(before.body1, before.body2, p.body1, p.body2);
            workbook::testing::expect_close(laws::immovable_after(unchanged), platform, free_after.velocity, rounding_tolerance(incoming),
                                            "m/s", case_text(before, i) + side + ": the movable body's velocity after");
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("two immovable bodies: nothing changes and nothing is NaN", "[inelastic][step:3:immovable-bodies][points:1]") {
    RigidBody wall1 = make_immovable_sphere(1.0, {0, 0, 0});
    RigidBody wall2 = make_immovable_sphere(1.0, {1.5, 0, 0});
    wall2.velocity = {-1, 0, 0};  // a moving kinematic body, approaching the other
    Contact contact;
    contact.normal = {-1, 0, 0};
    contact.add_point({0.75, 0, 0}, 0.5);
    const std::string situation = "body 1: " + describe(wall1) + "; body 2: " + describe(wall2);
    workbook::testing::expect_finite(laws::immovable, inelastic::common_velocity(wall1, wall2), "m/s",
                                     situation + ": common_velocity");
    const Vector3 v1 = wall1.velocity;
    const Vector3 v2 = wall2.velocity;
    inelastic::resolve(wall1, wall2, contact);
    workbook::testing::expect_close(laws::immovable, v1, wall1.velocity, 0.0, "m/s", situation + ": body 1 after resolve");
    workbook::testing::expect_close(laws::immovable, v2, wall2.velocity, 0.0, "m/s", situation + ": body 2 after resolve");
    // And a movable body against a wall must still stop, so that an empty resolve() cannot pass.
    RigidBody wall = make_immovable_sphere(1.0, {0, 0, 0});
    RigidBody mover = make_sphere(3.0, 0.5, {1.4, 0, 0}, {-4, 2, 0});
    Contact hit;
    hit.normal = {1, 0, 0};
    hit.add_point({1.0, 0, 0}, 0.1);
    const std::string hit_text = "body 1: " + describe(mover) + "; body 2: " + describe(wall);
    const RigidBody mover_before = mover;
    const RigidBody wall_before = wall;
    inelastic::resolve(mover, wall, hit);
    workbook::testing::expect_close(laws::immovable_after(laws::untouched(mover_before, wall_before, mover, wall)), Vector3{},
                                    mover.velocity, 0.0, "m/s", hit_text + ": body 1 after resolve");
}

TEST_CASE("random pairs already moving apart keep their velocities exactly, approaching ones do not",
          "[inelastic][step:4:separating-pairs][points:3]") {
    SeededRandom random(workbook::testing::run_seed() + 4);
    for (int i = 0; i < random_cases; ++i) {
        Pair apart = random_pair(random, false);
        const Pair before = apart;
        inelastic::resolve(apart.body1, apart.body2, apart.contact);
        if (!same_bits(apart.body1.velocity, before.body1.velocity) || !same_bits(apart.body2.velocity, before.body2.velocity)) {
            workbook::testing::expect_close(laws::separating, before.body1.velocity - before.body2.velocity,
                                            apart.body1.velocity - apart.body2.velocity, 0.0, "m/s",
                                            case_text(before, i) + " (moving apart: relative velocity after)");
            return;
        }
    }
    expect_no_longer_approaching(random, random_cases);  // the case drawn after the moving-apart ones
}

TEST_CASE("equal velocities are not a collision", "[inelastic][step:4:separating-pairs][points:1]") {
    SeededRandom random(workbook::testing::run_seed() + 5);
    Pair p = random_pair(random, true);
    p.body2.velocity = p.body1.velocity;
    const Pair before = p;
    inelastic::resolve(p.body1, p.body2, p.contact);
    workbook::testing::expect_close(laws::separating, before.body1.velocity, p.body1.velocity, 0.0, "m/s",
                                    case_text(before, 0) + " (body 1 after)");
    workbook::testing::expect_close(laws::separating, before.body2.velocity, p.body2.velocity, 0.0, "m/s",
                                    case_text(before, 0) + " (body 2 after)");
    expect_no_longer_approaching(random, 1);
}

TEST_CASE("random pairs: the energy lost is 1/2 mu |v1 - v2|^2", "[inelastic][step:5:energy-lost][points:3]") {
    SeededRandom random(workbook::testing::run_seed() + 6);
    for (int i = 0; i < random_cases; ++i) {
        const Pair p = random_pair(random, true);
        const double m1 = p.body1.mass();
        const double m2 = p.body2.mass();
        const double expected = 0.5 * (m1 * m2 / (m1 + m2)) * length_squared(p.body1.velocity - p.body2.velocity);
        const double actual = inelastic::energy_lost(p.body1, p.body2);
        const double tolerance = rounding_tolerance(expected);
        if (!(std::abs(actual - expected) <= tolerance)) {
            workbook::testing::expect_close(laws::energy, expected, actual, tolerance, "J", case_text(p, i));
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("energy lost against immovable bodies", "[inelastic][step:5:energy-lost][points:1]") {
    const RigidBody ball = make_sphere(2.5, 0.5, {0, 0, 0}, {1, -2, 2});
    const RigidBody wall = make_immovable_sphere(1.0, {1.4, 0, 0});
    const std::string situation = "body 1: " + describe(ball) + "; body 2: " + describe(wall);
    workbook::testing::expect_close(laws::energy, kinetic_energy(ball), inelastic::energy_lost(ball, wall), 1e-12, "J", situation);
    workbook::testing::expect_close(laws::energy, kinetic_energy(ball), inelastic::energy_lost(wall, ball), 1e-12, "J",
                                    situation + " (bodies in the other order)");
    const RigidBody wall2 = make_immovable_sphere(1.0, {-1.4, 0, 0});
    workbook::testing::expect_close(laws::energy, 0.0, inelastic::energy_lost(wall, wall2), 0.0, "J", "two immovable bodies");
}
