#!/usr/bin/env python3
"""The student edition on the systems students bring, through stand-ins that run here:

  macOS     Clang with LLVM's own C++ library, libc++ 14 (Debian's libc++-14-dev): what an
            Xcode's Clang uses, with the oldest library of the Xcodes the README supports and
            less. Catch2 and fmt are built from their sources through the workbook's
            FetchContent fallback (cmake/Dependencies.cmake), as on a Mac without Homebrew.
  Windows   mingw-w64's GCC (g++-mingw-w64-x86-64-posix), the step tests run under Wine
            (wine64). Catch2 and fmt are built for it once and found with find_package, as
            vcpkg's are on Windows; nlohmann-json, CLI11 and Python are not there for it, so
            configuring must go on without the simulator and the Python tests, and say so.

Each builds the edition's `check` target (public_steps_student, from the untouched skeleton)
with the student preset, with no warning from the edition's own files, and runs every
chapter's step tests with the "steps" reporter: the reports must be those of the Linux build
(--linux-steps, the same target built by this tree with GCC), byte for byte once Windows'
line ends are made Unix ones.

Catch2 and fmt come from Debian's source packages of the versions installed here (apt-get
source, with a list of source archives of its own made from the system's: nothing of the
system's apt set-up changes). Sources, builds and the Wine prefix are kept in --cache, so a
second run builds only what changed. A stand-in whose packages are not installed is skipped,
and says which packages to install.

    test_other_systems.py --linux-steps build/dev/tests/public_steps_student --cache build/dev/other-systems"""
import argparse
import difflib
import filecmp
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
from grader import pack_student  # noqa: E402
from tools import workbook_files  # noqa: E402

ARGS = None
SEED = (ROOT / "tests/RANDOM_SEED").read_text().split()[0]
MINGW_CXX = "x86_64-w64-mingw32-g++-posix"
MINGW_CC = "x86_64-w64-mingw32-gcc-posix"
MINGW_ROOT = "/usr/x86_64-w64-mingw32"
LIBCXX_HEADERS = pathlib.Path("/usr/lib/llvm-14/include/c++/v1/vector")
# The Debian packages each stand-in needs; ./workbook test installs them.
LIBCXX_PACKAGES = "clang libc++-14-dev libc++abi-14-dev"
MINGW_PACKAGES = "g++-mingw-w64-x86-64-posix wine64"
# Debian's source package of each library, by the binary package the Linux build uses.
SOURCES = {"Catch2": ("catch2", "libcatch2-dev"), "fmt": ("fmtlib", "libfmt-dev")}


def log(text):
    print(text, flush=True)


def run(argv, timeout=1200, **options):
    """Runs a command; a failure shows its last output."""
    started = time.monotonic()
    done = subprocess.run(argv, capture_output=True, text=True, timeout=timeout, **options)
    if done.returncode != 0:
        raise AssertionError(f"{' '.join(map(str, argv))} failed ({done.returncode}):\n{(done.stdout + done.stderr)[-4000:]}")
    log(f"  {time.monotonic() - started:6.1f} s  {' '.join(map(str, argv[:4]))} ...")
    return done


def wine_program():
    for name in ("wine64", "wine"):
        if shutil.which(name):
            return shutil.which(name)
    return "/usr/lib/wine/wine64" if os.access("/usr/lib/wine/wine64", os.X_OK) else None


def sync_tree(source, target):
    """Makes target a copy of source, rewriting only the files that differ, so that a build
    of target recompiles only what changed since the last run."""
    target.mkdir(parents=True, exist_ok=True)
    wanted = set()
    for path in source.rglob("*"):
        relative = path.relative_to(source)
        wanted.add(relative)
        copy = target / relative
        if path.is_dir():
            copy.mkdir(parents=True, exist_ok=True)
        elif not copy.is_file() or not filecmp.cmp(path, copy, shallow=False):
            shutil.copyfile(path, copy)  # dated now, not as the original: newer than the last build
            shutil.copymode(path, copy)
    for path in sorted(target.rglob("*"), reverse=True):
        if path.relative_to(target) not in wanted:
            shutil.rmtree(path) if path.is_dir() and not path.is_symlink() else path.unlink()


def apt_source_lists(folder):
    """A folder of deb-src entries for the archives the system's apt uses (deb822 and one-line)."""
    folder.mkdir(parents=True, exist_ok=True)
    entries = []
    parts = pathlib.Path("/etc/apt/sources.list.d")
    for path in sorted(parts.glob("*.sources")) if parts.is_dir() else []:
        entries.append(re.sub(r"(?m)^Types:.*$", "Types: deb-src", path.read_text()))
    (folder / "workbook.sources").write_text("\n\n".join(e.strip() for e in entries) + "\n")
    lines = []
    for path in [pathlib.Path("/etc/apt/sources.list"), *(sorted(parts.glob("*.list")) if parts.is_dir() else [])]:
        if path.is_file():
            lines += [re.sub(r"^deb(\s)", r"deb-src\1", line) for line in path.read_text().splitlines()
                      if line.startswith("deb ")]
    (folder / "workbook.list").write_text("\n".join(lines) + "\n")


def library_sources(cache):
    """{library: folder of its sources}, from Debian's source packages of the installed versions."""
    folders = {}
    for library, (source_package, binary_package) in SOURCES.items():
        version = subprocess.run(["dpkg-query", "-W", "-f=${source:Version}", binary_package], capture_output=True,
                                 text=True).stdout.strip()
        if not version:
            raise unittest.SkipTest(f"{binary_package} is not installed, so there is no version of {library} to build")
        upstream = re.sub(r"^\d+:", "", version).rsplit("-", 1)[0]
        folder = cache / "sources" / f"{source_package}-{upstream}"
        if not (folder / "CMakeLists.txt").is_file():
            download = cache / "sources" / "download"
            apt = cache / "apt"
            for sub in ("lists/partial", "archives/partial", "parts"):
                (apt / sub).mkdir(parents=True, exist_ok=True)
            apt_source_lists(apt / "parts")
            (apt / "empty.list").write_text("")
            options = ["-o", f"Dir::Etc::SourceList={apt / 'empty.list'}", "-o", f"Dir::Etc::SourceParts={apt / 'parts'}",
                       "-o", f"Dir::State::Lists={apt / 'lists'}", "-o", f"Dir::Cache={apt}", "-o", "Debug::NoLocking=1",
                       "-q"]
            if not any((apt / "lists").glob("*Sources*")):
                run(["apt-get", *options, "update"], timeout=600)
            download.mkdir(parents=True, exist_ok=True)
            run(["apt-get", *options, "source", "--download-only", f"{source_package}={version}"], cwd=download,
                timeout=600)
            original = next(download.glob(f"{source_package}_{upstream}.orig.tar.*"))
            unpacked = cache / "sources" / "unpacking"
            shutil.rmtree(unpacked, ignore_errors=True)
            with tarfile.open(original) as archive:
                archive.extractall(unpacked, filter="data")
            (top,) = list(unpacked.iterdir())
            shutil.rmtree(folder, ignore_errors=True)
            top.rename(folder)
            shutil.rmtree(unpacked)
        folders[library] = folder
    return folders


def own_warnings(output, pack):
    """The compiler's warnings about the edition's own files (not Catch2's or fmt's)."""
    return [line for line in output.splitlines() if re.search(r"warning[: ]", line) and str(pack) in line
            and "/_deps/" not in line]


class OtherSystems(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.cache = pathlib.Path(ARGS.cache).resolve()
        cls.cache.mkdir(parents=True, exist_ok=True)
        cls.pack = cls.cache / "workbook-student"
        with tempfile.TemporaryDirectory(prefix="other-systems-") as scratch:
            fresh = pathlib.Path(scratch) / "workbook-student"
            pack_student.write_pack(fresh)
            sync_tree(fresh, cls.pack)
        cls.chapters = workbook_files.chapters(cls.pack)
        cls.linux = {chapter: cls.step_report([ARGS.linux_steps], chapter) for chapter in cls.chapters}

    @staticmethod
    def step_report(command, chapter, **options):
        done = subprocess.run([*command, f"[{chapter}]", "--reporter", "steps", "--rng-seed", SEED],
                              capture_output=True, timeout=600, **options)
        return done.returncode, done.stdout.replace(b"\r\n", b"\n").decode("utf-8")

    def configure_and_build(self, name, options):
        build = self.cache / name / "build"
        configured = run(["cmake", "--preset", "student", "-S", str(self.pack), "-B", str(build), *options],
                         cwd=self.pack)
        built = run(["cmake", "--build", str(build), "--target", "public_steps_student"], timeout=2400)
        self.assertEqual(own_warnings(built.stdout + built.stderr, self.pack), [],
                         f"{name}: the student edition compiles with warnings")
        return build, configured.stdout + configured.stderr

    def assert_same_reports(self, name, command, **options):
        for chapter in self.chapters:
            with self.subTest(system=name, chapter=chapter):
                status, report = self.step_report(command, chapter, **options)
                linux_status, linux_report = self.linux[chapter]
                self.assertIn("Step 1", report)
                if report != linux_report:
                    diff = difflib.unified_diff(linux_report.splitlines(), report.splitlines(), "Linux", name, lineterm="")
                    self.fail(f"{name}: chapter {chapter}'s step report differs from Linux's:\n" +
                              "\n".join(line[:400] for line in list(diff)[:40]))
                self.assertEqual(status, linux_status, f"{name}: chapter {chapter}'s exit status differs from Linux's")

    def test_macos_stand_in_clang_with_libcxx_14(self):
        if not shutil.which("clang++") or not LIBCXX_HEADERS.is_file():
            self.skipTest(f"needs Debian's {LIBCXX_PACKAGES} (./workbook test installs them)")
        sources = library_sources(self.cache)
        flags = "-stdlib=libc++"
        build, _ = self.configure_and_build("libc++", [
            "-DCMAKE_CXX_COMPILER=clang++", f"-DCMAKE_CXX_FLAGS={flags}", f"-DCMAKE_EXE_LINKER_FLAGS={flags}",
            # Debian's Catch2 and fmt are built for libstdc++: built here from their sources instead.
            "-DCMAKE_DISABLE_FIND_PACKAGE_Catch2=ON", "-DCMAKE_DISABLE_FIND_PACKAGE_fmt=ON",
            "-DWORKBOOK_FETCH_MISSING=ON", f"-DFETCHCONTENT_SOURCE_DIR_CATCH2={sources['Catch2']}",
            f"-DFETCHCONTENT_SOURCE_DIR_FMT={sources['fmt']}"])
        binary = build / "tests/public_steps_student"
        linked = run(["ldd", str(binary)]).stdout
        self.assertIn("libc++.so", linked, "not linked with libc++")
        self.assertNotIn("libstdc++", linked, "libstdc++ linked in as well")
        self.assert_same_reports("libc++", [str(binary)])

    def test_windows_stand_in_mingw_under_wine(self):
        wine = wine_program()
        if not shutil.which(MINGW_CXX) or not wine:
            self.skipTest(f"needs Debian's {MINGW_PACKAGES} (./workbook test installs them)")
        sources = library_sources(self.cache)
        root = self.cache / "mingw"
        prefix = root / "prefix"
        toolchain = root / "toolchain.cmake"
        root.mkdir(parents=True, exist_ok=True)
        toolchain.write_text(f"""set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER {MINGW_CC})
set(CMAKE_CXX_COMPILER {MINGW_CXX})
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
set(CMAKE_FIND_ROOT_PATH {MINGW_ROOT} {prefix})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# One .exe with the C++ runtime inside: nothing to copy next to it for Wine to find.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
""")
        # Catch2 and fmt, built and installed once into the prefix, as vcpkg installs them.
        for library, folder in sources.items():
            stamp = prefix / f".{folder.name}.installed"
            if stamp.is_file():
                continue
            library_build = root / f"build-{folder.name}"
            run(["cmake", "-S", str(folder), "-B", str(library_build), "-G", "Ninja", f"-DCMAKE_TOOLCHAIN_FILE={toolchain}",
                 "-DCMAKE_BUILD_TYPE=Debug", f"-DCMAKE_INSTALL_PREFIX={prefix}", "-DBUILD_TESTING=OFF",
                 "-DCATCH_INSTALL_DOCS=OFF", "-DCATCH_INSTALL_EXTRAS=OFF", "-DFMT_TEST=OFF", "-DFMT_DOC=OFF",
                 # Unity files, as the workbook builds a downloaded Catch2: a quarter of the time.
                 "-DCMAKE_UNITY_BUILD=ON", "-DCMAKE_UNITY_BUILD_BATCH_SIZE=32"])
            run(["cmake", "--build", str(library_build)], timeout=2400)
            run(["cmake", "--install", str(library_build)])
            stamp.write_text("")
        # Python hidden from CMake too: `check`'s build needs none of the three.
        build, configured = self.configure_and_build("mingw", [
            f"-DCMAKE_TOOLCHAIN_FILE={toolchain}", f"-DCMAKE_PREFIX_PATH={prefix}", "-DWORKBOOK_FETCH_MISSING=OFF",
            "-DCMAKE_DISABLE_FIND_PACKAGE_Python3=ON"])
        # Neither nlohmann-json nor CLI11 is there for Windows, nor Python: configuring went on
        # without the simulator and with the tests written in Python disabled, and said so.
        self.assertIn("workbook-sim is not built: it needs nlohmann-json", configured)
        self.assertIn("Python 3 not found: the tests written in Python are disabled", configured)
        environment = dict(os.environ, WINEPREFIX=str(root / "wine"), WINEDEBUG="-all",
                           WINEDLLOVERRIDES="mscoree,mshtml=")
        try:
            self.assert_same_reports("mingw-w64 under Wine", [wine, str(build / "tests/public_steps_student.exe")],
                                     env=environment)
        finally:
            server = shutil.which("wineserver") or "/usr/lib/wine/wineserver64"
            if os.access(server, os.X_OK):
                subprocess.run([server, "-k"], env=environment, capture_output=True, timeout=60)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--linux-steps", required=True, help="public_steps_student of this tree's GCC build")
    parser.add_argument("--cache", required=True, help="folder for the sources, builds and Wine prefix, kept between runs")
    ARGS, rest = parser.parse_known_args()
    unittest.main(argv=[sys.argv[0], *rest], verbosity=2)
