// Ties chapter 4's figures to the physics: every scene of chapters/angular-impulse/scenes is
// run stage by stage with the responder it names, and every response is checked against the
// laws the page and the figure labels state. The long box is checked against its closed form
// and its description's numbers; the flat landing must never spin, its one-by-one twin must.
// The free box of the tennis-racket figure must flip at the period Euler's equations give in
// closed form, with |L| and E constant, as its description and the page's caption say.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "chapter_page.hpp"
#include "workbook/probes.hpp"
#include "workbook/response_model.hpp"
#include "workbook/scene.hpp"
#include "workbook/time_series.hpp"

namespace {

namespace fs = std::filesystem;
using workbook::Contact;
using workbook::RigidBody;
using workbook::Vector3;

fs::path scene_dir() { return fs::path(WORKBOOK_SOURCE_DIR) / "chapters" / "angular-impulse" / "scenes"; }

workbook::Scene load(const std::string& name) {
    std::vector<std::string_view> responders;
    for (const auto& model : workbook::response_models()) responders.push_back(model.name);
    return workbook::load_scene(scene_dir() / name, responders);
}

double point_normal_velocity(const RigidBody& a, const RigidBody& b, const Vector3& p, const Vector3& n) {
    return dot(a.velocity + cross(a.angular_velocity, p - a.position) - b.velocity - cross(b.angular_velocity, p - b.position), n);
}

Vector3 angular_momentum(std::span<const RigidBody> bodies) {
    Vector3 sum{};
    for (const RigidBody& b : bodies)
        if (!b.is_immovable()) sum += cross(b.position, b.mass() * b.velocity) + b.inertia_world() * b.angular_velocity;
    return sum;
}

workbook::testing::ChapterPage chapter_page() { return workbook::testing::read_chapter_page(WORKBOOK_SOURCE_DIR, "angular-impulse"); }

/// The caption of the page's figure of `scene`.
std::string caption_of(const std::string& scene) { return workbook::testing::figure_caption(chapter_page(), "angular-impulse/" + scene); }

/// The complete elliptic integral of the first kind K(k), from its modulus' complement
/// k' = sqrt(1 - k^2), by the arithmetic-geometric mean: K = pi / (2 AGM(1, k')). Taking k'
/// keeps the digits that 1 - k^2 would lose near k = 1, where the tennis racket lives.
double elliptic_k_from_complement(double complement) {
    double a = 1.0, b = complement;
    for (int i = 0; i < 40 && a != b; ++i) {
        const double mean = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = mean;
    }
    return std::numbers::pi / (2.0 * a);
}

/// The captions and descriptions print their numbers to three significant digits.
std::string three_digits(double v) { return workbook::testing::page_number(v, 3); }

}  // namespace

TEST_CASE("Every chapter 4 scene: momentum, restitution at the points and the energy law at every response", "[angular-impulse]") {
    int scenes = 0;
    for (const auto& entry : fs::directory_iterator(scene_dir())) {
        if (entry.path().extension() != ".json") continue;
        ++scenes;
        DYNAMIC_SECTION(entry.path().filename().string()) {
            const workbook::Scene scene = load(entry.path().filename().string());
            CHECK_FALSE(scene.description.empty());
            if (scene.responder != "angular-impulse") continue;  // the counter-example and the free box are checked below
            workbook::World world = workbook::make_world(scene, *workbook::find_response_model(scene.responder));
            const bool closed = scene.settings.gravity == Vector3{} &&
                                std::none_of(scene.bodies.begin(), scene.bodies.end(), [](const RigidBody& b) { return b.is_immovable(); });
            const workbook::Probes start = world.probes();
            const double p_scale = length(start.linear_momentum) + 1.0;
            const double l_scale = length(start.angular_momentum) + 1.0;
            int checked = 0;
            for (std::size_t step = 0; step < workbook::step_count(scene.duration, scene.settings.time_step); ++step) {
                world.integrate();
                world.detect();
                const std::vector<RigidBody> before(world.bodies().begin(), world.bodies().end());
                world.respond();
                const double change = world.probes().response_energy_change;
                const double kinetic = world.probes().kinetic();
                CHECK(change <= 1e-12 * (kinetic + 1.0));  // energy never rises
                for (const Contact& c : world.contacts()) {
                    if (world.contacts().size() != 1) break;
                    const RigidBody& b1 = before[c.body1];
                    const RigidBody& b2 = before[c.body2];
                    const RigidBody& a1 = world.bodies()[c.body1];
                    const RigidBody& a2 = world.bodies()[c.body2];
                    const double u = point_normal_velocity(b1, b2, c.points[0].position, c.normal);
                    bool equal = u < 0.0;
                    for (std::size_t i = 0; i < c.point_count; ++i)
                        equal = equal && std::abs(point_normal_velocity(b1, b2, c.points[i].position, c.normal) - u) <= 1e-9 * std::abs(u);
                    if (!equal) continue;  // the closed-form law below needs one approach speed
                    const double e = std::min(b1.restitution, b2.restitution);
                    for (std::size_t i = 0; i < c.point_count; ++i)
                        CHECK(std::abs(point_normal_velocity(a1, a2, c.points[i].position, c.normal) + e * u) <= 1e-9 * std::abs(u));
                    const double total_impulse = b1.is_immovable() ? -dot(a2.velocity - b2.velocity, c.normal) * b2.mass()
                                                                   : dot(a1.velocity - b1.velocity, c.normal) * b1.mass();
                    INFO("t = " << world.time() << " s: measured " << change << " J, 1/2 (1 - e) sum J u = " << 0.5 * (1.0 - e) * total_impulse * u);
                    CHECK(std::abs(change - 0.5 * (1.0 - e) * total_impulse * u) <= 1e-9 * std::abs(change) + 1e-12 * kinetic);
                    ++checked;
                }
                world.correct();
                if (closed) {
                    const workbook::Probes now = world.probes();
                    CHECK(length(now.linear_momentum - start.linear_momentum) <= 1e-12 * p_scale);
                    CHECK(length(now.angular_momentum - angular_momentum(world.bodies())) <= 1e-12 * l_scale);
                    CHECK(length(now.angular_momentum - start.angular_momentum) <= 1e-9 * l_scale);
                }
            }
            CHECK(checked > 0);
        }
    }
    CHECK(scenes >= 6);
}

TEST_CASE("The long box meets its closed form and its description's numbers", "[angular-impulse]") {
    const workbook::Scene scene = load("long-box-drop.json");
    workbook::World world = workbook::make_world(scene, *workbook::find_response_model(scene.responder));
    const RigidBody initial = world.bodies()[0];
    for (int i = 0; i < 1000 && world.contacts().empty(); ++i) world.step();
    REQUIRE(world.contacts().size() == 1);
    REQUIRE(world.contacts()[0].point_count == 2);
    const RigidBody& box = world.bodies()[0];
    const double m = box.mass(), e = box.restitution, u = -initial.velocity.z;
    const Vector3 half = box.shape.half_extents;
    const Vector3 edge = rotate(initial.orientation, Vector3{-half.x, 0, -half.z});  // the lower edge's middle
    const double moment = initial.inertia_world()(1, 1);
    const double j = (1.0 + e) * u / (1.0 / m + edge.x * edge.x / moment);
    const double spin = j * -edge.x / moment;
    CHECK(std::abs(box.velocity.z - (-u + j / m)) < 1e-9);
    CHECK(std::abs(box.angular_velocity.y - spin) < 1e-9);
    const double theta = 30.0 * std::numbers::pi / 180.0;
    const double rod = (1.0 + e) * m * u / (1.0 + 3.0 * std::cos(theta) * std::cos(theta));
    const double lost = 0.5 * m * u * u - workbook::kinetic_energy(box);
    // The caption's numbers are the scene's.
    const std::string caption = caption_of("long-box-drop");
    for (const std::string& printed : {three_digits(2.0 * half.x) + " m by " + three_digits(200.0 * half.z) + " cm",
                                       three_digits(2.0 * std::atan2(std::hypot(initial.orientation.x, initial.orientation.y, initial.orientation.z),
                                                                     initial.orientation.w) * 180.0 / std::numbers::pi) + " degrees",
                                       three_digits(u) + " m/s"}) {
        INFO("the caption should say " << printed);
        CHECK(caption.find(printed) != std::string::npos);
    }
    for (const std::string& printed : {three_digits(spin) + " rad/s", three_digits(-box.velocity.z) + " m/s",
                                       three_digits(lost) + " J", three_digits(j) + " N s", three_digits(rod) + " N s"}) {
        INFO("the description should say " << printed);
        CHECK(scene.description.find(printed) != std::string::npos);
    }
}

TEST_CASE("The flat landing never spins; resolved corner by corner it does", "[angular-impulse]") {
    for (const std::string name : {"box-lands-flat.json", "box-lands-flat-one-by-one.json"}) {
        const workbook::Scene scene = load(name);
        workbook::World world = workbook::make_world(scene, *workbook::find_response_model(scene.responder));
        double most_rotational = 0.0;
        int first_impact = -1;
        for (int i = 0; i < 400; ++i) {  // up to just after the first landing, at t = 0.319 s
            world.step();
            if (first_impact < 0 && !world.contacts().empty()) first_impact = i;
            most_rotational = std::max(most_rotational, world.probes().kinetic_rotational);
        }
        INFO(name << ": first impact at step " << first_impact << ", largest rotational energy " << most_rotational << " J");
        REQUIRE(first_impact > 0);
        if (scene.responder == "angular-impulse")
            CHECK(most_rotational <= 1e-20);
        else
            CHECK(most_rotational > 0.1);
    }
}

TEST_CASE("The tennis-racket box flips at the closed-form period while |L| and E stay constant", "[angular-impulse]") {
    const workbook::Scene scene = load("tennis-racket.json");
    REQUIRE(scene.responder == "none");
    workbook::World world = workbook::make_world(scene, *workbook::find_response_model(scene.responder));
    const auto spin_in_body = [](const RigidBody& b) { return rotate(conjugate(b.orientation), b.angular_velocity); };
    const RigidBody& box = world.bodies()[0];

    // Euler's equations in closed form (Landau and Lifshitz, Mechanics, section 37): with the
    // principal moments I1 < I2 < I3, energy E and |L| = M, when M^2 > 2 E I2 the spin about
    // the middle axis is w2 ~ sn(lambda t, k), which changes sign every 2 K(k) / lambda, with
    //   lambda = sqrt((I3 - I2)(M^2 - 2 E I1) / (I1 I2 I3)),
    //   k'^2 = 1 - k^2 = (I3 - I1)(M^2 - 2 E I2) / ((I3 - I2)(M^2 - 2 E I1)).
    // Each M^2 - 2 E Ij is summed as sum_i Ii (Ii - Ij) wi^2, which loses no digits to cancellation.
    const double moments[3] = {box.inertia_body(0, 0), box.inertia_body(1, 1), box.inertia_body(2, 2)};
    REQUIRE(moments[0] < moments[1]);
    REQUIRE(moments[1] < moments[2]);
    const Vector3 w0 = spin_in_body(box);
    const double w[3] = {w0.x, w0.y, w0.z};
    const auto excess = [&](int j) {  // M^2 - 2 E Ij
        double sum = 0.0;
        for (int i = 0; i < 3; ++i) sum += moments[i] * (moments[i] - moments[j]) * w[i] * w[i];
        return sum;
    };
    REQUIRE(excess(1) > 0.0);  // the branch of the closed form above
    const double lambda = std::sqrt((moments[2] - moments[1]) * excess(0) / (moments[0] * moments[1] * moments[2]));
    const double complement = std::sqrt((moments[2] - moments[0]) * excess(1) / ((moments[2] - moments[1]) * excess(0)));
    const double predicted = 2.0 * elliptic_k_from_complement(complement) / lambda;

    const workbook::Probes start = world.probes();
    const double e0 = start.kinetic(), l0 = length(start.angular_momentum);
    double energy_change = 0.0, momentum_change = 0.0, lowest = w0.y;
    std::vector<double> flips;  // when the spin about the middle axis changed sign, s
    double previous = w0.y, previous_time = 0.0;
    for (std::size_t step = 0; step < workbook::step_count(scene.duration, scene.settings.time_step); ++step) {
        world.step();
        const double now = spin_in_body(world.bodies()[0]).y;
        if ((now > 0.0) != (previous > 0.0))
            flips.push_back(previous_time + (world.time() - previous_time) * previous / (previous - now));
        previous = now;
        previous_time = world.time();
        lowest = std::min(lowest, now);
        const workbook::Probes probes = world.probes();
        energy_change = std::max(energy_change, std::abs(probes.kinetic() - e0) / e0);
        momentum_change = std::max(momentum_change, std::abs(length(probes.angular_momentum) - l0) / l0);
    }
    std::string measured;
    for (const double t : flips) measured += " " + std::to_string(t);
    INFO("predicted: a flip every " << predicted << " s; measured flips at (s):" << measured);
    INFO("largest relative change of E " << energy_change << ", of |L| " << momentum_change);
    // Several flips, each all the way over (the spin about the middle axis comes back reversed).
    CHECK(flips.size() >= 4);
    CHECK(lowest < -0.99 * w0.y);
    // The interval between flips as predicted, to the integrator's phase error: second order,
    // (|w| dt)^2 / 12 ~ 1e-4 at 6 rad/s and 5 ms (measured: 1.0e-4).
    for (std::size_t i = 1; i < flips.size(); ++i) CHECK(std::abs((flips[i] - flips[i - 1]) / predicted - 1.0) <= 1e-3);
    // Constant to 1e-13 of their values (measured: 1.4e-14 for E, 7.7e-15 for |L|).
    CHECK(energy_change <= 1e-13);
    CHECK(momentum_change <= 1e-13);

    // What the description and the page's caption say is what was measured and predicted.
    const std::string period = "every " + three_digits(predicted) + " s";
    for (const std::string& text : {scene.description, caption_of("tennis-racket")}) {
        INFO("in: " << text);
        CHECK(text.find(period) != std::string::npos);
        CHECK(text.find("1e-13") != std::string::npos);
        CHECK(text.find(three_digits(w0.y) + " rad/s") != std::string::npos);
    }
    CHECK(scene.description.find(three_digits(w0.x) + " rad/s") != std::string::npos);
    const std::string page = chapter_page().text;
    CHECK(page.find("for this box it is " + three_digits(predicted) + " s") != std::string::npos);
    CHECK(page.find("within \\f$10^{-3}\\f$ of it") != std::string::npos);  // the bound checked above
}

namespace {

/// Steps `world` until a step ends with a response that changed body 0's velocity (at most
/// `limit` steps); returns false when none came.
bool step_to_next_impact(workbook::World& world, std::size_t limit) {
    for (std::size_t i = 0; i < limit; ++i) {
        const Vector3 before = world.bodies()[0].velocity;
        world.step();
        if (!world.contacts().empty() && world.bodies()[0].velocity != before) return true;
    }
    return false;
}

}  // namespace

TEST_CASE("The long box strikes with its lower end, its far end, then its lower end again", "[angular-impulse]") {
    // What the caption says: three impacts in the run, the ends taking turns.
    const workbook::Scene scene = load("long-box-drop.json");
    workbook::World world = workbook::make_world(scene, *workbook::find_response_model(scene.responder));
    const std::size_t steps = workbook::step_count(scene.duration, scene.settings.time_step);
    std::vector<double> ends;  // for each impact, the contact point's offset along the box's long axis, m
    while (world.time() < scene.duration - 0.5 * scene.settings.time_step && step_to_next_impact(world, steps)) {
        const RigidBody& box = world.bodies()[0];
        const Vector3 axis = rotate(box.orientation, Vector3{1, 0, 0});
        ends.push_back(dot(world.contacts()[0].points[0].position - box.position, axis));
    }
    REQUIRE(ends.size() == 3);
    CHECK(ends[0] < -0.4);
    CHECK(ends[1] > 0.4);
    CHECK(ends[2] < -0.4);
}

TEST_CASE("The long box, made thinner, tends to the thin rod's closed form", "[angular-impulse]") {
    // The scene's box is 5 cm thick: its lower edge lies a little nearer the centre than a rod's
    // end and its moment is a little larger, so its impulse (2.89 N s) is not the rod's
    // (2.77 N s). Thinned by 10 and by 100, with the same mass, length, tilt and speed, it must
    // approach J = (1 + e) m u / (1 + 3 cos^2 theta) and w = 6 J cos(theta) / (m L), the error
    // shrinking in proportion to the thickness.
    const workbook::Scene scene = load("long-box-drop.json");
    const RigidBody original = scene.bodies[0];
    const double m = original.mass(), e = original.restitution, u = -original.velocity.z;
    const double length_ = 2.0 * original.shape.half_extents.x;
    const double theta = 30.0 * std::numbers::pi / 180.0;
    const double rod_j = (1.0 + e) * m * u / (1.0 + 3.0 * std::cos(theta) * std::cos(theta));
    const double rod_spin = 6.0 * rod_j * std::cos(theta) / (m * length_);
    double previous_error = 0.0;
    for (const double thinner : {10.0, 100.0}) {
        workbook::Scene thin = scene;
        const double h = original.shape.half_extents.y / thinner;
        RigidBody box = workbook::make_box(m, {0.5 * length_, h, h}, {}, original.orientation, original.velocity);
        box.restitution = e;
        double lowest = 0.0;  // the lowest corner's height above the centre
        for (const double sx : {-1.0, 1.0})
            for (const double sz : {-1.0, 1.0}) lowest = std::min(lowest, rotate(box.orientation, Vector3{sx * 0.5 * length_, 0, sz * h}).z);
        box.position = {0, 0, 1e-4 - lowest};
        thin.bodies[0] = box;
        thin.settings.time_step = 1e-6;  // 3 micrometres a step: one edge touches, not the end face
        workbook::World world = workbook::make_world(thin, *workbook::find_response_model(thin.responder));
        REQUIRE(step_to_next_impact(world, 1000));
        REQUIRE(world.contacts()[0].point_count == 2);
        const RigidBody& after = world.bodies()[0];
        const double j = m * (after.velocity.z + u);
        const double error = std::max(std::abs(j / rod_j - 1.0), std::abs(std::abs(after.angular_velocity.y) / rod_spin - 1.0));
        INFO(thinner << " times thinner: J = " << j << " N s (rod " << rod_j << "), w = " << after.angular_velocity.y
                     << " rad/s (rod " << rod_spin << "), relative error " << error);
        CHECK(error <= 4.0 * h / length_);
        if (previous_error > 0.0) CHECK(error < previous_error / 5.0);  // about tenfold for a tenth of the thickness
        previous_error = error;
    }
    CHECK(previous_error < 1e-3);
}

TEST_CASE("The flat landing keeps e^2 of its kinetic energy at every bounce", "[angular-impulse]") {
    // The caption: each bounce keeps a quarter of the kinetic energy (e = 0.5), and the box
    // never spins. Checked at every response, the rest on the ground included.
    const workbook::Scene scene = load("box-lands-flat.json");
    workbook::World world = workbook::make_world(scene, *workbook::find_response_model(scene.responder));
    const double e = scene.bodies[0].restitution;
    int bounces = 0;
    double largest_spin = 0.0;
    for (std::size_t step = 0; step < workbook::step_count(scene.duration, scene.settings.time_step); ++step) {
        world.integrate();
        world.detect();
        const double before = workbook::kinetic_energy(world.bodies()[0]);
        world.respond();
        const double after = workbook::kinetic_energy(world.bodies()[0]);
        world.correct();
        if (after == before) continue;
        ++bounces;
        INFO("t = " << world.time() << " s: kinetic energy " << before << " J before, " << after << " J after");
        CHECK(std::abs(after - e * e * before) <= 1e-12 * before);
        largest_spin = std::max(largest_spin, length(world.bodies()[0].angular_velocity));
    }
    INFO(bounces << " responses, largest |w| after one: " << largest_spin << " rad/s");
    CHECK(bounces >= 4);
    CHECK(e * e == 0.25);
    CHECK(largest_spin <= 1e-9);  // the law of step 6 (measured: 4.9e-14 rad/s)
    const std::string caption = caption_of("box-lands-flat");
    CHECK(caption.find("1e-9 rad/s") != std::string::npos);
    CHECK(caption.find("keeps a quarter of the kinetic energy") != std::string::npos);
}

TEST_CASE("The ball off centre: no energy lost, the ball never spins, a share turns the box", "[angular-impulse]") {
    const workbook::Scene scene = load("sphere-hits-box-off-centre.json");
    workbook::World world = workbook::make_world(scene, *workbook::find_response_model(scene.responder));
    const double e0 = world.probes().kinetic();
    for (std::size_t step = 0; step < workbook::step_count(scene.duration, scene.settings.time_step); ++step) world.step();
    const RigidBody& ball = world.bodies()[0];
    const RigidBody& box = world.bodies()[1];
    CHECK(scene.bodies[0].restitution == 1.0);
    CHECK(std::abs(world.probes().kinetic() - e0) <= 1e-12 * e0);
    CHECK(length(ball.angular_velocity) <= 1e-12 * length(box.angular_velocity));
    const double turning = 0.5 * dot(box.angular_velocity, box.inertia_world() * box.angular_velocity);
    const std::string printed = three_digits(turning) + " J of the " + three_digits(e0) + " J";
    INFO("the caption and the description should say: " << printed);
    CHECK(caption_of("sphere-hits-box-off-centre").find(printed) != std::string::npos);
    CHECK(scene.description.find(printed) != std::string::npos);
}

TEST_CASE("The spinning cube's momentum is the 2 kg m/s its description says", "[angular-impulse]") {
    const workbook::Scene scene = load("spinning-box-hits-box.json");
    const workbook::Probes start = workbook::measure(scene.bodies, scene.settings.gravity);
    CHECK(start.linear_momentum == Vector3{2, 0, 0});
    CHECK(scene.description.find("(2 kg m/s along x)") != std::string::npos);
}
