// Hostile submission for the grader's tests: looks for the reference solution and the hidden tests, while compiling and while running, and gives wrong answers if it finds one
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
#include <string>
#include <unistd.h>
// Relative to the header folder chapters/inelastic, and to the submission's own folder.
#if __has_include("../../solutions/inelastic.cpp") || __has_include("../../tests/hidden/inelastic.cpp") || \
    __has_include("../solutions/inelastic.cpp") || __has_include("../../../solutions/inelastic.cpp")
#define SECRETS_SEEN_WHILE_COMPILING 1
#else
#define SECRETS_SEEN_WHILE_COMPILING 0
#endif
namespace workbook::inelastic {

namespace {

/// The first secret file the running code can open (printed), or an empty string.
std::string readable_secret() {
    const char* const targets[] = {"solutions/inelastic.cpp", "tests/hidden/inelastic.cpp"};
    std::string prefixes[12] = {"", "/proc/" + std::to_string(getppid()) + "/cwd/", "/proc/1/cwd/"};
    std::string up = "../";
    for (int depth = 3; depth < 12; ++depth, up += "../") prefixes[depth] = up;
    for (const std::string& prefix : prefixes) {
        for (const char* target : targets) {
            const std::string path = prefix + target;
            if (std::FILE* file = std::fopen(path.c_str(), "r")) {
                char text[120] = {};
                std::fread(text, 1, sizeof text - 1, file);
                std::fclose(file);
                std::printf("read %s: %s\n", path.c_str(), text);
                return path;
            }
        }
    }
    return "";
}

}  // namespace

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    if (SECRETS_SEEN_WHILE_COMPILING || !readable_secret().empty()) return -1.0;
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
