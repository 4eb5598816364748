#include "workbook/scene.hpp"
#include "workbook/tolerances.hpp"

#include <cmath>
#include <fstream>
#include <functional>
#include <unordered_set>
#include <initializer_list>
#include <numbers>
#include <sstream>
#include <vector>
#include <nlohmann/json.hpp>

#include "workbook/rotation.hpp"
#include "workbook/scene_limits.hpp"

namespace workbook {

SceneError::SceneError(std::string file, std::string field, std::string problem)
    : std::runtime_error(file + ": " + (field.empty() ? "" : field + ": ") + problem),
      file_(std::move(file)),
      field_(std::move(field)),
      problem_(std::move(problem)) {}

namespace {

using nlohmann::json;

/// Reads one JSON object field by field; every error carries the file and the field's path.
class Reader {
public:
    Reader(const json& value, std::string path, const std::string& file) : value_(value), path_(std::move(path)), file_(file) {
        if (!value_.is_object()) fail(path_, "must be an object, got " + type_name(value_));
    }

    /// Rejects any key not in `allowed`, so that a typo ("veloctiy") is never silently ignored.
    void only_keys(std::initializer_list<std::string_view> allowed) const {
        for (const auto& [key, unused] : value_.items()) {
            bool known = false;
            for (auto name : allowed) known = known || key == name;
            if (!known) {
                std::string list;
                for (auto name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
                fail(field(key), "unknown key (allowed here: " + list + ")");
            }
        }
    }

    [[nodiscard]] bool has(const std::string& key) const { return value_.contains(key); }

    [[nodiscard]] const json& required(const std::string& key) const {
        if (!has(key)) fail(field(key), "missing required field");
        return value_.at(key);
    }

    [[nodiscard]] double number(const std::string& key) const { return as_number(required(key), field(key)); }

    [[nodiscard]] double number_or(const std::string& key, double fallback) const {
        return has(key) ? number(key) : fallback;
    }

    [[nodiscard]] double positive(const std::string& key) const {
        const double v = number(key);
        if (!(v > 0.0)) fail(field(key), "must be a positive finite number, got " + format(v));
        return v;
    }

    [[nodiscard]] std::string text(const std::string& key) const {
        const json& v = required(key);
        if (!v.is_string()) fail(field(key), "must be a string, got " + type_name(v));
        return v.get<std::string>();
    }

    [[nodiscard]] std::string text_or(const std::string& key, std::string fallback) const {
        return has(key) ? text(key) : fallback;
    }

    [[nodiscard]] bool boolean_or(const std::string& key, bool fallback) const {
        if (!has(key)) return fallback;
        const json& v = value_.at(key);
        if (!v.is_boolean()) fail(field(key), "must be true or false, got " + type_name(v));
        return v.get<bool>();
    }

    [[nodiscard]] Vector3 vector(const std::string& key) const { return as_vector(required(key), field(key)); }

    [[nodiscard]] Vector3 vector_or(const std::string& key, Vector3 fallback) const {
        return has(key) ? vector(key) : fallback;
    }

    [[nodiscard]] std::string field(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

    [[nodiscard]] const std::string& file() const { return file_; }

    [[noreturn]] void fail(const std::string& field_path, const std::string& problem) const {
        throw SceneError(file_, field_path, problem);
    }

    [[nodiscard]] double as_number(const json& v, const std::string& field_path) const {
        if (!v.is_number()) fail(field_path, "must be a number, got " + type_name(v));
        const double d = v.get<double>();
        if (!std::isfinite(d)) fail(field_path, "must be a finite number, got " + format(d));
        return d;
    }

    [[nodiscard]] Vector3 as_vector(const json& v, const std::string& field_path) const {
        if (!v.is_array() || v.size() != 3)
            fail(field_path, "must be an array of three numbers [x, y, z], got " + describe(v));
        return {as_number(v[0], field_path + "[0]"), as_number(v[1], field_path + "[1]"),
                as_number(v[2], field_path + "[2]")};
    }

    static std::string type_name(const json& v) {
        if (v.is_number()) return "the number " + v.dump();
        if (v.is_string()) return "the string " + shortened(v.dump());
        return std::string(v.type_name());
    }

    /// A value as an error message shows it: short arrays of plain values as written, anything
    /// else by its type and size, so that the message stays one short line whatever the file
    /// holds (never a dump of a whole nested value).
    static std::string describe(const json& v) {
        if (!v.is_array()) return v.is_object() ? "an object of " + std::to_string(v.size()) + " keys" : type_name(v);
        bool plain = v.size() <= 8;
        for (const json& element : v) plain = plain && element.is_primitive();
        if (plain) return shortened(v.dump());
        return "an array of " + std::to_string(v.size()) + (v.size() == 1 ? " element" : " elements");
    }

    /// At most 60 characters of `text`, with "..." when cut.
    static std::string shortened(const std::string& text) {
        return text.size() <= 60 ? text : text.substr(0, 57) + "...";
    }

    static std::string format(double v) {
        std::ostringstream out;
        out << v;
        return out.str();
    }

private:
    const json& value_;
    std::string path_;
    const std::string& file_;
};

/// The first pass over the text, before any document is built (nlohmann's SAX interface):
/// it follows the parser as a JSON path ("bodies[1].position[0]") so that every problem it
/// finds can name its field, and refuses what the document must never hold:
///  - nesting deeper than max_depth (a scene nests 5 levels; a value nested 100,000 deep once
///    overflowed the stack of whatever walked it recursively);
///  - a key given twice in one object (a JSON parser keeps one of them silently);
///  - a number too large for a double (1e999);
///  - more bodies than the limit, counted here, before a document of them is built.
/// It keeps only the path and each open object's keys, so it is linear in the text (a
/// parse callback, which nlohmann calls with the value built so far, was quadratic in the
/// number of bodies: a 300,000-body file took up to a minute to be refused).
class FirstPass {
public:
    using string_t = json::string_t;

    /// The deepest nesting a scene may have; a real one needs 5 (root, bodies, body, shape, vector).
    static constexpr std::size_t max_depth = 32;

    bool null() { return value(); }
    bool boolean(bool) { return value(); }
    bool number_integer(json::number_integer_t) { return value(); }
    bool number_unsigned(json::number_unsigned_t) { return value(); }
    bool number_float(json::number_float_t, const string_t&) { return value(); }
    bool string(string_t&) { return value(); }
    bool binary(json::binary_t&) { return value(); }
    bool start_object(std::size_t) { return open(false); }
    bool start_array(std::size_t) { return open(true); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }
    bool key(string_t& name) {
        Level& level = levels_.back();
        level.key = name;
        if (!level.keys.insert(name).second) return refuse(path(), "the key \"" + name + "\" is given twice in one object");
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) {
        // nlohmann reports a number too large for a double (406) as a parse error of its own.
        if (error.id == 406) return refuse(path(), "must be a finite number, got a value too large for a double");
        return refuse("", std::string("not valid JSON: ") + error.what());
    }

    [[nodiscard]] bool refused() const { return refused_; }
    [[nodiscard]] const std::string& field() const { return field_; }
    [[nodiscard]] const std::string& problem() const { return problem_; }
    /// The length of the root's "bodies" array when it is one.
    [[nodiscard]] std::size_t bodies() const { return bodies_; }

private:
    struct Level {
        bool in_array = false;
        std::size_t index = 0;
        std::string key;
        std::unordered_set<std::string> keys;  ///< an object's keys so far
    };

    bool open(bool array) {
        if (levels_.size() >= max_depth)
            return refuse(path(), "nested more than " + std::to_string(max_depth) +
                                      " levels deep (a scene needs 5: root, bodies, body, shape, vector)");
        levels_.push_back({array, 0, {}, {}});
        return true;
    }
    bool close() {
        // The root's "bodies" array: count its elements as it closes.
        if (levels_.size() == 2 && levels_.back().in_array && !levels_.front().in_array && levels_.front().key == "bodies")
            bodies_ = levels_.back().index;
        levels_.pop_back();
        return value();
    }
    bool value() {
        if (!levels_.empty() && levels_.back().in_array) ++levels_.back().index;
        return true;
    }
    bool refuse(std::string field, std::string problem) {
        refused_ = true;
        field_ = std::move(field);
        problem_ = std::move(problem);
        return false;
    }
    [[nodiscard]] std::string path() const {
        std::string path;
        for (const Level& level : levels_) {
            if (level.in_array) path += "[" + std::to_string(level.index) + "]";
            else if (!level.key.empty()) path += (path.empty() ? "" : ".") + level.key;
        }
        return path;
    }

    std::vector<Level> levels_;
    bool refused_ = false;
    std::string field_;
    std::string problem_;
    std::size_t bodies_ = 0;
};

Shape read_shape(const Reader& body, const std::string& path, const std::string& file) {
    const Reader shape(body.required("shape"), path, file);
    const std::string type = shape.text("type");
    if (type == "sphere") {
        shape.only_keys({"type", "radius"});
        return Shape::sphere(shape.positive("radius"));
    }
    if (type == "plane") {
        shape.only_keys({"type", "normal"});
        const Vector3 n = shape.vector("normal");
        if (length(n) == 0.0) shape.fail(shape.field("normal"), "must not be the zero vector");
        return Shape::plane(normalized(n));
    }
    if (type == "box") {
        shape.only_keys({"type", "half_extents"});
        const Vector3 h = shape.vector("half_extents");
        if (!(h.x > 0.0 && h.y > 0.0 && h.z > 0.0))
            shape.fail(shape.field("half_extents"), "every half extent must be a positive number of metres, got [" +
                                                        Reader::format(h.x) + ", " + Reader::format(h.y) + ", " +
                                                        Reader::format(h.z) + "]");
        return Shape::box(h);
    }
    shape.fail(shape.field("type"), "unknown shape type \"" + type + "\" (supported: sphere, plane, box)");
}

/// How far a scene's quaternion may stray from unit length (tolerances.hpp).
constexpr double quaternion_length_tolerance = tolerances::quaternion_length;

/// The body's orientation: {"axis": [x, y, z], "angle_degrees": a} or {"quaternion": [w, x, y, z]}.
Quaternion read_orientation(const Reader& body, const std::string& file) {
    const std::string path = body.field("orientation");
    const Reader orientation(body.required("orientation"), path, file);
    orientation.only_keys({"axis", "angle_degrees", "quaternion"});
    if (orientation.has("quaternion")) {
        if (orientation.has("axis") || orientation.has("angle_degrees"))
            orientation.fail(path, "give either \"quaternion\" or \"axis\" with \"angle_degrees\", not both");
        const std::string field = orientation.field("quaternion");
        const auto& value = orientation.required("quaternion");
        if (!value.is_array() || value.size() != 4)
            orientation.fail(field, "must be an array of four numbers [w, x, y, z], got " + Reader::describe(value));
        const Quaternion q{orientation.as_number(value[0], field + "[0]"), orientation.as_number(value[1], field + "[1]"),
                           orientation.as_number(value[2], field + "[2]"), orientation.as_number(value[3], field + "[3]")};
        const double n = norm(q);
        if (!(std::abs(n - 1.0) <= quaternion_length_tolerance))
            orientation.fail(field, "must be a unit quaternion (length 1 within " +
                                        Reader::format(quaternion_length_tolerance) + "), got length " + Reader::format(n));
        return normalized(q);
    }
    if (!orientation.has("axis") && !orientation.has("angle_degrees"))
        orientation.fail(path, "give \"axis\" and \"angle_degrees\", or \"quaternion\"");
    const Vector3 axis = orientation.vector("axis");
    const double degrees = orientation.number("angle_degrees");
    if (length(axis) == 0.0) orientation.fail(orientation.field("axis"), "must not be the zero vector");
    return normalized(from_axis_angle(normalized(axis), degrees * std::numbers::pi / 180.0));
}

/// The inertia tensor of a movable body of `mass` with this shape, in body space.
Matrix3 solid_inertia(const Shape& shape, double mass) {
    return shape.kind == ShapeKind::box ? solid_box_inertia(mass, shape.half_extents)
                                        : solid_sphere_inertia(mass, shape.radius);
}

RigidBody read_body(const json& value, const std::string& path, const std::string& file, std::string& name) {
    const Reader body(value, path, file);
    body.only_keys({"name", "shape", "mass", "immovable", "position", "velocity", "angular_velocity", "restitution",
                    "friction", "static_friction", "orientation", "kinematic"});
    name = body.text_or("name", path);

    RigidBody rb;
    rb.shape = read_shape(body, body.field("shape"), file);
    const bool immovable = body.boolean_or("immovable", false);
    // A kinematic body is immovable (inverse mass 0: no impulse changes it) but moves at the
    // velocity it was given, like a conveyor or a moving platform.
    const bool kinematic = body.boolean_or("kinematic", false);
    if (immovable && kinematic)
        body.fail(body.field("kinematic"),
                  "a body is either immovable (never moves) or kinematic (moves at a set velocity), not both");
    if (immovable && body.has("mass"))
        body.fail(body.field("mass"), "an immovable body has no mass; remove \"mass\" or \"immovable\"");
    if (kinematic && body.has("mass"))
        body.fail(body.field("mass"), "a kinematic body has no mass (impulses never change it); remove \"mass\" or \"kinematic\"");
    if (!immovable && !kinematic && rb.shape.kind == ShapeKind::plane)
        body.fail(body.field("immovable"), "a plane must be immovable (set \"immovable\": true)");
    if (immovable || kinematic) {
        rb.inverse_mass = 0.0;
        rb.inertia_body = Matrix3::zero();
    } else {
        const double mass = body.positive("mass");
        rb.inverse_mass = 1.0 / mass;
        rb.inertia_body = solid_inertia(rb.shape, mass);
    }
    rb.position = body.vector_or("position", {});
    if (body.has("orientation")) rb.orientation = read_orientation(body, file);
    rb.velocity = body.vector_or("velocity", {});
    rb.angular_velocity = body.vector_or("angular_velocity", {});
    rb.restitution = body.number_or("restitution", 1.0);
    if (rb.restitution < 0.0 || rb.restitution > 1.0)
        body.fail(body.field("restitution"), "must lie in [0, 1], got " + Reader::format(rb.restitution));
    // Friction (chapter 6): the dynamic coefficient, and the static one, by default the same.
    rb.friction = body.number_or("friction", 0.0);
    if (!(rb.friction >= 0.0 && rb.friction <= scene_limits.max_friction))
        body.fail(body.field("friction"), "must lie in [0, " + Reader::format(scene_limits.max_friction) + "], got " +
                                              Reader::format(rb.friction));
    rb.static_friction = body.number_or("static_friction", rb.friction);
    if (!(rb.static_friction >= rb.friction && rb.static_friction <= scene_limits.max_friction))
        body.fail(body.field("static_friction"),
                  "must lie in [friction, " + Reader::format(scene_limits.max_friction) + "] = [" +
                      Reader::format(rb.friction) + ", " + Reader::format(scene_limits.max_friction) +
                      "] (a body starts sliding at least as easily as it keeps sliding), got " +
                      Reader::format(rb.static_friction));
    if (immovable && rb.velocity != Vector3{})
        body.fail(body.field("velocity"), "an immovable body cannot move; give it no velocity (a moving platform is \"kinematic\": true)");
    if (immovable && rb.angular_velocity != Vector3{})
        body.fail(body.field("angular_velocity"),
                  "an immovable body cannot rotate; give it no angular_velocity (a turning platform is \"kinematic\": true)");
    if (kinematic && rb.velocity == Vector3{} && rb.angular_velocity == Vector3{})
        body.fail(body.field("velocity"),
                  "a kinematic body needs a velocity or an angular_velocity; one that never moves is \"immovable\": true");
    rb.update_world_inertia();
    return rb;
}

/// The projection knobs. A fraction of 2 or more makes the depth grow step by step instead of
/// shrinking; chapter 2 shows that on purpose, so up to 4 is accepted and beyond is refused.
PositionCorrection read_position_correction(const Reader& root) {
    const Reader knobs(root.required("position_correction"), "position_correction", root.file());
    knobs.only_keys({"fraction", "slop"});
    PositionCorrection result;
    result.fraction = knobs.number_or("fraction", result.fraction);
    if (!(result.fraction > 0.0 && result.fraction <= 4.0))
        knobs.fail(knobs.field("fraction"), "must lie in (0, 4], got " + Reader::format(result.fraction));
    result.slop = knobs.number_or("slop", result.slop);
    if (result.slop < 0.0) knobs.fail(knobs.field("slop"), "must be zero or positive, got " + Reader::format(result.slop));
    return result;
}

/// The contact solver's knobs (chapter 5): whole numbers of passes, warm starting, tolerances.
ContactSolverSettings read_contact_solver(const Reader& root) {
    const Reader knobs(root.required("contact_solver"), "contact_solver", root.file());
    // Friction was once one knob for every contact; it is now each body's own "friction".
    if (knobs.has("friction"))
        knobs.fail(knobs.field("friction"),
                   "is no longer a knob of the contact solver: give each body its own \"friction\" (the ground "
                   "too; a pair takes the geometric mean) and use the responder \"friction\"");
    knobs.only_keys({"velocity_iterations", "position_iterations", "warm_start", "tolerance", "bounce_threshold", "sleeping",
                     "shock_sweeps", "speculative_distance"});
    ContactSolverSettings result;
    auto passes = [&](const char* key, int fallback) {
        const double v = knobs.number_or(key, fallback);
        if (!(v >= 0.0 && v <= 10000.0 && v == std::floor(v)))
            knobs.fail(knobs.field(key), "must be a whole number from 0 to 10000, got " + Reader::format(v));
        return static_cast<int>(v);
    };
    result.velocity_iterations = passes("velocity_iterations", result.velocity_iterations);
    result.position_iterations = passes("position_iterations", result.position_iterations);
    result.shock_sweeps = passes("shock_sweeps", result.shock_sweeps);
    // A margin is a length like a radius: the same limit keeps every pair's sums finite.
    result.speculative_distance = knobs.number_or("speculative_distance", result.speculative_distance);
    if (!(result.speculative_distance >= 0.0 && result.speculative_distance <= scene_limits.max_radius))
        knobs.fail(knobs.field("speculative_distance"),
                   "must lie in [0, " + Reader::format(scene_limits.max_radius) + "] m, got " + Reader::format(result.speculative_distance));
    result.warm_start = knobs.boolean_or("warm_start", result.warm_start);
    result.sleeping = knobs.boolean_or("sleeping", result.sleeping);
    result.tolerance = knobs.number_or("tolerance", result.tolerance);
    if (!(result.tolerance > 0.0)) knobs.fail(knobs.field("tolerance"), "must be positive, got " + Reader::format(result.tolerance));
    result.bounce_threshold = knobs.number_or("bounce_threshold", result.bounce_threshold);
    if (result.bounce_threshold < 0.0)
        knobs.fail(knobs.field("bounce_threshold"), "must be zero or positive, got " + Reader::format(result.bounce_threshold));
    return result;
}

/// The optional "sweep": {"fraction": [b1, b2, ...]}, each value a valid fraction.
std::vector<double> read_fraction_sweep(const Reader& root) {
    const Reader sweep(root.required("sweep"), "sweep", root.file());
    sweep.only_keys({"fraction"});
    const json& values = sweep.required("fraction");
    if (!values.is_array() || values.empty()) sweep.fail(sweep.field("fraction"), "must be a non-empty array of numbers");
    std::vector<double> result;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::string path = sweep.field("fraction") + "[" + std::to_string(i) + "]";
        const double fraction = sweep.as_number(values[i], path);
        if (!(fraction > 0.0 && fraction <= 4.0)) sweep.fail(path, "must lie in (0, 4], got " + Reader::format(fraction));
        result.push_back(fraction);
    }
    return result;
}

/// Integrators past the first two (which parse_scene reads itself).
Integrator parse_more_integrators(const Reader& root, const std::string& integrator) {
    if (integrator == "exact-under-gravity") return Integrator::exact_under_gravity;
    root.fail("integrator", "unknown integrator \"" + integrator +
                                "\" (available: semi-implicit-euler, explicit-euler, exact-under-gravity)");
}

ContactTiming read_contact_timing(const Reader& root) {
    const std::string timing = root.text_or("contact_timing", "discrete");
    if (timing == "discrete") return ContactTiming::discrete;
    if (timing == "event") return ContactTiming::event;
    root.fail("contact_timing", "unknown contact timing \"" + timing + "\" (available: discrete, event)");
}

/// Refuses a scene that would need absurd work or memory, or overflow (workbook/scene_limits.hpp).
void check_limits(const Reader& root, const Scene& scene) {
    const SceneLimits& limits = scene_limits;
    if (!(scene.settings.time_step <= limits.max_time_step))
        root.fail("time_step", "must be at most " + Reader::format(limits.max_time_step) + " s, got " +
                                   Reader::format(scene.settings.time_step));
    const double steps = scene.duration / scene.settings.time_step;
    if (!(steps <= limits.max_steps))
        root.fail("duration", "needs " + Reader::format(steps) + " steps of " + Reader::format(scene.settings.time_step) +
                                  " s; the limit is " + Reader::format(limits.max_steps) + " steps (duration / time_step)");
    const auto check_vector = [&root](const std::string& field, const Vector3& v, double limit, const char* unit) {
        const double components[] = {v.x, v.y, v.z};
        for (int i = 0; i < 3; ++i)
            if (!(std::abs(components[i]) <= limit))
                root.fail(field + "[" + std::to_string(i) + "]", "magnitude " + Reader::format(std::abs(components[i])) +
                                                                     " is over the limit of " + Reader::format(limit) + " " + unit);
    };
    check_vector("gravity", scene.settings.gravity, limits.max_gravity, "m/s^2");
    if (scene.bodies.size() > limits.max_bodies)
        root.fail("bodies", std::to_string(scene.bodies.size()) + " bodies are over the limit of " +
                                std::to_string(limits.max_bodies));
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const RigidBody& body = scene.bodies[i];
        const std::string path = "bodies[" + std::to_string(i) + "]";
        check_vector(path + ".position", body.position, limits.max_coordinate, "m");
        check_vector(path + ".velocity", body.velocity, limits.max_speed, "m/s");
        check_vector(path + ".angular_velocity", body.angular_velocity, limits.max_angular_speed, "rad/s");
        if (!body.is_immovable() && (body.mass() < limits.min_mass || body.mass() > limits.max_mass))
            root.fail(path + ".mass", "must lie in [" + Reader::format(limits.min_mass) + ", " +
                                          Reader::format(limits.max_mass) + "] kg, got " + Reader::format(body.mass()));
        if (body.shape.kind == ShapeKind::sphere &&
            (body.shape.radius < limits.min_radius || body.shape.radius > limits.max_radius))
            root.fail(path + ".shape.radius", "must lie in [" + Reader::format(limits.min_radius) + ", " +
                                                  Reader::format(limits.max_radius) + "] m, got " +
                                                  Reader::format(body.shape.radius));
        if (body.shape.kind == ShapeKind::box) {
            const Vector3& h = body.shape.half_extents;
            const double components[] = {h.x, h.y, h.z};
            for (int k = 0; k < 3; ++k)
                if (!(components[k] >= limits.min_half_extent && components[k] <= limits.max_half_extent))
                    root.fail(path + ".shape.half_extents[" + std::to_string(k) + "]",
                              "must lie in [" + Reader::format(limits.min_half_extent) + ", " +
                                  Reader::format(limits.max_half_extent) + "] m, got " + Reader::format(components[k]));
        }
        // A free body with unequal moments: how far it may turn in a step (workbook/rotation.hpp).
        if (!body.is_immovable() && body.angular_velocity != Vector3{} && !is_isotropic(body.inertia_body)) {
            const double turn = largest_spin(body) * scene.settings.time_step;
            if (!(turn <= limits.max_turn_per_step))
                root.fail(path + ".angular_velocity",
                          "body \"" + scene.body_names[i] + "\" may spin at up to " + Reader::format(largest_spin(body)) +
                              " rad/s, " + Reader::format(turn) + " rad per time step; the rotation step follows at most " +
                              Reader::format(limits.max_turn_per_step) + " rad per step (take a smaller time_step)");
        }
    }
}

}  // namespace

Scene parse_scene(std::string_view json_text, const std::string& source, std::span<const std::string_view> known_responders) {
    FirstPass first;
    (void)json::sax_parse(json_text, &first);
    if (first.refused()) throw SceneError(source, first.field(), first.problem());
    // Counted before any body is read or built, so that a huge array is refused at once.
    if (first.bodies() > scene_limits.max_bodies)
        throw SceneError(source, "bodies", std::to_string(first.bodies()) + " bodies are over the limit of " +
                                               std::to_string(scene_limits.max_bodies));
    // The first pass accepted the text, so this parse succeeds, without a callback (linear).
    const json document = json::parse(json_text);

    const Reader root(document, "", source);
    root.only_keys({"title", "description", "responder", "time_step", "duration", "gravity", "integrator",
                    "position_correction", "sweep", "bodies", "contact_timing", "swept_spheres", "contact_solver"});

    Scene scene;
    scene.source = source;
    scene.title = root.text("title");
    scene.description = root.text_or("description", "");
    scene.responder = root.text("responder");
    if (!known_responders.empty()) {
        bool known = false;
        std::string list;
        for (auto name : known_responders) {
            known = known || name == scene.responder;
            list += (list.empty() ? "" : ", ") + std::string(name);
        }
        if (!known) root.fail("responder", "unknown responder \"" + scene.responder + "\" (available: " + list + ")");
    }
    scene.settings.time_step = root.positive("time_step");
    scene.duration = root.positive("duration");
    if (scene.duration < scene.settings.time_step)
        root.fail("duration", "must be at least one time step (" + Reader::format(scene.settings.time_step) + " s)");
    scene.settings.gravity = root.vector_or("gravity", {});
    const std::string integrator = root.text_or("integrator", "semi-implicit-euler");
    if (integrator == "semi-implicit-euler")
        scene.settings.integrator = Integrator::semi_implicit_euler;
    else if (integrator == "explicit-euler")
        scene.settings.integrator = Integrator::explicit_euler;
    else
        scene.settings.integrator = parse_more_integrators(root, integrator);
    scene.settings.contact_timing = read_contact_timing(root);
    scene.settings.swept_spheres = root.boolean_or("swept_spheres", scene.settings.swept_spheres);

    if (root.has("position_correction")) scene.settings.position_correction = read_position_correction(root);
    if (root.has("sweep")) scene.fraction_sweep = read_fraction_sweep(root);
    if (root.has("contact_solver")) scene.settings.contact_solver = read_contact_solver(root);

    const json& bodies = root.required("bodies");
    if (!bodies.is_array() || bodies.empty()) root.fail("bodies", "must be a non-empty array of bodies");
    // Counted before any body is read, so that a huge array is refused at once.
    if (bodies.size() > scene_limits.max_bodies)
        root.fail("bodies", std::to_string(bodies.size()) + " bodies are over the limit of " +
                                std::to_string(scene_limits.max_bodies));
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        std::string name;
        scene.bodies.push_back(read_body(bodies[i], "bodies[" + std::to_string(i) + "]", source, name));
        scene.body_names.push_back(std::move(name));
    }
    check_limits(root, scene);
    return scene;
}

Scene load_scene(const std::filesystem::path& path, std::span<const std::string_view> known_responders) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path.string(), "", "cannot open the file");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_scene(text.str(), path.string(), known_responders);
}

World make_world(const Scene& scene, const ResponseModel& model) {
    // A body with friction needs a model with a friction pass (chapter 6's responder
    // "friction"): any other would silently let it slide as if on ice.
    const bool has_friction_pass = model.contact_solver != nullptr && model.contact_solver->solve_friction != nullptr;
    for (std::size_t i = 0; i < scene.bodies.size() && !has_friction_pass; ++i) {
        const RigidBody& body = scene.bodies[i];
        if (body.friction > 0.0 || body.static_friction > 0.0)
            throw SceneError(scene.source, "bodies[" + std::to_string(i) + "]." + (body.friction > 0.0 ? "friction" : "static_friction"),
                             "the responder \"" + std::string(model.name) +
                                 "\" has no friction; use the responder \"friction\" (chapter 6) or remove the field");
    }
    World world(scene.bodies, scene.settings, model);
    world.name_bodies(scene.body_names);
    return world;
}

}  // namespace workbook
