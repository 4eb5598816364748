#pragma once
/// \file
/// Running a world for a fixed time and keeping its probes, plus the CSV form of the result.

#include <iosfwd>
#include <vector>

#include "workbook/probes.hpp"
#include "workbook/world.hpp"

namespace workbook {

/// Steps `world` until `duration` seconds have passed, recording the probes before the
/// first step and after every step. The record is reserved up front, so the loop itself
/// allocates nothing.
std::vector<Probes> run(World& world, double duration);

/// Number of steps `run` takes for `duration` at `time_step` (rounded to the nearest step).
std::size_t step_count(double duration, double time_step);

/// The CSV header line, without a newline; the columns and their units are documented in
/// docs/scene-format.md.
const char* csv_header();

/// Writes the header and one line per sample, at full double precision.
void write_csv(std::ostream& out, const std::vector<Probes>& samples);

}  // namespace workbook
