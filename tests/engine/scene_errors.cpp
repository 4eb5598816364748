// Every way a scene file can be wrong must come back as a SceneError that names the file,
// the field's JSON path and the problem, so that a student can fix it without reading the
// loader. A handful of messages are pinned word for word; the rest check the three parts.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "workbook/contact_solver.hpp"
#include "workbook/response_model.hpp"
#include "workbook/scene.hpp"
#include "workbook/world.hpp"

using namespace workbook;
using Catch::Matchers::ContainsSubstring;
using Catch::Matchers::StartsWith;

namespace {

constexpr std::string_view file_name = "bad.json";

const std::string valid_ball = R"({"name": "ball", "shape": {"type": "sphere", "radius": 0.5}, "mass": 1})";

/// A complete scene around the given top-level members (each followed by a comma).
std::string scene_with(const std::string& members, const std::string& bodies) {
    return R"({"title": "test", "responder": "elastic", )" + members + R"("bodies": [)" + bodies + "]}";
}

/// A valid scene whose bodies[1] is `body`, so that errors must carry the right index.
std::string scene_with_second_body(const std::string& body) {
    return scene_with(R"("time_step": 0.01, "duration": 1, )", valid_ball + ", " + body);
}

/// The error parse_scene raises for `text`; fails the test if it raises none.
SceneError error_from(const std::string& text, std::span<const std::string_view> known_responders = {}) {
    try {
        (void)parse_scene(text, std::string(file_name), known_responders);
    } catch (const SceneError& error) {
        return error;
    }
    FAIL("parse_scene accepted a bad scene:\n" << text);
    return SceneError("", "", "");
}

/// The three parts are consistent with what(), which is "FILE: FIELD: PROBLEM".
void check_parts(const SceneError& error, std::string_view field, std::string_view problem_start) {
    CAPTURE(error.what());
    CHECK(error.file() == file_name);
    CHECK(error.field() == field);
    CHECK_THAT(error.problem(), StartsWith(std::string(problem_start)));
    CHECK(std::string(error.what()) == std::string(file_name) + ": " + std::string(field) + ": " + error.problem());
}

}  // namespace

TEST_CASE("scene error messages read FILE: FIELD: PROBLEM, word for word", "[scene][errors]") {
    const auto check_message = [](const std::string& text, std::string_view field, std::string_view problem,
                                  std::string_view what) {
        const SceneError error = error_from(text);
        check_parts(error, field, problem);
        CHECK(error.problem() == problem);
        CHECK(error.what() == what);
    };
    check_message(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": 0.5}, "mass": -2})"), "bodies[1].mass",
                  "must be a positive finite number, got -2",
                  "bad.json: bodies[1].mass: must be a positive finite number, got -2");
    check_message(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": 0}, "mass": 1})"),
                  "bodies[1].shape.radius", "must be a positive finite number, got 0",
                  "bad.json: bodies[1].shape.radius: must be a positive finite number, got 0");
    check_message(
        scene_with_second_body(R"({"shape": {"type": "sphere", "radius": 0.5}, "mass": 1, "veloctiy": [1, 0, 0]})"),
        "bodies[1].veloctiy",
        "unknown key (allowed here: name, shape, mass, immovable, position, velocity, angular_velocity, restitution, "
        "friction, static_friction, orientation, kinematic)",
        "bad.json: bodies[1].veloctiy: unknown key (allowed here: name, shape, mass, immovable, position, velocity, "
        "angular_velocity, restitution, friction, static_friction, orientation, kinematic)");
    check_message(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": 0.5}, "mass": "2"})"),
                  "bodies[1].mass", R"(must be a number, got the string "2")",
                  R"(bad.json: bodies[1].mass: must be a number, got the string "2")");
    check_message(scene_with(R"("time_step": 0.01, "duration": 1, )",
                             valid_ball + R"(, {"shape": {"type": "sphere", "radius": 1}, "mass": 1e999})"),
                  "bodies[1].mass", "must be a finite number, got a value too large for a double",
                  "bad.json: bodies[1].mass: must be a finite number, got a value too large for a double");
    check_message(scene_with(R"("time_step": 0.01, )", valid_ball), "duration", "missing required field",
                  "bad.json: duration: missing required field");
}

TEST_CASE("unknown keys are named with their full path", "[scene][errors]") {
    SECTION("top level") {
        check_parts(error_from(scene_with(R"("time_step": 0.01, "duration": 1, "gravty": [0, -9.81, 0], )", valid_ball)),
                    "gravty",
                    "unknown key (allowed here: title, description, responder, time_step, duration, gravity, integrator, "
                    "position_correction, sweep, bodies, contact_timing, swept_spheres, contact_solver)");
    }
    SECTION("in a body") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "sphere", "radius": 0.5}, "mass": 1, "colour": "red"})")),
                    "bodies[1].colour", "unknown key");
    }
    SECTION("in a sphere's shape") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "sphere", "radius": 0.5, "normal": [0, 1, 0]}, "mass": 1})")),
                    "bodies[1].shape.normal", "unknown key (allowed here: type, radius)");
    }
    SECTION("in a plane's shape") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "plane", "normal": [0, 1, 0], "radius": 1}, "immovable": true})")),
                    "bodies[1].shape.radius", "unknown key (allowed here: type, normal)");
    }
}

TEST_CASE("missing required fields are named", "[scene][errors]") {
    SECTION("title") {
        check_parts(error_from(R"({"responder": "elastic", "time_step": 0.01, "duration": 1, "bodies": [)" + valid_ball +
                               "]}"),
                    "title", "missing required field");
    }
    SECTION("bodies") {
        check_parts(error_from(R"({"title": "t", "responder": "elastic", "time_step": 0.01, "duration": 1})"), "bodies",
                    "missing required field");
    }
    SECTION("a body's shape") {
        check_parts(error_from(scene_with_second_body(R"({"mass": 1})")), "bodies[1].shape", "missing required field");
    }
    SECTION("a shape's type") {
        check_parts(error_from(scene_with_second_body(R"({"shape": {"radius": 1}, "mass": 1})")), "bodies[1].shape.type",
                    "missing required field");
    }
    SECTION("a sphere's radius") {
        check_parts(error_from(scene_with_second_body(R"({"shape": {"type": "sphere"}, "mass": 1})")),
                    "bodies[1].shape.radius", "missing required field");
    }
    SECTION("a movable body's mass") {
        check_parts(error_from(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": 1}})")),
                    "bodies[1].mass", "missing required field");
    }
}

TEST_CASE("masses, radii and times must be positive", "[scene][errors]") {
    SECTION("zero mass") {
        check_parts(error_from(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": 1}, "mass": 0})")),
                    "bodies[1].mass", "must be a positive finite number, got 0");
    }
    SECTION("a mass that underflows to zero") {
        check_parts(error_from(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1e-999})")),
                    "bodies[1].mass", "must be a positive finite number, got 0");
    }
    SECTION("negative radius") {
        check_parts(error_from(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": -0.5}, "mass": 1})")),
                    "bodies[1].shape.radius", "must be a positive finite number, got -0.5");
    }
    SECTION("zero time step") {
        check_parts(error_from(scene_with(R"("time_step": 0, "duration": 1, )", valid_ball)), "time_step",
                    "must be a positive finite number, got 0");
    }
    SECTION("negative duration") {
        check_parts(error_from(scene_with(R"("time_step": 0.01, "duration": -1, )", valid_ball)), "duration",
                    "must be a positive finite number, got -1");
    }
    SECTION("a duration shorter than one step") {
        check_parts(error_from(scene_with(R"("time_step": 0.01, "duration": 0.001, )", valid_ball)), "duration",
                    "must be at least one time step (0.01 s)");
    }
}

TEST_CASE("numbers too large for a double are rejected by field, not by a parser exception", "[scene][errors]") {
    // JSON has no NaN or infinity literal; 1e999 is the nearest a file can come to one.
    SECTION("a top-level number") {
        check_parts(error_from(scene_with(R"("time_step": 1e999, "duration": 1, )", valid_ball)), "time_step",
                    "must be a finite number");
    }
    SECTION("a body's mass") {
        check_parts(error_from(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": 1}, "mass": -1e999})")),
                    "bodies[1].mass", "must be a finite number");
    }
    SECTION("a component of a vector") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "position": [0, 1e999, 0]})")),
                    "bodies[1].position[1]", "must be a finite number");
    }
    SECTION("a shape's radius, after an array and a nested object") {
        check_parts(error_from(scene_with(R"("time_step": 0.01, "duration": 1, "gravity": [0, -9.81, 0], )",
                                          valid_ball + ", " + valid_ball +
                                              R"(, {"shape": {"type": "sphere", "radius": 2e400}, "mass": 1})")),
                    "bodies[2].shape.radius", "must be a finite number");
    }
}

TEST_CASE("values of the wrong type are named with what was found", "[scene][errors]") {
    SECTION("a string where a number belongs") {
        check_parts(error_from(scene_with(R"("time_step": "fast", "duration": 1, )", valid_ball)), "time_step",
                    R"(must be a number, got the string "fast")");
    }
    SECTION("NaN spelled as a string") {
        check_parts(error_from(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": "NaN"}, "mass": 1})")),
                    "bodies[1].shape.radius", R"(must be a number, got the string "NaN")");
    }
    SECTION("null where a number belongs") {
        check_parts(error_from(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": 1}, "mass": null})")),
                    "bodies[1].mass", "must be a number, got null");
    }
    SECTION("a number where a string belongs") {
        check_parts(error_from(scene_with(R"("time_step": 0.01, "duration": 1, "description": 5, )", valid_ball)),
                    "description", "must be a string, got the number 5");
    }
    SECTION("a number where true or false belongs") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "immovable": 1})")),
                    "bodies[1].immovable", "must be true or false, got the number 1");
    }
    SECTION("a vector with two components") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "velocity": [1, 2]})")),
                    "bodies[1].velocity", "must be an array of three numbers [x, y, z], got [1,2]");
    }
    SECTION("a vector with a string component") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "angular_velocity": [0, "1", 0]})")),
                    "bodies[1].angular_velocity[1]", R"(must be a number, got the string "1")");
    }
    SECTION("a body that is not an object") {
        check_parts(error_from(scene_with_second_body("3")), "bodies[1]", "must be an object, got the number 3");
    }
    SECTION("a shape that is not an object") {
        check_parts(error_from(scene_with_second_body(R"({"shape": "sphere", "mass": 1})")), "bodies[1].shape",
                    R"(must be an object, got the string "sphere")");
    }
    SECTION("bodies that are not an array") {
        check_parts(error_from(R"({"title": "t", "responder": "r", "time_step": 0.01, "duration": 1, "bodies": {}})"),
                    "bodies", "must be a non-empty array of bodies");
    }
    SECTION("no bodies at all") {
        check_parts(error_from(scene_with(R"("time_step": 0.01, "duration": 1, )", "")), "bodies",
                    "must be a non-empty array of bodies");
    }
}

TEST_CASE("body-level rules: restitution, planes, immovable bodies, shapes", "[scene][errors]") {
    SECTION("restitution above 1") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "restitution": 1.5})")),
                    "bodies[1].restitution", "must lie in [0, 1], got 1.5");
    }
    SECTION("negative restitution") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "restitution": -0.25})")),
                    "bodies[1].restitution", "must lie in [0, 1], got -0.25");
    }
    SECTION("negative friction") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "friction": -0.5})")),
                    "bodies[1].friction", "must lie in [0, 10], got -0.5");
    }
    SECTION("static friction below the dynamic one") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "friction": 0.5, "static_friction": 0.4})")),
                    "bodies[1].static_friction",
                    "must lie in [friction, 10] = [0.5, 10] (a body starts sliding at least as easily as it keeps "
                    "sliding), got 0.4");
    }
    SECTION("a plane that is not immovable") {
        check_parts(error_from(scene_with_second_body(R"({"shape": {"type": "plane", "normal": [0, 1, 0]}, "mass": 5})")),
                    "bodies[1].immovable", "a plane must be immovable");
    }
    SECTION("a plane with a zero normal") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "plane", "normal": [0, 0, 0]}, "immovable": true})")),
                    "bodies[1].shape.normal", "must not be the zero vector");
    }
    SECTION("an immovable body with a mass") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "sphere", "radius": 1}, "immovable": true, "mass": 3})")),
                    "bodies[1].mass", "an immovable body has no mass");
    }
    SECTION("an immovable body with an angular velocity") {
        check_parts(error_from(scene_with_second_body(
                        R"({"shape": {"type": "sphere", "radius": 1}, "immovable": true, "angular_velocity": [0, 1, 0]})")),
                    "bodies[1].angular_velocity", "an immovable body cannot rotate");
    }
    SECTION("an unknown shape type") {
        check_parts(error_from(scene_with_second_body(R"({"shape": {"type": "cube", "size": 1}, "mass": 1})")),
                    "bodies[1].shape.type", R"(unknown shape type "cube" (supported: sphere, plane, box))");
    }
}

TEST_CASE("the integrator is one of those the world has", "[scene][errors]") {
    const std::string explicit_euler =
        scene_with(R"("time_step": 0.01, "duration": 1, "integrator": "explicit-euler", )", valid_ball);
    CHECK(parse_scene(explicit_euler, "good.json").settings.integrator == Integrator::explicit_euler);
    const SceneError error = error_from(scene_with(R"("time_step": 0.01, "duration": 1, "integrator": "rk4", )", valid_ball));
    check_parts(error, "integrator", R"(unknown integrator "rk4" (available: semi-implicit-euler, explicit-euler, exact-under-gravity))");
}

TEST_CASE("an unknown responder is named with the ones that exist", "[scene][errors]") {
    const std::array<std::string_view, 2> known{"inelastic", "impulse"};
    const std::string text = scene_with(R"("time_step": 0.01, "duration": 1, )", valid_ball);  // responder "elastic"
    const SceneError error = error_from(text, known);
    check_parts(error, "responder", R"(unknown responder "elastic" (available: inelastic, impulse))");
    CHECK(std::string(error.what()) ==
          R"(bad.json: responder: unknown responder "elastic" (available: inelastic, impulse))");

    const std::array<std::string_view, 1> elastic{"elastic"};
    CHECK(parse_scene(text, "good.json", elastic).responder == "elastic");
    CHECK(parse_scene(text, "good.json").responder == "elastic");  // an empty list accepts any name
}

TEST_CASE("invalid JSON syntax is reported with the file and the parser's position", "[scene][errors]") {
    const SceneError error = error_from(R"({"title": "t", "bodies": [1, 2)");
    CHECK(error.file() == file_name);
    CHECK(error.field().empty());  // no field to name: the text never became a document
    CHECK_THAT(error.problem(), StartsWith("not valid JSON: "));
    CHECK_THAT(error.problem(), ContainsSubstring("line 1, column 31"));
    CHECK(std::string(error.what()) == "bad.json: " + error.problem());

    CHECK_THAT(error_from(R"({"mass": NaN})").problem(), StartsWith("not valid JSON: "));
    CHECK_THAT(error_from("").problem(), StartsWith("not valid JSON: "));
}

TEST_CASE("a document that is not an object", "[scene][errors]") {
    const SceneError error = error_from("[1, 2, 3]");
    CHECK(error.file() == file_name);
    CHECK(error.field().empty());  // the root has no name of its own
    CHECK(error.problem() == "must be an object, got array");
}

TEST_CASE("a missing file is a SceneError naming the file", "[scene][errors]") {
    const std::filesystem::path missing = std::filesystem::path("no-such-directory") / "no-such-scene.json";
    try {
        (void)load_scene(missing);
        FAIL("load_scene read a file that does not exist");
    } catch (const SceneError& error) {
        CHECK(error.file() == missing.string());
        CHECK(error.field().empty());
        CHECK(error.problem() == "cannot open the file");
        CHECK(std::string(error.what()) == missing.string() + ": cannot open the file");
    }
}

TEST_CASE("position correction knobs are checked with their path", "[scene][errors]") {
    const auto with_knobs = [](const std::string& knobs) {
        return scene_with(R"("time_step": 0.01, "duration": 1, "position_correction": )" + knobs + ", ", valid_ball);
    };
    check_parts(error_from(with_knobs(R"({"fraction": 0})")), "position_correction.fraction", "must lie in (0, 4], got 0");
    check_parts(error_from(with_knobs(R"({"fraction": 4.5})")), "position_correction.fraction", "must lie in (0, 4], got 4.5");
    check_parts(error_from(with_knobs(R"({"slop": -0.001})")), "position_correction.slop",
                "must be zero or positive, got -0.001");
    check_parts(error_from(with_knobs(R"({"percent": 0.2})")), "position_correction.percent",
                "unknown key (allowed here: fraction, slop)");
    check_parts(error_from(with_knobs("0.2")), "position_correction", "must be an object");
}

TEST_CASE("a fraction sweep is checked value by value, with its path", "[scene][errors]") {
    const auto with_sweep = [](const std::string& sweep) {
        return scene_with(R"("time_step": 0.01, "duration": 1, "sweep": )" + sweep + ", ", valid_ball);
    };
    check_parts(error_from(with_sweep(R"({"fraction": []})")), "sweep.fraction", "must be a non-empty array of numbers");
    check_parts(error_from(with_sweep(R"({"fraction": [0.5, 0]})")), "sweep.fraction[1]", "must lie in (0, 4], got 0");
    check_parts(error_from(with_sweep(R"({"fraction": [0.5, "1"]})")), "sweep.fraction[1]",
                "must be a number, got the string \"1\"");
    check_parts(error_from(with_sweep(R"({"slop": [0.5]})")), "sweep.slop", "unknown key (allowed here: fraction)");
}

TEST_CASE("a key given twice in one object is refused, naming it, at any depth", "[scene][errors]") {
    const SceneError body = error_from(scene_with_second_body(
        R"({"shape": {"type": "sphere", "radius": 0.5}, "mass": 1, "mass": 2})"));
    CHECK(body.field() == "bodies[1].mass");
    CHECK(body.problem() == "the key \"mass\" is given twice in one object");
    CHECK(error_from(scene_with(R"("time_step": 0.01, "time_step": 0.02, "duration": 1, )", valid_ball)).field() ==
          "time_step");
    CHECK(error_from(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": 0.5, "radius": 1}, "mass": 1})"))
              .field() == "bodies[1].shape.radius");
}

TEST_CASE("a value nested absurdly deep is refused by its path, without walking it recursively", "[scene][errors]") {
    // 100,000 nested arrays once overflowed the stack: the error message dumped the value
    // recursively. The first pass stops at the depth limit; nothing else ever sees the value.
    constexpr int depth = 100'000;
    const std::string nested = std::string(depth, '[') + std::string(depth, ']');
    const SceneError error = error_from(scene_with_second_body(
        R"({"shape": {"type": "sphere", "radius": 0.5}, "mass": 1, "position": )" + nested + "}"));
    CHECK_THAT(error.field(), StartsWith("bodies[1].position[0][0]"));
    CHECK(error.problem() == "nested more than 32 levels deep (a scene needs 5: root, bodies, body, shape, vector)");
    // Within the depth limit, a wrong value is described by its type and size, not dumped.
    const SceneError shallow = error_from(scene_with_second_body(
        R"({"shape": {"type": "sphere", "radius": 0.5}, "mass": 1, "position": [[[[1, 2, 3]]]]})"));
    CHECK(shallow.field() == "bodies[1].position");
    CHECK(shallow.problem() == "must be an array of three numbers [x, y, z], got an array of 1 element");
    const SceneError flat = error_from(scene_with_second_body(
        R"({"shape": {"type": "sphere", "radius": 0.5}, "mass": 1, "position": [1, 2]})"));
    CHECK(flat.problem() == "must be an array of three numbers [x, y, z], got [1,2]");
}

TEST_CASE("the contact solver's knobs are checked", "[scene][errors]") {
    const std::string start = R"({"title": "t", "responder": "none", "time_step": 0.01, "duration": 1,
        "bodies": [{"shape": {"type": "sphere", "radius": 1}, "mass": 1, "position": [0, 0, 0]}], "contact_solver": )";
    auto problem = [&](const std::string& knobs) {
        try {
            (void)workbook::parse_scene(start + knobs + "}", "bad.json");
        } catch (const workbook::SceneError& error) {
            return error.field() + ": " + error.problem();
        }
        return std::string("no error");
    };
    CHECK(problem(R"({"velocity_iterations": 2.5})") == "contact_solver.velocity_iterations: must be a whole number from 0 to 10000, got 2.5");
    CHECK(problem(R"({"friction": 0.5})") ==
          "contact_solver.friction: is no longer a knob of the contact solver: give each body its own \"friction\" (the "
          "ground too; a pair takes the geometric mean) and use the responder \"friction\"");
    CHECK(problem(R"({"warm_start": 1})") == "contact_solver.warm_start: must be true or false, got the number 1");
    CHECK(problem(R"({"sleeping": "no"})").starts_with("contact_solver.sleeping: must be true or false"));
    CHECK(problem(R"({"iterations": 5})").starts_with("contact_solver.iterations: unknown key"));
    CHECK(problem(R"({"velocity_iterations": 7, "warm_start": false})") == "no error");
    CHECK(problem(R"({"shock_sweeps": 1.5})") == "contact_solver.shock_sweeps: must be a whole number from 0 to 10000, got 1.5");
    CHECK(problem(R"({"speculative_distance": -0.01})") == "contact_solver.speculative_distance: must lie in [0, 1e+09] m, got -0.01");
    CHECK(problem(R"({"speculative_distance": 1e10})") == "contact_solver.speculative_distance: must lie in [0, 1e+09] m, got 1e+10");
    CHECK(problem(R"({"shock_sweeps": 1, "speculative_distance": 0.02})") == "no error");
    const Scene both = parse_scene(start + R"({"shock_sweeps": 2, "speculative_distance": 0.02}})", "good.json");
    CHECK(both.settings.contact_solver.shock_sweeps == 2);
    CHECK(both.settings.contact_solver.speculative_distance == 0.02);
}

TEST_CASE("friction: static defaults to dynamic, and a responder without friction refuses it", "[scene][errors]") {
    const std::string start = R"({"title": "t", "responder": "r", "time_step": 0.01, "duration": 1, "bodies": [
        {"shape": {"type": "sphere", "radius": 1}, "mass": 1, "position": [0, 0, 2]}, )";
    const Scene plain = parse_scene(start + R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "friction": 0.3}]})", "f.json");
    CHECK(plain.bodies[0].friction == 0.0);
    CHECK(plain.bodies[0].static_friction == 0.0);
    CHECK(plain.bodies[1].friction == 0.3);
    CHECK(plain.bodies[1].static_friction == 0.3);
    const Scene both = parse_scene(
        start + R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "friction": 0.3, "static_friction": 0.6}]})", "f.json");
    CHECK(both.bodies[1].static_friction == 0.6);

    // A contact solver without a friction pass (chapter 5's) and no solver at all: refused,
    // naming the file and the body's field.
    const ContactSolverHooks frictionless{};
    for (const ResponseModel& model : {ResponseModel{"plain", nullptr, nullptr}, ResponseModel{"solver", nullptr, nullptr, &frictionless}}) {
        try {
            (void)make_world(plain, model);
            FAIL("a body with friction was accepted by the responder " << model.name);
        } catch (const SceneError& error) {
            CHECK(error.file() == "f.json");
            CHECK(error.field() == "bodies[1].friction");
            CHECK(error.problem() == "the responder \"" + std::string(model.name) +
                                         "\" has no friction; use the responder \"friction\" (chapter 6) or remove the field");
        }
    }
}
