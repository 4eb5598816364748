// Boxes, orientations and kinematic bodies in scene files: what a valid file gives, and the
// path-named error each mistake gets (in the style of scene_errors.cpp).
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>

#include "checks.hpp"
#include "workbook/scene.hpp"

using namespace workbook;
using workbook::engine_tests::is_close_to;
using Catch::Matchers::StartsWith;
using Catch::Matchers::WithinAbs;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr std::string_view file_name = "boxes.json";

const std::string valid_ball = R"({"name": "ball", "shape": {"type": "sphere", "radius": 0.5}, "mass": 1})";

/// A valid scene whose bodies[1] is `body`.
std::string scene_with_second_body(const std::string& body) {
    return R"({"title": "t", "responder": "none", "time_step": 0.01, "duration": 1, "bodies": [)" + valid_ball + ", " +
           body + "]}";
}

/// The error parse_scene raises for `text`, checked to read FILE: FIELD: PROBLEM.
void check_error(const std::string& text, std::string_view field, std::string_view problem_start) {
    try {
        (void)parse_scene(text, std::string(file_name));
    } catch (const SceneError& error) {
        CAPTURE(error.what());
        CHECK(error.file() == file_name);
        CHECK(error.field() == field);
        CHECK_THAT(error.problem(), StartsWith(std::string(problem_start)));
        CHECK(std::string(error.what()) == std::string(file_name) + ": " + std::string(field) + ": " + error.problem());
        return;
    }
    FAIL("parse_scene accepted a bad scene:\n" << text);
}

RigidBody second_body(const std::string& body) { return parse_scene(scene_with_second_body(body), "good.json").bodies[1]; }

}  // namespace

TEST_CASE("a box has its half extents and the inertia m/12 (b^2 + c^2) of its full edges", "[scene][box]") {
    const RigidBody box = second_body(R"({"shape": {"type": "box", "half_extents": [1, 2, 3]}, "mass": 12})");
    CHECK(box.shape.kind == ShapeKind::box);
    CHECK(box.shape.half_extents == Vector3{1, 2, 3});
    CHECK(box.inverse_mass == 1.0 / 12.0);
    // Edges 2, 4, 6 m: Ixx = 12/12 (16 + 36) = 52, Iyy = 12/12 (4 + 36) = 40, Izz = 12/12 (4 + 16) = 20.
    CHECK(box.inertia_body == Matrix3::diagonal({52, 40, 20}));
    CHECK(box.orientation == Quaternion{});  // the default
    CHECK_THAT(box.inverse_inertia_world, is_close_to(Matrix3::diagonal({1.0 / 52, 1.0 / 40, 1.0 / 20}), eps));
}

TEST_CASE("an orientation as axis and angle in degrees, or as a unit quaternion", "[scene][box]") {
    const std::string box = R"({"shape": {"type": "box", "half_extents": [1, 2, 3]}, "mass": 12, "orientation": )";
    SECTION("a quarter turn about z, axis not normalised") {
        const RigidBody b = second_body(box + R"({"axis": [0, 0, 5], "angle_degrees": 90}})");
        const double s = std::sqrt(0.5);
        CHECK_THAT(b.orientation, is_close_to(Quaternion{s, 0, 0, s}, eps));
        // Body x now lies along world y: the world inverse inertia swaps its first two entries.
        CHECK_THAT(b.inverse_inertia_world, is_close_to(Matrix3::diagonal({1.0 / 40, 1.0 / 52, 1.0 / 20}), 4 * eps));
    }
    SECTION("the same turn as a quaternion, normalised within the tolerance") {
        const RigidBody b = second_body(box + R"({"quaternion": [0.7071068, 0, 0, 0.7071068]}})");
        CHECK_THAT(norm(b.orientation), WithinAbs(1.0, 2 * eps));
        CHECK_THAT(b.orientation, is_close_to(Quaternion{std::sqrt(0.5), 0, 0, std::sqrt(0.5)}, 2 * eps));
    }
    SECTION("a sphere may be turned too") {
        const RigidBody b = second_body(
            R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "orientation": {"axis": [1, 0, 0], "angle_degrees": 180}})");
        CHECK_THAT(b.orientation, is_close_to(Quaternion{0, 1, 0, 0}, eps));
    }
}

TEST_CASE("a kinematic body: immovable, with its velocity", "[scene][kinematic]") {
    const RigidBody platform = second_body(
        R"({"shape": {"type": "box", "half_extents": [2, 0.1, 1]}, "kinematic": true, "velocity": [0.5, 0, 0]})");
    CHECK(platform.is_immovable());
    CHECK(platform.velocity == Vector3{0.5, 0, 0});
    CHECK(platform.inertia_body == Matrix3::zero());
    CHECK(platform.inverse_inertia_world == Matrix3::zero());

    const RigidBody turntable = second_body(
        R"({"shape": {"type": "plane", "normal": [0, 1, 0]}, "kinematic": true, "angular_velocity": [0, 1, 0]})");
    CHECK(turntable.is_immovable());
    CHECK(turntable.angular_velocity == Vector3{0, 1, 0});
}

TEST_CASE("box shapes are checked with their path", "[scene][box][errors]") {
    check_error(scene_with_second_body(R"({"shape": {"type": "box", "half_extents": [1, 0, 1]}, "mass": 1})"),
                "bodies[1].shape.half_extents", "every half extent must be a positive number of metres, got [1, 0, 1]");
    check_error(scene_with_second_body(R"({"shape": {"type": "box", "half_extents": [1, -2, 1]}, "mass": 1})"),
                "bodies[1].shape.half_extents", "every half extent must be a positive number");
    check_error(scene_with_second_body(R"({"shape": {"type": "box"}, "mass": 1})"), "bodies[1].shape.half_extents",
                "missing required field");
    check_error(scene_with_second_body(R"({"shape": {"type": "box", "half_extents": [1, 1]}, "mass": 1})"),
                "bodies[1].shape.half_extents", "must be an array of three numbers");
    check_error(scene_with_second_body(R"({"shape": {"type": "box", "half_extents": [1, 1, 1], "radius": 1}, "mass": 1})"),
                "bodies[1].shape.radius", "unknown key (allowed here: type, half_extents)");
}

TEST_CASE("orientations are checked with their path", "[scene][box][errors]") {
    const auto with = [](const std::string& orientation) {
        return scene_with_second_body(R"({"shape": {"type": "box", "half_extents": [1, 1, 1]}, "mass": 1, "orientation": )" +
                                      orientation + "}");
    };
    check_error(with(R"({"axis": [0, 0, 0], "angle_degrees": 30})"), "bodies[1].orientation.axis",
                "must not be the zero vector");
    check_error(with(R"({"quaternion": [1, 0, 0, 0.01]})"), "bodies[1].orientation.quaternion",
                "must be a unit quaternion (length 1 within 1e-06), got length 1.00005");
    check_error(with(R"({"quaternion": [0, 0, 0, 0]})"), "bodies[1].orientation.quaternion",
                "must be a unit quaternion (length 1 within 1e-06), got length 0");
    check_error(with(R"({"quaternion": [1, 0, 0]})"), "bodies[1].orientation.quaternion",
                "must be an array of four numbers [w, x, y, z], got [1,0,0]");
    check_error(with(R"({"quaternion": [1, 0, "0", 0]})"), "bodies[1].orientation.quaternion[2]",
                R"(must be a number, got the string "0")");
    check_error(with(R"({"quaternion": [1, 0, 0, 1e999]})"), "bodies[1].orientation.quaternion[3]",
                "must be a finite number");
    check_error(with(R"({"axis": [0, 1, 0], "angle_degrees": 30, "quaternion": [1, 0, 0, 0]})"), "bodies[1].orientation",
                R"(give either "quaternion" or "axis" with "angle_degrees", not both)");
    check_error(with(R"({"axis": [0, 1, 0]})"), "bodies[1].orientation.angle_degrees", "missing required field");
    check_error(with(R"({"angle_degrees": 30})"), "bodies[1].orientation.axis", "missing required field");
    check_error(with("{}"), "bodies[1].orientation", R"(give "axis" and "angle_degrees", or "quaternion")");
    check_error(with(R"({"axis": [0, 1, 0], "angle": 30})"), "bodies[1].orientation.angle",
                "unknown key (allowed here: axis, angle_degrees, quaternion)");
    check_error(with("30"), "bodies[1].orientation", "must be an object, got the number 30");
}

TEST_CASE("kinematic bodies are checked with their path", "[scene][kinematic][errors]") {
    check_error(scene_with_second_body(
                    R"({"shape": {"type": "sphere", "radius": 1}, "kinematic": true, "immovable": true, "velocity": [1, 0, 0]})"),
                "bodies[1].kinematic", "a body is either immovable (never moves) or kinematic (moves at a set velocity), not both");
    check_error(scene_with_second_body(
                    R"({"shape": {"type": "sphere", "radius": 1}, "kinematic": true, "mass": 2, "velocity": [1, 0, 0]})"),
                "bodies[1].mass", "a kinematic body has no mass");
    check_error(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": 1}, "kinematic": true})"),
                "bodies[1].velocity", "a kinematic body needs a velocity or an angular_velocity");
    check_error(scene_with_second_body(R"({"shape": {"type": "sphere", "radius": 1}, "kinematic": "yes"})"),
                "bodies[1].kinematic", R"(must be true or false, got the string "yes")");
    // The immovable body's refusal now points at the kinematic alternative.
    check_error(scene_with_second_body(
                    R"({"shape": {"type": "sphere", "radius": 1}, "immovable": true, "velocity": [1, 0, 0]})"),
                "bodies[1].velocity",
                R"(an immovable body cannot move; give it no velocity (a moving platform is "kinematic": true))");
}

TEST_CASE("a kinematic platform from a scene file moves through the world at its velocity", "[scene][kinematic][world]") {
    const Scene scene = parse_scene(R"({"title": "lift", "responder": "none", "time_step": 0.0078125, "duration": 1,
        "gravity": [0, -8, 0],
        "bodies": [
          {"name": "lift", "shape": {"type": "box", "half_extents": [1, 0.125, 1]}, "kinematic": true,
           "velocity": [0, 0.5, 0], "orientation": {"axis": [0, 1, 0], "angle_degrees": 30}},
          {"name": "crate", "shape": {"type": "box", "half_extents": [0.25, 0.25, 0.25]}, "mass": 2, "position": [0, 0.375, 0]}
        ]})",
                                    "lift.json");
    World world = make_world(scene, ResponseModel{"none", nullptr, nullptr});
    // Resting on the platform's top face at the start; one step later they overlap, the
    // crate's bottom face inside the platform's turned top face: four points.
    world.step();
    REQUIRE(world.contacts().size() == 1);
    CHECK(world.contacts()[0].point_count == 4);
    CHECK(world.contacts()[0].body1 == 0);
    CHECK_THAT(world.contacts()[0].normal, is_close_to(Vector3{0, -1, 0}, eps));
    for (int n = 1; n < 128; ++n) world.step();
    // 128 steps of 1/128 s at 0.5 m/s, in exact binary arithmetic; gravity does not pull it.
    CHECK(world.bodies()[0].position == Vector3{0, 0.5, 0});
    CHECK(world.bodies()[0].velocity == Vector3{0, 0.5, 0});
    CHECK(world.bodies()[0].orientation == scene.bodies[0].orientation);
    // The crate, with no responder, fell through it.
    CHECK(world.bodies()[1].velocity.y == -8.0);
    CHECK(world.probes().kinetic_linear == 0.5 * 2 * 64);  // the platform is left out
}
