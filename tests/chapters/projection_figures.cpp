// Ties chapter 2's scenes and figures to the closed forms they illustrate. Each scene of
// chapters/projection/scenes is loaded and run with the reference projection, and the probes
// the figures are drawn from are checked: projection never changes a velocity, so kinetic
// energy and momentum follow from the initial state alone; the depths follow the recurrence
// d(k+1) - s = (1 - beta)(d(k) - s) + closing per step.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "workbook/response_model.hpp"
#include "workbook/scene.hpp"
#include "workbook/time_series.hpp"

namespace {

namespace fs = std::filesystem;
using namespace workbook;

constexpr double epsilon = std::numeric_limits<double>::epsilon();

Scene load(std::string_view name) {
    std::vector<std::string_view> responders;
    for (const auto& model : response_models()) responders.push_back(model.name);
    return load_scene(fs::path(WORKBOOK_SOURCE_DIR) / "chapters" / "projection" / "scenes" / (std::string(name) + ".json"),
                      responders);
}

std::vector<Probes> run_scene(const Scene& scene, World* keep = nullptr) {
    World world = make_world(scene, *find_response_model(scene.responder));
    std::vector<Probes> samples = run(world, scene.duration);
    if (keep != nullptr) *keep = world;
    return samples;
}

Vector3 centre_of_mass(std::span<const RigidBody> bodies) {
    Vector3 weighted{};
    double mass = 0.0;
    for (const RigidBody& b : bodies) {
        weighted += b.mass() * b.position;
        mass += b.mass();
    }
    return weighted / mass;
}

}  // namespace

TEST_CASE("Every projection scene keeps velocities: no response energy, momentum and energy as free flight says", "[projection]") {
    for (const auto& entry : fs::directory_iterator(fs::path(WORKBOOK_SOURCE_DIR) / "chapters" / "projection" / "scenes")) {
        if (entry.path().extension() != ".json") continue;
        DYNAMIC_SECTION(entry.path().filename().string()) {
            const Scene scene = load(entry.path().stem().string());
            CHECK(scene.responder == "projection");
            CHECK_FALSE(scene.description.empty());
            const std::vector<Probes> samples = run_scene(scene);
            const double dt = scene.settings.time_step;
            for (std::size_t k = 0; k < samples.size(); ++k) {
                CHECK(samples[k].response_energy_change == 0.0);
                // Only gravity changes velocities: v(k) = v(0) + g k dt for every movable body.
                double kinetic = 0.0;
                Vector3 momentum{};
                for (const RigidBody& b : scene.bodies) {
                    if (b.is_immovable()) continue;
                    const Vector3 v = b.velocity + scene.settings.gravity * (static_cast<double>(k) * dt);
                    kinetic += 0.5 * b.mass() * length_squared(v);
                    momentum += b.mass() * v;
                }
                INFO("step " << k);
                CHECK(std::abs(samples[k].kinetic_linear - kinetic) <= 64 * epsilon * std::max(kinetic, 1.0));
                CHECK(length(samples[k].linear_momentum - momentum) <= 64 * epsilon * std::max(length(momentum), 1.0));
            }
        }
    }
}

TEST_CASE("Spheres spawned overlapping are separated in one step, the light one moving w2/(w1+w2) of the depth", "[projection]") {
    for (const std::string_view name : {"overlapping-spheres", "heavy-and-light"}) {
        INFO(name);
        const Scene scene = load(name);
        World world = make_world(scene, *find_response_model(scene.responder));
        const Vector3 centre = centre_of_mass(world.bodies());
        const RigidBody first = world.bodies()[0];
        const RigidBody second = world.bodies()[1];
        const double depth = 1.0 - length(first.position - second.position);
        CHECK(std::abs(depth - 0.1) <= 4 * epsilon);
        world.step();
        CHECK(std::abs(length(world.bodies()[0].position - world.bodies()[1].position) - 1.0) <= 4 * epsilon);
        CHECK(length(centre_of_mass(world.bodies()) - centre) <= 4 * epsilon);
        // Each moves its inverse-mass share of the depth (the 1 kg ball 9 cm next to a 9 kg one).
        const double share2 = second.inverse_mass / (first.inverse_mass + second.inverse_mass);
        CHECK(std::abs(length(world.bodies()[1].position - second.position) - share2 * depth) <= 4 * epsilon);
        for (int k = 0; k < 10; ++k) world.step();
        CHECK(world.contacts().empty());
    }
}

TEST_CASE("A ball between two others: both depths measured first, so each step halves the overlap", "[projection]") {
    const Scene scene = load("ball-between-two");
    const std::vector<Probes> samples = run_scene(scene);
    for (std::size_t k = 1; k < samples.size(); ++k) {
        INFO("step " << k);
        CHECK(std::abs(samples[k].penetration_max - 0.1 / std::pow(2.0, static_cast<double>(k - 1))) <= 8 * epsilon);
        CHECK(samples[k].contacts == 2);
    }
}

TEST_CASE("A ball on the ground with projection only sinks |v| dt each step and is lifted back; its speed grows as g t", "[projection]") {
    const Scene scene = load("ball-on-ground");
    const std::vector<Probes> samples = run_scene(scene);
    const double dt = scene.settings.time_step;
    const double g = -scene.settings.gravity.y;
    const auto first = static_cast<std::size_t>(
        std::find_if(samples.begin(), samples.end(), [](const Probes& p) { return p.contacts > 0; }) - samples.begin());
    REQUIRE(first < samples.size() / 2);
    // From the step after the first contact on the ball starts each step on the surface
    // (fraction 1, no slop), so it sinks exactly by its speed times dt.
    for (std::size_t k = first + 1; k < samples.size(); ++k) {
        INFO("step " << k);
        const double speed = g * static_cast<double>(k) * dt;
        CHECK(std::abs(samples[k].penetration_max - speed * dt) <= 1e-12);
    }
    CHECK(samples.back().kinetic_linear > 50.0 * samples[first].kinetic_linear / 10.0);
}

TEST_CASE("Carts driven together stay stuck at a depth of s + closing per step / beta", "[projection]") {
    const Scene scene = load("carts-pushed-together");
    const std::vector<Probes> samples = run_scene(scene);
    const PositionCorrection knobs = scene.settings.position_correction;
    const double closing = length(scene.bodies[0].velocity - scene.bodies[1].velocity) * scene.settings.time_step;
    const double steady = knobs.slop + closing / knobs.fraction;
    CHECK(std::abs(steady - 0.041) <= 4 * epsilon);
    CHECK(std::abs(samples.back().penetration_max - steady) <= 1e-12);
    CHECK(samples.back().contacts == 1);
    CHECK(std::abs(samples.back().kinetic_linear - 1.5) <= 8 * epsilon);
}

TEST_CASE("The beta sweep: the error about s + c/beta shrinks by exactly (1 - beta) per step while in contact", "[projection]") {
    const Scene scene = load("beta-sweep");
    REQUIRE(scene.fraction_sweep.size() >= 5);
    const double closing = length(scene.bodies[0].velocity - scene.bodies[1].velocity) * scene.settings.time_step;
    const double slop = scene.settings.position_correction.slop;
    for (const double beta : scene.fraction_sweep) {
        INFO("beta " << beta);
        Scene variant = scene;
        variant.settings.position_correction.fraction = beta;
        const std::vector<Probes> samples = run_scene(variant);
        const double steady = slop + closing / beta;
        int checked = 0;
        for (std::size_t k = 1; k + 1 < samples.size(); ++k) {
            // Deeper than the slop and still in contact the next step: the recurrence holds, to rounding.
            if (samples[k].penetration_max <= slop || samples[k + 1].contacts == 0) continue;
            INFO("step " << k);
            CHECK(std::abs((samples[k + 1].penetration_max - steady) - (1.0 - beta) * (samples[k].penetration_max - steady)) <=
                  1e-14);
            ++checked;
        }
        CHECK(checked >= 10);
        const double last = samples.back().penetration_max;
        const double before_last = samples[samples.size() - 2].penetration_max;
        if (beta < 2.0) {
            // (1 - beta)^k has shrunk the error to under 2 % of the first step's by the end.
            CHECK(std::abs(last - steady) < 0.02 * std::abs(samples[1].penetration_max - steady));
        } else {
            // |1 - beta| > 1: the error grows every pass in contact and the depth never settles.
            CHECK(std::abs(last - before_last) > 5e-4);
        }
    }
}
