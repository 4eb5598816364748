// Hostile submission for the grader's tests: pulls a hidden test file into the program with the assembler's .incbin and prints it
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
asm(".section .rodata\n.global secret_text\nsecret_text:\n.incbin \"/work/tests/hidden/inelastic.cpp\"\n.byte 0\n.previous");
namespace workbook::inelastic {

}  // namespace workbook::inelastic
