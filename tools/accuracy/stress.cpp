#include "stress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

#include "models.hpp"
#include "workbook/guards.hpp"
#include "workbook/probes.hpp"
#include "workbook/scene.hpp"

namespace workbook::accuracy {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

/// A fixed seed, so the corpus is the same scene every run.
constexpr std::uint64_t corpus_seed = 13;

std::vector<RigidBody> walls(const Box& box) {
    return {make_immovable_plane({1, 0, 0}, box.low),  make_immovable_plane({-1, 0, 0}, box.high),
            make_immovable_plane({0, 1, 0}, box.low),  make_immovable_plane({0, -1, 0}, box.high),
            make_immovable_plane({0, 0, 1}, box.low),  make_immovable_plane({0, 0, -1}, box.high)};
}

Box cube(const Vector3& centre, double half) {
    return {centre - Vector3{half, half, half}, centre + Vector3{half, half, half}};
}

/// `count` balls on a grid inside `box` (no initial overlaps), random directions at `speed`.
std::vector<RigidBody> balls_in(const Box& box, int count, double radius, double speed, double restitution,
                                std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::normal_distribution<double> gauss;
    const Vector3 size = box.high - box.low;
    const double spacing = 2.5 * radius;
    const int per_axis = std::max(1, static_cast<int>((std::min({size.x, size.y, size.z}) - 2 * radius) / spacing));
    std::vector<RigidBody> balls;
    for (int i = 0; i < count; ++i) {
        const int x = i % per_axis;
        const int y = (i / per_axis) % per_axis;
        const int z = i / (per_axis * per_axis);
        const Vector3 at = box.low + Vector3{radius * 1.5 + spacing * x, radius * 1.5 + spacing * y,
                                             radius * 1.5 + spacing * z};
        Vector3 direction{gauss(random), gauss(random), gauss(random)};
        direction = normalized(direction);
        RigidBody ball = make_sphere(1.0, radius, at, direction * speed);
        ball.restitution = restitution;
        balls.push_back(ball);
    }
    return balls;
}

WorldSettings settings_with(double dt, const Vector3& gravity) {
    WorldSettings s;
    s.time_step = dt;
    s.gravity = gravity;
    return s;
}

StressScene boxed(std::string name, std::string what, std::uint64_t steps, int count, double speed, double restitution,
                  double dt, const Vector3& gravity, const Vector3& centre = {}, double half = 5.0,
                  double radius = 0.25) {
    const Box box = cube(centre, half);
    StressScene scene;
    scene.name = std::move(name);
    scene.what = std::move(what);
    scene.steps = steps;
    scene.box = box;
    scene.build = [=](const ResponseModel& model) {
        std::vector<RigidBody> bodies = walls(box);
        for (const RigidBody& ball : balls_in(box, count, radius, speed, restitution, corpus_seed)) bodies.push_back(ball);
        return World(bodies, settings_with(dt, gravity), model);
    };
    return scene;
}

/// Two balls in free space, no gravity: momentum must hold.
StressScene pair(std::string name, std::string what, std::uint64_t steps, RigidBody a, RigidBody b, double dt = 1.0 / 240) {
    StressScene scene;
    scene.name = std::move(name);
    scene.what = std::move(what);
    scene.steps = steps;
    scene.check_momentum = true;
    scene.build = [=](const ResponseModel& model) { return World({a, b}, settings_with(dt, {}), model); };
    return scene;
}

RigidBody ball(double mass, const Vector3& at, const Vector3& velocity, double radius = 0.5) {
    return make_sphere(mass, radius, at, velocity);
}

double energy_scale(const World& world) {
    double scale = 0.0;
    const double g = length(world.settings().gravity);
    for (const RigidBody& body : world.bodies())
        if (!body.is_immovable()) scale += kinetic_energy(body) + body.mass() * g * length(body.position);
    return scale;
}

double momentum_scale(const World& world) {
    double scale = 0.0;
    for (const RigidBody& body : world.bodies())
        if (!body.is_immovable()) scale += body.mass() * length(body.velocity);
    return scale;
}

/// How far any centre lies outside the box, m.
double escape(const World& world, const Box& box) {
    double worst = 0.0;
    for (const RigidBody& body : world.bodies()) {
        if (body.is_immovable()) continue;
        const Vector3& x = body.position;
        worst = std::max({worst, box.low.x - x.x, x.x - box.high.x, box.low.y - x.y, x.y - box.high.y,
                          box.low.z - x.z, x.z - box.high.z});
    }
    return worst;
}


/// A 10 cm cube of 1 kg with friction 0.5 and e = 0, resting on its face, at `at`.
RigidBody cube_with_friction(const Vector3& at) {
    RigidBody box = make_box(1.0, {0.05, 0.05, 0.05}, at);
    box.restitution = 0.0;
    box.friction = box.static_friction = 0.5;
    return box;
}

/// The ground (y = 0, up y) with friction 0.5 and e = 0.
RigidBody ground_with_friction() {
    RigidBody ground = make_immovable_plane({0, 1, 0}, {0, 0, 0});
    ground.restitution = 0.0;
    ground.friction = ground.static_friction = 0.5;
    return ground;
}

/// How far the furthest body has strayed sideways (in x and z) from where it started, over
/// `allowed` m; the starting places are the first `count` bodies' of `start`.
double strayed(const World& world, const std::vector<Vector3>& start, double allowed) {
    double furthest = 0.0;
    for (std::size_t b = 0; b < start.size(); ++b) {
        const Vector3 d = world.bodies()[b].position - start[b];
        furthest = std::max(furthest, std::hypot(d.x, d.z));
    }
    return furthest / allowed;
}

/// The deepest overlap of two spheres of the world, m (every pair: for the corpus's piles).
double deepest_between_balls(const World& world) {
    const auto bodies = world.bodies();
    double deepest = 0.0;
    for (std::size_t a = 0; a < bodies.size(); ++a) {
        if (bodies[a].shape.kind != ShapeKind::sphere) continue;
        for (std::size_t b = a + 1; b < bodies.size(); ++b)
            if (bodies[b].shape.kind == ShapeKind::sphere)
                deepest = std::max(deepest, bodies[a].shape.radius + bodies[b].shape.radius - length(bodies[a].position - bodies[b].position));
    }
    return deepest;
}

/// A rise of 1 micrometre for every movable body of `bodies` under `gravity`, J
/// (StressScene::energy_allowance).
double micrometre_rise(const std::vector<RigidBody>& bodies, const Vector3& gravity) {
    double energy = 0.0;
    for (const RigidBody& body : bodies)
        if (!body.is_immovable()) energy += body.mass() * length(gravity) * 1e-6;
    return energy;
}

/// Thirty cubes with friction (cube_with_friction()) in a column on the ground, `gap` m apart
/// and every other one `aside` m to the side, for 6 s with chapter 6's responder; from
/// `settled` s on, no box may stray sideways from where it started by more than `allowed` m.
StressScene column_of_cubes(std::string name, std::string what, double gap, double aside, double settled, double allowed) {
    const Vector3 earth{0.0, -9.81, 0.0};
    StressScene scene;
    scene.name = std::move(name);
    scene.what = std::move(what);
    scene.steps = 360;
    scene.responder = "friction";
    std::vector<RigidBody> bodies;
    for (int i = 0; i < 30; ++i) bodies.push_back(cube_with_friction({i % 2 == 1 ? aside : 0.0, 0.05 + (0.1 + gap) * i, 0}));
    bodies.push_back(ground_with_friction());
    std::vector<Vector3> start;
    for (const RigidBody& body : bodies) start.push_back(body.position);
    scene.energy_allowance = micrometre_rise(bodies, earth);
    scene.build = [bodies, earth](const ResponseModel& model) { return World(bodies, settings_with(1.0 / 60, earth), model); };
    scene.own_check_name = "stands";
    scene.own_check = [start, settled, allowed](const World& world) {
        return world.time() < settled ? 0.0 : strayed(world, start, allowed);
    };
    return scene;
}

/// Stacks and piles, the scenes games have most, with the contact solver of chapters 5 and 6
/// on its defaults (StressScene::responder).
void add_resting_scenes(std::vector<StressScene>& corpus, bool full) {
    const Vector3 earth{0.0, -9.81, 0.0};
    // Thirty cubes built touching: ten times a box's width and more, the weight of 29 boxes
    // on the lowest contact. The stack must stand: no box strays sideways by 1 mm.
    corpus.push_back(column_of_cubes("stack-30-friction", "thirty 10 cm cubes with friction 0.5 stacked touching, 6 s (responder friction)",
                                     0.0, 0.0, 0.0, 1e-3));
    // The same cubes dropped 2 cm apart, every other one 3 mm aside: the column lands on
    // itself at up to 2.5 m/s. Once landed (2 s) it must stand where it landed: no box more
    // than 1 cm from where it started sideways (the offsets are 3 mm).
    corpus.push_back(column_of_cubes("column-30-dropped",
                                     "thirty 10 cm cubes with friction 0.5 dropped 2 cm apart, every other one 3 mm aside, 6 s (responder friction)",
                                     0.02, 0.003, 2.0, 0.01));
    // A pile: balls of 5 cm thrown at 1 m/s in random directions from a loose grid into a
    // closed box, e = 0, frictionless (they flow like a liquid until they lie packed). Once
    // landed (3 s), no two balls may overlap by more than 5 mm (the slop is 2 mm), measured
    // every half second; the box invariant keeps every ball inside.
    {
        const int count = full ? 4'000 : 200;
        StressScene scene = boxed(full ? "pile-4000" : "pile-200",
                                  full ? "4,000 balls of 5 cm thrown into a 2.1 m box, e = 0, 10 s (responder resting-contact)"
                                       : "200 balls of 5 cm thrown into a 1 m box, e = 0, 10 s (responder resting-contact)",
                                  600, count, 1.0, 0.0, 1.0 / 60, earth, {}, full ? 1.05 : 0.5, 0.05);
        scene.responder = "resting-contact";
        scene.energy_allowance = count * length(earth) * 1e-6;  // balls of 1 kg: micrometre_rise()
        scene.own_check_name = "overlap";
        scene.own_check = [](const World& world) {
            if (world.time() < 3.0 || world.steps_taken() % 30 != 0) return 0.0;
            return deepest_between_balls(world) / 0.005;
        };
        corpus.push_back(scene);
    }
}

}  // namespace

std::vector<StressScene> stress_corpus(bool full) {
    const Vector3 earth{0.0, -9.81, 0.0};
    const std::uint64_t long_run = full ? 1'000'000 : 20'000;
    std::vector<StressScene> corpus;
    corpus.push_back(pair("mass-ratio-1e-9", "a 1 kg ball meets a 1e-9 kg ball head-on, e = 1", 600,
                          ball(1.0, {-1, 0, 0}, {1, 0, 0}), ball(1e-9, {1, 0, 0}, {-1, 0, 0})));
    corpus.push_back(pair("mass-ratio-1e9", "a 1 kg ball meets a 1e9 kg ball head-on, e = 1", 600,
                          ball(1.0, {-1, 0, 0}, {1, 0, 0}), ball(1e9, {1, 0, 0}, {-1, 0, 0})));
    {
        StressScene scene = boxed("mass-ratios-in-box", "1e-9, 1 and 1e9 kg balls in a closed box, e = 1, no gravity",
                                  full ? 100'000 : 5'000, 3, 2.0, 1.0, 1.0 / 240, {});
        const auto inner = scene.build;
        scene.build = [inner](const ResponseModel& model) {
            World world = inner(model);
            const double masses[] = {1e-9, 1.0, 1e9};
            for (std::size_t i = 0; i < 3; ++i) {
                RigidBody& b = world.bodies()[6 + i];
                b.inverse_mass = 1.0 / masses[i];
                b.inertia_body = solid_sphere_inertia(masses[i], b.shape.radius);
                b.update_world_inertia();
            }
            return world;
        };
        corpus.push_back(scene);
    }
    corpus.push_back(boxed("speed-1e4-box", "one ball at 1e4 m/s in a 10 m box (42 m per step), e = 1", 2'400, 1, 1e4,
                           1.0, 1.0 / 240, {}));
    corpus.push_back(pair("speed-1e4-pair", "two balls closing at 2e4 m/s (83 m per step), e = 1", 240,
                          ball(1.0, {-100, 0, 0}, {1e4, 0, 0}, 0.1), ball(1.0, {100, 0, 0}, {-1e4, 0, 0}, 0.1)));
    corpus.push_back(boxed("time-step-1e-6", "20 balls falling in a box at dt = 1e-6 s, e = 0.9",
                           full ? 1'000'000 : 5'000, 20, 1.0, 0.9, 1e-6, earth));
    corpus.push_back(boxed("time-step-0.1", "20 balls falling in a box at dt = 0.1 s, e = 0.9", 2'000, 20, 1.0, 0.9,
                           0.1, earth));
    if (full)
        corpus.push_back(boxed("bodies-10000", "10,000 balls in a box, e = 1, no gravity", 30, 10'000, 1.0, 1.0,
                               1.0 / 240, {}, {}, 20.0, 0.25));
    else
        corpus.push_back(boxed("bodies-300", "300 balls in a box, e = 1, no gravity (10,000 in the full corpus)", 40, 300,
                               1.0, 1.0, 1.0 / 240, {}, {}, 5.0, 0.25));
    corpus.push_back(boxed(full ? "steps-1e6" : "steps-2e4", "two balls in a box for many steps, e = 1, no gravity",
                           long_run, 2, 3.0, 1.0, 1.0 / 240, {}));
    corpus.push_back(pair("deep-overlap", "two balls starting 90% of a radius inside each other, approaching", 240,
                          ball(1.0, {-0.05, 0, 0}, {1, 0, 0}), ball(2.0, {0.05, 0, 0}, {-1, 0, 0})));
    corpus.push_back(pair("coincident-centres", "two balls with the same centre (the normal must still be defined)", 240,
                          ball(1.0, {0, 0, 0}, {0.5, 0, 0}), ball(3.0, {0, 0, 0}, {0, 0, 0})));
    corpus.push_back(boxed("far-from-origin", "20 balls falling in a box centred 1e6 m from the origin on every axis", 2'400,
                           20, 1.0, 0.9, 1.0 / 240, earth, {1e6, 1e6, 1e6}));
    corpus.push_back(boxed("zero-gravity", "200 balls in a box, e = 1, no gravity", full ? 20'000 : 100, 200, 2.0, 1.0,
                           1.0 / 240, {}));
    corpus.push_back(boxed("gravity-100g", "200 balls in a box under 100 g, e = 0.5", full ? 20'000 : 150, 200, 2.0, 0.5,
                           1.0 / 240, {0.0, -981.0, 0.0}));
    // Kinematic bodies under event timing: a kinematic ball sweeps through 20 falling balls.
    {
        StressScene scene = boxed("kinematic-event", "a kinematic ball crosses a box of 20 falling balls, event timing, e = 0.9",
                                  1'800, 20, 1.0, 0.9, 1.0 / 240, earth);
        scene.check_energy = false;  // the kinematic ball does work on the others
        const auto inner = scene.build;
        scene.build = [inner](const ResponseModel& model) {
            const World boxed_world = inner(model);
            std::vector<RigidBody> bodies(boxed_world.bodies().begin(), boxed_world.bodies().end());
            RigidBody mover = make_immovable_sphere(0.5, {-4.0, 0.0, 0.0});
            mover.velocity = {1.0, 0.0, 0.0};
            bodies.push_back(mover);
            WorldSettings settings = boxed_world.settings();
            settings.contact_timing = ContactTiming::event;
            return World(bodies, settings, model);
        };
        // The kinematic ball ends where its velocity takes it: 1 m/s for 7.5 s.
        scene.own_check_name = "kinematic";
        scene.own_check = [](const World& world) {
            const RigidBody& mover = world.bodies().back();
            const double expected = -4.0 + world.time();
            return std::abs(mover.position.x - expected) / (64.0 * eps * (4.0 + std::abs(expected)) * static_cast<double>(world.steps_taken()));
        };
        corpus.push_back(scene);
    }
    // Free rotation far beyond one radian a step: energy must hold (sub-steps).
    {
        StressScene scene;
        scene.name = "spin-1e4-skew";
        scene.what = "a box spinning at 10,000 rad/s on a skew axis (42 rad a step), no gravity";
        scene.steps = full ? 240'000 : 2'400;
        scene.check_momentum = true;
        scene.build = [](const ResponseModel& model) {
            RigidBody box = make_box(1.0, {0.3, 0.2, 0.1}, {0, 0, 0});
            box.angular_velocity = normalized(Vector3{1, 2, 3}) * 1e4;
            box.update_world_inertia();
            return World({box}, settings_with(1.0 / 240, {}), model);
        };
        corpus.push_back(scene);
    }
    // A fast small ball against a thin pinned box: it must bounce, never pass through.
    {
        StressScene scene = boxed("thin-box-fast-ball", "a 1 cm ball at 100 m/s against a 2 cm thick pinned box, e = 1",
                                  2'400, 0, 0.0, 1.0, 1.0 / 240, {});
        const auto inner = scene.build;
        scene.build = [inner](const ResponseModel& model) {
            const World walls_only = inner(model);
            std::vector<RigidBody> bodies(walls_only.bodies().begin(), walls_only.bodies().end());
            RigidBody thin = make_box(1.0, {0.01, 5.0, 5.0}, {0, 0, 0});  // wall to wall: no way round it
            thin.inverse_mass = 0.0;
            thin.inertia_body = Matrix3::zero();
            thin.update_world_inertia();
            bodies.push_back(thin);
            bodies.push_back(make_sphere(1.0, 0.01, {-2.5, 0.3, 0.2}, normalized(Vector3{1, 0.2, -0.1}) * 100.0));
            return World(bodies, walls_only.settings(), model);
        };
        scene.own_check_name = "thin box";
        scene.own_check = [](const World& world) { return world.bodies().back().position.x < 0.0 ? 0.0 : 2.0; };
        corpus.push_back(scene);
    }
    // Event timing, balls at rest knocked into each other: two balls that impacts set moving
    // towards each other within one step must meet (each is searched again when it moves).
    {
        StressScene scene;
        scene.name = "event-knocked-crowd";
        scene.what = "144 balls 2 cm apart, one in eight thrown, and two at rest knocked into each other, event timing, e = 1";
        scene.steps = 240;
        scene.box = cube({0.3, 0.18, 0.3}, 1.0);
        scene.build = [box = *scene.box](const ResponseModel& model) {
            std::mt19937_64 random(corpus_seed);
            std::uniform_real_distribution<double> unit(0.0, 1.0);
            std::vector<RigidBody> bodies = walls(box);
            for (int i = 0; i < 6; ++i)
                for (int j = 0; j < 4; ++j)
                    for (int k = 0; k < 6; ++k) {
                        const bool thrown = unit(random) < 0.125;
                        const Vector3 velocity = thrown ? Vector3{6.0 * unit(random) - 3.0, 0.0, 6.0 * unit(random) - 3.0} : Vector3{};
                        bodies.push_back(make_sphere(1.0, 0.05, {0.12 * i, 0.12 * j, 0.12 * k}, velocity));
                    }
            // Below the crowd, the smallest such case: two balls at rest 2 cm apart, each hit
            // from outside within the first step, each search alone short of the other ball.
            for (const auto& [x, vx] : {std::pair{0.0, 0.0}, {0.12, 0.0}, {-0.12, 2.0}, {0.24, -2.2}})
                bodies.push_back(make_sphere(1.0, 0.05, {x, -0.5, 0.3}, {vx, 0.0, 0.0}));
            WorldSettings settings = settings_with(1.0 / 60, {});
            settings.contact_timing = ContactTiming::event;
            return World(bodies, settings, model);
        };
        // No two balls overlap by more than a millionth of a radius after a step: a missed
        // impact leaves them a good part of a radius into each other.
        scene.own_check_name = "overlap";
        scene.own_check = [](const World& world) {
            const auto balls = world.bodies().subspan(6);
            double deepest = 0.0;
            for (std::size_t a = 0; a < balls.size(); ++a)
                for (std::size_t b = a + 1; b < balls.size(); ++b)
                    deepest = std::max(deepest, 0.1 - length(balls[a].position - balls[b].position));
            return deepest / (1e-6 * 0.05);
        };
        corpus.push_back(scene);
    }
    // Event timing with many bodies: scales with N (candidates from the broad phase).
    {
        StressScene scene = boxed("event-gas", full ? "2,000 balls in a box, event timing, e = 1, no gravity"
                                                    : "300 balls in a box, event timing, e = 1, no gravity",
                                  full ? 2'400 : 120, full ? 2'000 : 300, 2.0, 1.0, 1.0 / 240, {});
        const auto inner = scene.build;
        scene.build = [inner](const ResponseModel& model) {
            const World world = inner(model);
            WorldSettings settings = world.settings();
            settings.contact_timing = ContactTiming::event;
            return World(std::vector<RigidBody>(world.bodies().begin(), world.bodies().end()), settings, model);
        };
        corpus.push_back(scene);
    }
    add_resting_scenes(corpus, full);
    return corpus;
}

StressResult run_stress(const StressScene& scene, const ResponseModel& model,
                        const std::function<void(std::uint64_t)>& progress) {
    StressResult result;
    result.scene = scene.name;
    const auto started = std::chrono::steady_clock::now();
    World world = scene.build(scene.responder.empty() ? model : chapter_model(scene.responder));
    result.bodies = world.bodies().size();
    const Probes start = world.probes();
    const double e_scale = energy_scale(world);
    const double p_scale = momentum_scale(world);
    const Box box = scene.box.value_or(Box{});
    const double box_allowed =
        64.0 * eps * (length(box.low) + length(box.high) + length(box.high - box.low));

    const auto note = [&result](double ratio, const char* invariant) {
        if (ratio > result.worst) {
            result.worst = ratio;
            result.worst_invariant = invariant;
        }
    };
    const std::uint64_t every = std::max<std::uint64_t>(1, scene.steps / 100);
    try {
        for (std::uint64_t n = 1; n <= scene.steps; ++n) {
            world.step();
            result.steps = n;
            const Probes now = world.probes();
            const double rounding = 16.0 * eps * static_cast<double>(n + 1);
            if (scene.check_energy) {
                const double gain = now.total_energy() - start.total_energy();
                const double ratio = gain <= 0.0 ? 0.0 : gain / (rounding * e_scale + scene.energy_allowance);
                result.energy_ratio = std::max(result.energy_ratio, ratio);
                note(ratio, "energy");
            }
            if (scene.check_momentum) {
                const double drift = length(now.linear_momentum - start.linear_momentum);
                const double ratio = drift == 0.0 ? 0.0 : drift / (rounding * p_scale);
                result.momentum_ratio = std::max(result.momentum_ratio, ratio);
                note(ratio, "momentum");
            }
            if (scene.box) {
                const double out = escape(world, box);
                result.box_escape = std::max(result.box_escape, out);
                const double ratio = out <= 0.0 ? 0.0 : out / box_allowed;
                result.box_ratio = std::max(result.box_ratio, ratio);
                note(ratio, "box");
            }
            if (scene.own_check) note(scene.own_check(world), scene.own_check_name.c_str());
            if (progress && n % every == 0) progress(n);
        }
    } catch (const NonFiniteState& error) {
        result.error = error.what();
        result.worst_invariant = "finite";
        result.worst = std::numeric_limits<double>::infinity();
    }
    if (result.worst_invariant.empty()) result.worst_invariant = "-";
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

namespace {

/// A scene with the given top-level members (each followed by a comma) and bodies.
std::string scene_text(const std::string& members, const std::string& bodies) {
    return R"({"title": "stress", "responder": "none", )" + members + R"("bodies": [)" + bodies + "]}";
}

const std::string one_ball = R"({"shape": {"type": "sphere", "radius": 0.1}, "mass": 1})";

}  // namespace

std::vector<RefusedScene> refused_scenes() {
    const std::string step = R"("time_step": 0.01, "duration": 1, )";
    std::vector<RefusedScene> scenes;
    scenes.push_back({"nested-1e5", "a position nested 100,000 arrays deep", [step] {
                          const std::string deep = std::string(100'000, '[') + std::string(100'000, ']');
                          return scene_text(step, R"({"shape": {"type": "sphere", "radius": 0.1}, "mass": 1, "position": )" +
                                                      deep + "}");
                      },
                      "bodies[0].position[0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0]"});
    scenes.push_back({"duplicate-key", "a body gives its mass twice", [step] {
                          return scene_text(step, R"({"shape": {"type": "sphere", "radius": 0.1}, "mass": 1, "mass": 2})");
                      },
                      "bodies[0].mass"});
    scenes.push_back({"box-1e-160", "a box 1e-160 m thick", [step] {
                          return scene_text(step, R"({"shape": {"type": "box", "half_extents": [1, 1e-160, 1]}, "mass": 1})");
                      },
                      "bodies[0].shape.half_extents[1]"});
    scenes.push_back({"box-1e200", "a box 1e200 m long", [step] {
                          return scene_text(step, R"({"shape": {"type": "box", "half_extents": [1e200, 1, 1]}, "mass": 1})");
                      },
                      "bodies[0].shape.half_extents[0]"});
    scenes.push_back({"time-step-1e200", "a time step of 1e200 s", [] {
                          return scene_text(R"("time_step": 1e200, "duration": 1e201, )", one_ball);
                      },
                      "time_step"});
    scenes.push_back({"spin-1e6-skew", "a box spinning at 1e6 rad/s on a skew axis, dt = 0.01 s", [step] {
                          return scene_text(step, R"({"shape": {"type": "box", "half_extents": [1, 0.5, 0.2]}, "mass": 1, )"
                                                  R"("angular_velocity": [1e6, 1e6, 0]})");
                      },
                      "bodies[0].angular_velocity"});
    scenes.push_back({"bodies-3e5", "a file of 300,000 bodies (refused in about its reading time)", [step] {
                          std::string bodies = one_ball;
                          bodies.reserve(300'000 * (one_ball.size() + 2));
                          for (int i = 1; i < 300'000; ++i) bodies += ", " + one_ball;
                          return scene_text(step, bodies);
                      },
                      "bodies"});
    scenes.push_back({"number-1e999", "a position of 1e999 m", [step] {
                          return scene_text(step, R"({"shape": {"type": "sphere", "radius": 0.1}, "mass": 1, "position": [1e999, 0, 0]})");
                      },
                      "bodies[0].position[0]"});
    scenes.push_back({"speculative-1e10", "speculative contacts 1e10 m apart (every pair of a scene a contact)", [step] {
                          return scene_text(step + R"("contact_solver": {"speculative_distance": 1e10}, )", one_ball);
                      },
                      "contact_solver.speculative_distance"});
    scenes.push_back({"shock-sweeps-half", "one and a half shock sweeps", [step] {
                          return scene_text(step + R"("contact_solver": {"shock_sweeps": 1.5}, )", one_ball);
                      },
                      "contact_solver.shock_sweeps"});
    return scenes;
}

RefusalResult check_refusal(const RefusedScene& scene) {
    RefusalResult result;
    result.scene = scene.name;
    const std::string text = scene.text();
    const auto started = std::chrono::steady_clock::now();
    try {
        (void)parse_scene(text, scene.name + ".json");
        result.message = "accepted";
    } catch (const SceneError& error) {
        result.field = error.field();
        result.message = error.what();
        result.passed = error.field() == scene.field;
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

}  // namespace workbook::accuracy
