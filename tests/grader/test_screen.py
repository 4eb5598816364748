#!/usr/bin/env python3
"""The grader's include and assembler screen (grader/screen.py) on the tricks a textual
screen misses, and on the preprocessor's output; no build needed.

    python3 -m tests.grader.test_screen   (from the workbook's folder; ctest runs it: label grader)"""
import pathlib
import unittest

from grader import screen

ROOT = pathlib.Path(__file__).resolve().parents[2]


def problems(text):
    return [problem for _, problem in screen.check_text(text)]


class TextTest(unittest.TestCase):
    def test_refused_whatever_hides_them(self):
        refused = {
            "comment between # and include": '#/**/include "/etc/passwd"\n',
            "spliced directive": '#inc\\\nlude "/etc/passwd"\n',
            "angle brackets": "#include </etc/passwd>\n",
            "leaving the submission": '#include "../../solutions/inelastic.cpp"\n',
            "include through a macro": '#define F "/etc/passwd"\n#include F\n',
            "has_include after a comment": '#if __has_include/**/("/autograder/x")\n#endif\n',
            "has_include through a macro": "#define P(x) __has_include(x)\n",
            "asm from string pieces": 'asm(".inc" "bin \\"/etc/passwd\\"");\n',
            "asm behind a macro": "#define A __asm__\n",
            "__asm": '__asm(".byte 0");\n',
            "token pasting": "#define C(a, b) a##b\n",
            "digraph pasting": "#define C(a, b) a%:%:b\n",
            "_Pragma": '_Pragma("GCC dependency \\"/etc/passwd\\"")\n',
            "pragma dependency": '#pragma GCC dependency "/etc/passwd"\n',
            "line directive": '#line 1 "/usr/include/stdio.h"\n',
            "line marker": '# 1 "/usr/include/stdio.h" 1 3\n',
            "a '#' a macro could turn into a line marker": "#define H # 1\n",
            "a '#' passed to a macro": "#define ID(x) x\nint z = ID(#) 1;\n",
            "embed": '#embed "/etc/passwd"\n',
        }
        for what, text in refused.items():
            with self.subTest(what):
                self.assertTrue(problems(text), text)

    def test_ordinary_code_passes(self):
        fine = ('#include <cmath>\n#include "inelastic.hpp"\n#define SQUARE(x) ((x) * (x))\n#define NAME(x) #x\n'
                'const char* s = "asm(\\".incbin\\") #include \\"/etc/passwd\\"";  // asm, ##, /etc/passwd\n'
                '/* __has_include("/x") */ auto r = R"x(#include "/etc" asm ## )x";\n'
                "bool less = 1 < 2 && 3 > 2; char c = '#';\n")
        self.assertEqual(problems(fine), [])
        for folder in ("solutions", "skeleton"):
            for path in (ROOT / folder).glob("*.cpp"):
                with self.subTest(path=str(path)):
                    self.assertEqual(problems(path.read_text()), [])

    def test_lines_are_named(self):
        self.assertEqual(screen.check_text('int a;\n/* x\n */ #include "/etc/passwd"\n')[0][0], 3)


class PreprocessedTest(unittest.TestCase):
    SOURCE = "/work/sub/inelastic.cpp"

    def check(self, text):
        return [problem for _, problem in screen.check_preprocessed(text, self.SOURCE, ["/work/kit/engine/include"])]

    def test_files_entered(self):
        allowed = (f'# 0 "{self.SOURCE}"\n# 0 "<built-in>"\n# 1 "/usr/include/stdc-predef.h" 1 3 4\n'
                   f'# 0 "<command-line>" 2\n# 1 "{self.SOURCE}"\n# 1 "/work/kit/engine/include/vec.hpp" 1\n'
                   f'int x;\n# 2 "{self.SOURCE}" 2\nint y;\n')
        self.assertEqual(self.check(allowed), [])
        outside = f'# 1 "{self.SOURCE}"\nint a;\n# 1 "/etc/passwd" 1\nroot:x:0:0\n# 3 "{self.SOURCE}" 2\n'
        found = screen.check_preprocessed(outside, self.SOURCE, [])
        self.assertEqual(len(found), 1)
        self.assertEqual(found[0][0], 2)  # the including line
        self.assertNotIn("passwd", found[0][1])  # the refusal never names the file

    def test_asm_only_on_the_submissions_lines(self):
        system = (f'# 1 "{self.SOURCE}"\n# 1 "/usr/include/stdio.h" 1 3 4\n'
                  'extern int f() __asm__ ("" "g");\n'
                  f'# 2 "{self.SOURCE}" 2\nint a;\n')
        self.assertEqual(self.check(system), [])
        own = f'# 1 "{self.SOURCE}"\nint a;\n__asm__(".inc" "bin \\"x\\"");\n'
        self.assertEqual(screen.check_preprocessed(own, self.SOURCE, [])[0][0], 2)
        self.assertEqual(self.check(f'# 1 "{self.SOURCE}"\nconst char* s = "asm";\n'), [])


class AssemblyTest(unittest.TestCase):
    def test_directives_that_read_files(self):
        injected = '\t.section\t.rodata.a\n.global x\nx:\n.incbin "/etc/passwd"\n.byte 0,"aw"\n'
        self.assertTrue(screen.check_assembly(injected))
        for hidden in ('\t.INCLUDE "x.s"\n', "a: .macro m\n", "\t.irpc c, abc\n", "\t.rept 3\n"):
            with self.subTest(hidden):
                self.assertTrue(screen.check_assembly(hidden))

    def test_ordinary_assembly_passes(self):
        ordinary = ('\t.file\t"inelastic.cpp"\n\t.text\n\t.globl\t_ZN1f\n_ZN1f:\n.LFB0:\n\t.cfi_startproc\n'
                    '\tmovsd\t.LC0(%rip), %xmm0\n\tret\n\t.section\t.rodata.str1.1,"aMS",@progbits,1\n'
                    '.LC1:\n\t.string\t"#include <x> and .included"\n\t.ident\t"GCC"\n')
        self.assertEqual(screen.check_assembly(ordinary), [])


if __name__ == "__main__":
    unittest.main()
