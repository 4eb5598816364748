// Hostile submission for the grader's tests: energy_lost() fills /tmp and /dev/shm with 8 MiB files, up to 1 GiB (memory inside bubblewrap, the machine's disk and memory without), says how much it wrote and returns a wrong value
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
#include <string>
#include <vector>
namespace workbook::inelastic {

double energy_lost(const RigidBody&, const RigidBody&) {
    const std::vector<char> block(8 << 20, 'x');
    int written = 0;
    for (const char* folder : {"/tmp/", "/dev/shm/"}) {
        for (int index = 0; index < 64; ++index) {
            const std::string path = std::string(folder) + "workbook-tmp-fill-" + std::to_string(index);
            std::FILE* file = std::fopen(path.c_str(), "w");
            if (!file) break;
            const bool whole = std::fwrite(block.data(), 1, block.size(), file) == block.size();
            if (std::fclose(file) != 0 || !whole) break;
            written += 8;
        }
    }
    std::printf("wrote %d MiB\n", written);
    return -1.0;
}
}  // namespace workbook::inelastic
