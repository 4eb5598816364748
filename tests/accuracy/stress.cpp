// The small stress corpus, every invariant after every step (tools/accuracy/stress.hpp states
// the bounds), with chapter 3's linear-impulse from the response model table; chapter 1's
// inelastic runs too. The scenes of resting contact run with their own responder
// (StressScene::responder), once.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cstdint>
#include <string>

#include "models.hpp"
#include "stress.hpp"

using namespace workbook::accuracy;

namespace {

#ifdef WORKBOOK_UNDER_SANITIZERS
constexpr bool under_sanitizers = true;
#else
constexpr bool under_sanitizers = false;
#endif

/// The scene as the tests run it: under the sanitizers, which slow a step some 20 times and
/// catch their errors in a short stretch as well as in the whole, a scene of resting contact
/// runs its first second only (its own checks start later: the invariants still hold).
StressScene as_tested(StressScene scene) {
    if (under_sanitizers && !scene.responder.empty()) scene.steps = std::min<std::uint64_t>(scene.steps, 60);
    return scene;
}

void check_scene(const StressResult& r) {
    INFO(r.scene << ": worst " << r.worst << " (" << r.worst_invariant << ") after " << r.steps << " steps " << r.error);
    CHECK(r.error.empty());
    CHECK(r.energy_ratio <= 1.0);
    CHECK(r.momentum_ratio <= 1.0);
    CHECK(r.box_ratio <= 1.0);
    CHECK(r.worst <= 1.0);  // the scene's own check too
}

}  // namespace

TEST_CASE("the small stress corpus keeps every invariant with chapter 3's linear-impulse", "[stress]") {
    for (const StressScene& corpus_scene : stress_corpus(false)) {
        const StressScene scene = as_tested(corpus_scene);
        const StressResult result = run_stress(scene, chapter_model("linear-impulse"));
        CHECK(result.steps == scene.steps);
        check_scene(result);
    }
}

TEST_CASE("the small stress corpus stays finite and gains no energy with chapter 1's inelastic model", "[stress]") {
    for (const StressScene& scene : stress_corpus(false)) {
        if (!scene.responder.empty()) continue;  // the same run as with linear-impulse
        const StressResult r = run_stress(scene, chapter_model("inelastic"));
        INFO(scene.name << ": " << r.error);
        CHECK(r.steps == scene.steps);
        CHECK(r.error.empty());
        CHECK(r.energy_ratio <= 1.0);
        CHECK(r.momentum_ratio <= 1.0);
    }
}

TEST_CASE("the corpus covers what the issue asks for", "[stress]") {
    std::string names;
    for (const StressScene& scene : stress_corpus(true)) names += scene.name + " ";
    for (const char* expected : {"mass-ratio-1e-9", "mass-ratio-1e9", "speed-1e4-box", "time-step-1e-6", "time-step-0.1",
                                 "bodies-10000", "steps-1e6", "deep-overlap", "coincident-centres", "far-from-origin",
                                 "zero-gravity", "gravity-100g", "kinematic-event", "spin-1e4-skew", "thin-box-fast-ball",
                                 "event-gas", "stack-30-friction", "column-30-dropped", "pile-4000"})
        CHECK(names.find(std::string(expected) + " ") != std::string::npos);
}

TEST_CASE("every refused scene of the corpus is refused, naming its field", "[stress][refused]") {
    for (const RefusedScene& scene : refused_scenes()) {
        const RefusalResult result = check_refusal(scene);
        CAPTURE(scene.name, result.message);
        CHECK(result.field == scene.field);
        CHECK(result.passed);
    }
}
