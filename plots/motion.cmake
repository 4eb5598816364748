# Motion pictures (plots/strobe.py, plots/animate.py), included by plots/CMakeLists.txt.
# For every chapter:
#   strobe-<chapter>[-student]   <scene>-strobe[.student].{svg,pdf,png} and the trajectory they
#                                are drawn from, built as part of figures-<chapter>[-student]
#   animations-<chapter>         <scene>.mp4, <scene>.gif and the site player's data; slow, so
#                                only `animations` (./workbook animations) builds them
# plus `animations` (every chapter) and `motion-comparison` (one scene under every responder).
set(_motion_common "${CMAKE_CURRENT_SOURCE_DIR}/motion.py" "${_style}")

function(workbook_strobe_commands chapter kind out_var)
  file(GLOB scenes CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/chapters/${chapter}/scenes/*.json")
  set(out_dir "${CMAKE_BINARY_DIR}/book/figures/${chapter}")
  workbook_simulator_options(${kind} args sims)
  set(stamps "")
  foreach(scene IN LISTS scenes)
    get_filename_component(name "${scene}" NAME_WE)
    set(stamp "${_stamps}/${chapter}/${name}.strobe.${kind}.stamp")
    # The reference's motion shipped for the student edition (plots/reference_runs.py), if any.
    file(GLOB shipped_motion "${PROJECT_SOURCE_DIR}/chapters/${chapter}/reference-runs/${name}.trajectory*.csv")
    add_custom_command(
      OUTPUT "${stamp}"
      COMMAND Python3::Interpreter -m plots.strobe ${chapter} "${out_dir}" --scene "${scene}" ${args}
      COMMAND ${CMAKE_COMMAND} -E touch "${stamp}"
      DEPENDS "${scene}" ${shipped_motion} "${CMAKE_CURRENT_SOURCE_DIR}/strobe.py" "${CMAKE_CURRENT_SOURCE_DIR}/reference_runs.py"
              ${_motion_common} ${sims}
      WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"  # python3 -m plots.<module>: the root of the imports
      COMMENT "Strobe picture: ${chapter}/${name} (${kind}) -> book/figures/${chapter}/"
      VERBATIM)
    list(APPEND stamps "${stamp}")
  endforeach()
  set(${out_var} ${stamps} PARENT_SCOPE)
endfunction()

foreach(chapter IN LISTS WORKBOOK_CHAPTERS)
  foreach(kind IN ITEMS reference student)
    if(kind STREQUAL "reference" AND NOT WORKBOOK_HAVE_SOLUTIONS)
      continue()
    endif()
    workbook_strobe_commands(${chapter} ${kind} stamps)
    set(suffix "")
    if(kind STREQUAL "student")
      set(suffix "-student")
    endif()
    add_custom_target(strobe-${chapter}${suffix} DEPENDS ${stamps})
    add_dependencies(figures-${chapter}${suffix} strobe-${chapter}${suffix})
  endforeach()
  if(NOT WORKBOOK_HAVE_SOLUTIONS)
    add_dependencies(figures-${chapter} strobe-${chapter}-student)
  endif()
endforeach()

# Animations: slow (gnuplot renders every frame), so they are their own targets and not part
# of `figures` or of ./workbook test (which makes one animation to check it).
find_program(WORKBOOK_FFMPEG ffmpeg)
if(WORKBOOK_FFMPEG)
  set(_all_animations "")
  set(_all_student_animations "")
  foreach(chapter IN LISTS WORKBOOK_CHAPTERS)
    file(GLOB scenes CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/chapters/${chapter}/scenes/*.json")
    set(out_dir "${CMAKE_BINARY_DIR}/book/figures/${chapter}")
    foreach(kind IN ITEMS reference student)
      if(kind STREQUAL "reference" AND NOT WORKBOOK_HAVE_SOLUTIONS)
        continue()
      endif()
      set(args "")
      set(suffix "")
      if(kind STREQUAL "student")
        set(suffix "-student")
        if(WORKBOOK_HAVE_SOLUTIONS)
          set(args --student)
        else()
          set(args --no-reference)
        endif()
      endif()
      set(stamps "")
      foreach(scene IN LISTS scenes)
        get_filename_component(name "${scene}" NAME_WE)
        set(stamp "${_stamps}/${chapter}/${name}.animation.${kind}.stamp")
        add_custom_command(
          OUTPUT "${stamp}"
          COMMAND Python3::Interpreter -m plots.animate "${scene}" "${out_dir}" ${args}
          COMMAND ${CMAKE_COMMAND} -E touch "${stamp}"
          DEPENDS "${_stamps}/${chapter}/${name}.strobe.${kind}.stamp" "${CMAKE_CURRENT_SOURCE_DIR}/animate.py"
                  "${CMAKE_CURRENT_SOURCE_DIR}/strobe.py" ${_motion_common}
          WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
          COMMENT "Animation: ${chapter}/${name} (${kind}) -> book/figures/${chapter}/${name}.{mp4,gif}"
          VERBATIM)
        list(APPEND stamps "${stamp}")
      endforeach()
      add_custom_target(animations-${chapter}${suffix} DEPENDS ${stamps})
      if(kind STREQUAL "student")
        list(APPEND _all_student_animations animations-${chapter}${suffix})
      else()
        list(APPEND _all_animations animations-${chapter})
      endif()
    endforeach()
    if(NOT WORKBOOK_HAVE_SOLUTIONS)
      add_custom_target(animations-${chapter} DEPENDS animations-${chapter}-student)
      list(APPEND _all_animations animations-${chapter})
    endif()
  endforeach()
  add_custom_target(animations DEPENDS ${_all_animations})
  add_custom_target(animations-student DEPENDS ${_all_student_animations})
else()
  message(STATUS "ffmpeg not found: the animations targets are not available (apt install ffmpeg)")
endif()

# One scene under every responder the simulator has (plots/comparison/*.json), part of `figures`
# and of every chapter's figures-<chapter> (what `./workbook figures` builds), so that the
# comparison/ folder the README describes is there after any of them; a stamp keeps it to once.
if(WORKBOOK_HAVE_SOLUTIONS)
  file(GLOB _comparison_scenes CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/comparison/*.json")
  set(_comparison_stamp "${_stamps}/comparison.stamp")
  add_custom_command(
    OUTPUT "${_comparison_stamp}"
    COMMAND Python3::Interpreter -m plots.compare "${CMAKE_BINARY_DIR}/book/figures/comparison"
            --sim $<TARGET_FILE:workbook-sim>
    COMMAND ${CMAKE_COMMAND} -E touch "${_comparison_stamp}"
    DEPENDS ${_comparison_scenes} "${CMAKE_CURRENT_SOURCE_DIR}/compare.py" "${CMAKE_CURRENT_SOURCE_DIR}/strobe.py"
            ${_motion_common} workbook-sim
    WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
    COMMENT "Comparison: one scene under every responder -> book/figures/comparison/"
    VERBATIM)
  add_custom_target(motion-comparison DEPENDS "${_comparison_stamp}")
  add_dependencies(figures motion-comparison)
  foreach(chapter IN LISTS WORKBOOK_CHAPTERS)
    add_dependencies(figures-${chapter} motion-comparison)
  endforeach()
endif()
