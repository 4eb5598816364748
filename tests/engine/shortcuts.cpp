// Each of the world's shortcuts (World::Shortcuts) changes nothing but speed: a crowded scene
// with spinning and still bodies, pinned balls and planes steps to the same state hash and
// the same probes with every shortcut on as with any one of them off.
#include <catch2/catch_test_macros.hpp>
#include <catch2/generators/catch_generators.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "seeded_random.hpp"
#include "state_hash.hpp"
#include "workbook/world.hpp"

namespace {

using namespace workbook;
using workbook::testing::SeededRandom;
using workbook::testing::StateHash;

void elastic(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const double approach = dot(body1.velocity - body2.velocity, contact.normal);
    const double inverse_masses = body1.inverse_mass + body2.inverse_mass;
    if (approach >= 0.0 || inverse_masses == 0.0) return;
    const double impulse = -1.8 * approach / inverse_masses;
    body1.velocity += contact.normal * (impulse * body1.inverse_mass);
    body2.velocity -= contact.normal * (impulse * body2.inverse_mass);
}

constexpr ResponseModel bouncing{"test", elastic, nullptr};

std::vector<RigidBody> scene(std::uint64_t seed) {
    SeededRandom random(seed);
    std::vector<RigidBody> bodies{make_immovable_plane({0, 1, 0}, {0, -2, 0}), make_immovable_plane({1, 0, 0}, {-2, 0, 0})};
    for (int i = 0; i < 300; ++i) {
        const Vector3 at{random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-0.5, 0.5)};
        if (i % 29 == 3) {
            bodies.push_back(make_immovable_sphere(0.2, at));
            continue;
        }
        const double mass = random.uniform(0.5, 2);  // one draw a statement: the same balls on every compiler
        const double radius = random.uniform(0.03, 0.12);
        RigidBody ball = make_sphere(mass, radius, at, {random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2)});
        if (i % 3 == 0) ball.angular_velocity = {random.uniform(-9, 9), random.uniform(-9, 9), random.uniform(-9, 9)};
        if (i % 7 == 0) ball.velocity.x = -0.0;  // a negative zero that a zero gravity kick would turn positive
        bodies.push_back(ball);
    }
    bodies.push_back(make_immovable_plane({0, -1, 0}, {0, 2, 0}));
    bodies.push_back(make_immovable_plane({-1, 0, 0}, {2, 0, 0}));
    return bodies;
}

std::vector<std::uint64_t> path_of(const std::vector<RigidBody>& bodies, const Vector3& gravity, const Shortcuts& shortcuts) {
    World world(bodies, WorldSettings{1.0 / 120.0, gravity}, bouncing);
    world.set_shortcuts(shortcuts);
    std::vector<std::uint64_t> hashes;
    for (int step = 0; step < 150; ++step) {
        world.step();
        const Probes p = world.probes();
        StateHash h;
        h.add(testing::state_hash(world));
        h.add(p.kinetic_linear);
        h.add(p.kinetic_rotational);
        h.add(p.potential);
        h.add(p.linear_momentum);
        h.add(p.angular_momentum);
        if (shortcuts.response_energy_probe) h.add(p.response_energy_change);
        hashes.push_back(h.value());
    }
    return hashes;
}

}  // namespace

TEST_CASE("each shortcut off gives the path of all shortcuts on, with and without gravity", "[world][shortcuts]") {
    const std::vector<RigidBody> bodies = scene(workbook::testing::run_seed());
    for (const Vector3 gravity : {Vector3{}, Vector3{0, -9.81, 0}}) {
        CAPTURE(gravity.y);
        const auto reference = path_of(bodies, gravity, Shortcuts{});
        struct Variant {
            std::string name;
            Shortcuts shortcuts;
        };
        const std::vector<Variant> variants{
            {"no broad phase", {.broad_phase = false}},
            {"immovable pairs tested", {.skip_immovable_pairs = false}},
            {"rotation work for still bodies", {.skip_still_rotation = false}},
            {"gravity kick when zero", {.skip_zero_gravity = false}},
            {"everything off", {.broad_phase = false, .skip_immovable_pairs = false, .skip_still_rotation = false,
                                .skip_zero_gravity = false}},
        };
        for (const Variant& variant : variants) {
            CAPTURE(variant.name);
            CHECK(path_of(bodies, gravity, variant.shortcuts) == reference);
        }
    }
}

TEST_CASE("without the energy probe the bodies take the same path and the probe reads 0", "[world][shortcuts]") {
    const std::vector<RigidBody> bodies = scene(workbook::testing::run_seed() + 7);
    // Under either timing: event timing measures the impacts it answers within the step itself.
    const ContactTiming timing = GENERATE(ContactTiming::discrete, ContactTiming::event);
    CAPTURE(timing == ContactTiming::event);
    WorldSettings settings{1.0 / 120.0, {}};
    settings.contact_timing = timing;
    World probed(bodies, settings, bouncing);
    World unprobed(bodies, settings, bouncing);
    unprobed.set_shortcuts({.response_energy_probe = false});
    double changed = 0.0;
    for (int step = 0; step < 100; ++step) {
        probed.step();
        unprobed.step();
        changed += std::abs(probed.probes().response_energy_change);
        REQUIRE(testing::state_hash(probed) == testing::state_hash(unprobed));
        REQUIRE(unprobed.probes().response_energy_change == 0.0);
    }
    CHECK(changed > 0.0);  // the responder (e = 0.8) did take energy, so the probe had work to skip
}

TEST_CASE("the plan names the stages a scene uses and those it skips", "[world][shortcuts]") {
    World gas(scene(1), WorldSettings{1.0 / 120.0, {}}, bouncing);
    const auto plan = gas.plan();
    auto find = [&plan](std::string_view name) {
        for (const StageUse& use : plan)
            if (use.stage == name) return use;
        FAIL("no stage " << name);
        return StageUse{};
    };
    CHECK_FALSE(find("integrate: gravity").used);
    CHECK(find("integrate: rotation").used);
    CHECK(find("detect: broad phase (grid)").used);
    CHECK_FALSE(find("detect: pairs of immovable bodies").used);
    CHECK(find("respond").used);
    CHECK_FALSE(find("correct").used);
    const StageUse swept = find("detect: swept test");
    CHECK(swept.used);
    CHECK(swept.why.find("the grid finds") != std::string::npos);
    WorldSettings unswept{1.0 / 120.0, {}};
    unswept.swept_spheres = false;
    const World off(scene(1), unswept, bouncing);
    CHECK_FALSE(off.plan()[5].used);
    CHECK(off.plan()[5].why == "off in this scene (swept_spheres)");
    const World two({make_sphere(1, 0.5, {}), make_sphere(1, 0.5, {2, 0, 0})}, WorldSettings{0.01, {0, -9.81, 0}}, bouncing);
    CHECK_FALSE(two.plan()[3].used);  // two bodies: every pair, no grid
    CHECK(two.plan()[1].used);        // gravity
}
