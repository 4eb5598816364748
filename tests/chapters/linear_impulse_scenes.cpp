// Ties chapter 3's scenes (chapters/linear-impulse/scenes/) and the claims its page makes
// about them to the engine: the carts' energy staircase, e = 0 against chapter 1, the
// bouncing ball's apexes against e^(2k) h0, Newton's cradle in three contact orders, the
// billiard break's momentum and energy, and the stacked balls' rise against the ideal factor.
// The numbers the page prints are produced here (linear_impulse_page.cpp looks them up).
#include "linear_impulse_scenes.hpp"

#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "inelastic.hpp"
#include "linear-impulse.hpp"
#include "workbook/probes.hpp"

using namespace workbook;
using namespace workbook::chapter3;

namespace {
constexpr double epsilon = std::numeric_limits<double>::epsilon();
}  // namespace

TEST_CASE("head-on carts: the energy staircase 3 (1 - e^2) J and momentum 6 kg m/s", "[linear-impulse]") {
    for (const CartsCase& c : carts_cases()) {
        INFO("scene " << c.file << ", e = " << c.e);
        const Run run = run_scene(c.file);
        const double j = 2.0 * (1.0 + c.e);
        CHECK(std::abs(run.bodies[0].velocity.x - (3.0 - j / 2.0)) <= 8 * epsilon * 3.0);
        CHECK(std::abs(run.bodies[1].velocity.x - j) <= 8 * epsilon * 3.0);
        CHECK(std::abs(run.last.linear_momentum.x - 6.0) <= 8 * epsilon * 6.0);
        CHECK(std::abs((9.0 - run.last.kinetic()) - 3.0 * (1.0 - c.e * c.e)) <= 16 * epsilon * 9.0);
    }
}

TEST_CASE("e = 0 gives chapter 1's velocities: the carts scene and collinear random pairs", "[linear-impulse]") {
    const Run impulse = run_scene("chapters/linear-impulse/scenes/head-on-carts-e0.json");
    const Run merged = run_scene("chapters/inelastic/scenes/head-on-carts.json");
    for (std::size_t i = 0; i < 2; ++i) {
        CHECK(std::abs(impulse.bodies[i].velocity.x - merged.bodies[i].velocity.x) <= 8 * epsilon * 3.0);
        CHECK(impulse.bodies[i].velocity.y == 0.0);
    }
    // Head-on (v12 parallel to n) the two models agree to rounding, for any masses.
    std::uint64_t state = 20261122;
    auto uniform = [&state](double lo, double hi) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return lo + (hi - lo) * static_cast<double>(state >> 11) * 0x1.0p-53;
    };
    for (int i = 0; i < 1000; ++i) {
        const Vector3 n = normalized(Vector3{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)});
        RigidBody a = make_sphere(std::pow(10.0, uniform(-3, 3)), 0.5, {}, uniform(-20, 20) * n);
        RigidBody b = make_sphere(std::pow(10.0, uniform(-3, 3)), 0.5, {}, uniform(-20, 20) * n);
        a.restitution = b.restitution = 0.0;
        Contact contact;
        contact.normal = dot(a.velocity - b.velocity, n) < 0.0 ? n : -n;
        contact.add_point({}, 0.01);
        RigidBody a1 = a, b1 = b;
        // Rounding is relative to the incoming speeds, which the two forms subtract differently.
        const double scale = 64 * epsilon * (length(a.velocity) + length(b.velocity));
        linear_impulse::resolve(a, b, contact);
        inelastic::resolve(a1, b1, contact);
        INFO("pair " << i);
        CHECK(length(a.velocity - a1.velocity) <= scale);
        CHECK(length(b.velocity - b1.velocity) <= scale);
    }
    // An oblique hit is where they part: e = 0 keeps the sliding velocity, chapter 1 does not.
    RigidBody a = make_sphere(2.0, 0.5, {}, {3, 1, 0});
    RigidBody b = make_sphere(1.0, 0.5, {1, 0, 0}, {});
    a.restitution = b.restitution = 0.0;
    Contact contact;
    contact.normal = {-1, 0, 0};
    contact.add_point({0.5, 0, 0}, 0.01);
    RigidBody a1 = a, b1 = b;
    linear_impulse::resolve(a, b, contact);
    inelastic::resolve(a1, b1, contact);
    CHECK(a.velocity == Vector3{2, 1, 0});
    CHECK(a1.velocity.y != a.velocity.y);
}

TEST_CASE("bouncing ball: apexes near e^(2k) h0, every bounce keeping e^2 of the energy", "[linear-impulse]") {
    const BounceReport report = bouncing_ball_report();
    REQUIRE(report.apexes.size() >= 5);
    for (std::size_t k = 0; k < report.apexes.size(); ++k) {
        const double ideal = std::pow(0.8, 2.0 * static_cast<double>(k + 1));
        INFO("apex " << k + 1 << ": " << report.apexes[k] << " m against " << ideal << " m");
        // The discrete-time error the page reports: below, and growing with k as the bounces
        // get shorter against the fixed step.
        CHECK(report.apexes[k] < ideal);
        CHECK(std::abs(report.apexes[k] - ideal) / ideal < 0.05);
        if (k > 0) CHECK(report.apexes[k] / std::pow(0.8, 2.0 * static_cast<double>(k + 1)) < report.apexes[k - 1] / std::pow(0.8, 2.0 * static_cast<double>(k)));
    }
}

TEST_CASE("Newton's cradle: the last ball leaves at 1 m/s; other orders and all at once", "[linear-impulse]") {
    const Run run = run_scene("chapters/linear-impulse/scenes/newtons-cradle.json");
    for (std::size_t i = 0; i < 5; ++i) {
        INFO("ball " << i + 1);
        CHECK(std::abs(run.bodies[i].velocity.x - (i == 4 ? 1.0 : 0.0)) <= 8 * epsilon);
    }
    const CradleOrders orders = cradle_orders();
    // A pressed row: all four contacts in one step. Index order: done in that step.
    CHECK(orders.forward_after_one_step == std::vector<double>{0, 0, 0, 0, 1});
    // Reverse order: one ball per step, the same result three steps later.
    CHECK(orders.reverse_after_one_step == std::vector<double>{0, 1, 0, 0, 0});
    CHECK(orders.reverse_steps_to_finish == 4);
    CHECK(orders.reverse_final == std::vector<double>{0, 0, 0, 0, 1});
    // All four contacts solved at once: the first ball bounces back, the rest move as a block.
    const std::vector<double>& s = orders.simultaneous;
    CHECK(std::abs(s[0] + 0.6) < 1e-15);
    for (std::size_t i = 1; i < 5; ++i) CHECK(std::abs(s[i] - 0.4) < 1e-15);
    double p = 0.0, e2 = 0.0;
    for (const double v : s) {
        p += v;
        e2 += 0.5 * v * v;
    }
    CHECK(std::abs(p - 1.0) < 1e-15);
    CHECK(std::abs(e2 - 0.5) < 1e-15);
}

TEST_CASE("billiard break: momentum and, at e = 1, kinetic energy kept to rounding", "[linear-impulse]") {
    const Run run = run_scene("chapters/linear-impulse/scenes/billiard-break.json");
    CHECK(run.responses >= 5);
    CHECK(std::abs(run.last.linear_momentum.x - 1.36) <= 64 * epsilon * 1.36);
    CHECK(std::abs(run.last.linear_momentum.y) <= 64 * epsilon * 1.36);
    CHECK(std::abs(run.last.kinetic() - 5.44) <= 64 * epsilon * 5.44);
    // Angular momentum about the origin: every impulse acts along the line of centres and
    // keeps it, but the position correction moves the balls apart with no such balance.
    const double l0 = -0.0027200000000000002;  // (0, 0.002, 0) x (1.36, 0, 0)
    CHECK(std::abs(run.last.angular_momentum.z - l0) > 1e-4);
    const Run uncorrected = run_scene_with_slop("chapters/linear-impulse/scenes/billiard-break.json", 1.0);
    CHECK(std::abs(uncorrected.last.angular_momentum.z - l0) <= 64 * epsilon * 1.36);
    int moving = 0;
    for (const RigidBody& b : run.bodies) moving += length(b.velocity) > 0.1 ? 1 : 0;
    CHECK(moving >= 8);
}

TEST_CASE("stacked balls: the small ball rises about ((3M - m)/(M + m))^2 times its fall", "[linear-impulse]") {
    const StackReport report = stacked_balls_report();
    CHECK(std::abs(report.ideal_factor - 841.0 / 121.0) < 1e-12);
    INFO("fell " << report.fall << " m, rose " << report.rise << " m, factor " << report.factor);
    CHECK(report.factor > 0.9 * report.ideal_factor);
    CHECK(report.factor < 1.05 * report.ideal_factor);
}

TEST_CASE("chapter 3 scene measurements, printed", "[.print][linear-impulse-print]") {
    const BounceReport bounce = bouncing_ball_report();
    for (std::size_t k = 0; k < bounce.apexes.size(); ++k) WARN("apex " << k + 1 << " " << bounce.apexes[k]);
    const StackReport stack = stacked_balls_report();
    WARN("stack fall " << stack.fall << " rise " << stack.rise << " factor " << stack.factor << " ideal " << stack.ideal_factor);
}
