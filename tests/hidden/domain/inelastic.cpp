// Chapter 1 over its whole legal domain (chapters/inelastic/inelastic.hpp): a thousand sampled
// legal inputs per function and step, each judged against the reference's answer computed
// here from the checker's own copy of the input (see sampling.hpp).
#include <catch2/catch_test_macros.hpp>

#include <limits>

#include "../reference.hpp"
#include "../../steps/inelastic_laws.hpp"
#include "inelastic.hpp"
#include "sampling.hpp"

using namespace workbook;
using namespace workbook::domain;
namespace laws = workbook::inelastic_laws;
namespace reference = workbook::reference_inelastic;

namespace {

/// resolve() on copies, judged against the reference's velocities and the unchanged fields.
Verdict judge_resolve(const Case& c, const Law& law) {
    RigidBody a1 = c.body1;
    RigidBody a2 = c.body2;
    inelastic::resolve(a1, a2, c.contact);
    RigidBody e1 = c.body1;
    RigidBody e2 = c.body2;
    reference::resolve(e1, e2, c.contact);
    if (Verdict v = unchanged(c, a1, a2, {.velocity = true}, "resolve"); v.failed()) return v;
    const double tolerance = rounding(speeds(c));
    for (int side = 1; side <= 2; ++side) {
        const RigidBody& was = side == 1 ? c.body1 : c.body2;
        const RigidBody& is = side == 1 ? a1 : a2;
        if (was.is_immovable())
            if (Verdict v = compare(laws::immovable, "the immovable body " + std::to_string(side) + "'s velocity after resolve", "m/s",
                                    was.velocity, is.velocity, 0.0);
                v.failed())
                return v;
    }
    if (&law == &laws::stick && !within(Vector3{}, a1.velocity - a2.velocity, 2 * tolerance))
        return compare(laws::stick, "v1' - v2' after resolve", "m/s", Vector3{}, a1.velocity - a2.velocity, 2 * tolerance);
    if (Verdict v = compare(law, "body 1's velocity after resolve", "m/s", e1.velocity, a1.velocity, tolerance); v.failed()) return v;
    return compare(law, "body 2's velocity after resolve", "m/s", e2.velocity, a2.velocity, tolerance);
}

}  // namespace

TEST_CASE("sampled pairs over the whole domain: the common velocity", "[inelastic][step:1:common-velocity][points:3]") {
    sample(
        101, {},
        [](SeededRandom& random, Case& c) {
            const int count = immovable_count(random, 0.2, 0.05);
            const Approach how = any_motion(random);
            return draw_pair_moving(random, c, count, how);
        },
        [](const Case& c) -> Verdict {
            const Vector3 actual = inelastic::common_velocity(c.body1, c.body2);
            if (pinned(c) == 2)  // undefined, but it must not be NaN
                return compare(laws::immovable, "common_velocity of two immovable bodies: any finite value", "m/s", Vector3{},
                               actual, std::numeric_limits<double>::infinity());
            const Vector3 expected = reference::common_velocity(c.body1, c.body2);
            return compare(laws::momentum, "common_velocity", "m/s", expected, actual, rounding(speeds(c)));
        },
        [](const Case&) { return true; });
}

TEST_CASE("sampled approaching pairs of two movable bodies stick together", "[inelastic][step:2:stick-together][points:3]") {
    sample(
        102, {.contact = true},
        [](SeededRandom& random, Case& c) {
            const Approach how = chance(random, 0.8) ? Approach::approaching : Approach::creeping;
            return draw_pair_moving(random, c, 0, how);
        },
        [](const Case& c) { return judge_resolve(c, laws::stick); },
        [](const Case& c) { return pinned(c) == 0 && normal_velocity(c) < 0.0; });
}

TEST_CASE("sampled pairs with one or two immovable bodies, at rest or kinematic",
          "[inelastic][step:3:immovable-bodies][points:3]") {
    sample(
        103, {.contact = true},
        [](SeededRandom& random, Case& c) {
            const int count = chance(random, 0.85) ? 1 : 2;
            const Approach how = count == 2 ? any_motion(random) : chance(random, 0.8) ? Approach::approaching : Approach::creeping;
            return draw_pair_moving(random, c, count, how);
        },
        [](const Case& c) { return judge_resolve(c, laws::immovable); },
        [](const Case& c) { return pinned(c) == 2 || (pinned(c) == 1 && normal_velocity(c) < 0.0); });
}

TEST_CASE("sampled pairs that do not approach: moving apart, sliding, equal velocities, resting",
          "[inelastic][step:4:separating-pairs][points:3]") {
    sample(
        104, {.contact = true},
        [](SeededRandom& random, Case& c) {
            const int count = chance(random, 0.3) ? 1 : 0;
            const Approach how = not_approaching(random);
            return draw_pair_moving(random, c, count, how);
        },
        [](const Case& c) { return judge_resolve(c, laws::separating); },
        [](const Case& c) { return pinned(c) < 2 && normal_velocity(c) >= 0.0; });
    // And a pair that approaches must still be resolved, so that a resolve() that does nothing
    // cannot pass this step.
    RigidBody left = make_sphere(2.0, 0.5, {0, 0, 0}, {1, 0, 0});
    RigidBody right = make_sphere(1.0, 0.5, {1, 0, 0}, {-1, 0, 0});
    Contact contact;
    contact.normal = {-1, 0, 0};
    contact.add_point({0.5, 0, 0}, 0.0);
    inelastic::resolve(left, right, contact);
    testing::expect_at_least(laws::approach, 0.0, dot(left.velocity - right.velocity, contact.normal), rounding(2.0), "m/s",
                             "body 1: m = 2 kg, v = (1, 0, 0) m/s; body 2: m = 1 kg, v = (-1, 0, 0) m/s; normal (-1, 0, 0) "
                             "(approaching: normal relative velocity after)");
}

TEST_CASE("sampled pairs over the whole domain: the energy lost", "[inelastic][step:5:energy-lost][points:3]") {
    sample(
        105, {},
        [](SeededRandom& random, Case& c) {
            const int count = immovable_count(random, 0.2, 0.05);
            const Approach how = any_motion(random);
            return draw_pair_moving(random, c, count, how);
        },
        [](const Case& c) -> Verdict {
            const double actual = inelastic::energy_lost(c.body1, c.body2);
            const double expected = reference::energy_lost(c.body1, c.body2);
            const double w = c.body1.inverse_mass + c.body2.inverse_mass;
            const double mu = w == 0.0 ? 0.0 : 1.0 / w;
            const double s = speeds(c);
            return compare(laws::energy, "energy_lost", "J", expected, actual, rounding(0.5 * mu * s * s));
        },
        [](const Case&) { return true; });
}
