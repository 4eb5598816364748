#pragma once
// The gas as a workbook World, for the gas driver and the stage micro benchmarks.

#include "gas.hpp"
#include "workbook/world.hpp"

namespace workbook::bench {

/// The discs first (in the gas's order), then the four walls as immovable planes.
World make_gas_world(const Gas& gas);

/// The gas's responder, written here rather than taken from a chapter (the chapters' responders
/// are exercises, and the benchmark must not depend on them): e = 1 along the normal, only while
/// the pair approaches; no position correction, so the kinetic energy changes only by rounding.
void elastic_impulse(RigidBody& body1, RigidBody& body2, const Contact& contact);

}  // namespace workbook::bench
