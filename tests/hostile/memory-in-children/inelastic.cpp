// Hostile submission for the grader's tests: energy_lost() starts two child processes that each fill 64 MiB and say so: under the limit of a single process, over the limit of the test case together (the grader's test gives 96 MiB), and waits for them
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/wait.h>
#include <unistd.h>
namespace workbook::inelastic {

namespace {
char* volatile held = nullptr;
}  // namespace

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    for (int child = 0; child < 2; ++child) {
        if (fork() == 0) {
            const std::size_t size = std::size_t{64} << 20;
            char* block = static_cast<char*>(std::malloc(size));
            if (block) std::memset(block, 1, size);
            held = block;  // kept where the compiler must assume it is read, so the filling stays
            // What the test shows if the grader ever misses the memory: was it really held?
            std::printf(block ? "a child holds 64 MiB\n" : "a child could not allocate 64 MiB\n");
            std::fflush(stdout);
            sleep(30);
            _exit(0);
        }
    }
    while (wait(nullptr) > 0) {
    }
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}
}  // namespace workbook::inelastic
