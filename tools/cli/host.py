"""What differs between Linux, macOS and Windows, in one place: lists of paths, the names of
programs, where packages are searched and how a console shows text."""
import glob
import os
import pathlib
import platform
import shutil


def windows():
    return os.name == "nt"


def program_name(name):
    """A program's file name on this system: name.exe on Windows."""
    return name + ".exe" if windows() and not name.endswith(".exe") else name


def built_program(folder, name):
    """The path of a program CMake built into folder: with .exe on Windows, and in the
    configuration's subfolder (Debug/, Release/) when a multi-configuration generator (Visual
    Studio) built it. The plain path when none exists yet, for the error to name."""
    folder = pathlib.Path(folder)
    plain = folder / program_name(name)
    for candidate in [plain] + [folder / config / program_name(name)
                                for config in ("Debug", "RelWithDebInfo", "Release", "MinSizeRel")]:
        if candidate.is_file():
            return candidate
    return plain


def path_list(value):
    """A list of folders from an environment variable such as CMAKE_PREFIX_PATH, split as CMake
    splits it: at ';' on Windows (where ':' follows a drive letter) and at ':' elsewhere."""
    return [part for part in (value or "").split(os.pathsep) if part]


def package_prefixes(environ=None):
    """Where CMake packages are searched: CMAKE_PREFIX_PATH first, then the system's usual places."""
    environ = os.environ if environ is None else environ
    prefixes = path_list(environ.get("CMAKE_PREFIX_PATH"))
    if windows():
        vcpkg = environ.get("VCPKG_ROOT")
        if vcpkg:
            prefixes += sorted(glob.glob(os.path.join(vcpkg, "installed", "*-windows")))
    else:
        prefixes += ["/usr", "/usr/local", "/opt/homebrew", "/opt/local"]
    return prefixes


def cmake_package_dir(name, environ=None):
    """The folder holding a CMake package's <name>Config.cmake (or <name>-config.cmake),
    searched where CMake would look; None when there is none."""
    for prefix in package_prefixes(environ):
        for pattern in (f"lib/cmake/{name}", f"lib64/cmake/{name}", f"lib/*/cmake/{name}", f"share/cmake/{name}",
                        f"share/{name}/cmake", f"share/{name}", f"lib/cmake/{name}-*"):
            for folder in sorted(glob.glob(os.path.join(glob.escape(prefix), pattern))):
                if glob.glob(os.path.join(glob.escape(folder), "*onfig.cmake")):
                    return folder
    return None


def which(*names):
    """The first of the programs found on PATH, or None."""
    for name in names:
        found = shutil.which(name)
        if found:
            return found
    return None


def machine():
    return platform.machine()


def system():
    return platform.system()
