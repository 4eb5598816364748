"""Configuring and building the CMake presets (CMakePresets.json): dev (the whole workbook),
student (what ./workbook check builds) and sanitize (./workbook test's second half). Build
folders are build/<preset>/; each is configured once, then built incrementally."""
import json
import os
import re
import subprocess
import sys

from tools.cli import edition, host, prerequisites
from tools.cli.console import Failure, say

# Cache entries of the peers and of Google Benchmark (bench/CMakeLists.txt,
# cmake/PeerEngines.cmake). A configure made before their packages were installed leaves them
# NOTFOUND; they are forgotten so that the next configure looks again.
PEER_CACHE_ENTRY = re.compile(r"^((?:WORKBOOK_(?:PEER_)?(?:CHIPMUNK|BOX2D|BULLET)\w*)|box2d_DIR|benchmark_DIR|"
                              r"PKG_CONFIG_EXECUTABLE)(?::\w+)?=(.*)$")


def cmake_preset(preset):
    """The CMake preset that makes build/<preset> on this system: on Windows its windows-<preset>
    twin (Visual Studio's compiler, the libraries from vcpkg) where CMakePresets.json has one."""
    if not host.windows():
        return preset
    try:
        presets = json.loads((edition.ROOT / "CMakePresets.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return preset
    names = {p.get("name") for p in presets.get("configurePresets", [])}
    return f"windows-{preset}" if f"windows-{preset}" in names else preset


def _run(argv, **options):
    sys.stdout.flush()
    sys.stderr.flush()
    return subprocess.run(argv, cwd=edition.ROOT, **options)


def configured(preset):
    return (edition.build_dir(preset) / "build.ninja").is_file()


def configure(preset, extra=(), again=False):
    """Configures build/<preset> unless it is already (or again); the log is shown only when it fails."""
    if configured(preset) and not again:
        return
    say(f"Configuring build/{preset}")
    extra = list(extra)
    # The dev preset names g++; a system with another compiler alone (Clang, macOS) uses that.
    if cmake_preset(preset) == "dev" and not host.which("g++"):
        cxx = os.environ.get("CXX") or host.which("clang++", "c++", "cl", "clang-cl")
        if not cxx:
            raise Failure("no C++ compiler found (g++, clang++ or c++)")
        say(f"g++ not found: build/dev uses {cxx}")
        extra.append(f"-DCMAKE_CXX_COMPILER={cxx}")
    log = edition.ROOT / f"build-{preset}.log"
    with open(log, "wb") as out:
        status = _run(["cmake", "--preset", cmake_preset(preset), *extra], stdout=out,
                      stderr=subprocess.STDOUT).returncode
    if status != 0:
        sys.stderr.write(log.read_text(errors="replace"))
        log.unlink()
        raise Failure(f"configuring build/{preset} failed")
    log.unlink()


def build(preset, *targets, to_stderr=False):
    """Installs what is missing, configures once and builds the targets (everything when none)."""
    prerequisites.setup_tools()
    configure(preset)
    say(f"Building build/{preset}" + (f" ({' '.join(targets)})" if targets else ""))
    argv = ["cmake", "--build", "--preset", cmake_preset(preset)]
    if targets:
        argv += ["--target", *targets]
    status = _run(argv, stdout=sys.stderr if to_stderr else None).returncode
    if status != 0:
        raise Failure("", status)


def forget_missing_peers(preset="dev"):
    """The cache entries of the peers that a configure did not find (NOTFOUND), removed, so that
    peers installed since are found. Returns their names."""
    cache = edition.build_dir(preset) / "CMakeCache.txt"
    try:
        lines = cache.read_text(errors="replace").splitlines()
    except OSError:
        return []
    return [m.group(1) for m in map(PEER_CACHE_ENTRY.match, lines) if m and m.group(2).endswith("NOTFOUND")]


def prepare_bench(preset="dev"):
    """Installs the benchmark's packages and makes the build find them: a configure that ran
    before they were installed (./workbook book on a fresh clone) is run again, without its
    NOTFOUND entries."""
    installed = prerequisites.install_bench_packages()
    stale = forget_missing_peers(preset)
    if configured(preset) and (installed or (stale and _packages_changed_since(preset))):
        prerequisites.setup_tools()
        configure(preset, [arg for name in stale for arg in ("-U", name)], again=True)


def _packages_changed_since(preset):
    """Whether the system's packages may have changed since build/<preset> was configured: on
    Debian, dpkg's record is newer than the cache; elsewhere there is no telling, so yes."""
    status = "/var/lib/dpkg/status"
    cache = edition.build_dir(preset) / "CMakeCache.txt"
    try:
        return os.path.getmtime(status) > os.path.getmtime(cache)
    except OSError:
        return True
