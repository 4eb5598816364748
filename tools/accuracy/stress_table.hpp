#pragma once
/// \file
/// The stress corpus's table, for people (aligned text) and for tools (CSV).

#include <iosfwd>
#include <vector>

#include "stress.hpp"

namespace workbook::accuracy {

/// scene, steps, bodies, worst violation (measured / allowed, and which invariant), verdict.
void print_stress_table(std::ostream& out, const std::vector<StressResult>& results);

/// One line per scene, every invariant's worst ratio, at full precision.
void write_stress_csv(std::ostream& out, const std::vector<StressResult>& results);

}  // namespace workbook::accuracy
