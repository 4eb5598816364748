# Where the third-party libraries come from, and which command needs which.
#
#   Catch2 3        the tests, so `check` (the step tests)          required when BUILD_TESTING
#   fmt             the step tests' feedback and the tools          required
#   nlohmann-json   reading scene files: workbook-sim, engine tests optional (see WORKBOOK_SIMULATOR)
#   CLI11           workbook-sim's command line                     optional (see WORKBOOK_SIMULATOR)
#
# Each library is first looked for with find_package: Debian's or Homebrew's packages, or
# vcpkg's (the `windows-*` presets read vcpkg.json through vcpkg's toolchain). One that is not
# found is downloaded and built here with FetchContent, pinned to a release and its SHA-256,
# unless WORKBOOK_FETCH_MISSING is OFF. FETCHCONTENT_SOURCE_DIR_<NAME> (a folder holding the
# library's sources, e.g. FETCHCONTENT_SOURCE_DIR_CATCH2) builds it from that folder instead of
# downloading; CMAKE_DISABLE_FIND_PACKAGE_<Name>=ON skips the search, e.g. for a library built
# for another C++ standard library than the one installed (tests/pack/test_other_systems.py
# does both).
#
# Python is no library of the build: the front end, the figures and the tests written in
# Python need it, the step tests do not (tests/CMakeLists.txt and plots/ look for it).
include(FetchContent)

option(WORKBOOK_FETCH_MISSING
       "Download and build (FetchContent) a library that find_package does not find; needs a network connection once" ON)
option(WORKBOOK_SIMULATOR
       "Build workbook-sim (run, figures, animations), which needs nlohmann-json and CLI11; check does not" ON)

# The release each library is downloaded at: GitHub's archive of the release's tag, whose
# SHA-256 is checked before anything in it is built. Catch2 is the release Debian's backports
# carry, so that a build with a downloaded Catch2 runs the tests as the Linux build does.
FetchContent_Declare(Catch2
  URL https://github.com/catchorg/Catch2/archive/refs/tags/v3.7.1.tar.gz
  URL_HASH SHA256=c991b247a1a0d7bb9c39aa35faf0fe9e19764213f28ffba3109388e62ee0269c
  FIND_PACKAGE_ARGS 3)
FetchContent_Declare(fmt
  URL https://github.com/fmtlib/fmt/archive/refs/tags/11.0.2.tar.gz
  URL_HASH SHA256=6cb1e6d37bdcb756dbbe59be438790db409cdb4868c66e888d5df9f13f7c027f
  FIND_PACKAGE_ARGS)
FetchContent_Declare(nlohmann_json
  URL https://github.com/nlohmann/json/archive/refs/tags/v3.11.3.tar.gz
  URL_HASH SHA256=0d8ef5af7f9794e3263480193c491549b2ba6cc74bb018906202ada498a79406
  FIND_PACKAGE_ARGS 3.10)
FetchContent_Declare(CLI11
  URL https://github.com/CLIUtils/CLI11/archive/refs/tags/v2.4.2.tar.gz
  URL_HASH SHA256=f2d893a65c3b1324c50d4e682c0cdc021dd0477ae2c048544f39eed6654b699a
  FIND_PACKAGE_ARGS)

# The libraries' own options when they are built here: no tests, docs or install rules of theirs.
set(CATCH_INSTALL_DOCS OFF CACHE BOOL "")
set(CATCH_INSTALL_EXTRAS OFF CACHE BOOL "")
set(JSON_BuildTests OFF CACHE BOOL "")
set(CLI11_BUILD_TESTS OFF CACHE BOOL "")
set(CLI11_BUILD_EXAMPLES OFF CACHE BOOL "")
set(CLI11_BUILD_DOCS OFF CACHE BOOL "")

# How to install each library, for the messages below.
set(_workbook_install_Catch2 "Catch2 3 (Debian: libcatch2-dev from bookworm-backports; Homebrew: catch2; vcpkg: catch2)")
set(_workbook_install_fmt "fmt (Debian: libfmt-dev; Homebrew: fmt; vcpkg: fmt)")
set(_workbook_install_nlohmann_json "nlohmann-json 3.10 or newer (Debian: nlohmann-json3-dev; Homebrew: nlohmann-json; vcpkg: nlohmann-json)")
set(_workbook_install_CLI11 "CLI11 (Debian: libcli11-dev; Homebrew: cli11; vcpkg: cli11)")

# Makes each named library available: found, or fetched when WORKBOOK_FETCH_MISSING allows.
# Sets WORKBOOK_HAVE_<name> to ON or OFF. A macro, so that the found packages' imported
# targets are seen by every folder below the one that calls it (the top-level CMakeLists.txt).
set(_workbook_target_Catch2 Catch2::Catch2WithMain)
set(_workbook_target_fmt fmt::fmt)
set(_workbook_target_nlohmann_json nlohmann_json::nlohmann_json)
set(_workbook_target_CLI11 CLI11::CLI11)
set(_workbook_version_Catch2 3)
set(_workbook_version_nlohmann_json 3.10)
# The targets a library built here defines, marked SYSTEM below.
set(_workbook_built_Catch2 Catch2 Catch2WithMain)
set(_workbook_built_fmt fmt)
set(_workbook_built_nlohmann_json nlohmann_json)
set(_workbook_built_CLI11 CLI11)
macro(workbook_use_libraries)
  foreach(_library ${ARGN})
    if(WORKBOOK_FETCH_MISSING)
      FetchContent_MakeAvailable(${_library})
      # A library built here is SYSTEM: its headers are not the workbook's, so no warning of
      # theirs is shown. Set on its targets rather than by FetchContent_Declare's SYSTEM, which
      # CMake 3.25.0 and 3.25.1 pass on to the download's sub-build, where it is read as part
      # of URL_HASH and every download fails ("URL_HASH ... must be ALGO=value").
      foreach(_built ${_workbook_built_${_library}})
        if(TARGET ${_built})
          get_target_property(_imported ${_built} IMPORTED)
          if(NOT _imported)
            set_target_properties(${_built} PROPERTIES SYSTEM ON)
          endif()
        endif()
      endforeach()
    else()
      find_package(${_library} ${_workbook_version_${_library}} QUIET)
    endif()
    if(TARGET ${_workbook_target_${_library}})
      set(WORKBOOK_HAVE_${_library} ON)
    else()
      set(WORKBOOK_HAVE_${_library} OFF)
    endif()
  endforeach()
endmacro()

# A Catch2 built here (downloaded, or from FETCHCONTENT_SOURCE_DIR_CATCH2) is compiled as unity
# files of 32 sources each: about a quarter of the compile time of its hundred files, on a
# student's first configure, in four files that still build side by side.
macro(workbook_compile_fetched_catch2_as_one_file)
  if(TARGET Catch2)
    get_target_property(_imported Catch2 IMPORTED)
    if(NOT _imported)
      set_target_properties(Catch2 Catch2WithMain PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 32)
      target_compile_options(Catch2 PRIVATE $<$<CXX_COMPILER_ID:MSVC>:/bigobj>)  # the sections of a big file
    endif()
  endif()
endmacro()

# Like workbook_use_libraries, and stops configuring, saying what to install, when one is missing.
macro(workbook_require_libraries)
  workbook_use_libraries(${ARGN})
  foreach(_library ${ARGN})
    if(NOT WORKBOOK_HAVE_${_library})
      message(FATAL_ERROR "${_library} was not found. Install ${_workbook_install_${_library}}, "
                          "or configure with -DWORKBOOK_FETCH_MISSING=ON to download it (needs a network connection once).")
    endif()
  endforeach()
endmacro()
