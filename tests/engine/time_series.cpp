// run(), step_count() and the CSV form of a run.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "checks.hpp"
#include "csv_table.hpp"
#include "workbook/time_series.hpp"

using namespace workbook;
using Catch::Matchers::WithinAbs;
using workbook::testing::parse_csv_number;
using workbook::testing::split_csv_line;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

const ResponseModel no_response{"none", nullptr, nullptr};

/// The lines of a text in which every line, the last included, ends with '\n'.
std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::string line;
    std::istringstream in(text);
    while (std::getline(in, line)) lines.push_back(line);
    return lines;
}

/// Samples whose values need all 17 significant digits to survive a round trip.
std::vector<Probes> awkward_samples() {
    Probes first;
    first.time = 0.1;
    first.kinetic_linear = 1.0 / 3.0;
    first.kinetic_rotational = 2.0 / 3.0 * 1e-10;
    first.potential = -9.81 * 7.0 / 11.0;
    first.linear_momentum = {0.1 + 0.2, -1e300, 5e-324};
    first.angular_momentum = {1.0 / 7.0, -0.0, 123456789.123456789};
    first.response_energy_change = -std::numeric_limits<double>::epsilon();
    first.contacts = 3;
    first.penetration_max = 0.1 + 0.2;
    Probes second = first;
    second.time = 0.2;
    second.kinetic_linear = std::numeric_limits<double>::max();
    second.potential = -std::numeric_limits<double>::max();  // so the total stays finite
    second.contacts = 0;
    return {first, second};
}

}  // namespace

TEST_CASE("step_count rounds duration / time_step to the nearest whole step", "[time_series]") {
    // 1 / (1 / 240) is not exactly 240 in floating point; rounding must still give 240.
    CHECK(step_count(1.0, 1.0 / 240.0) == 240);
    CHECK(step_count(0.3, 0.1) == 3);  // 2.9999999999999996
    CHECK(step_count(0.26, 0.1) == 3);
    CHECK(step_count(0.24, 0.1) == 2);
    CHECK(step_count(0.01, 0.01) == 1);
    CHECK(step_count(10.0, 1.0 / 1024.0) == 10240);
}

TEST_CASE("run records the state before the first step and after each of the steps", "[time_series]") {
    const double dt = 1.0 / 64.0;
    const Vector3 g{0.0, -8.0, 0.0};
    World world({make_sphere(2.0, 0.5, {0, 10, 0}, {1, 0, 0})}, WorldSettings{dt, g}, no_response);
    const std::vector<Probes> samples = run(world, 0.5);

    REQUIRE(samples.size() == 32 + 1);
    CHECK(world.time() == 0.5);
    for (std::size_t n = 0; n < samples.size(); ++n) {
        CAPTURE(n);
        const double steps = static_cast<double>(n);
        // dt and g are powers of two: every value below is exact.
        CHECK(samples[n].time == steps * dt);
        CHECK(samples[n].linear_momentum == Vector3{2.0, 2.0 * -8.0 * steps * dt, 0.0});
        CHECK(samples[n].kinetic_linear == 0.5 * 2.0 * (1.0 + 64.0 * steps * dt * steps * dt));
        const double height = 10.0 - 8.0 * dt * dt * steps * (steps + 1) / 2;
        CHECK(samples[n].potential == 2.0 * 8.0 * height);
        CHECK(samples[n].contacts == 0);
    }
    // The first sample is the untouched initial state.
    CHECK(samples.front().potential == 160.0);
    CHECK(samples.front().kinetic_linear == 1.0);
}

TEST_CASE("run rounds the duration to whole steps", "[time_series]") {
    World world({make_sphere(1.0, 0.5, {0, 0, 0})}, WorldSettings{0.1, {}}, no_response);
    CHECK(run(world, 0.26).size() == 4);
    CHECK_THAT(world.time(), WithinAbs(0.3, 4 * eps));
}

TEST_CASE("write_csv starts with csv_header() and writes one line per sample", "[time_series][csv]") {
    std::ostringstream out;
    write_csv(out, awkward_samples());
    const std::vector<std::string> lines = lines_of(out.str());
    REQUIRE(lines.size() == 3);
    CHECK(lines[0] == csv_header());
    CHECK(out.str().back() == '\n');

    const std::vector<std::string> columns = split_csv_line(csv_header());
    REQUIRE(columns.size() == 14);
    CHECK(columns.front() == "t");
    CHECK(columns[4] == "total");
    CHECK(columns[12] == "contacts");
    CHECK(columns.back() == "penetration_max");
    for (std::size_t i = 1; i < lines.size(); ++i) CHECK(split_csv_line(lines[i]).size() == columns.size());
}

TEST_CASE("write_csv values read back bit for bit", "[time_series][csv]") {
    const std::vector<Probes> samples = awkward_samples();
    std::ostringstream out;
    write_csv(out, samples);
    const std::vector<std::string> lines = lines_of(out.str());
    REQUIRE(lines.size() == samples.size() + 1);

    for (std::size_t i = 0; i < samples.size(); ++i) {
        CAPTURE(i, lines[i + 1]);
        const Probes& p = samples[i];
        const std::vector<std::string> cells = split_csv_line(lines[i + 1]);
        REQUIRE(cells.size() == 14);
        const std::vector<double> expected{p.time,
                                           p.kinetic_linear,
                                           p.kinetic_rotational,
                                           p.potential,
                                           p.total_energy(),
                                           p.linear_momentum.x,
                                           p.linear_momentum.y,
                                           p.linear_momentum.z,
                                           p.angular_momentum.x,
                                           p.angular_momentum.y,
                                           p.angular_momentum.z,
                                           p.response_energy_change};
        for (std::size_t c = 0; c < expected.size(); ++c) {
            CAPTURE(c, cells[c]);
            CHECK(parse_csv_number(cells[c]) == expected[c]);
        }
        CHECK(cells[12] == std::to_string(p.contacts));
        CHECK(parse_csv_number(cells[13]) == p.penetration_max);
    }
}

TEST_CASE("write_csv leaves the stream's precision as it found it", "[time_series][csv]") {
    std::ostringstream out;
    out.precision(3);
    write_csv(out, awkward_samples());
    CHECK(out.precision() == 3);
}
