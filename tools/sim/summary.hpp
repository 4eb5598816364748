#pragma once
// The human-readable report printed after a run.

#include <iosfwd>
#include <vector>

#include "workbook/probes.hpp"
#include "workbook/scene.hpp"

namespace workbook::sim {

/// Prints the scene, the run's length, and every step in which a response changed the
/// kinetic energy, with the change in joules.
void print_summary(std::ostream& out, const Scene& scene, const std::vector<Probes>& samples);

}  // namespace workbook::sim
