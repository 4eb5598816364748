#pragma once
/// \file
/// Scene files: JSON in, a validated scene out, or an error that says exactly what is wrong.

#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "workbook/rigid_body.hpp"
#include "workbook/world.hpp"

namespace workbook {

/// A scene file after validation: everything needed to build a World and run it.
struct Scene {
    std::string title;
    std::string description;
    std::string responder;          ///< name of a ResponseModel
    WorldSettings settings;
    double duration = 0.0;          ///< s
    std::vector<RigidBody> bodies;
    std::vector<std::string> body_names;  ///< parallel to bodies
};

/// A scene that cannot be used. what() reads "FILE: FIELD: PROBLEM", for example
/// "carts.json: bodies[1].mass: must be a positive finite number, got -2".
class SceneError : public std::runtime_error {
public:
    SceneError(std::string file, std::string field, std::string problem);
    [[nodiscard]] const std::string& file() const { return file_; }
    [[nodiscard]] const std::string& field() const { return field_; }    ///< JSON path such as "bodies[1].mass"; empty for syntax errors
    [[nodiscard]] const std::string& problem() const { return problem_; }

private:
    std::string file_;
    std::string field_;
    std::string problem_;
};

/// Parses and validates scene text. `source` names the text in errors (usually its path).
/// `known_responders` lists the accepted values of "responder"; empty accepts any name.
Scene parse_scene(std::string_view json_text, const std::string& source,
                  std::span<const std::string_view> known_responders = {});

/// Reads a scene file; a missing or unreadable file is a SceneError too.
Scene load_scene(const std::filesystem::path& path, std::span<const std::string_view> known_responders = {});

/// Builds the world a scene describes, with the given response model.
World make_world(const Scene& scene, const ResponseModel& model);

}  // namespace workbook
