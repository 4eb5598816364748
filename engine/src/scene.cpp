#include "workbook/scene.hpp"

#include <cmath>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <sstream>
#include <vector>
#include <nlohmann/json.hpp>

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
            fail(field_path, "must be an array of three numbers [x, y, z], got " + v.dump());
        return {as_number(v[0], field_path + "[0]"), as_number(v[1], field_path + "[1]"),
                as_number(v[2], field_path + "[2]")};
    }

    static std::string type_name(const json& v) {
        if (v.is_number()) return "the number " + v.dump();
        if (v.is_string()) return "the string " + v.dump();
        return std::string(v.type_name());
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

/// Follows the parser through the document as a JSON path ("bodies[1].position[0]"). A
/// number too large for a double (1e999) is rejected by nlohmann while parsing, before any
/// Reader sees it; this is how that error can still name its field.
class ParsePath {
public:
    bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
        switch (event) {
            case json::parse_event_t::object_start: levels_.push_back({false, 0, {}}); break;
            case json::parse_event_t::array_start: levels_.push_back({true, 0, {}}); break;
            case json::parse_event_t::key: levels_.back().key = parsed.get<std::string>(); break;
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                levels_.pop_back();
                next_element();
                break;
            case json::parse_event_t::value: next_element(); break;
        }
        return true;
    }

    [[nodiscard]] std::string path() const {
        std::string path;
        for (const Level& level : levels_) {
            if (level.in_array) path += "[" + std::to_string(level.index) + "]";
            else if (!level.key.empty()) path += (path.empty() ? "" : ".") + level.key;
        }
        return path;
    }

private:
    struct Level {
        bool in_array;
        std::size_t index;
        std::string key;
    };

    void next_element() {
        if (!levels_.empty() && levels_.back().in_array) ++levels_.back().index;
    }

    std::vector<Level> levels_;
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
    shape.fail(shape.field("type"), "unknown shape type \"" + type + "\" (supported: sphere, plane)");
}

RigidBody read_body(const json& value, const std::string& path, const std::string& file, std::string& name) {
    const Reader body(value, path, file);
    body.only_keys({"name", "shape", "mass", "immovable", "position", "velocity", "angular_velocity", "restitution"});
    name = body.text_or("name", path);

    RigidBody rb;
    rb.shape = read_shape(body, body.field("shape"), file);
    const bool immovable = body.boolean_or("immovable", false);
    if (immovable && body.has("mass"))
        body.fail(body.field("mass"), "an immovable body has no mass; remove \"mass\" or \"immovable\"");
    if (!immovable && rb.shape.kind == ShapeKind::plane)
        body.fail(body.field("immovable"), "a plane must be immovable (set \"immovable\": true)");
    if (immovable) {
        rb.inverse_mass = 0.0;
        rb.inertia_body = Matrix3::zero();
    } else {
        const double mass = body.positive("mass");
        rb.inverse_mass = 1.0 / mass;
        rb.inertia_body = solid_sphere_inertia(mass, rb.shape.radius);
    }
    rb.position = body.vector_or("position", {});
    rb.velocity = body.vector_or("velocity", {});
    rb.angular_velocity = body.vector_or("angular_velocity", {});
    rb.restitution = body.number_or("restitution", 1.0);
    if (rb.restitution < 0.0 || rb.restitution > 1.0)
        body.fail(body.field("restitution"), "must lie in [0, 1], got " + Reader::format(rb.restitution));
    if (immovable && (rb.velocity != Vector3{} || rb.angular_velocity != Vector3{}))
        body.fail(body.field("velocity"), "an immovable body cannot move; give it no velocity");
    rb.update_world_inertia();
    return rb;
}

}  // namespace

Scene parse_scene(std::string_view json_text, const std::string& source, std::span<const std::string_view> known_responders) {
    json document;
    ParsePath parse_path;
    try {
        document = json::parse(json_text, std::ref(parse_path));
    } catch (const json::parse_error& error) {
        throw SceneError(source, "", std::string("not valid JSON: ") + error.what());
    } catch (const json::out_of_range&) {
        throw SceneError(source, parse_path.path(), "must be a finite number, got a value too large for a double");
    }

    const Reader root(document, "", source);
    root.only_keys({"title", "description", "responder", "time_step", "duration", "gravity", "integrator", "bodies"});

    Scene scene;
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
        root.fail("integrator", "unknown integrator \"" + integrator + "\" (available: semi-implicit-euler, explicit-euler)");

    const json& bodies = root.required("bodies");
    if (!bodies.is_array() || bodies.empty()) root.fail("bodies", "must be a non-empty array of bodies");
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        std::string name;
        scene.bodies.push_back(read_body(bodies[i], "bodies[" + std::to_string(i) + "]", source, name));
        scene.body_names.push_back(std::move(name));
    }
    return scene;
}

Scene load_scene(const std::filesystem::path& path, std::span<const std::string_view> known_responders) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path.string(), "", "cannot open the file");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_scene(text.str(), path.string(), known_responders);
}

World make_world(const Scene& scene, const ResponseModel& model) { return World(scene.bodies, scene.settings, model); }

}  // namespace workbook
