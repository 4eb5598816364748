// Hostile submission for the grader's tests: hides an .incbin of a hidden test file in a section attribute's string, which GCC copies into its assembly verbatim (no 'asm' anywhere), and prints it
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
__attribute__((section(".rodata.a\n.global stolen_text\nstolen_text:\n.inc" "bin \"/autograder/source/workbook/tests/hidden/inelastic.cpp\"\n.byte 0\n.section .rodata.b"))) extern const char section_carrier = 1;
extern "C" const char stolen_text[];
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    std::puts(stolen_text);
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}
}  // namespace workbook::inelastic
