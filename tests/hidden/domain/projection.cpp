// Chapter 2 over its whole legal domain (chapters/projection/projection.hpp): a thousand
// sampled legal inputs per function and step, each judged against the reference's answer
// computed here from the checker's own copy of the input (see sampling.hpp).
#include <catch2/catch_test_macros.hpp>

#include "../reference.hpp"
#include "../../steps/projection_laws.hpp"
#include "projection.hpp"
#include "sampling.hpp"

using namespace workbook;
using namespace workbook::domain;
namespace laws = workbook::projection_laws;
namespace reference = workbook::reference_projection;

namespace {

/// A depth, m: 1 nm to 1 m, exactly 0 with probability `zero`.
double draw_depth(SeededRandom& random, double zero) {
    if (chance(random, zero)) return 0.0;
    return decades(random, -9.0, 0.0);
}

/// Knobs over their domain: fraction 1, in (0, 1), above 1 or 0; slop 0, or about the depth
/// (so that a contact may lie within it), or exactly the depth.
PositionCorrection draw_knobs(SeededRandom& random, double depth) {
    PositionCorrection knobs;
    const double pick = random.uniform(0.0, 1.0);
    knobs.fraction = pick < 0.3 ? 1.0 : pick < 0.8 ? random.uniform(0.0, 1.0) : pick < 0.95 ? random.uniform(1.0, 2.0) : 0.0;
    const double slop = random.uniform(0.0, 1.0);
    const double depth_scale = depth > 0.0 ? depth : decades(random, -9.0, 0.0);
    knobs.slop = slop < 0.35 ? 0.0 : slop < 0.45 ? depth : depth_scale * random.uniform(0.0, 2.0);
    return knobs;
}

/// A contact of 1 to 4 points around the bodies' meeting place, some points exactly 0 deep,
/// the contact's depth the deepest point's (or, as for a box pair, a little more).
void draw_contact(SeededRandom& random, Case& c) {
    c.contact.normal = unit_normal(random);
    c.body1.position = position(random);
    const double gap = decades(random, -2.0, 1.0);
    c.body2.position = c.body1.position - c.contact.normal * gap;
    if (chance(random, 0.4)) {  // a plane's anchor or a box's centre far to the side
        const Vector3 side = cross(c.contact.normal, random.direction());
        const double away = decades(random, -2.0, 2.0);
        c.body2.position = c.body2.position + side * away;
    }
    const int count = 1 + int(random.uniform(0.0, 4.0));
    const double zero = chance(random, 0.1) ? 1.0 : 0.15;
    c.contact.point_count = 0;
    c.contact.penetration = 0.0;
    for (int i = 0; i < count; ++i) {
        const Vector3 side = cross(c.contact.normal, random.direction());
        const double reach = decades(random, -3.0, 0.0);
        const double depth = draw_depth(random, zero);
        c.contact.add_point(c.body1.position - c.contact.normal * (gap / 2) + side * reach, depth);
    }
    const bool deeper = chance(random, 0.2);
    if (deeper) c.contact.penetration *= random.uniform(1.0, 2.0);
}

/// Two bodies with `pinned` immovable ones, moving and spinning (projection must not touch that).
bool draw_pair(SeededRandom& random, Case& c, int pinned) {
    double w1 = 1.0;
    double w2 = 1.0;
    pair_masses(random, w1, w2);
    c.body1 = movable(random, w1);
    c.body2 = movable(random, w2);
    const bool first = chance(random, 0.5);
    if (pinned >= 1) pin(random, first ? c.body1 : c.body2, 0.5, true);
    if (pinned == 2) pin(random, first ? c.body2 : c.body1, 0.5, true);
    for (RigidBody* b : {&c.body1, &c.body2}) {
        if (b->is_immovable()) continue;
        b->velocity = velocity(random);
        b->angular_velocity = velocity(random);
    }
    draw_contact(random, c);
    return true;
}

bool plain_knobs(const Case& c) { return c.knobs.fraction == 1.0 && c.knobs.slop == 0.0; }

/// correct() on copies, judged against the reference's positions.
Verdict judge_positions(const Case& c, const Law& law) {
    RigidBody a1 = c.body1;
    RigidBody a2 = c.body2;
    projection::correct(a1, a2, c.contact, c.knobs);
    RigidBody e1 = c.body1;
    RigidBody e2 = c.body2;
    reference::correct(e1, e2, c.contact, c.knobs);
    const double moved = c.knobs.fraction * c.contact.penetration;
    for (int side = 1; side <= 2; ++side) {
        const RigidBody& was = side == 1 ? c.body1 : c.body2;
        const RigidBody& is = side == 1 ? a1 : a2;
        const RigidBody& expected = side == 1 ? e1 : e2;
        const std::string which = "body " + std::to_string(side) + "'s position after correct";
        if (was.is_immovable()) {
            if (Verdict v = compare(laws::immovable, "the immovable " + which, "m", was.position, is.position, 0.0); v.failed()) return v;
        } else if (Verdict v = compare(law, which, "m", expected.position, is.position, rounding(length(was.position) + moved));
                   v.failed()) {
            return v;
        }
    }
    return {};
}

/// Step 4's own question, how deep one pass goes: the change of (x1 - x2) . n, which does
/// not depend on how the push is split (step 1's question).
Verdict judge_depth_removed(const Case& c) {
    RigidBody a1 = c.body1;
    RigidBody a2 = c.body2;
    projection::correct(a1, a2, c.contact, c.knobs);
    RigidBody e1 = c.body1;
    RigidBody e2 = c.body2;
    reference::correct(e1, e2, c.contact, c.knobs);
    const Vector3 n = c.contact.normal;
    const Vector3 before = c.body1.position - c.body2.position;
    const double actual = dot((a1.position - a2.position) - before, n);
    const double expected = dot((e1.position - e2.position) - before, n);
    const double moved = c.knobs.fraction * c.contact.penetration;
    const double terms = length(c.body1.position) + length(c.body2.position) + moved;
    return compare(laws::knobs, "the depth removed, (x1' - x2') . n - (x1 - x2) . n", "m", expected, actual, rounding(terms, 64.0));
}

}  // namespace

TEST_CASE("sampled depths and knobs over the whole domain: the depth to remove", "[projection][step:4:fraction-and-slop][points:2]") {
    sample(
        201, {.body2 = false, .knobs = true, .depth = true},
        [](SeededRandom& random, Case& c) {
            c.depth = draw_depth(random, 0.1);
            c.knobs = draw_knobs(random, c.depth);
            return true;
        },
        [](const Case& c) {
            const double actual = projection::depth_to_remove(c.depth, c.knobs);
            const double expected = reference::depth_to_remove(c.depth, c.knobs);
            return compare(laws::knobs, "depth_to_remove", "m", expected, actual,
                           rounding(c.knobs.fraction * (c.depth + c.knobs.slop)));
        },
        [](const Case&) { return true; });
}

TEST_CASE("sampled overlapping pairs of two movable bodies: the split by inverse mass", "[projection][step:1:split-by-inverse-mass][points:3]") {
    sample(
        202, {.contact = true, .knobs = true},
        [](SeededRandom& random, Case& c) {
            draw_pair(random, c, 0);
            return c.contact.penetration > 0.0;
        },
        [](const Case& c) { return judge_positions(c, laws::split); },
        [](const Case& c) { return pinned(c) == 0 && plain_knobs(c) && c.contact.penetration > 0.0; });
}

TEST_CASE("sampled pairs with one or two immovable bodies, at rest or kinematic", "[projection][step:2:immovable-bodies][points:3]") {
    sample(
        203, {.contact = true, .knobs = true},
        [](SeededRandom& random, Case& c) {
            const int count = chance(random, 0.8) ? 1 : 2;
            return draw_pair(random, c, count);
        },
        [](const Case& c) { return judge_positions(c, laws::immovable); },
        [](const Case& c) { return pinned(c) >= 1 && plain_knobs(c); });
}

TEST_CASE("sampled pairs and knobs over the whole domain: only positions change", "[projection][step:3:positions-only][points:3]") {
    sample(
        204, {.contact = true, .knobs = true},
        [](SeededRandom& random, Case& c) {
            const int count = immovable_count(random, 0.25, 0.05);
            draw_pair(random, c, count);
            c.knobs = draw_knobs(random, c.contact.penetration);
            return true;
        },
        [](const Case& c) {
            RigidBody a1 = c.body1;
            RigidBody a2 = c.body2;
            projection::correct(a1, a2, c.contact, c.knobs);
            return unchanged(c, a1, a2, {.position = true}, "correct");
        },
        [](const Case&) { return true; });
    // And an overlapping pair must still be pushed apart, so that a correct() that does nothing
    // cannot pass this step.
    RigidBody top = make_sphere(1.0, 0.5, {0, 0.45, 0});
    RigidBody bottom = make_sphere(3.0, 0.5, {0, -0.45, 0});
    Contact contact;
    contact.normal = {0, 1, 0};
    contact.add_point({0, 0, 0}, 0.1);
    projection::correct(top, bottom, contact, PositionCorrection{});
    testing::expect_at_least(laws::still_pushed, 1.0, top.position.y - bottom.position.y, rounding(1.0), "m",
                             "body 1: m = 1 kg at (0, 0.45, 0) m; body 2: m = 3 kg at (0, -0.45, 0) m; normal (0, 1, 0), depth 0.1 m "
                             "(the distance between the centres along n after)");
}

TEST_CASE("sampled pairs of two movable bodies with any fraction and slop, depths of 0 among them",
          "[projection][step:4:fraction-and-slop][points:3]") {
    sample(
        205, {.contact = true, .knobs = true},
        [](SeededRandom& random, Case& c) {
            draw_pair(random, c, 0);
            c.knobs = draw_knobs(random, c.contact.penetration);
            return true;
        },
        [](const Case& c) { return judge_depth_removed(c); },
        [](const Case& c) { return pinned(c) == 0; });
}
