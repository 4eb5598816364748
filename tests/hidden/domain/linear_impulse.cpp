// Chapter 3 over its whole legal domain (chapters/linear-impulse/linear-impulse.hpp): a
// thousand sampled legal inputs per function and step, each judged against the reference's
// answer computed here from the checker's own copy of the input (see sampling.hpp).
#include <catch2/catch_test_macros.hpp>

#include "../reference.hpp"
#include "../../steps/linear_impulse_laws.hpp"
#include "linear-impulse.hpp"
#include "sampling.hpp"
#include "workbook/restitution.hpp"

using namespace workbook;
using namespace workbook::domain;
namespace laws = workbook::linear_impulse_laws;
namespace reference = workbook::reference_linear_impulse;

namespace {

/// A normal argument of any length: unit half the time, else 1e-3 to 1e3 times a unit one.
Vector3 any_length(SeededRandom& random, const Vector3& unit) {
    if (chance(random, 0.5)) return unit;
    const double l = decades(random, -3.0, 3.0);
    return unit * l;
}

/// resolve() on copies: unchanged fields, immovable bodies exact, then restitution and the
/// tangential velocity from the checker's own input, then each body against the reference.
Verdict judge_resolve(const Case& c, const Law& law) {
    RigidBody a1 = c.body1;
    RigidBody a2 = c.body2;
    linear_impulse::resolve(a1, a2, c.contact);
    RigidBody e1 = c.body1;
    RigidBody e2 = c.body2;
    reference::resolve(e1, e2, c.contact);
    if (Verdict v = unchanged(c, a1, a2, {.velocity = true}, "resolve"); v.failed()) return v;
    for (int side = 1; side <= 2; ++side) {
        const RigidBody& was = side == 1 ? c.body1 : c.body2;
        const RigidBody& is = side == 1 ? a1 : a2;
        if (was.is_immovable())
            if (Verdict v = compare(laws::immovable, "the immovable body " + std::to_string(side) + "'s velocity after resolve", "m/s",
                                    was.velocity, is.velocity, 0.0);
                v.failed())
                return v;
    }
    // A velocity change is at most (1 + e) |v12 . n| <= 2 |v12|: the answer's terms add up to 3 speeds.
    const double tolerance = rounding(3.0 * speeds(c));
    const Vector3 n = c.contact.normal;
    const double vn = dot(c.body1.velocity - c.body2.velocity, n);
    if (vn < 0.0 && pinned(c) < 2) {
        const double e = combined_restitution(c.body1, c.body2);
        if (Verdict v = compare(laws::restitution, "v12' . n after resolve", "m/s", -e * vn, dot(a1.velocity - a2.velocity, n),
                                2 * tolerance);
            v.failed())
            return v;
    }
    if (Verdict v = compare(law, "body 1's velocity after resolve", "m/s", e1.velocity, a1.velocity, tolerance); v.failed()) return v;
    return compare(law, "body 2's velocity after resolve", "m/s", e2.velocity, a2.velocity, tolerance);
}

}  // namespace

TEST_CASE("sampled pairs and normals of any length over the whole domain: v12 . n",
          "[linear-impulse][step:1:relative-normal-velocity][points:3]") {
    sample(
        301, {.normal = true},
        [](SeededRandom& random, Case& c) {
            const int count = immovable_count(random, 0.2, 0.05);
            const Approach how = any_motion(random);
            if (!draw_pair_moving(random, c, count, how)) return false;
            c.normal = any_length(random, c.contact.normal);
            return true;
        },
        [](const Case& c) {
            const double actual = linear_impulse::relative_normal_velocity(c.body1, c.body2, c.normal);
            const double expected = reference::relative_normal_velocity(c.body1, c.body2, c.normal);
            return compare(laws::normal_velocity, "relative_normal_velocity", "m/s", expected, actual,
                           rounding(speeds(c) * length(c.normal)));
        },
        [](const Case&) { return true; });
}

TEST_CASE("sampled pairs that do not approach get no impulse: moving apart, sliding, equal velocities, resting",
          "[linear-impulse][step:2:separating-contacts][points:3]") {
    sample(
        302, {.contact = true},
        [](SeededRandom& random, Case& c) {
            const int count = immovable_count(random, 0.3, 0.1);
            const Approach how = not_approaching(random);
            return draw_pair_moving(random, c, count, how);
        },
        [](const Case& c) { return judge_resolve(c, laws::separating); },
        [](const Case& c) { return normal_velocity(c) >= 0.0; });
    // And a pair that approaches must still get an impulse (on either body: how much each gets
    // is step 4's), so that a resolve() that does nothing cannot pass this step.
    RigidBody left = make_sphere(2.0, 0.5, {0, 0, 0}, {1, 0, 0});
    RigidBody right = make_sphere(1.0, 0.5, {1, 0, 0}, {-1, 0, 0});
    left.restitution = right.restitution = 0.5;  // whether resolve responds, not how much (a wrong J may vanish at e = 1)
    Contact contact;
    contact.normal = {-1, 0, 0};
    contact.add_point({0.5, 0, 0}, 0.0);
    linear_impulse::resolve(left, right, contact);
    const double change = length(left.velocity - Vector3{1, 0, 0}) + length(right.velocity - Vector3{-1, 0, 0});
    testing::expect_at_least(laws::respond, 1e-6, change, 0.0, "m/s",
                             "body 1: m = 2 kg, v = (1, 0, 0) m/s; body 2: m = 1 kg, v = (-1, 0, 0) m/s; e = 0.5; normal (-1, 0, 0) "
                             "(approaching: |v1' - v1| + |v2' - v2|, how much resolve changed the velocities)");
}

TEST_CASE("sampled pairs, normals of any length, e from 0 to 1: the impulse size", "[linear-impulse][step:3:impulse-size][points:3]") {
    sample(
        303, {.normal = true, .restitution = true},
        [](SeededRandom& random, Case& c) {
            const int count = immovable_count(random, 0.2, 0.05);
            const Approach how = chance(random, 0.8) ? (chance(random, 0.8) ? Approach::approaching : Approach::creeping) : any_motion(random);
            if (!draw_pair_moving(random, c, count, how)) return false;
            c.normal = any_length(random, c.contact.normal);
            c.restitution = draw_restitution(random);
            return true;
        },
        [](const Case& c) {
            const double actual = linear_impulse::impulse_magnitude(c.body1, c.body2, c.normal, c.restitution);
            const double expected = reference::impulse_magnitude(c.body1, c.body2, c.normal, c.restitution);
            const double w = c.body1.inverse_mass + c.body2.inverse_mass;
            const double n = length(c.normal);
            const double scale = w == 0.0 ? 0.0 : (1.0 + c.restitution) * speeds(c) * n / (n * n * w);
            return compare(laws::impulse, "impulse_magnitude", "kg m/s", expected, actual, rounding(scale));
        },
        [](const Case&) { return true; });
}

TEST_CASE("sampled approaching pairs, creeping ones and kinematic platforms among them: the response",
          "[linear-impulse][step:4:apply-impulse][points:3]") {
    sample(
        304, {.contact = true},
        [](SeededRandom& random, Case& c) {
            const int count = immovable_count(random, 0.3, 0.05);
            const Approach how = chance(random, 0.75) ? Approach::approaching : Approach::creeping;
            return draw_pair_moving(random, c, count, how);
        },
        [](const Case& c) { return judge_resolve(c, laws::momentum); },
        [](const Case& c) { return normal_velocity(c) < 0.0; });
}
