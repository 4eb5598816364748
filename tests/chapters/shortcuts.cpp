// Every chapter scene steps bit-identically with each shortcut of the world on and off
// (World::Shortcuts); the grid broad phase is forced on even for scenes of two bodies,
// where the world would not use it, so that it is compared on every scene.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "sanitized_run.hpp"
#include "state_hash.hpp"
#include "workbook/response_model.hpp"
#include "workbook/scene.hpp"
#include "workbook/time_series.hpp"

namespace {

namespace fs = std::filesystem;
using namespace workbook;

std::vector<fs::path> every_chapter_scene() {
    std::vector<fs::path> files;
    for (const auto& chapter : fs::directory_iterator(fs::path(WORKBOOK_SOURCE_DIR) / "chapters")) {
        const fs::path scenes = chapter.path() / "scenes";
        if (!fs::is_directory(scenes)) continue;
        for (const auto& entry : fs::directory_iterator(scenes))
            if (entry.path().extension() == ".json") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// How many steps of a scene the tests below compare: at most 20,000 body-steps a run, which
/// every scene of chapters 1 to 4 is within (the billiard break has 16,000): the pile of
/// chapter 5 (1,003 bodies, 180 steps) is compared over its first 19 steps, so that four runs
/// of each scene keep the suite cheap. In the sanitizer build, chapter 5's heavy scenes over
/// their first half second at most (sanitized_run.hpp); the dev build compares the rest too.
std::size_t steps_compared(const Scene& scene) {
    const std::size_t work_limit = 20000;
    return testing::sanitized_steps(scene, std::min(step_count(scene.duration, scene.settings.time_step),
                                                    std::max<std::size_t>(1, work_limit / scene.bodies.size())));
}

/// The state hash after every step of the scene, with the given shortcuts, followed by the
/// hash of the probes after every step (the energy probe's column only when recorded).
std::vector<std::uint64_t> path_of(const Scene& scene, const Shortcuts& shortcuts) {
    World world = make_world(scene, *find_response_model(scene.responder));
    world.set_shortcuts(shortcuts);
    std::vector<std::uint64_t> hashes;
    const std::size_t steps = steps_compared(scene);
    for (std::size_t i = 0; i < steps; ++i) {
        world.step();
        hashes.push_back(testing::state_hash(world));
        const Probes p = world.probes();
        testing::StateHash h;
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

TEST_CASE("every chapter scene takes the same path with every shortcut on as with all off", "[shortcuts]") {
    const auto files = every_chapter_scene();
    REQUIRE(files.size() >= 5);
    const Shortcuts all_on{.broad_phase = true, .broad_phase_from = 0};
    const Shortcuts all_off{.broad_phase = false,
                            .skip_immovable_pairs = false,
                            .skip_still_rotation = false,
                            .skip_zero_gravity = false,
                            .response_energy_probe = true};
    for (const fs::path& file : files) {
        CAPTURE(file.string());
        const Scene scene = load_scene(file);
        const auto reference = path_of(scene, all_off);
        REQUIRE(!reference.empty());
        CHECK(path_of(scene, all_on) == reference);
        CHECK(path_of(scene, Shortcuts{}) == reference);  // the defaults
        Shortcuts without_probe = all_on;
        without_probe.response_energy_probe = false;
        const auto unprobed = path_of(scene, without_probe);
        // Bodies and contacts after each step (every other hash) as with the probe.
        for (std::size_t i = 0; i < reference.size(); i += 2) {
            if (unprobed[i] != reference[i]) {
                CAPTURE(i / 2);
                FAIL("turning the energy probe off changed the bodies' path");
            }
        }
    }
}

TEST_CASE("print each chapter scene's path hash (run by hand around a change that must not change results)",
          "[.hashes]") {
    for (const fs::path& file : every_chapter_scene()) {
        const Scene scene = load_scene(file);
        testing::StateHash h;
        for (const std::uint64_t step_hash : path_of(scene, Shortcuts{})) h.add(step_hash);
        std::printf("%016llx %s\n", static_cast<unsigned long long>(h.value()), file.filename().string().c_str());
    }
}

namespace {

/// The state hash after each of `steps` steps, by step() or by calling the four stages in order.
std::vector<std::uint64_t> stage_path(World world, std::size_t steps, bool by_stages) {
    std::vector<std::uint64_t> hashes;
    for (std::size_t n = 0; n < steps; ++n) {
        if (by_stages) {
            world.integrate();
            world.detect();
            if (world.model().contact_solver != nullptr) {
                world.solve_contacts();  // a model with a contact solver: stages 3 and 4 together
            } else {
                world.respond();
                world.correct();
            }
        } else {
            world.step();
        }
        hashes.push_back(testing::state_hash(world));
    }
    return hashes;
}

}  // namespace

TEST_CASE("step() is its public stages in order: same state hash after every step", "[shortcuts][stages]") {
    SECTION("every chapter scene (discrete timing)") {
        for (const fs::path& file : every_chapter_scene()) {
            const Scene scene = load_scene(file);
            if (scene.settings.contact_timing != ContactTiming::discrete) continue;
            CAPTURE(file.filename().string());
            const World world = make_world(scene, *find_response_model(scene.responder));
            const std::size_t steps = steps_compared(scene);  // as path_of() above
            CHECK(stage_path(world, steps, true) == stage_path(world, steps, false));
        }
    }
    SECTION("fast bodies: a ball at 200 m/s against a ball, alone and among 20 others (the grid)") {
        for (const int others : {0, 20}) {
            CAPTURE(others);
            std::vector<RigidBody> bodies{make_sphere(1.0, 0.05, {-1, 0, 0}, {200, 0, 0}), make_sphere(1.0, 0.05, {0, 0, 0}, {})};
            for (int n = 0; n < others; ++n) bodies.push_back(make_sphere(1.0, 0.1, {0.3 * n, 5, 0}, {0, -50, 0}));
            bodies.push_back(make_immovable_plane({0, 1, 0}, {0, -1, 0}));
            const World world(bodies, WorldSettings{1.0 / 240, {0, -9.81, 0}}, *find_response_model("linear-impulse"));
            const auto by_step = stage_path(world, 240, false);
            CHECK(stage_path(world, 240, true) == by_step);
        }
    }
}
