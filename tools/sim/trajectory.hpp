#pragma once
// Trajectories: every body's state per recorded frame, and every contact with the impulse
// the responder gave it. The plot and animation tools read these files instead of running
// the simulation again. The columns are documented in docs/scene-format.md.

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "workbook/probes.hpp"
#include "workbook/scene.hpp"
#include "workbook/response_model.hpp"

namespace workbook::sim {

/// Header line of the bodies file, without a newline.
const char* trajectory_header();
/// Header line of the contacts file, without a newline.
const char* contacts_header();

/// Runs the scene with `model` like workbook::run (same world, same steps, same probes) and
/// writes, besides returning the probes:
///  - to `bodies`: one row per body for step 0 and every `stride`-th step, and always the
///    last step, so the file starts at the scene's initial state and ends at the final one;
///  - to `contacts`: one row per contact point of every step that has contacts (whatever the
///    stride, so that no impact is lost between two recorded frames), with the impulse the
///    responder gave the contact.
std::vector<Probes> run_recording(const Scene& scene, const ResponseModel& model, std::size_t stride,
                                  std::ostream& bodies, std::ostream& contacts);

/// `OUT.csv` -> `OUT.contacts.csv`; a name without `.csv` gets `.contacts.csv` appended.
std::string contacts_path_for(const std::string& trajectory_path);

/// Runs the scene with its responder, as workbook::run does; with a non-empty
/// `trajectory_path` also writes the trajectory there and the contacts beside it. Returns the
/// probes, or nothing when a file cannot be written (the error is printed to stderr).
std::optional<std::vector<Probes>> simulate(const Scene& scene, const std::string& trajectory_path, std::size_t stride);

}  // namespace workbook::sim
