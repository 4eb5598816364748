// Hostile submission for the grader's tests: energy_lost() looks for what other test cases left (files in /tmp and /dev/shm) and for test names in other processes' command lines, prints all it finds, leaves its own inputs for the next cases, and returns a wrong value so that its printing is shown
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
#include <dirent.h>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/stat.h>
namespace workbook::inelastic {

namespace {

std::string read_all(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

/// Prints what earlier or concurrent test cases left, then leaves this case's inputs.
void spy(const RigidBody& body1, const RigidBody& body2) {
    for (const char* folder : {"/tmp/", "/dev/shm/", "/var/tmp/"}) {
        const std::string path = std::string(folder) + "workbook-spy.txt";
        const std::string seen = read_all(path);
        if (!seen.empty()) std::printf("left by another test case in %s: %s\n", folder, seen.c_str());
        if (std::FILE* file = std::fopen(path.c_str(), "a")) {
            std::fprintf(file, "inputs %.17g %.17g;", body1.velocity.x, body2.velocity.x);
            std::fclose(file);
            chmod(path.c_str(), 0666);
        }
    }
    if (DIR* proc = opendir("/proc")) {
        while (dirent* entry = readdir(proc)) {
            std::string line = read_all(std::string("/proc/") + entry->d_name + "/cmdline");
            if (line.find("checker") == std::string::npos) continue;
            for (char& c : line) if (c == '\0') c = ' ';
            std::printf("command line: %s\n", line.c_str());
        }
        closedir(proc);
    }
    std::printf("my inputs inputs %.17g %.17g;\n", body1.velocity.x, body2.velocity.x);
    std::fflush(stdout);
}

}  // namespace

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    spy(body1, body2);
    return -1.0;
}

}  // namespace workbook::inelastic
