// Hidden step tests for chapter 2, the projection method. Broader than the public ones:
// seeded random pairs in 3D with normals off every axis and mass ratios from 1e-9 to 1e9,
// an immovable body on either side, two immovable bodies, zero and exactly-touching depth,
// a very deep overlap, several contacts on one body, random knobs. Every tolerance is a few
// ulps of the lengths and momenta in play, not one absolute epsilon.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "../steps/projection_laws.hpp"
#include "feedback.hpp"
#include "sent_values.hpp"
#include "projection.hpp"
#include "seeded_random.hpp"
#include "workbook/probes.hpp"

using namespace workbook;
namespace laws = workbook::projection_laws;
using workbook::testing::describe;
using workbook::testing::expect_close;
using workbook::testing::format;
using workbook::testing::rounding_tolerance;
using workbook::testing::SeededRandom;

namespace {

constexpr int random_cases = 2000;
constexpr PositionCorrection whole_depth{1.0, 0.0};

/// A random overlapping pair: masses over eighteen decades of ratio, positions up to 100 m from
/// the origin, a random unit normal and a depth between 1e-4 m and 1 m.
struct Pair {
    RigidBody body1;
    RigidBody body2;
    Contact contact;
};

Pair random_pair(SeededRandom& random) {
    const double scale = random.log_uniform(-2.0, 2.0);
    const double ratio = random.log_uniform(-9.0, 9.0);
    const Vector3 position1 = random.vector(100.0);  // one draw a statement: the same pairs on every compiler
    const Vector3 velocity1 = random.vector(20.0);
    Pair p{make_sphere(scale, 0.5, position1, velocity1), make_sphere(scale * ratio, 0.5, {}, random.vector(20.0)), {}};
    p.body1.angular_velocity = random.vector(10.0);
    p.body2.angular_velocity = random.vector(10.0);
    p.contact.normal = random.direction();
    const double depth = random.log_uniform(-4.0, 0.0);
    p.body2.position = p.body1.position - p.contact.normal * (1.0 - depth);
    p.contact.add_point(p.body2.position + p.contact.normal * 0.5, depth);
    return p;
}

void make_immovable(RigidBody& body) {
    body.inverse_mass = 0.0;
    body.inertia_body = Matrix3::zero();
    body.update_world_inertia();
}

std::string case_text(const Pair& p, int index) {
    return "random case " + std::to_string(index) + " of seed " + std::to_string(workbook::testing::run_seed()) +
           ": body 1: " + describe(p.body1) + ", x = " + format(p.body1.position) + " m; body 2: " + describe(p.body2) +
           ", x = " + format(p.body2.position) + " m; normal " + format(p.contact.normal) + ", depth " +
           format(p.contact.penetration) + " m";
}

/// A few ulps of the positions and depth involved: how exact a moved position can be.
double position_tolerance(const Pair& p) {
    return rounding_tolerance(length(p.body1.position) + length(p.body2.position) + p.contact.penetration, 32.0);
}

bool within(const Vector3& expected, const Vector3& actual, double tolerance) {
    return is_finite(actual) && std::abs(expected.x - actual.x) <= tolerance && std::abs(expected.y - actual.y) <= tolerance &&
           std::abs(expected.z - actual.z) <= tolerance;
}

bool same_bits(const Vector3& a, const Vector3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/// Checks one pair moved by the inverse-mass split of `depth` along the normal; false after a failure.
bool expect_split(const Pair& before, const Pair& after, double depth, const workbook::testing::Law& law, const std::string& situation) {
    const double w1 = before.body1.inverse_mass;
    const double w2 = before.body2.inverse_mass;
    const Vector3 expected1 = before.body1.position + before.contact.normal * (depth * w1 / (w1 + w2));
    const Vector3 expected2 = before.body2.position - before.contact.normal * (depth * w2 / (w1 + w2));
    const double tolerance = position_tolerance(before);
    if (!within(expected1, after.body1.position, tolerance)) {
        expect_close(law, expected1, after.body1.position, tolerance, "m", situation + " (body 1's position after)");
        return false;
    }
    if (!within(expected2, after.body2.position, tolerance)) {
        expect_close(law, expected2, after.body2.position, tolerance, "m", situation + " (body 2's position after)");
        return false;
    }
    return true;
}

}  // namespace

TEST_CASE("random pairs over eighteen decades of mass ratio are split by inverse mass along the normal",
          "[projection][step:1:split-by-inverse-mass][points:3]") {
    SeededRandom random(workbook::testing::run_seed() + 20);
    for (int i = 0; i < random_cases; ++i) {
        const Pair before = random_pair(random);
        Pair p = before;
        projection::correct(p.body1, p.body2, p.contact, whole_depth);
        if (!expect_split(before, p, before.contact.penetration, laws::split, case_text(before, i))) return;
    }
    SUCCEED();
}

TEST_CASE("the centre of mass of random pairs stays put, to rounding", "[projection][step:1:split-by-inverse-mass][points:2]") {
    SeededRandom random(workbook::testing::run_seed() + 21);
    for (int i = 0; i < random_cases; ++i) {
        const Pair before = random_pair(random);
        Pair p = before;
        projection::correct(p.body1, p.body2, p.contact, whole_depth);
        const double m1 = before.body1.mass();
        const double m2 = before.body2.mass();
        const Vector3 weighted = m1 * (p.body1.position - before.body1.position) + m2 * (p.body2.position - before.body2.position);
        // Each displacement is exact to a few ulps of the position it was added to.
        const double tolerance = (m1 + m2) * position_tolerance(before);
        if (!within(Vector3{}, weighted, tolerance)) {
            expect_close(laws::centre_of_mass, Vector3{}, weighted, tolerance, "kg m", case_text(before, i) + " (m1 dx1 + m2 dx2)");
            return;
        }
        // Not moving at all also keeps the centre of mass: the pair must have separated too.
        const Vector3 n = before.contact.normal;
        const double opened = dot(p.body1.position - p.body2.position, n) - dot(before.body1.position - before.body2.position, n);
        if (!(std::abs(opened - before.contact.penetration) <= position_tolerance(before))) {
            expect_close(laws::split, before.contact.penetration, opened, position_tolerance(before), "m",
                         case_text(before, i) + " (how much the separation along n grew)");
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("mass ratios 1e-9 and 1e9: the light body takes all but a billionth of the depth",
          "[projection][step:1:split-by-inverse-mass][points:2]") {
    for (const double ratio : {1e-9, 1e9}) {
        Pair p{make_sphere(1.0, 0.5, {0, 0, 0}), make_sphere(ratio, 0.5, {0, -0.9, 0}), {}};
        p.contact.normal = {0, 1, 0};
        p.contact.add_point({0, -0.5, 0}, 0.1);
        projection::correct(p.body1, p.body2, p.contact, whole_depth);
        // body 1 (1 kg) moves 0.1 m2 / (m1 + m2), body 2 (m2) the rest.
        const double share1 = 0.1 * ratio / (1.0 + ratio);
        const std::string situation = "body 1: a 1 kg ball at the origin; body 2: a " + format(ratio) +
                                      " kg ball at (0, -0.9, 0) m; normal (0, 1, 0), depth 0.1 m";
        expect_close(laws::split, share1, p.body1.position.y, rounding_tolerance(0.1), "m", situation + " (body 1's height after)");
        expect_close(laws::split, -0.9 - (0.1 - share1), p.body2.position.y, rounding_tolerance(1.0), "m",
                     situation + " (body 2's height after)");
    }
}

TEST_CASE("a very deep overlap, centres nearly coincident, is removed whole", "[projection][step:1:split-by-inverse-mass][points:1]") {
    Pair p{make_sphere(2.0, 1.0, {0.001, 0, 0}), make_sphere(6.0, 1.0, {0, 0, 0}), {}};
    p.contact.normal = {1, 0, 0};
    p.contact.add_point({-0.999, 0, 0}, 1.999);
    const Pair before = p;
    projection::correct(p.body1, p.body2, p.contact, whole_depth);
    expect_close(laws::split, 2.0, p.body1.position.x - p.body2.position.x, rounding_tolerance(2.0), "m",
                 "two balls of radius 1 m, 2 kg and 6 kg, 1.999 m deep (distance between centres after)");
    expect_split(before, p, 1.999, laws::split, "two balls of radius 1 m, 2 kg and 6 kg, 1.999 m deep");
}

TEST_CASE("several contact points: the deepest sets the push", "[projection][step:1:split-by-inverse-mass][points:1]") {
    SeededRandom random(workbook::testing::run_seed() + 22);
    for (int i = 0; i < 200; ++i) {
        Pair p = random_pair(random);
        const double deepest = p.contact.penetration;
        // Shallower points, in random order around the deepest one.
        Contact c;
        c.normal = p.contact.normal;
        const int count = 2 + i % 3;
        const int deepest_at = i % count;
        for (int k = 0; k < count; ++k)
            c.add_point(p.contact.points[0].position, k == deepest_at ? deepest : deepest * random.uniform(0.0, 1.0));
        p.contact = c;
        const Pair before = p;
        projection::correct(p.body1, p.body2, p.contact, whole_depth);
        if (!expect_split(before, p, deepest, laws::split,
                          case_text(before, i) + " (" + std::to_string(count) + " points, the deepest is point " +
                              std::to_string(deepest_at + 1) + ")"))
            return;
    }
    SUCCEED();
}

TEST_CASE("several contacts on one body, all measured before any is corrected: the pushes add up",
          "[projection][step:1:split-by-inverse-mass][points:1]") {
    // A middle body with two neighbours at random; each contact is corrected with the depth
    // detection measured, as World::correct does, so the middle body's displacement is the
    // sum of its two shares and each neighbour moves its own share.
    SeededRandom random(workbook::testing::run_seed() + 27);
    for (int i = 0; i < 500; ++i) {
        const Pair left = random_pair(random);   // body 1: the middle body, body 2: a neighbour
        Pair right = random_pair(random);
        right.body1 = left.body1;
        right.body2.position = right.body1.position - right.contact.normal * (1.0 - right.contact.penetration);
        RigidBody middle = left.body1;
        RigidBody neighbour1 = left.body2;
        RigidBody neighbour2 = right.body2;
        projection::correct(middle, neighbour1, left.contact, whole_depth);
        projection::correct(middle, neighbour2, right.contact, whole_depth);
        const double wm = middle.inverse_mass;
        const double w1 = neighbour1.inverse_mass;
        const double w2 = neighbour2.inverse_mass;
        const Vector3 expected = left.body1.position + left.contact.normal * (left.contact.penetration * wm / (wm + w1)) +
                                 right.contact.normal * (right.contact.penetration * wm / (wm + w2));
        const double tolerance = 2.0 * (position_tolerance(left) + position_tolerance(right));
        if (!within(expected, middle.position, tolerance)) {
            expect_close(laws::split, expected, middle.position, tolerance, "m",
                         case_text(left, i) + "; a second contact: " + case_text(right, i) + " (the middle body after both)");
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("an immovable body on either side never moves, the other takes the whole depth",
          "[projection][step:2:immovable-bodies][points:3]") {
    SeededRandom random(workbook::testing::run_seed() + 23);
    for (int i = 0; i < random_cases; ++i) {
        Pair p = random_pair(random);
        const bool first = i % 2 == 0;
        make_immovable(first ? p.body1 : p.body2);
        const Pair before = p;
        projection::correct(p.body1, p.body2, p.contact, whole_depth);
        const std::string situation = case_text(before, i) + (first ? " (body 1 immovable)" : " (body 2 immovable)");
        const RigidBody& fixed_before = first ? before.body1 : before.body2;
        const RigidBody& fixed_after = first ? p.body1 : p.body2;
        if (!same_bits(fixed_before.position, fixed_after.position)) {
            expect_close(laws::immovable, fixed_before.position, fixed_after.position, 0.0, "m",
                         situation + ": the immovable body's position after");
            return;
        }
        if (!expect_split(before, p, before.contact.penetration, laws::immovable, situation)) return;
    }
    SUCCEED();
}

TEST_CASE("two immovable bodies overlapping stay exactly where they are", "[projection][step:2:immovable-bodies][points:1]") {
    Pair walls{make_immovable_sphere(0.5, {0, 0, 0}), make_immovable_sphere(0.5, {0.2, 0.3, 0}), {}};
    walls.contact.normal = normalized(Vector3{-0.2, -0.3, 0});
    walls.contact.add_point({0.1, 0.15, 0}, 0.64);
    projection::correct(walls.body1, walls.body2, walls.contact, PositionCorrection{0.8, 0.01});
    expect_close(laws::immovable, Vector3{0, 0, 0}, walls.body1.position, 0.0, "m", "two immovable balls 0.64 m deep: body 1 after");
    expect_close(laws::immovable, Vector3{0.2, 0.3, 0}, walls.body2.position, 0.0, "m", "two immovable balls 0.64 m deep: body 2 after");
    // And a movable body against an immovable plane must still be lifted, so that an empty correct() cannot pass.
    RigidBody ball = make_sphere(1e9, 0.5, {4, 0.3, -2});
    RigidBody ground = make_immovable_plane({0, 1, 0}, {0, 0, 0});
    // The ground as body 1, so the normal (from body 2 to body 1) points down, into the ground.
    Contact contact;
    contact.normal = {0, -1, 0};
    contact.add_point({4, 0, -2}, 0.2);
    projection::correct(ground, ball, contact, whole_depth);
    expect_close(laws::immovable, Vector3{4, 0.5, -2}, ball.position, rounding_tolerance(5.0), "m",
                 "a 1e9 kg ball 0.2 m into immovable ground given as body 1, normal (0, -1, 0): the ball after");
    expect_close(laws::immovable, Vector3{}, ground.position, 0.0, "m", "the same ground, body 1, after");
}

TEST_CASE("random pairs keep every velocity and spin bit for bit while being pushed apart",
          "[projection][step:3:positions-only][points:3]") {
    SeededRandom random(workbook::testing::run_seed() + 24);
    for (int i = 0; i < random_cases; ++i) {
        Pair p = random_pair(random);
        const Pair before = p;
        const double energy = kinetic_energy(p.body1) + kinetic_energy(p.body2);
        projection::correct(p.body1, p.body2, p.contact, whole_depth);
        const std::string situation = case_text(before, i);
        if (!same_bits(before.body1.velocity, p.body1.velocity) || !same_bits(before.body2.velocity, p.body2.velocity) ||
            !same_bits(before.body1.angular_velocity, p.body1.angular_velocity) ||
            !same_bits(before.body2.angular_velocity, p.body2.angular_velocity)) {
            expect_close(laws::positions_only, energy,
                         kinetic_energy(workbook::testing::judged(before.body1, p.body1)) + kinetic_energy(workbook::testing::judged(before.body2, p.body2)), 0.0, "J",
                         situation + " (kinetic energy after)");
            expect_close(laws::positions_only, before.body1.velocity - before.body2.velocity, p.body1.velocity - p.body2.velocity,
                         0.0, "m/s", situation + " (relative velocity after)");
            return;
        }
        const double gap_before = dot(before.body1.position - before.body2.position, before.contact.normal);
        const double gap_after = dot(p.body1.position - p.body2.position, before.contact.normal);
        const double wanted = gap_before + before.contact.penetration;
        if (!(gap_after >= wanted - position_tolerance(before))) {
            workbook::testing::expect_at_least(laws::still_pushed, wanted, gap_after, position_tolerance(before), "m",
                                               situation + " (separation along n after)");
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("zero depth, exactly touching: nothing moves; the slightest overlap does",
          "[projection][step:3:positions-only][points:1]") {
    Pair touching{make_sphere(1.0, 0.5, {1, 0, 0}, {-1, 0, 0}), make_sphere(3.0, 0.5, {0, 0, 0}, {2, 0, 0}), {}};
    touching.contact.normal = {1, 0, 0};
    touching.contact.add_point({0.5, 0, 0}, 0.0);
    const Pair before = touching;
    projection::correct(touching.body1, touching.body2, touching.contact, whole_depth);
    expect_close(laws::no_overlap, before.body1.position, touching.body1.position, 0.0, "m",
                 "two balls exactly touching (depth 0): body 1 after");
    expect_close(laws::no_overlap, before.body2.position, touching.body2.position, 0.0, "m",
                 "two balls exactly touching (depth 0): body 2 after");
    expect_close(laws::positions_only, Vector3{-1, 0, 0}, touching.body1.velocity, 0.0, "m/s",
                 "two balls exactly touching (depth 0): body 1's velocity after");

    Pair barely{make_sphere(1.0, 0.5, {1 - 1e-9, 0, 0}), make_sphere(3.0, 0.5, {0, 0, 0}), {}};
    barely.contact.normal = {1, 0, 0};
    barely.contact.add_point({0.5, 0, 0}, 1e-9);
    projection::correct(barely.body1, barely.body2, barely.contact, whole_depth);
    workbook::testing::expect_at_least(laws::still_pushed, 1.0, barely.body1.position.x - barely.body2.position.x,
                                       rounding_tolerance(1.0), "m", "two balls (1 kg, 3 kg) 1 nm deep: distance between centres after");
}

TEST_CASE("random depths and knobs: one pass removes fraction times the depth beyond the slop",
          "[projection][step:4:fraction-and-slop][points:3]") {
    SeededRandom random(workbook::testing::run_seed() + 25);
    for (int i = 0; i < random_cases; ++i) {
        const PositionCorrection knobs{random.uniform(0.01, 1.0), random.uniform(0.0, 0.05)};
        const double depth = random.uniform(0.0, 0.1);
        const double expected = knobs.fraction * std::max(depth - knobs.slop, 0.0);
        const double actual = projection::depth_to_remove(depth, knobs);
        const std::string situation = "depth_to_remove(" + format(depth) + " m) with fraction " + format(knobs.fraction) +
                                      " and slop " + format(knobs.slop) + " m, random case " + std::to_string(i);
        if (!(std::abs(actual - expected) <= rounding_tolerance(depth))) {
            expect_close(laws::knobs, expected, actual, rounding_tolerance(depth), "m", situation);
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("random pairs with knobs move by the inverse-mass split of fraction times the depth beyond the slop",
          "[projection][step:4:fraction-and-slop][points:3]") {
    SeededRandom random(workbook::testing::run_seed() + 26);
    for (int i = 0; i < random_cases; ++i) {
        const Pair before = random_pair(random);
        const PositionCorrection knobs{random.uniform(0.01, 1.0), before.contact.penetration * random.uniform(0.0, 1.5)};
        Pair p = before;
        projection::correct(p.body1, p.body2, p.contact, knobs);
        const double removed = knobs.fraction * std::max(before.contact.penetration - knobs.slop, 0.0);
        // Judged by how far the pair separates along n, so that a wrong split (step 1) is not
        // reported here a second time.
        const Vector3 n = before.contact.normal;
        const double opened = dot(p.body1.position - p.body2.position, n) - dot(before.body1.position - before.body2.position, n);
        const double tolerance = position_tolerance(before);
        if (!(std::abs(opened - removed) <= tolerance)) {
            expect_close(laws::knobs, removed, opened, tolerance, "m",
                         case_text(before, i) + ", fraction " + format(knobs.fraction) + ", slop " + format(knobs.slop) +
                             " m (how much the separation along n grew)");
            return;
        }
    }
    SUCCEED();
}

TEST_CASE("overshoot for 1 < beta < 2: the depth beyond the slop flips sign and shrinks by |1 - beta| per pass",
          "[projection][step:4:fraction-and-slop][points:1]") {
    // Measured afresh each pass as the overlap of two balls of radius 0.5 m; beta = 1.5 turns
    // 2 cm beyond a 1 mm slop into -1 cm (a gap), then the gap is left alone.
    const PositionCorrection knobs{1.5, 0.001};
    RigidBody ball1 = make_sphere(1.0, 0.5, {0.4895, 0, 0});
    RigidBody ball2 = make_sphere(1.0, 0.5, {-0.4895, 0, 0});
    Contact contact;
    contact.normal = {1, 0, 0};
    contact.add_point({0, 0, 0}, 0.021);
    projection::correct(ball1, ball2, contact, knobs);
    const double depth = 1.0 - (ball1.position.x - ball2.position.x);
    expect_close(laws::decay, 0.001 + 0.02 * (1.0 - 1.5), depth, rounding_tolerance(1.0, 64.0), "m",
                 "two 1 kg balls 2.1 cm deep, fraction 1.5, slop 1 mm: the depth after one pass (negative: a gap)");
}
