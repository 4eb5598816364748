"""Finding the tools the workbook needs and installing what is missing.

The tools are looked for first, and no package manager is touched when all are there, so any
system that has them works (Fedora, Arch, macOS, Windows, a container). When something is
missing it is installed with apt where apt exists (Debian, Ubuntu); elsewhere the front end
prints what to install on Fedora, Arch, macOS (Homebrew) and Windows, and stops only when a
tool every command needs is missing."""
import glob
import os
import pathlib
import subprocess
import sys

from tools.cli import edition, host
from tools.cli.console import Failure, say

# Debian bookworm's own packages, plus Catch2 3 from bookworm-backports (bookworm itself ships
# only Catch2 2.13).
PACKAGES = ["cmake", "ninja-build", "g++", "clang", "libclang-rt-14-dev", "python3", "git", "nlohmann-json3-dev",
            "libcli11-dev", "libfmt-dev", "gnuplot-nox", "fonts-dejavu-core", "ffmpeg", "doxygen", "libjs-mathjax",
            "doxygen-awesome-css", "bubblewrap", "zip", "unzip", "chromium"]
# The test suite's builds of the student edition for the other systems' libraries: libc++
# (macOS's) and mingw-w64 run under Wine (Windows). Only the instructor's tree has that test.
OTHER_SYSTEMS_PACKAGES = ["libc++-14-dev", "libc++abi-14-dev", "g++-mingw-w64-x86-64-posix", "wine64"]
# Only `./workbook bench` needs these: Google Benchmark and the peer engines it is measured
# against (Bullet is found through pkg-config). Students never install them.
BENCH_PACKAGES = ["libbenchmark-dev", "libchipmunk-dev", "libbox2d-dev", "libbullet-dev", "pkgconf"]

EVERY_COMMAND = "every command"


def windows_guide():
    """(file, heading) of the README section that takes a Windows student step by step: the
    student edition's README (grader/student-README.md here, README.md in that edition)."""
    for name in ("grader/student-README.md", "README.md"):
        try:
            lines = (edition.ROOT / name).read_text(encoding="utf-8").splitlines()
        except OSError:
            continue
        for line in lines:
            if line.startswith("#") and "Windows" in line:
                return name, line.lstrip("#").strip()
    return "README.md", "Windows"


def windows_advice():
    name, heading = windows_guide()
    return (f"follow {name}, section '{heading}': Visual Studio 2022 with its C++ workload (it brings CMake, "
            f"Ninja and vcpkg), then py workbook.py check CHAPTER in its Developer PowerShell")


# One tool a line: id | what needs it ("every command" stops without it) | Fedora (dnf) |
# Arch (pacman) | macOS (Homebrew). A "-" means no package: the note after it says what to do.
TOOLS = """\
cmake|every command|cmake|cmake|cmake
ninja|every command|ninja-build|ninja|ninja
c++|every command|gcc-c++|gcc|- (Xcode's command line tools: xcode-select --install)
python3|every command|python3|python|python
catch2-3|every command|catch-devel|catch2|catch2
fmt|every command|fmt-devel|fmt|fmt
nlohmann-json|every command|json-devel|nlohmann-json|nlohmann-json
cli11|every command|cli11-devel|cli11|cli11
gnuplot|figures|gnuplot|gnuplot|gnuplot
ffmpeg|animations|ffmpeg|ffmpeg|ffmpeg
doxygen|docs (the site)|doxygen|doxygen|doxygen
mathjax2|docs (the site)|mathjax|mathjax2|- (npm install mathjax@2, then cmake --preset dev -DWORKBOOK_MATHJAX_DIR=$PWD/node_modules/mathjax)
doxygen-awesome-css|docs (the site)|- (the doxygen-awesome-css project's release: cmake --preset dev -DWORKBOOK_DOXYGEN_AWESOME_DIR=FOLDER)|- (AUR: doxygen-awesome-css)|- (the doxygen-awesome-css project's release: cmake --preset dev -DWORKBOOK_DOXYGEN_AWESOME_DIR=FOLDER)
clang|test (Clang with sanitizers)|clang compiler-rt|clang compiler-rt|llvm
git|pack|git|git|git
bubblewrap|grade|bubblewrap|bubblewrap|- (Linux only)
zip|grade, pack|zip unzip|zip unzip|zip
chromium|test (the site in a browser)|chromium|chromium|--cask chromium"""
TABLE = {line.split("|")[0]: line.split("|") for line in TOOLS.splitlines()}
# The C++ libraries, by the name of their CMake package: on Windows vcpkg brings them while
# CMake configures (vcpkg.json).
LIBRARIES = {"catch2-3": "Catch2", "fmt": "fmt", "nlohmann-json": "nlohmann_json", "cli11": "CLI11"}


def wanted_tools():
    """[(id, what needs it)] of the tools this edition uses: the student edition has no grader
    and no browser test; Windows has no bubblewrap, and its sanitizer build is not offered."""
    wanted = []
    for tool_id, row in TABLE.items():
        if tool_id in ("bubblewrap", "zip") and not edition.have_grader():
            continue
        if tool_id == "chromium" and not edition.have_site_tests():
            continue
        if host.windows() and tool_id in ("bubblewrap", "clang"):
            continue
        wanted.append((tool_id, row[1]))
    return wanted


def _catch2_3():
    folder = host.cmake_package_dir("Catch2")
    if folder is None:
        return False
    for version_file in glob.glob(os.path.join(glob.escape(folder), "*ConfigVersion.cmake")):
        try:
            if 'PACKAGE_VERSION "3.' in pathlib.Path(version_file).read_text(errors="replace"):
                return True
        except OSError:
            pass
    return False


def _vcpkg():
    return bool(os.environ.get("VCPKG_ROOT") or host.which("vcpkg"))


def _clang_with_sanitizers():
    clang = host.which("clang++")
    if clang is None:
        return False
    if host.system() != "Linux":
        return True
    run = subprocess.run([clang, f"-print-file-name=libclang_rt.asan-{host.machine()}.a"],
                         capture_output=True, text=True)
    return os.path.isfile(run.stdout.strip())


def tool_found(tool_id):
    if host.windows() and tool_id in LIBRARIES:
        return _vcpkg() or host.cmake_package_dir(LIBRARIES[tool_id]) is not None
    if tool_id == "c++":
        cxx = os.environ.get("CXX", "").split()
        return bool((cxx and host.which(cxx[0])) or host.which("g++", "clang++", "c++", "cl", "clang-cl"))
    if tool_id == "python3":
        return True  # this very program runs on it
    if tool_id == "catch2-3":
        return _catch2_3()
    if tool_id in LIBRARIES:
        return host.cmake_package_dir(LIBRARIES[tool_id]) is not None
    if tool_id == "mathjax2":
        return os.path.isfile(os.path.join(os.environ.get("WORKBOOK_MATHJAX_DIR") or "/usr/share/javascript/mathjax",
                                           "MathJax.js"))
    if tool_id == "doxygen-awesome-css":
        return os.path.isfile(os.path.join(os.environ.get("WORKBOOK_DOXYGEN_AWESOME_DIR")
                                           or "/usr/share/doxygen-awesome-css", "doxygen-awesome.css"))
    if tool_id == "clang":
        return _clang_with_sanitizers()
    if tool_id == "zip":
        return bool(host.which("zip") and host.which("unzip"))
    if tool_id == "bubblewrap":
        return bool(host.which("bwrap"))
    if tool_id == "chromium":
        return bool(host.which("chromium", "chromium-browser", "google-chrome"))
    return bool(host.which(tool_id))


def missing_tools():
    return [(tool_id, needs) for tool_id, needs in wanted_tools() if not tool_found(tool_id)]


def install_advice(missing):
    """What to type on each system for the missing tools; a tool without a package gets a line of its own."""
    lines = ["Install them with:"]
    for name, column, command in (("Fedora", 2, "sudo dnf install"), ("Arch", 3, "sudo pacman -S --needed"),
                                  ("macOS (Homebrew)", 4, "brew install")):
        packages, notes = [], []
        for tool_id, _ in missing:
            field = TABLE[tool_id][column]
            if field.startswith("-"):
                notes.append(f"    {tool_id}: {field[1:].strip()}")
            else:
                packages.append(field)
        lines.append(f"  {name + ':':<17} {command + ' ' + ' '.join(packages) if packages else ''}".rstrip())
        lines += notes
    lines.append(f"  {'Windows:':<17} {windows_advice()}")
    return "\n".join(lines)


# --- apt (Debian, Ubuntu) ------------------------------------------------------------------
def _installed(package):
    run = subprocess.run(["dpkg-query", "-W", "-f=${Status}\n", package], capture_output=True, text=True)
    return run.returncode == 0 and run.stdout.startswith("install ok installed")


def missing_packages():
    missing = []
    for package in PACKAGES:
        if package in ("bubblewrap", "zip", "unzip") and not edition.have_grader():
            continue
        if package == "chromium" and not edition.have_site_tests():
            continue
        if not _installed(package):
            missing.append(package)
    if (edition.ROOT / "tests/pack/test_other_systems.py").is_file():
        missing += [package for package in OTHER_SYSTEMS_PACKAGES if not _installed(package)]
    version = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "catch2"], capture_output=True, text=True)
    if not (version.returncode == 0 and version.stdout.startswith("3.")):
        missing.append("catch2")
    return missing


def as_root(argv):
    """Runs argv as root: directly when root, else through sudo."""
    if os.geteuid() != 0:
        if not host.which("sudo"):
            raise Failure(f"need root to run: {' '.join(argv)}")
        argv = ["sudo", *argv]
    status = subprocess.run(argv).returncode
    if status != 0:
        raise Failure(f"{' '.join(argv)} failed", status)


def _bookworm():
    try:
        return "bookworm" in pathlib.Path("/etc/os-release").read_text()
    except OSError:
        return False


def ensure_backports():
    """Debian bookworm lacks Catch2 3: add bookworm-backports where no package source names it yet."""
    if not _bookworm():
        return
    sources = [pathlib.Path("/etc/apt/sources.list"), *pathlib.Path("/etc/apt/sources.list.d").glob("*")]
    if any(path.is_file() and "bookworm-backports" in path.read_text(errors="replace") for path in sources):
        return
    say("Adding Debian bookworm-backports (for Catch2 3)")
    text = ("Types: deb\nURIs: http://deb.debian.org/debian\nSuites: bookworm-backports\nComponents: main\n"
            "Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg\n")
    argv = ["tee", "/etc/apt/sources.list.d/bookworm-backports.sources"]
    if os.geteuid() != 0:
        argv = ["sudo", *argv]
    subprocess.run(argv, input=text, text=True, stdout=subprocess.DEVNULL, check=True)


def apt_install(packages, options=("--no-install-recommends",)):
    as_root(["env", "DEBIAN_FRONTEND=noninteractive", "apt-get", "install", "-y", "-qq", *options, *packages])


def install_with_apt():
    missing = missing_packages()
    if not missing:
        return
    say(f"Installing missing Debian packages: {' '.join(missing)}")
    ensure_backports()
    as_root(["apt-get", "update", "-qq"])
    regular = [p for p in missing if p != "catch2"]
    if regular:
        apt_install(regular)
    if "catch2" in missing:
        apt_install(["catch2"], ["-t", "bookworm-backports"] if _bookworm() else [])


def have_apt():
    return bool(host.which("apt-get") and host.which("dpkg-query"))


def setup_tools():
    """Makes sure the tools are there (run by every command); returns without a word when they are."""
    missing = missing_tools()
    if not missing:
        return
    if have_apt():
        install_with_apt()
        return
    print("workbook: missing, and no apt to install them with:", file=sys.stderr)
    for tool_id, needs in missing:
        print(f"  {tool_id:<20} needed by {needs}", file=sys.stderr)
    print(install_advice(missing), file=sys.stderr)
    if any(needs == EVERY_COMMAND for _, needs in missing):
        raise Failure("install the tools every command needs (above), then run the command again")
    print("workbook: going on; the commands that need the missing tools will say so.\n", file=sys.stderr)


def install_bench_packages():
    """The benchmark's own packages (Google Benchmark and the peers), apart from what students
    need. Returns True when it installed something (the build must then look for them again)."""
    if not have_apt():
        return False  # elsewhere the peers a system has are used, and the others are rows that say so
    missing = [p for p in BENCH_PACKAGES if not _installed(p)]
    if not missing:
        return False
    say(f"Installing the benchmark's Debian packages: {' '.join(missing)}")
    as_root(["apt-get", "update", "-qq"])
    apt_install(missing)
    return True
