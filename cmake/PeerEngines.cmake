# The peer engines the accuracy bench measures the workbook against (tools/accuracy/peers.hpp):
# Chipmunk, Box2D and Bullet from Debian's packages (libchipmunk-dev, libbox2d-dev,
# libbullet-dev). They are optional: `./workbook bench` installs them, and a build without one
# leaves it out. workbook_add_peer_engines(target dir) adds dir/peer_<engine>.cpp and the
# engine's library to `target` for each engine found, with WORKBOOK_HAVE_<ENGINE> defined.
# (bench/ finds the same packages for the speed bench under names of its own.)
function(workbook_add_peer_engines target dir)
  find_path(WORKBOOK_PEER_CHIPMUNK_INCLUDE chipmunk/chipmunk.h)
  find_library(WORKBOOK_PEER_CHIPMUNK_LIBRARY chipmunk)
  if(WORKBOOK_PEER_CHIPMUNK_INCLUDE AND WORKBOOK_PEER_CHIPMUNK_LIBRARY)
    target_sources(${target} PRIVATE ${dir}/peer_chipmunk.cpp)
    target_include_directories(${target} SYSTEM PRIVATE ${WORKBOOK_PEER_CHIPMUNK_INCLUDE})
    target_link_libraries(${target} PRIVATE ${WORKBOOK_PEER_CHIPMUNK_LIBRARY})
    target_compile_definitions(${target} PRIVATE WORKBOOK_HAVE_CHIPMUNK)
    # Chipmunk's inline functions in its headers cast the C way.
    set_source_files_properties(${dir}/peer_chipmunk.cpp PROPERTIES COMPILE_OPTIONS "-Wno-old-style-cast;-Wno-conversion;-Wno-pedantic")
  endif()

  find_package(box2d QUIET)
  if(box2d_FOUND)
    target_sources(${target} PRIVATE ${dir}/peer_box2d.cpp)
    target_link_libraries(${target} PRIVATE box2d::box2d)
    # The package's version: Box2D 2.4.1's own b2_version still reads 2.4.0.
    target_compile_definitions(${target} PRIVATE WORKBOOK_HAVE_BOX2D WORKBOOK_BOX2D_VERSION="${box2d_VERSION}")
  endif()

  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(WORKBOOK_PEER_BULLET QUIET IMPORTED_TARGET bullet)
  endif()
  if(WORKBOOK_PEER_BULLET_FOUND)
    target_sources(${target} PRIVATE ${dir}/peer_bullet.cpp)
    target_link_libraries(${target} PRIVATE PkgConfig::WORKBOOK_PEER_BULLET)
    target_compile_definitions(${target} PRIVATE WORKBOOK_HAVE_BULLET)
  endif()
endfunction()
