// The grid broad phase finds exactly the contacts testing every pair finds, in the same
// order, so that a world steps bit-identically with it and without it.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "elastic_impulse.hpp"
#include "seeded_random.hpp"
#include "state_hash.hpp"
#include "workbook/broad_phase.hpp"
#include "workbook/tolerances.hpp"
#include "workbook/world.hpp"

namespace {

using namespace workbook;
using workbook::testing::SeededRandom;
using workbook::testing::state_hash;

/// The elastic impulse of the engine's tests (each contact sees the velocities the previous
/// ones left), plus a projection, so any reordering of contacts shows.
void push_apart(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double inverse_masses = body1.inverse_mass + body2.inverse_mass;
    if (inverse_masses == 0.0) return;
    const Vector3 push = contact.normal * (knobs.fraction * contact.penetration / inverse_masses);
    body1.position += push * body1.inverse_mass;
    body2.position -= push * body2.inverse_mass;
}

constexpr ResponseModel bouncing{"test", workbook::testing::elastic_impulse, push_apart};

/// A crowded 3D box of balls of mixed sizes and masses, a few pinned balls, walls and a floor
/// (planes placed among the balls in index order, not only at the end), under gravity.
std::vector<RigidBody> crowd(std::uint64_t seed, int balls) {
    SeededRandom random(seed);
    std::vector<RigidBody> bodies;
    const double half = 2.0;
    for (int i = 0; i < balls; ++i) {
        if (i == balls / 3) bodies.push_back(make_immovable_plane({0, 1, 0}, {0, -half, 0}));
        if (i == balls / 2) bodies.push_back(make_immovable_plane({1, 0, 0}, {-half, 0, 0}));
        const Vector3 at{random.uniform(-half, half), random.uniform(-half, half), random.uniform(-half, half)};
        if (i % 17 == 5) {
            bodies.push_back(make_immovable_sphere(random.uniform(0.05, 0.3), at));
            continue;
        }
        const Vector3 v{random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3)};
        const double mass = random.uniform(0.5, 4.0);  // one draw a statement: the same crowd on every compiler
        bodies.push_back(make_sphere(mass, random.uniform(0.02, 0.2), at, v));
    }
    bodies.push_back(make_immovable_plane({-1, 0, 0}, {half, 0, 0}));
    bodies.push_back(make_immovable_plane({0, 0, 1}, {0, 0, -half}));
    bodies.push_back(make_immovable_plane({0, 0, -1}, {0, 0, half}));
    bodies.push_back(make_immovable_plane({0, -1, 0}, {0, half, 0}));
    return bodies;
}

/// The same bodies gathered as a full set and as a compact one (event timing's), each sphere
/// widened by its `inflates` entry, with fine cells, and each set's grid and pairs.
struct FullAndCompact {
    ProxySet full;
    ProxySet compact;
    BroadPhase full_grid;
    BroadPhase compact_grid;
    std::vector<BodyPair> full_pairs;
    std::vector<BodyPair> compact_pairs;

    FullAndCompact(const std::vector<RigidBody>& bodies, const std::vector<double>& inflates) {
        full.clear(bodies.size());
        compact.clear(bodies.size(), true);
        for (std::uint32_t i = 0; i < bodies.size(); ++i) {
            full.add(bodies[i], i, 0.0, {}, inflates[i]);
            compact.add(bodies[i], i, 0.0, {}, inflates[i]);
        }
        full.fine_cells = compact.fine_cells = true;
        full_grid.find_pairs(full, full_pairs);
        compact_grid.find_pairs(compact, compact_pairs);
    }

    /// The bodies each grid finds near `centre` (BroadPhase::bodies_near()), each list sorted.
    void bodies_near(const Vector3& centre, double radius, const Vector3& box, std::vector<std::uint32_t>& near_compact,
                     std::vector<std::uint32_t>& near_full) const {
        near_compact.clear();
        near_full.clear();
        compact_grid.bodies_near(compact, centre, radius, near_compact, box);
        full_grid.bodies_near(full, centre, radius, near_full, box);
        std::sort(near_compact.begin(), near_compact.end());
        std::sort(near_full.begin(), near_full.end());
    }

    /// Whether both grids found the same pairs, in the same order.
    [[nodiscard]] bool same_pairs() const {
        const auto same = [](BodyPair a, BodyPair b) { return a.first == b.first && a.second == b.second; };
        return std::equal(full_pairs.begin(), full_pairs.end(), compact_pairs.begin(), compact_pairs.end(), same);
    }
};

}  // namespace

TEST_CASE("the grid finds the contacts of testing every pair, in the same order, step after step", "[world][broad_phase]") {
    const std::uint64_t seed = workbook::testing::run_seed();
    CAPTURE(seed);
    const std::vector<RigidBody> bodies = crowd(seed, 600);
    const WorldSettings settings{1.0 / 120.0, {0, -9.81, 0}};
    World grid(bodies, settings, bouncing);
    World every_pair(bodies, settings, bouncing);
    every_pair.set_shortcuts({.broad_phase = false});

    std::size_t contacts = 0;
    for (int step = 0; step < 200; ++step) {
        grid.step();
        every_pair.step();
        contacts += grid.contacts().size();
        if (state_hash(grid) != state_hash(every_pair)) {
            CAPTURE(step, grid.contacts().size(), every_pair.contacts().size());
            FAIL("the grid's world left the all-pairs world's path");
        }
    }
    CHECK(grid.used_broad_phase());
    CHECK_FALSE(every_pair.used_broad_phase());
    // Worth something only if there were many contacts to get wrong.
    CHECK(contacts > 2000);
}

TEST_CASE("the grid's pairs are sorted, unique, and a superset of the overlapping ones", "[broad_phase]") {
    const std::vector<RigidBody> bodies = crowd(workbook::testing::run_seed() + 1, 400);
    BroadPhase broad;
    std::vector<BodyPair> pairs;
    broad.find_pairs(bodies, pairs);
    REQUIRE_FALSE(pairs.empty());
    CHECK(std::is_sorted(pairs.begin(), pairs.end(), [](BodyPair a, BodyPair b) { return a.first != b.first ? a.first < b.first : a.second < b.second; }));
    CHECK(std::adjacent_find(pairs.begin(), pairs.end(), [](BodyPair a, BodyPair b) { return a.first == b.first && a.second == b.second; }) == pairs.end());
    std::size_t overlapping = 0;
    for (std::uint32_t i = 0; i < bodies.size(); ++i) {
        for (std::uint32_t j = i + 1; j < bodies.size(); ++j) {
            if (bodies[i].shape.kind == ShapeKind::plane || bodies[j].shape.kind == ShapeKind::plane) continue;
            if (bodies[i].is_immovable() && bodies[j].is_immovable()) continue;
            const double reach = bodies[i].shape.radius + bodies[j].shape.radius;
            if (length_squared(bodies[i].position - bodies[j].position) >= reach * reach) continue;
            ++overlapping;
            const bool found = std::find_if(pairs.begin(), pairs.end(), [&](BodyPair p) { return p.first == i && p.second == j; }) != pairs.end();
            if (!found) {
                CAPTURE(i, j);
                FAIL("an overlapping pair is missing");
            }
        }
    }
    CHECK(overlapping > 10);
}

TEST_CASE("bodies_near() finds with the grid exactly the bodies and planes a test of every one finds",
          "[broad_phase][event]") {
    // Event timing searches again, from the grid's cells, around a body that outran its reach;
    // the search visits only the cells its interval covers, so a body just inside the radius
    // whose centre lies in a cell at the interval's edge must still be found.
    const std::vector<RigidBody> bodies = crowd(workbook::testing::run_seed() + 7, 1500);
    SeededRandom random(workbook::testing::run_seed() + 8);
    ProxySet set;
    set.clear(bodies.size());
    for (std::uint32_t i = 0; i < bodies.size(); ++i) set.add(bodies[i], i, 0.0, {}, random.uniform(0.0, 0.1));
    BroadPhase broad;
    std::vector<BodyPair> pairs;
    broad.find_pairs(set, pairs, false, false);
    REQUIRE(broad.has_grid());
    constexpr double slack = 1.0 + tolerances::conservative_slack;
    std::vector<std::uint32_t> near;
    std::vector<std::uint32_t> expected;
    std::size_t found = 0;
    for (int query = 0; query < 300; ++query) {
        // Centres inside the crowd and up to a metre outside it; radii from none to a third of it.
        const Vector3 centre{random.uniform(-3.0, 3.0), random.uniform(-3.0, 3.0), random.uniform(-3.0, 3.0)};
        const double radius = random.uniform(0.0, 1.3);
        near.clear();
        broad.bodies_near(set, centre, radius, near);
        expected.clear();
        for (const GridProxy& q : set.proxies) {
            if (q.plane) continue;
            const double within = (radius + q.radius) * slack;
            const double dx = q.x - centre.x, dy = q.y - centre.y, dz = q.z - centre.z;
            if (dx * dx + dy * dy + dz * dz <= within * within) expected.push_back(q.index);
        }
        for (const PlaneProxy& plane : set.planes)
            if (dot(centre - plane.point, plane.normal) <= radius * slack) expected.push_back(plane.index);
        std::sort(near.begin(), near.end());
        std::sort(expected.begin(), expected.end());
        CAPTURE(query, centre.x, centre.y, centre.z, radius);
        REQUIRE(near == expected);
        found += near.size();
    }
    CHECK(found > 3000);  // the queries did find bodies, not only empty answers
}

TEST_CASE("a compact set finds the pairs and the bodies near that a full one finds; a box leaves out exactly the "
          "bodies outside it",
          "[broad_phase][event]") {
    // Event timing gathers its widened spheres as compact copies (ProxySet::cells), and its
    // search again passes a box outside which it keeps no body (BroadPhase::bodies_near()).
    const std::vector<RigidBody> bodies = crowd(workbook::testing::run_seed() + 21, 1500);
    SeededRandom random(workbook::testing::run_seed() + 22);
    std::vector<double> inflates;
    for (std::size_t i = 0; i < bodies.size(); ++i) inflates.push_back(random.uniform(0.0, 0.1));
    const FullAndCompact sets(bodies, inflates);
    const ProxySet& full = sets.full;
    const ProxySet& compact = sets.compact;
    REQUIRE(compact.proxies.empty());
    REQUIRE(compact.size() == full.size());
    REQUIRE(sets.compact_grid.has_grid());
    REQUIRE(sets.full_pairs.size() > bodies.size() / 4);
    REQUIRE(sets.same_pairs());
    constexpr double slack = 1.0 + tolerances::conservative_slack;
    std::vector<std::uint32_t> near;
    std::vector<std::uint32_t> near_full;
    std::vector<std::uint32_t> expected;
    std::size_t found = 0;
    for (int query = 0; query < 300; ++query) {
        const Vector3 centre{random.uniform(-3.0, 3.0), random.uniform(-3.0, 3.0), random.uniform(-3.0, 3.0)};
        const double radius = random.uniform(0.0, 1.3);
        // Half the queries with a box, each side from a tenth of the radius to past it.
        const bool boxed = query % 2 == 0;
        const Vector3 box = boxed ? Vector3{random.uniform(0.1, 1.5) * radius, random.uniform(0.1, 1.5) * radius,
                                            random.uniform(0.1, 1.5) * radius}
                                  : BroadPhase::unbounded;
        sets.bodies_near(centre, radius, box, near, near_full);
        expected.clear();
        for (const CellProxy& q : compact.cells) {
            if (q.plane) continue;
            const double within = (radius + q.radius) * slack;
            const double dx = q.x - centre.x, dy = q.y - centre.y, dz = q.z - centre.z;
            const bool inside = std::abs(dx) <= box.x * slack * slack && std::abs(dy) <= box.y * slack * slack &&
                                std::abs(dz) <= box.z * slack * slack;
            if (dx * dx + dy * dy + dz * dz <= within * within && inside) expected.push_back(q.index);
        }
        for (const PlaneProxy& plane : compact.planes)
            if (dot(centre - plane.point, plane.normal) <= radius * slack) expected.push_back(plane.index);
        std::sort(expected.begin(), expected.end());
        CAPTURE(query, boxed, centre.x, centre.y, centre.z, radius);
        REQUIRE(near == expected);
        REQUIRE(near_full == expected);
        found += near.size();
    }
    CHECK(found > 1000);  // the queries did find bodies, not only empty answers
}

TEST_CASE("a compact set's grid laid in the order its bodies come finds the pairs and the bodies near of the world's "
          "order",
          "[broad_phase][event]") {
    // The grid of a compact set lays its rows along the axis along which consecutive bodies
    // jump most and its layers along the one with the fewest jumps (BroadPhase::lay_axes()).
    // Balls on a jittered lattice, numbered along each of the six orders of the axes in turn,
    // must give the pairs and the bodies near of a full set, whose grid keeps the world's axes.
    constexpr int side = 12;
    constexpr double spacing = 0.22;
    const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto& order : orders) {
        CAPTURE(order[0], order[1], order[2]);
        SeededRandom random(workbook::testing::run_seed() + 31);
        std::vector<RigidBody> bodies;
        std::vector<double> inflates;
        for (int n = 0; n < side * side * side; ++n) {
            // Along order[0] fastest: consecutive balls jump a spacing along it, and along the
            // others only at the end of a row or a layer (the jitter stays within the radii).
            const int step[3] = {n % side, (n / side) % side, n / (side * side)};
            double at[3];
            for (int g = 0; g < 3; ++g) at[order[g]] = spacing * step[g] + random.uniform(-0.025, 0.025);
            const double radius = random.uniform(0.06, 0.12);
            bodies.push_back(make_sphere(1.0, radius, {at[0], at[1], at[2]}));
            inflates.push_back(random.uniform(0.0, 0.05));
        }
        bodies.push_back(make_immovable_plane({0, 1, 0}, {0, 0.1, 0}));
        inflates.push_back(0.0);
        const FullAndCompact sets(bodies, inflates);
        REQUIRE(sets.compact_grid.has_grid());
        REQUIRE(sets.compact_grid.row_axis() == order[0]);
        REQUIRE(sets.full_grid.row_axis() == 0);
        REQUIRE(sets.full_pairs.size() > bodies.size() / 2);
        REQUIRE(sets.same_pairs());
        std::vector<std::uint32_t> near;
        std::vector<std::uint32_t> near_full;
        std::size_t found = 0;
        for (int query = 0; query < 200; ++query) {
            const Vector3 centre{random.uniform(-0.2, 2.6), random.uniform(-0.2, 2.6), random.uniform(-0.2, 2.6)};
            const double radius = random.uniform(0.0, 0.6);
            const Vector3 box = query % 2 == 0 ? Vector3{random.uniform(0.1, 1.5) * radius, random.uniform(0.1, 1.5) * radius,
                                                         random.uniform(0.1, 1.5) * radius}
                                               : BroadPhase::unbounded;
            sets.bodies_near(centre, radius, box, near, near_full);
            CAPTURE(query, centre.x, centre.y, centre.z, radius);
            REQUIRE(near == near_full);
            found += near.size();
        }
        CHECK(found > 500);  // the queries did find bodies, not only empty answers
    }
}

TEST_CASE("fine cells find the pairs and the bodies near that whole cells find", "[broad_phase][event]") {
    // Event timing walks cells half a reach wide, each against the two around it each way; the
    // pairs must be those of cells a reach wide (in another order), and a search again around
    // a body must still find every body near it.
    for (const int balls : {300, 1500, 4000}) {
        const std::vector<RigidBody> bodies = crowd(workbook::testing::run_seed() + 11 + static_cast<std::uint64_t>(balls), balls);
        SeededRandom random(workbook::testing::run_seed() + 12);
        ProxySet whole;
        whole.clear(bodies.size());
        for (std::uint32_t i = 0; i < bodies.size(); ++i) whole.add(bodies[i], i, 0.0, {}, random.uniform(0.0, 0.1));
        ProxySet fine = whole;
        fine.fine_cells = true;
        BroadPhase whole_grid;
        BroadPhase fine_grid;
        std::vector<BodyPair> whole_pairs;
        std::vector<BodyPair> fine_pairs;
        whole_grid.find_pairs(whole, whole_pairs, false, false);
        fine_grid.find_pairs(fine, fine_pairs, false, false);
        REQUIRE(fine_grid.has_grid());
        const auto order = [](BodyPair a, BodyPair b) { return a.first != b.first ? a.first < b.first : a.second < b.second; };
        std::sort(whole_pairs.begin(), whole_pairs.end(), order);
        std::sort(fine_pairs.begin(), fine_pairs.end(), order);
        CAPTURE(balls, whole_pairs.size(), fine_pairs.size());
        REQUIRE(whole_pairs.size() > static_cast<std::size_t>(balls) / 4);
        const auto same = [](BodyPair a, BodyPair b) { return a.first == b.first && a.second == b.second; };
        REQUIRE(std::equal(whole_pairs.begin(), whole_pairs.end(), fine_pairs.begin(), fine_pairs.end(), same));
        std::vector<std::uint32_t> near_whole;
        std::vector<std::uint32_t> near_fine;
        for (int query = 0; query < 100; ++query) {
            const Vector3 centre{random.uniform(-3.0, 3.0), random.uniform(-3.0, 3.0), random.uniform(-3.0, 3.0)};
            const double radius = random.uniform(0.0, 1.3);
            near_whole.clear();
            near_fine.clear();
            whole_grid.bodies_near(whole, centre, radius, near_whole);
            fine_grid.bodies_near(fine, centre, radius, near_fine);
            std::sort(near_whole.begin(), near_whole.end());
            std::sort(near_fine.begin(), near_fine.end());
            CAPTURE(query);
            REQUIRE(near_whole == near_fine);
        }
    }
}

TEST_CASE("a body at NaN makes the grid fall back to every pair, with the same answer", "[broad_phase]") {
    std::vector<RigidBody> bodies{make_sphere(1, 0.5, {0, 0, 0}), make_sphere(1, 0.5, {0.5, 0, 0}),
                                  make_sphere(1, 0.5, {std::numeric_limits<double>::quiet_NaN(), 0, 0})};
    BroadPhase broad;
    std::vector<BodyPair> pairs;
    broad.find_pairs(bodies, pairs);
    CHECK(pairs.size() == 3);
}

TEST_CASE("bodies spread far apart keep the grid small and the answer right", "[broad_phase]") {
    // Two touching pairs 1e12 m apart: a grid of one-diameter cells would need 1e12 cells.
    std::vector<RigidBody> bodies{make_sphere(1, 0.5, {0, 0, 0}), make_sphere(1, 0.5, {0.9, 0, 0}),
                                  make_sphere(1, 0.5, {1e12, 0, 0}), make_sphere(1, 0.5, {1e12, 0.9, 0})};
    BroadPhase broad;
    std::vector<BodyPair> pairs;
    broad.find_pairs(bodies, pairs);
    REQUIRE(pairs.size() == 2);
    CHECK((pairs[0].first == 0 && pairs[0].second == 1));
    CHECK((pairs[1].first == 2 && pairs[1].second == 3));
}

namespace {

/// Fast small balls in a closed box, most of which travel further than the smallest radius in
/// a step, so that the swept test runs for most of them; a few pinned balls, and one ball so
/// fast that it crosses the box in a step (kept out of the grid's cells, tried against all).
/// With `mixed`, larger balls, most of them slow and one in twenty fast: those travel further
/// than the cells, which are sized for the mean travel, and look for partners beyond them.
/// Which speeds and sizes fast_crowd() gives its balls.
enum class Speeds {
    fast,     ///< every ball at up to 8 m/s per axis, small radii
    mixed,    ///< one ball in 20 at up to 15 m/s, the others at 1, larger radii
    /// Radii 1 cm and 6 cm, the small balls at 14.5 to 16 m/s, the large ones at 7.2 to 14.4:
    /// in the first steps, at 1/60 s, the small ones travel more than four of the largest radii
    /// (0.24 m) yet reach less than the grid's cells are sized for (wide but not large), while
    /// the fastest large ones reach further without being wide (see BroadPhase::build_grid()).
    spread,
};

std::vector<RigidBody> fast_crowd(std::uint64_t seed, Speeds speeds) {
    const bool mixed = speeds == Speeds::mixed;
    SeededRandom random(seed);
    std::vector<RigidBody> bodies;
    const double half = 2.0;
    for (int i = 0; i < 500; ++i) {
        if (i == 100) bodies.push_back(make_immovable_plane({0, 1, 0}, {0, -half, 0}));
        if (i == 300) bodies.push_back(make_immovable_plane({1, 0, 0}, {-half, 0, 0}));
        const Vector3 at = random.vector(half * 0.95);
        if (i % 25 == 7) {
            // (Small for the spread: a larger one would widen every ball's cell.)
            bodies.push_back(make_immovable_sphere(speeds == Speeds::spread ? 0.01 : random.uniform(0.02, 0.08), at));
            continue;
        }
        if (speeds == Speeds::spread) {
            const bool small = i % 2 == 0;
            const double radius = small ? 0.01 : 0.06;
            const Vector3 direction = random.vector(1.0);
            const double speed = small ? random.uniform(14.5, 16.0) : random.uniform(7.2, 14.4);
            const Vector3 velocity = direction * (speed / std::max(length(direction), 1e-9));
            bodies.push_back(make_sphere(random.uniform(0.5, 2.0), radius, at, velocity));
            continue;
        }
        const double speed = !mixed ? 8.0 : i % 20 == 0 ? 15.0 : 1.0;
        const double radius = mixed ? random.uniform(0.1, 0.2) : random.uniform(0.02, 0.06);
        const double mass = random.uniform(0.5, 2.0);
        bodies.push_back(make_sphere(mass, radius, at, random.vector(speed)));
    }
    bodies.push_back(make_sphere(1.0, 0.03, {0, 0, 0}, {240.0, 35.0, -20.0}));
    bodies.push_back(make_immovable_plane({-1, 0, 0}, {half, 0, 0}));
    bodies.push_back(make_immovable_plane({0, 0, 1}, {0, 0, -half}));
    bodies.push_back(make_immovable_plane({0, 0, -1}, {0, 0, half}));
    bodies.push_back(make_immovable_plane({0, -1, 0}, {0, half, 0}));
    return bodies;
}

}  // namespace

TEST_CASE("the swept test finds with the grid what it finds trying every body, step after step",
          "[world][broad_phase][swept]") {
    const std::uint64_t seed = workbook::testing::run_seed();
    CAPTURE(seed);
    struct Variant {
        const char* name;
        WorldSettings settings;
        Speeds speeds;
    };
    const Variant variants[] = {
        {"no gravity", WorldSettings{1.0 / 60.0, {}}, Speeds::fast},
        {"gravity, exact-under-gravity", WorldSettings{1.0 / 60.0, {0, -9.81, 0}, Integrator::exact_under_gravity}, Speeds::fast},
        {"mixed speeds", WorldSettings{1.0 / 60.0, {}}, Speeds::mixed},
        {"speeds spread across the wide limit", WorldSettings{1.0 / 60.0, {}}, Speeds::spread},
    };
    for (const Variant& variant : variants) {
        CAPTURE(variant.name);
        const std::vector<RigidBody> bodies = fast_crowd(seed, variant.speeds);
        World grid(bodies, variant.settings, bouncing);
        World every_body(bodies, variant.settings, bouncing);
        every_body.set_shortcuts({.broad_phase = false});
        std::size_t touches = 0;
        for (int step = 0; step < 60; ++step) {
            grid.step();
            every_body.step();
            // The swept test's contacts are the touching ones (depth 0); detection's overlap.
            for (const Contact& contact : grid.contacts()) touches += contact.penetration == 0.0 ? 1 : 0;
            if (state_hash(grid) != state_hash(every_body)) {
                CAPTURE(step, grid.contacts().size(), every_body.contacts().size());
                FAIL("the grid's swept test left the path of trying every body");
            }
        }
        CHECK(grid.used_broad_phase());
        // Worth something only if many spheres were moved back to where they touched.
        CHECK(touches > 100);
    }
}

namespace {

/// Both worlds of `bodies` after one step: one with the grid however few the bodies, one trying
/// every body.
struct BothWays {
    World grid;
    World every_body;
};

BothWays one_step_both_ways(const std::vector<RigidBody>& bodies, const WorldSettings& settings) {
    BothWays run{World(bodies, settings, bouncing), World(bodies, settings, bouncing)};
    run.grid.set_shortcuts({.broad_phase_from = 0});
    run.every_body.set_shortcuts({.broad_phase = false});
    run.grid.step();
    run.every_body.step();
    return run;
}

}  // namespace

TEST_CASE("two equally early touches go to the partner of smaller index, as when trying every body",
          "[world][broad_phase][swept]") {
    // Ball 0 starts touching balls 1 and 2 (gaps exactly 0) and runs through both within the
    // step (dt = 1 s, every number exact), so both touches come at s = 0. The grid meets ball 2
    // before ball 1 (ball 2 lies in the cell before ball 0's end, ball 3 stretches the grid so
    // that it does); the answer must still be ball 1.
    const std::vector<RigidBody> bodies{make_sphere(1, 0.5, {0, 0, 0}, {1.25, -1.25, 0}), make_immovable_sphere(0.5, {1, 0, 0}),
                                        make_immovable_sphere(0.5, {0, -1, 0}), make_immovable_sphere(0.5, {-3.9, -1.25, 0})};
    const auto [grid, every_body] = one_step_both_ways(bodies, WorldSettings{1.0, {}});
    REQUIRE(grid.used_broad_phase());
    REQUIRE(grid.contacts().size() == 1);
    CHECK(grid.contacts()[0].body1 == 0);
    CHECK(grid.contacts()[0].body2 == 1);
    CHECK(grid.bodies()[0].position == Vector3{0, 0, 0});  // moved back to where it touched, s = 0
    CHECK(state_hash(grid) == state_hash(every_body));
}

TEST_CASE("a sphere that travels past its neighbouring cells still finds what it passes through",
          "[world][broad_phase][swept]") {
    // Pinned balls of radius 0.2 on a lattice 0.5 apart, so that the grid's cells are about
    // 0.4 wide; in the channel between two rows a small ball travels 0.78 in one step, through a
    // resting small ball 0.25 ahead of it, and ends one or two cells beyond it, depending on
    // where the cell borders fall: the moving pair is shifted along x in eighths of a cell.
    for (int shift = 0; shift < 8; ++shift) {
        CAPTURE(shift);
        const double dx = 0.05 * shift;
        std::vector<RigidBody> bodies;
        for (int i = 0; i < 10; ++i)
            for (int j = 0; j < 10; ++j) bodies.push_back(make_immovable_sphere(0.2, {-2.25 + 0.5 * i, -2.0 + 0.5 * j, 0}));
        bodies.push_back(make_sphere(1, 0.04, {dx - 0.5, 0.25, 0}, {1.56, 0, 0}));
        bodies.push_back(make_sphere(1, 0.04, {dx - 0.25, 0.25, 0}));
        const auto [grid, every_body] = one_step_both_ways(bodies, WorldSettings{0.5, {}});
        REQUIRE(grid.used_broad_phase());
        REQUIRE(grid.contacts().size() == 1);
        CHECK(grid.contacts()[0].body1 == 100);
        CHECK(grid.contacts()[0].body2 == 101);
        CHECK(state_hash(grid) == state_hash(every_body));
    }
}

TEST_CASE("each fast sphere's swept partners are listed once, wide and large alike", "[broad_phase][swept]") {
    // The spread crowd's first step, gathered as the world gathers it: every sphere's start and
    // how far it went in 1/60 s. Wide spheres (that travelled more than four of the largest
    // radii) that reach less than the cells are sized for make their own search; a pair met by
    // two searches would be traced twice.
    const std::uint64_t seed = workbook::testing::run_seed();
    CAPTURE(seed);
    const double dt = 1.0 / 60.0;
    std::vector<RigidBody> bodies = fast_crowd(seed, Speeds::spread);
    ProxySet set;
    set.clear(bodies.size());
    double smallest_radius = std::numeric_limits<double>::infinity();
    std::size_t wide = 0;
    for (std::uint32_t i = 0; i < bodies.size(); ++i) {
        RigidBody& body = bodies[i];
        const Vector3 start = body.position;
        body.position += body.velocity * dt;
        const bool sphere = body.shape.kind == ShapeKind::sphere;
        const double travel = sphere ? length(body.position - start) : 0.0;
        if (sphere) smallest_radius = std::min(smallest_radius, body.shape.radius);
        wide += travel > 4.0 * 0.06 ? 1 : 0;
        set.add(body, i, travel, start);
    }
    set.swept = true;
    set.fast_travel = smallest_radius;
    BroadPhase broad_phase;
    std::vector<BodyPair> pairs;
    broad_phase.find_pairs(set, pairs);
    REQUIRE(broad_phase.has_grid());
    CHECK(wide > 100);  // the small balls, at 14.5 m/s and more
    std::size_t listed = 0;
    for (std::uint32_t i = 0; i < bodies.size(); ++i) {
        std::vector<std::uint32_t> partners;
        for (const std::uint32_t entry : broad_phase.sweep_partners(i)) partners.push_back(entry & BroadPhase::partner_index);
        std::sort(partners.begin(), partners.end());
        CAPTURE(i);
        CHECK(std::adjacent_find(partners.begin(), partners.end()) == partners.end());
        listed += partners.size();
    }
    CHECK(listed > 1000);
}
