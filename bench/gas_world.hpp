#pragma once
// The gas as a workbook World, for the gas driver and the stage micro benchmarks.

#include "gas.hpp"
#include "workbook/world.hpp"

namespace workbook::bench {

/// The discs first (in the gas's order), then the four walls as immovable planes.
World make_gas_world(const Gas& gas);

}  // namespace workbook::bench
