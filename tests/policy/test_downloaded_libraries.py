#!/usr/bin/env python3
"""A library that find_package does not find is downloaded by the first configure (Windows and
macOS without vcpkg or Homebrew's package). That path is taken here with the CMake installed:
cmake/Dependencies.cmake is read with each library's URL and SHA-256 replaced by a local
archive of a stand-in project that defines the library's targets, find_package is disabled for
all four, and a project that calls workbook_require_libraries must configure, have every
library, and see each built target marked SYSTEM (no warning of a library's headers is shown).

CMake 3.25.0 and 3.25.1 pass FetchContent_Declare's SYSTEM on to the download's sub-build, where
it is read as part of URL_HASH: every download failed there while the Debian build, which finds
the packages, passed.

    test_downloaded_libraries.py     exit status 1 and what failed, when it fails"""
import hashlib
import pathlib
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
DEPENDENCIES = ROOT / "cmake" / "Dependencies.cmake"

# Each library's targets as its own CMakeLists.txt defines them: {name: (targets, aliases)}.
LIBRARIES = {
    "Catch2": (["Catch2", "Catch2WithMain"], {"Catch2::Catch2": "Catch2", "Catch2::Catch2WithMain": "Catch2WithMain"}),
    "fmt": (["fmt"], {"fmt::fmt": "fmt"}),
    "nlohmann_json": (["nlohmann_json"], {"nlohmann_json::nlohmann_json": "nlohmann_json"}),
    "CLI11": (["CLI11"], {"CLI11::CLI11": "CLI11"}),
}


def stand_in_archive(folder, name):
    """A .tar.gz of a project named `name` that defines the library's targets; its SHA-256."""
    targets, aliases = LIBRARIES[name]
    source = folder / f"{name}-stand-in"
    (source / "include").mkdir(parents=True)
    lines = ["cmake_minimum_required(VERSION 3.25)", f"project({name} LANGUAGES CXX)"]
    lines += [f"add_library({t} INTERFACE)\ntarget_include_directories({t} INTERFACE ${{CMAKE_CURRENT_SOURCE_DIR}}/include)"
              for t in targets]
    lines += [f"add_library({alias} ALIAS {target})" for alias, target in aliases.items()]
    (source / "CMakeLists.txt").write_text("\n".join(lines) + "\n")
    archive = folder / f"{name}.tar.gz"
    with tarfile.open(archive, "w:gz") as tar:
        tar.add(source, arcname=source.name)
    return archive, hashlib.sha256(archive.read_bytes()).hexdigest()


def main():
    if not shutil.which("cmake"):
        print("cmake is not installed")
        return 1
    with tempfile.TemporaryDirectory() as scratch:
        folder = pathlib.Path(scratch)
        text = DEPENDENCIES.read_text()
        for name in LIBRARIES:
            archive, digest = stand_in_archive(folder, name)
            declaration = re.compile(r"(FetchContent_Declare\(" + name + r"\s+URL\s+)\S+(\s+URL_HASH\s+SHA256=)[0-9a-f]+")
            text, count = declaration.subn(lambda m: m.group(1) + archive.as_uri() + m.group(2) + digest, text)
            if count != 1:
                print(f"{DEPENDENCIES}: no FetchContent_Declare({name} URL ... URL_HASH SHA256=...) to redirect")
                return 1
        (folder / "Dependencies.cmake").write_text(text)
        checks = "\n".join(
            f'get_target_property(_system {t} SYSTEM)\nif(NOT _system)\n  message(FATAL_ERROR "{t} is not SYSTEM")\nendif()'
            for targets, _ in LIBRARIES.values() for t in targets)
        project = folder / "project"
        project.mkdir()
        (project / "CMakeLists.txt").write_text(
            "cmake_minimum_required(VERSION 3.25)\nproject(consumer LANGUAGES CXX)\n"
            f'include("{(folder / "Dependencies.cmake").as_posix()}")\n'
            f"workbook_require_libraries({' '.join(LIBRARIES)})\n{checks}\n")
        configure = subprocess.run(
            ["cmake", "-S", str(project), "-B", str(folder / "build"), "-DWORKBOOK_FETCH_MISSING=ON"] +
            [f"-DCMAKE_DISABLE_FIND_PACKAGE_{name}=ON" for name in LIBRARIES],
            capture_output=True, text=True, timeout=600)
        if configure.returncode != 0:
            print(f"configuring with every library downloaded failed (CMake {cmake_version()}):")
            print((configure.stdout + configure.stderr)[-3000:])
            return 1
    print(f"every library downloaded, built and marked SYSTEM (CMake {cmake_version()})")
    return 0


def cmake_version():
    return subprocess.run(["cmake", "--version"], capture_output=True, text=True).stdout.split("\n")[0].split()[-1]


if __name__ == "__main__":
    sys.exit(main())
