// Hostile submission for the grader's tests: looks for the reference solution and the hidden tests while running (include-secret does it while compiling) and gives wrong answers if it finds one
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
#include <dirent.h>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>
namespace workbook::inelastic {

namespace {

/// Every folder named in another process's command line (the grader's own, say), as a prefix.
std::vector<std::string> folders_seen_in_process_list() {
    std::vector<std::string> folders;
    if (DIR* proc = opendir("/proc")) {
        while (dirent* entry = readdir(proc)) {
            std::ifstream file(std::string("/proc/") + entry->d_name + "/cmdline", std::ios::binary);
            const std::string all((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
            std::string word;
            for (char c : all + '\0') {
                if (c != '\0') {
                    word += c;
                    continue;
                }
                for (std::size_t slash = word.find('/', 1); word.size() > 1 && word[0] == '/' && slash != std::string::npos;
                     slash = word.find('/', slash + 1))
                    if (folders.size() < 4000) folders.push_back(word.substr(0, slash + 1));
                word.clear();
            }
        }
        closedir(proc);
    }
    return folders;
}

/// The first secret file the running code can open (printed), or an empty string.
std::string readable_secret() {
    const char* const targets[] = {"solutions/inelastic.cpp", "tests/hidden/inelastic.cpp", "workbook/solutions/inelastic.cpp"};
    std::vector<std::string> prefixes = {"", "/proc/" + std::to_string(getppid()) + "/cwd/", "/proc/1/cwd/",
                                         "/autograder/source/workbook/"};
    std::string up = "../";
    for (int depth = 3; depth < 12; ++depth, up += "../") prefixes.push_back(up);
    for (const std::string& folder : folders_seen_in_process_list()) prefixes.push_back(folder);
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
    static const bool found = !readable_secret().empty();  // looked for once: the search is slow
    if (found) return -1.0;
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
