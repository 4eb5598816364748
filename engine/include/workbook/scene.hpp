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
    std::string source;             ///< the file (or source name) it was read from, for errors
    std::string title;              ///< one line, shown on figures
    std::string description;        ///< what the scene shows and what to expect
    std::string responder;          ///< name of a ResponseModel
    WorldSettings settings;         ///< time step, gravity and integrator
    double duration = 0.0;          ///< s
    std::vector<RigidBody> bodies;  ///< the bodies, in file order
    std::vector<std::string> body_names;  ///< parallel to bodies
    /// Position-correction fractions to compare, from the optional "sweep" field: the figure
    /// driver runs the scene once per value and draws the runs in one figure. A plain run
    /// uses settings.position_correction and ignores this list.
    std::vector<double> fraction_sweep;
};

/// A scene that cannot be used. what() reads "FILE: FIELD: PROBLEM", for example
/// "carts.json: bodies[1].mass: must be a positive finite number, got -2".
class SceneError : public std::runtime_error {
public:
    /// An error in `file` at JSON path `field` (may be empty), described by `problem`.
    SceneError(std::string file, std::string field, std::string problem);
    /// The file (or source name) the error is in.
    [[nodiscard]] const std::string& file() const { return file_; }
    [[nodiscard]] const std::string& field() const { return field_; }    ///< JSON path such as "bodies[1].mass"; empty for syntax errors
    /// What is wrong, in words.
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
