// Hostile submission for the grader's tests: looks for other submissions graded beside it (the grader's work folder, paths in other processes' command lines) and gives wrong answers if it can read any of their files
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>
namespace workbook::inelastic {

namespace {

std::string read_all(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

std::string parent(const std::string& path) { return path.substr(0, path.rfind('/')); }

/// Whether a file of another submission (under the grader's work folder, outside this
/// submission's folder and the public kit) can be read; what it read is printed.
bool reads_another_submission() {
    char self[PATH_MAX] = {};
    if (readlink("/proc/self/exe", self, sizeof self - 1) <= 0) return false;
    const std::string own = parent(parent(self));   // <work root>/<submission>
    const std::string root = parent(own);           // <work root>
    std::vector<std::string> paths;
    if (DIR* folder = opendir(root.c_str())) {       // the work root must not be listable
        while (dirent* entry = readdir(folder)) paths.push_back(root + "/" + entry->d_name + "/inelastic/inelastic.cpp");
        closedir(folder);
    }
    if (DIR* proc = opendir("/proc")) {              // compilers of other submissions name their files
        while (dirent* entry = readdir(proc)) {
            std::string word;
            for (char c : read_all(std::string("/proc/") + entry->d_name + "/cmdline") + '\0') {
                if (c != '\0') { word += c; continue; }
                if (word.rfind(root + "/", 0) == 0) paths.push_back(word);
                word.clear();
            }
        }
        closedir(proc);
    }
    for (const std::string& path : paths) {
        if (path.rfind(own + "/", 0) == 0 || path.rfind(root + "/kit/", 0) == 0) continue;
        const std::string text = read_all(path);
        if (!text.empty()) {
            std::printf("read another submission's %s: %.80s\n", path.c_str(), text.c_str());
            return true;
        }
    }
    return false;
}

}  // namespace

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    static const bool found = reads_another_submission();  // looked for once: the search is slow
    if (found) return -1.0;
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
