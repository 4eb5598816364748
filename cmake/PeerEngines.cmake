# The peer engines the benches measure the workbook against (tools/accuracy/peers.hpp, the gas
# and the pile of bench/): Chipmunk, Box2D and Bullet from Debian's packages (libchipmunk-dev,
# libbox2d-dev, libbullet-dev). They are optional: `./workbook bench` installs them, and a build
# without one leaves it out. workbook_add_peer_engines(target prefix) adds <prefix>_<engine>.cpp
# (accuracy/peer_box2d.cpp, pile_box2d.cpp) and the engine's library to `target` for each
# engine found, with WORKBOOK_HAVE_<ENGINE> defined.
function(workbook_add_peer_engines target prefix)
  find_path(WORKBOOK_PEER_CHIPMUNK_INCLUDE chipmunk/chipmunk.h)
  find_library(WORKBOOK_PEER_CHIPMUNK_LIBRARY chipmunk)
  if(WORKBOOK_PEER_CHIPMUNK_INCLUDE AND WORKBOOK_PEER_CHIPMUNK_LIBRARY)
    target_sources(${target} PRIVATE ${prefix}_chipmunk.cpp)
    target_include_directories(${target} SYSTEM PRIVATE ${WORKBOOK_PEER_CHIPMUNK_INCLUDE})
    target_link_libraries(${target} PRIVATE ${WORKBOOK_PEER_CHIPMUNK_LIBRARY})
    target_compile_definitions(${target} PRIVATE WORKBOOK_HAVE_CHIPMUNK)
    # Chipmunk's inline functions in its headers cast the C way.
    set_source_files_properties(${prefix}_chipmunk.cpp PROPERTIES COMPILE_OPTIONS "-Wno-old-style-cast;-Wno-conversion;-Wno-pedantic")
  endif()

  find_package(box2d QUIET)
  if(box2d_FOUND)
    target_sources(${target} PRIVATE ${prefix}_box2d.cpp)
    target_link_libraries(${target} PRIVATE box2d::box2d)
    # The package's version: Box2D 2.4.1's own b2_version still reads 2.4.0.
    target_compile_definitions(${target} PRIVATE WORKBOOK_HAVE_BOX2D WORKBOOK_BOX2D_VERSION="${box2d_VERSION}")
  endif()

  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(WORKBOOK_PEER_BULLET QUIET IMPORTED_TARGET bullet)
  endif()
  if(WORKBOOK_PEER_BULLET_FOUND)
    target_sources(${target} PRIVATE ${prefix}_bullet.cpp)
    target_link_libraries(${target} PRIVATE PkgConfig::WORKBOOK_PEER_BULLET)
    target_compile_definitions(${target} PRIVATE WORKBOOK_HAVE_BULLET)
  endif()
endfunction()
