// "After the first step the stepping loop allocates nothing", proved by counting.
//
// Replacing the global allocation functions is the only standard way to see every heap
// allocation, and a replacement is program-wide: this file's operator new serves the whole
// engine_tests binary. It therefore just forwards to std::malloc and counts only while a
// test has switched counting on, so every other test runs as before.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "elastic_impulse.hpp"
#include "solver_doubles.hpp"
#include "workbook/time_series.hpp"
#include "workbook/world.hpp"

namespace {

std::atomic<bool> counting{false};
std::atomic<std::size_t> allocations{0};

void* allocate(std::size_t size) {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
    // malloc(0) may return null; operator new must not.
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

/// Counts the allocations made while it lives. Nothing inside its scope may use Catch2's
/// assertion macros, which allocate themselves.
class AllocationCounter {
public:
    AllocationCounter() {
        allocations.store(0);
        counting.store(true);
    }
    ~AllocationCounter() { counting.store(false); }
    AllocationCounter(const AllocationCounter&) = delete;
    AllocationCounter& operator=(const AllocationCounter&) = delete;

    [[nodiscard]] static std::size_t count() { return allocations.load(); }
};

using namespace workbook;

/// The elastic impulse of the engine's tests and a projection that splits the overlap by
/// inverse mass: enough to keep a pile of balls bouncing on the ground, so that detection and
/// both stages do real work every step.
void split_overlap(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double inverse_masses = body1.inverse_mass + body2.inverse_mass;
    if (inverse_masses == 0.0) return;
    const double depth = knobs.fraction * std::max(contact.penetration - knobs.slop, 0.0);
    const Vector3 push = contact.normal * (depth / inverse_masses);
    body1.position += push * body1.inverse_mass;
    body2.position -= push * body2.inverse_mass;
}

const ResponseModel bouncing{"test", testing::elastic_impulse, split_overlap};

World pile_of_balls() {
    std::vector<RigidBody> bodies{make_immovable_plane({0, 1, 0}, {0, 0, 0})};
    for (int i = 0; i < 6; ++i) {
        const double x = 0.9 * i;
        bodies.push_back(make_sphere(1.0 + i, 0.5, {x, 0.45 + 0.3 * (i % 2), 0.1 * i}, {(i % 3) - 1.0, -1.0, 0.0}));
    }
    return World(std::move(bodies), WorldSettings{1.0 / 240.0, {0.0, -9.81, 0.0}}, bouncing);
}

/// A 2D gas of 400 balls in a box, enough bodies for the world's grid broad phase, whose
/// contact count changes from step to step. With `radius` 0.05 most balls move further than
/// their radius in a step, so that the swept test traces them and moves some back.
World gas_in_a_box(double radius = 0.2) {
    std::vector<RigidBody> bodies;
    for (int i = 0; i < 400; ++i) {
        const double x = -4.75 + 0.5 * (i % 20), y = -4.75 + 0.5 * (i / 20);
        bodies.push_back(make_sphere(1.0, radius, {x, y, 0}, {std::sin(1.0 * i) * 4, std::cos(1.7 * i) * 4, 0}));
    }
    bodies.push_back(make_immovable_plane({1, 0, 0}, {-5, 0, 0}));
    bodies.push_back(make_immovable_plane({-1, 0, 0}, {5, 0, 0}));
    bodies.push_back(make_immovable_plane({0, 1, 0}, {0, -5, 0}));
    bodies.push_back(make_immovable_plane({0, -1, 0}, {0, 5, 0}));
    return World(std::move(bodies), WorldSettings{1.0 / 60.0, {}}, bouncing);
}

/// `world`'s bodies, settings and model, with event timing (event_timing.hpp).
World event_timed(const World& world) {
    WorldSettings settings = world.settings();
    settings.contact_timing = ContactTiming::event;
    return World(std::vector<RigidBody>(world.bodies().begin(), world.bodies().end()), settings, world.model());
}

/// 400 balls on a square lattice dropped under gravity onto a floor inside four walls: a
/// pile that keeps bouncing (the responder is elastic), with events every step.
World bouncing_pile() {
    std::vector<RigidBody> bodies;
    for (int i = 0; i < 400; ++i) {
        const double x = -0.45 + 0.11 * (i % 10), z = -0.45 + 0.11 * ((i / 10) % 10), y = 0.06 + 0.11 * (i / 100);
        bodies.push_back(make_sphere(1.0, 0.05, {x, y, z}));
    }
    bodies.push_back(make_immovable_plane({0, 1, 0}, {0, 0, 0}));
    bodies.push_back(make_immovable_plane({1, 0, 0}, {-0.56, 0, 0}));
    bodies.push_back(make_immovable_plane({-1, 0, 0}, {0.56, 0, 0}));
    bodies.push_back(make_immovable_plane({0, 0, 1}, {0, 0, -0.56}));
    bodies.push_back(make_immovable_plane({0, 0, -1}, {0, 0, 0.56}));
    return World(std::move(bodies), WorldSettings{1.0 / 60.0, {0.0, -9.81, 0.0}}, bouncing);
}

/// What `world` allocates over `steps` steps; `watch(world)` runs after each step, inside the
/// count, to record what the test wants to know the steps did.
template <class Watch>
std::size_t allocations_over(World& world, int steps, Watch&& watch) {
    const AllocationCounter counter;
    for (int i = 0; i < steps; ++i) {
        world.step();
        watch(world);
    }
    return AllocationCounter::count();
}

/// A column of five balls on the ground and a sixth falling onto it from 2 m, solved by the
/// engine tests' stand-ins for chapter 5's functions with `solver`, after one step.
World column_and_falling_ball(const ContactSolverSettings& solver) {
    std::vector<RigidBody> bodies;
    for (int i = 0; i < 5; ++i) bodies.push_back(make_sphere(1.0, 0.05, {0, 0.05 + 0.0995 * i, 0}));
    bodies.push_back(make_sphere(1.0, 0.05, {0, 2.0, 0}));
    bodies.push_back(make_immovable_plane({0, 1, 0}, {0, 0, 0}));
    WorldSettings settings{1.0 / 60, {0, -9.81, 0}};
    settings.position_correction = {0.2, 0.001};
    settings.contact_solver = solver;
    World world(std::move(bodies), settings, testing::solver_model);
    world.step();
    return world;
}

}  // namespace

// The replaceable global allocation functions ([new.delete]). The array and nothrow forms
// of the standard library call these, so replacing this set covers them too; the aligned
// forms are left to the library, which pairs them with their own deletes.
void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

TEST_CASE("the counter sees allocations, so a zero below means something", "[world][allocation]") {
    std::size_t seen = 0;
    {
        const AllocationCounter counter;
        auto probe = std::make_unique<std::vector<int>>(100);
        seen = AllocationCounter::count();
        // Keep the allocation observable so that it cannot be elided.
        if (probe->size() != 100) seen = 0;
    }
    CHECK(seen == 2);
}

TEST_CASE("after the first step, stepping a world allocates nothing", "[world][allocation]") {
    World world = pile_of_balls();
    world.step();

    constexpr int steps = 480;
    std::size_t contacts_seen = 0;
    const std::size_t allocated = allocations_over(world, steps, [&](const World& w) { contacts_seen += w.contacts().size(); });
    CHECK(allocated == 0);
    // The claim is only worth something if contacts were stored and answered meanwhile.
    CHECK(contacts_seen >= steps);
}

TEST_CASE("once warm, a gas stepped with the grid broad phase allocates nothing", "[world][allocation][broad_phase]") {
    // Contacts and pairs are stored in proportion to what a step finds, growing while the
    // scene warms up; after that their capacity suffices.
    World world = gas_in_a_box();
    std::size_t most_contacts = 0;
    for (int i = 0; i < 120; ++i) {
        world.step();
        most_contacts = std::max(most_contacts, world.contacts().size());
    }

    constexpr int steps = 600;
    std::size_t contacts_seen = 0;
    const std::size_t allocated = allocations_over(world, steps, [&](const World& w) { contacts_seen += w.contacts().size(); });
    CHECK(allocated == 0);
    CHECK(world.used_broad_phase());
    CHECK(contacts_seen >= steps * 10);
    // Stored in proportion: far below one contact per pair of bodies.
    CHECK(world.contacts().size() < world.bodies().size());
    CHECK(most_contacts > 0);
}

TEST_CASE("once warm, a gas the swept test traces allocates nothing", "[world][allocation][broad_phase][swept]") {
    // Small fast balls: the grid finds the swept test's candidates, and balls that went through
    // each other are moved back, every step.
    World world = gas_in_a_box(0.05);
    for (int i = 0; i < 120; ++i) world.step();

    constexpr int steps = 600;
    std::size_t touches = 0;
    const std::size_t allocated = allocations_over(world, steps, [&](const World& w) {
        for (const Contact& contact : w.contacts()) touches += contact.penetration == 0.0 ? 1 : 0;
    });
    CHECK(allocated == 0);
    CHECK(world.used_broad_phase());
    // Worth something only if the swept test moved balls back (its contacts touch, depth 0).
    CHECK(touches > 100);
}

TEST_CASE("each stage on its own allocates nothing after the first step", "[world][allocation]") {
    World world = pile_of_balls();
    world.step();

    std::size_t allocated = 0;
    {
        const AllocationCounter counter;
        for (int i = 0; i < 100; ++i) {
            world.integrate();
            world.detect();
            world.respond();
            world.correct();
            (void)world.probes();
        }
        allocated = AllocationCounter::count();
    }
    CHECK(allocated == 0);
}

TEST_CASE("run() allocates its record once, up front", "[world][allocation][time_series]") {
    // The world stores contacts in proportion to those it finds, so its own storage grows
    // while the scene warms up; warm it first, so that what is counted is run()'s own.
    World world = pile_of_balls();
    (void)run(world, 1.0);
    std::size_t allocated = 0;
    std::size_t samples = 0;
    {
        const AllocationCounter counter;
        const std::vector<Probes> record = run(world, 1.0);
        allocated = AllocationCounter::count();
        samples = record.size();
    }
    CHECK(samples == 241);
    CHECK(allocated == 1);
}

TEST_CASE("boxes too: box detection and the rotation step allocate nothing after the first step",
          "[world][allocation][box]") {
    // Spinning boxes dropped on the ground and on each other, next to a ball: box-plane,
    // box-box and sphere-box detection, the clipping and the free-rotation solve all run.
    std::vector<RigidBody> bodies{make_immovable_plane({0, 1, 0}, {0, 0, 0})};
    for (int i = 0; i < 4; ++i) {
        RigidBody box = make_box(1.0 + i, {0.5, 0.3, 0.2}, {0.7 * i, 0.25 + 0.5 * i, 0.0},
                                 normalized(from_axis_angle(normalized(Vector3{1.0, 2.0, 0.5 * i}), 0.3 * i)));
        box.angular_velocity = {1.0, 3.0 - i, 0.5};
        bodies.push_back(box);
    }
    bodies.push_back(make_sphere(1.0, 0.3, {1.2, 0.9, 0.1}));
    World world(std::move(bodies), WorldSettings{1.0 / 240.0, {0.0, -9.81, 0.0}}, bouncing);
    world.step();

    std::size_t points_seen = 0;
    const std::size_t allocated = allocations_over(world, 240, [&](const World& w) {
        for (const Contact& contact : w.contacts()) points_seen += contact.point_count;
    });
    CHECK(allocated == 0);
    CHECK(points_seen >= 240);
}

TEST_CASE("the contact solver with sleeping allocates nothing once warm, through sleep and wake",
          "[world][allocation][contact-solver][sleeping]") {
    // A column of 5 balls, and a sixth dropped from 2 m onto it: the column falls asleep, the
    // ball wakes it, and all six fall asleep again, all within the counted steps.
    World world = column_and_falling_ball({});
    std::size_t most_asleep = 0, fewest_asleep_after = 6;
    const std::size_t allocated = allocations_over(world, 300, [&](const World& w) {
        most_asleep = std::max(most_asleep, w.sleeping().sleeping());
        if (most_asleep == 5) fewest_asleep_after = std::min(fewest_asleep_after, w.sleeping().sleeping());
    });
    CHECK(allocated == 0);
    CHECK(fewest_asleep_after == 0);              // woken by the ball
    CHECK(world.sleeping().sleeping() == 6);     // asleep again
}

TEST_CASE("the contact solver in substeps allocates nothing once warm", "[world][allocation][contact-solver][substeps]") {
    // The scene above, solved in substeps of soft contacts: the ball's impact adds a contact
    // within the counted steps.
    World world = column_and_falling_ball({.substeps = 4});
    const std::size_t allocated = allocations_over(world, 300, [](const World&) {});
    CHECK(allocated == 0);
    CHECK(world.bodies()[5].position.y < 0.6);  // the ball came down onto the column
}

TEST_CASE("the contact solver with shock sweeps allocates nothing once warm", "[world][allocation][contact-solver][shock]") {
    // The scene above, solved in one solve a step with two sweeps after the velocity passes.
    World world = column_and_falling_ball({.shock_sweeps = 2, .sleeping = false});
    const std::size_t allocated = allocations_over(world, 300, [](const World&) {});
    CHECK(allocated == 0);
    CHECK(world.bodies()[5].position.y < 0.6);  // the ball came down onto the column
}

TEST_CASE("the contact solver with speculative contacts allocates nothing once warm",
          "[world][allocation][contact-solver][speculative]") {
    // The scene above, with speculative contacts, solved in one solve and in substeps: the
    // ball's gap to the column becomes a contact, then its impact, within the counted steps.
    for (const int substeps : {0, 4}) {
        World world = column_and_falling_ball({.substeps = substeps, .speculative_distance = 0.02});
        const std::size_t allocated = allocations_over(world, 300, [](const World&) {});
        CHECK(allocated == 0);
        CHECK(world.bodies()[5].position.y < 0.6);  // the ball came down onto the column
    }
}

TEST_CASE("once warm, event timing allocates nothing, in a gas and in a bouncing pile", "[world][allocation][event]") {
    // The event loop's lists (candidates, pending events, the impacts' contacts) grow while the
    // scene warms up and keep their capacity; after that a step finds room in them.
    for (const bool gas : {true, false}) {
        CAPTURE(gas);
        World world = event_timed(gas ? gas_in_a_box() : bouncing_pile());
        for (int i = 0; i < 120; ++i) world.step();

        constexpr int steps = 600;
        std::size_t contacts_seen = 0;
        const std::size_t allocated =
            allocations_over(world, steps, [&](const World& w) { contacts_seen += w.contacts().size(); });
        CHECK(allocated == 0);
        CHECK(contacts_seen >= steps * 10);  // impacts every step: the loop had work to do
    }
}
