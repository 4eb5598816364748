#include "seeded_random.hpp"

#include <catch2/catch_get_random_seed.hpp>

namespace workbook::testing {

std::uint64_t run_seed() { return Catch::getSeed(); }

}  // namespace workbook::testing
