// Scenes that would need absurd work or memory, or overflow double arithmetic, are refused by
// the loader with the field's path and the limit, before anything runs: never a bad_alloc or
// a length_error from deep inside a run.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <string>

#include "workbook/scene.hpp"
#include "workbook/scene_limits.hpp"

using namespace workbook;
using Catch::Matchers::ContainsSubstring;
using Catch::Matchers::StartsWith;

namespace {

std::string ball(const std::string& extra = "") {
    return R"({"shape": {"type": "sphere", "radius": 0.5}, "mass": 1)" + extra + "}";
}

std::string scene(const std::string& members, const std::string& bodies) {
    return R"({"title": "t", "responder": "x", )" + members + R"(, "bodies": [)" + bodies + "]}";
}

SceneError refused(const std::string& text) {
    try {
        (void)parse_scene(text, "big.json");
    } catch (const SceneError& error) {
        return error;
    }
    FAIL("accepted:\n" << text);
    return SceneError("", "", "");
}

}  // namespace

TEST_CASE("a run of more steps than the cap is refused, naming duration and the cap", "[scene][limits]") {
    const SceneError error = refused(scene(R"("time_step": 1e-6, "duration": 1e9)", ball()));
    CHECK(error.field() == "duration");
    CHECK(error.problem() == "needs 1e+15 steps of 1e-06 s; the limit is 1e+07 steps (duration / time_step)");
    // A time step so small that duration / time_step overflows to infinity is refused the same way.
    CHECK(refused(scene(R"("time_step": 1e-320, "duration": 1e10)", ball())).field() == "duration");
    // Exactly at the cap is fine.
    CHECK_NOTHROW(parse_scene(scene(R"("time_step": 1e-6, "duration": 10)", ball()), "ok.json"));
}

TEST_CASE("absurd speeds and positions are refused with the component's path and the limit", "[scene][limits]") {
    const SceneError speed = refused(scene(R"("time_step": 0.01, "duration": 1)", ball() + ", " + ball(R"(, "velocity": [0, 1e300, 0])")));
    CHECK(speed.field() == "bodies[1].velocity[1]");
    CHECK(speed.problem() == "magnitude 1e+300 is over the limit of 1e+08 m/s");
    const SceneError where = refused(scene(R"("time_step": 0.01, "duration": 1)", ball(R"(, "position": [-1e13, 0, 0])")));
    CHECK(where.field() == "bodies[0].position[0]");
    CHECK_THAT(where.problem(), StartsWith("magnitude 1e+13 is over the limit of 1e+12 m"));
    CHECK(refused(scene(R"("time_step": 0.01, "duration": 1, "gravity": [0, -1e200, 0])", ball())).field() == "gravity[1]");
    CHECK(refused(scene(R"("time_step": 0.01, "duration": 1)", ball(R"(, "angular_velocity": [0, 0, 1e9])"))).field() ==
          "bodies[0].angular_velocity[2]");
    // 10^4 m/s, 10^6 m from the origin and 100 g are well inside.
    CHECK_NOTHROW(parse_scene(scene(R"("time_step": 0.01, "duration": 1, "gravity": [0, -981, 0])",
                                    ball(R"(, "velocity": [1e4, 0, 0], "position": [1e6, 0, 0])")), "ok.json"));
}

TEST_CASE("masses and radii outside the stated range are refused", "[scene][limits]") {
    const SceneError heavy = refused(scene(R"("time_step": 0.01, "duration": 1)",
                                           R"({"shape": {"type": "sphere", "radius": 0.5}, "mass": 1e200})"));
    CHECK(heavy.field() == "bodies[0].mass");
    CHECK(heavy.problem() == "must lie in [1e-12, 1e+12] kg, got 1e+200");
    const SceneError tiny = refused(scene(R"("time_step": 0.01, "duration": 1)",
                                          R"({"shape": {"type": "sphere", "radius": 1e-300}, "mass": 1})"));
    CHECK(tiny.field() == "bodies[0].shape.radius");
}

TEST_CASE("more bodies than the cap are refused before any world reserves for them", "[scene][limits]") {
    // The count is checked before any body is read, so empty objects stand in for bodies
    // (100,001 whole balls take minutes to parse under the sanitizers).
    std::string bodies = "{}";
    for (std::size_t i = 0; i < scene_limits.max_bodies; ++i) bodies += ", {}";
    const SceneError error = refused(scene(R"("time_step": 0.01, "duration": 1)", bodies));
    CHECK(error.field() == "bodies");
    CHECK(error.problem() == "10001 bodies are over the limit of 10000");
}

TEST_CASE("contact timing and the exact-under-gravity integrator are scene choices", "[scene][limits]") {
    const Scene parsed = parse_scene(scene(R"("time_step": 0.01, "duration": 1, "contact_timing": "event",
                                             "integrator": "exact-under-gravity", "swept_spheres": false)", ball()), "ok.json");
    CHECK(parsed.settings.contact_timing == ContactTiming::event);
    CHECK(parsed.settings.integrator == Integrator::exact_under_gravity);
    CHECK_FALSE(parsed.settings.swept_spheres);
    const SceneError error = refused(scene(R"("time_step": 0.01, "duration": 1, "contact_timing": "later")", ball()));
    CHECK(error.field() == "contact_timing");
    CHECK(error.problem() == "unknown contact timing \"later\" (available: discrete, event)");
}

TEST_CASE("a box's half extents have the same range as a radius", "[scene][limits]") {
    const auto box = [](const std::string& half_extents) {
        return R"({"shape": {"type": "box", "half_extents": )" + half_extents + R"(}, "mass": 1})";
    };
    const SceneError tiny = refused(scene(R"("time_step": 0.01, "duration": 1)", box("[1, 1e-160, 1]")));
    CHECK(tiny.field() == "bodies[0].shape.half_extents[1]");
    CHECK(tiny.problem() == "must lie in [1e-09, 1e+09] m, got 1e-160");
    CHECK(refused(scene(R"("time_step": 0.01, "duration": 1)", box("[1e200, 1, 1]"))).field() ==
          "bodies[0].shape.half_extents[0]");
    CHECK(refused(scene(R"("time_step": 0.01, "duration": 1)", box("[1, 1, 1e-300]"))).field() ==
          "bodies[0].shape.half_extents[2]");
    // The ends of the range are fine.
    CHECK_NOTHROW(parse_scene(scene(R"("time_step": 0.01, "duration": 1)", box("[1e-9, 1e9, 1]")), "ok.json"));
}

TEST_CASE("a time step longer than the limit is refused, not left to overflow", "[scene][limits]") {
    const SceneError error = refused(scene(R"("time_step": 1e200, "duration": 1e201)", ball()));
    CHECK(error.field() == "time_step");
    CHECK(error.problem() == "must be at most 1 s, got 1e+200");
    CHECK_NOTHROW(parse_scene(scene(R"("time_step": 1, "duration": 10)", ball()), "ok.json"));
}

TEST_CASE("a spin the rotation step cannot follow is refused, naming the body and the limit", "[scene][limits]") {
    const std::string box = R"({"name": "top", "shape": {"type": "box", "half_extents": [1, 0.5, 0.2]}, "mass": 1, )";
    const SceneError error =
        refused(scene(R"("time_step": 0.01, "duration": 1)", box + R"("angular_velocity": [1e6, 1e6, 0]})"));
    CHECK(error.field() == "bodies[0].angular_velocity");
    CHECK_THAT(error.problem(), StartsWith("body \"top\" may spin at up to "));
    CHECK_THAT(error.problem(), ContainsSubstring("the rotation step follows at most 1024 rad per step"));
    // 10,000 rad/s at 1/240 s (about 40 rad a step) runs, in sub-steps; a ball of any spin turns exactly.
    CHECK_NOTHROW(parse_scene(scene(R"("time_step": 0.004166666666666667, "duration": 1)",
                                    box + R"("angular_velocity": [7000, 7000, 0]})"), "ok.json"));
    CHECK_NOTHROW(parse_scene(scene(R"("time_step": 0.01, "duration": 1)", ball(R"(, "angular_velocity": [1e8, 1e8, 0])")),
                              "ok.json"));
}

TEST_CASE("a file of far more bodies than the limit is refused from its text, in about its reading time", "[scene][limits]") {
    // 300,000 small bodies (about 20 MB): counted by the first pass, before any document of
    // them is built. This once took up to a minute (a parse callback is quadratic in
    // nlohmann 3.11); the count is what is checked here, the speed by its absence of a timeout.
    std::string bodies = R"({"shape": {"type": "sphere", "radius": 0.1}, "mass": 1})";
    std::string all = bodies;
    all.reserve(300'000 * (bodies.size() + 2));
    for (int i = 1; i < 300'000; ++i) all += ", " + bodies;
    const SceneError error = refused(scene(R"("time_step": 0.01, "duration": 1)", all));
    CHECK(error.field() == "bodies");
    CHECK(error.problem() == "300000 bodies are over the limit of 10000");
}
