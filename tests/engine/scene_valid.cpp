// A valid scene parses to exactly the bodies and settings it describes, with the defaults
// the format promises, from text and from a file.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "checks.hpp"
#include "workbook/scene.hpp"

using namespace workbook;
using workbook::engine_tests::is_close_to;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

const std::string two_balls_on_the_ground = R"({
  "title": "Two balls on the ground",
  "description": "A heavy ball hits a light one.",
  "responder": "impulse",
  "time_step": 0.005,
  "duration": 2,
  "gravity": [0, -9.81, 0],
  "bodies": [
    {"name": "heavy", "shape": {"type": "sphere", "radius": 0.5}, "mass": 4,
     "position": [-2, 0.5, 0], "velocity": [3, 0, 0], "angular_velocity": [0, 0, -6], "restitution": 0.75},
    {"shape": {"type": "sphere", "radius": 0.25}, "mass": 0.5, "position": [1, 0.25, 0]},
    {"name": "ground", "shape": {"type": "plane", "normal": [0, 2, 0]}, "immovable": true},
    {"name": "post", "shape": {"type": "sphere", "radius": 0.125}, "immovable": true, "position": [4, 0, 0],
     "restitution": 0}
  ]
})";

const ResponseModel no_response{"none", nullptr, nullptr};

}  // namespace

TEST_CASE("a valid scene parses to its settings", "[scene]") {
    const Scene scene = parse_scene(two_balls_on_the_ground, "two_balls.json");
    CHECK(scene.title == "Two balls on the ground");
    CHECK(scene.description == "A heavy ball hits a light one.");
    CHECK(scene.responder == "impulse");
    CHECK(scene.settings.time_step == 0.005);
    CHECK(scene.duration == 2.0);
    CHECK(scene.settings.gravity == Vector3{0, -9.81, 0});
    CHECK(scene.settings.integrator == Integrator::semi_implicit_euler);  // the default
    CHECK(scene.settings.position_correction.fraction == 1.0);           // the default: the whole depth
    CHECK(scene.settings.position_correction.slop == 0.0);
    REQUIRE(scene.bodies.size() == 4);
    CHECK(scene.body_names == std::vector<std::string>{"heavy", "bodies[1]", "ground", "post"});
}

TEST_CASE("a valid scene parses to the right movable bodies", "[scene]") {
    const Scene scene = parse_scene(two_balls_on_the_ground, "two_balls.json");
    REQUIRE(scene.bodies.size() == 4);

    const RigidBody& heavy = scene.bodies[0];
    CHECK(heavy.shape.kind == ShapeKind::sphere);
    CHECK(heavy.shape.radius == 0.5);
    CHECK(heavy.inverse_mass == 0.25);
    CHECK(heavy.mass() == 4.0);
    CHECK(heavy.inertia_body == solid_sphere_inertia(4.0, 0.5));
    CHECK_THAT(heavy.inverse_inertia_world, is_close_to(Matrix3::diagonal({2.5, 2.5, 2.5}), 4 * eps));
    CHECK(heavy.position == Vector3{-2, 0.5, 0});
    CHECK(heavy.velocity == Vector3{3, 0, 0});
    CHECK(heavy.angular_velocity == Vector3{0, 0, -6});
    CHECK(heavy.orientation == Quaternion{});
    CHECK(heavy.restitution == 0.75);

    // Everything optional left out: at rest, not spinning, perfectly elastic.
    const RigidBody& light = scene.bodies[1];
    CHECK(light.shape.radius == 0.25);
    CHECK(light.inverse_mass == 2.0);
    CHECK(light.velocity == Vector3{});
    CHECK(light.angular_velocity == Vector3{});
    CHECK(light.restitution == 1.0);
}

TEST_CASE("a valid scene parses to the right immovable bodies", "[scene]") {
    const Scene scene = parse_scene(two_balls_on_the_ground, "two_balls.json");
    REQUIRE(scene.bodies.size() == 4);

    const RigidBody& ground = scene.bodies[2];
    CHECK(ground.shape.kind == ShapeKind::plane);
    CHECK(ground.shape.normal == Vector3{0, 1, 0});  // normalized from [0, 2, 0]
    CHECK(ground.is_immovable());
    CHECK(ground.inverse_mass == 0.0);
    CHECK(ground.inverse_inertia_world == Matrix3::zero());
    CHECK(ground.position == Vector3{});

    const RigidBody& post = scene.bodies[3];
    CHECK(post.shape.kind == ShapeKind::sphere);
    CHECK(post.shape.radius == 0.125);
    CHECK(post.is_immovable());
    CHECK(post.inverse_inertia_world == Matrix3::zero());
    CHECK(post.position == Vector3{4, 0, 0});
    CHECK(post.restitution == 0.0);
}

TEST_CASE("a kinematic body with a velocity is a moving platform", "[scene]") {
    const Scene scene = parse_scene(R"({"title": "Platform", "description": "A ball lands on a moving platform.",
      "responder": "none", "time_step": 0.01, "duration": 1, "bodies": [
        {"shape": {"type": "sphere", "radius": 0.5}, "mass": 1, "position": [0, 1, 0]},
        {"name": "platform", "shape": {"type": "plane", "normal": [0, 1, 0]}, "kinematic": true, "velocity": [1.5, 0, 0]}]})",
                                    "platform.json");
    REQUIRE(scene.bodies.size() == 2);
    CHECK(scene.bodies[1].is_immovable());
    CHECK(scene.bodies[1].velocity == Vector3{1.5, 0, 0});
}

TEST_CASE("make_world builds the world a scene describes", "[scene]") {
    const Scene scene = parse_scene(two_balls_on_the_ground, "two_balls.json");
    const World world = make_world(scene, no_response);
    CHECK(world.settings().time_step == 0.005);
    CHECK(world.settings().gravity == Vector3{0, -9.81, 0});
    CHECK(world.model().name == "none");
    CHECK(world.time() == 0.0);
    REQUIRE(world.bodies().size() == scene.bodies.size());
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        CAPTURE(i);
        CHECK(world.bodies()[i].position == scene.bodies[i].position);
        CHECK(world.bodies()[i].inverse_mass == scene.bodies[i].inverse_mass);
    }
}

TEST_CASE("load_scene reads the same scene from a file", "[scene]") {
    // A name of its own, so that parallel runs of the test binary do not share the file.
    std::random_device entropy;
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("workbook-engine-test-" + std::to_string(entropy()) + ".json");
    {
        std::ofstream out(path, std::ios::binary);
        out << two_balls_on_the_ground;
    }
    const Scene from_text = parse_scene(two_balls_on_the_ground, path.string());
    const Scene from_file = load_scene(path);
    std::filesystem::remove(path);

    CHECK(from_file.title == from_text.title);
    CHECK(from_file.body_names == from_text.body_names);
    REQUIRE(from_file.bodies.size() == from_text.bodies.size());
    for (std::size_t i = 0; i < from_text.bodies.size(); ++i) {
        CAPTURE(i);
        CHECK(from_file.bodies[i].position == from_text.bodies[i].position);
        CHECK(from_file.bodies[i].velocity == from_text.bodies[i].velocity);
        CHECK(from_file.bodies[i].inverse_mass == from_text.bodies[i].inverse_mass);
        CHECK(from_file.bodies[i].shape.kind == from_text.bodies[i].shape.kind);
    }
}

TEST_CASE("position correction knobs are read from the scene", "[scene]") {
    std::string text = two_balls_on_the_ground;
    text.replace(text.find(R"("gravity")"), 0, R"("position_correction": {"fraction": 0.2, "slop": 0.005}, )");
    const Scene scene = parse_scene(text, "knobs.json");
    CHECK(scene.settings.position_correction.fraction == 0.2);
    CHECK(scene.settings.position_correction.slop == 0.005);
}

TEST_CASE("a fraction sweep is read from the scene and leaves the run's own knobs alone", "[scene]") {
    std::string text = two_balls_on_the_ground;
    text.replace(text.find(R"("gravity")"), 0, R"("sweep": {"fraction": [0.2, 1.5, 2.5]}, )");
    const Scene scene = parse_scene(text, "sweep.json");
    CHECK(scene.fraction_sweep == std::vector<double>{0.2, 1.5, 2.5});
    CHECK(scene.settings.position_correction.fraction == 1.0);
    CHECK(parse_scene(two_balls_on_the_ground, "plain.json").fraction_sweep.empty());
}
