# The glTF files of every module checked by real consumers, as two ctest entries:
#   gltf_validator       the Khronos glTF validator (tests/gltf/validate.mjs): no error and
#                        no warning in any file (STRICT files: no info or hint either)
#   gltf_blender_import  Blender's glTF importer (tests/blender/import_gltf.py), one Blender
#                        run for all files, checking the counts given below
# Each skips (ctest SKIP_RETURN_CODE 77) with a message when its tool is absent.
#
# A module adds its files with, e.g. in tests/<module>/CMakeLists.txt:
#
#   add_test(NAME hand_write_glb COMMAND hand_write_glb ${SK_GLTF_CHECK_DIR}/hand)
#   set_tests_properties(hand_write_glb PROPERTIES FIXTURES_SETUP hand_glb)
#   sk_gltf_check(FIXTURE hand_glb FILE ${SK_GLTF_CHECK_DIR}/hand/hand.glb
#                 MESHES 1 JOINTS 20 ANIMATIONS 1 SHAPE_KEYS 0 [STRICT])
#
# FIXTURE names the ctest fixture whose setup test writes the file (ctest runs it first);
# MESHES, JOINTS (bones), ANIMATIONS and SHAPE_KEYS (morph targets, without Blender's
# "Basis") are what Blender must find after importing the file; an omitted count is not
# checked. The checks are created at the end of the configure step, so sk_gltf_check may
# be called from any folder.

set(SK_GLTF_CHECK_DIR ${PROJECT_BINARY_DIR}/tests/tmp/gltf-check)

function(sk_gltf_check)
  cmake_parse_arguments(A "STRICT" "FIXTURE;FILE;MESHES;JOINTS;ANIMATIONS;SHAPE_KEYS" "" ${ARGN})
  if(NOT A_FIXTURE OR NOT A_FILE)
    message(FATAL_ERROR "sk_gltf_check: FIXTURE and FILE are required")
  endif()
  set(expect "${A_FILE}")
  foreach(key MESHES JOINTS ANIMATIONS SHAPE_KEYS)
    if(DEFINED A_${key})
      string(TOLOWER ${key} name)
      string(APPEND expect ":${name}=${A_${key}}")
    endif()
  endforeach()
  if(A_STRICT)
    set_property(GLOBAL APPEND PROPERTY SK_GLTF_STRICT_FILES ${A_FILE})
  else()
    set_property(GLOBAL APPEND PROPERTY SK_GLTF_FILES ${A_FILE})
  endif()
  set_property(GLOBAL APPEND PROPERTY SK_GLTF_EXPECT "${expect}")
  set_property(GLOBAL APPEND PROPERTY SK_GLTF_FIXTURES ${A_FIXTURE})
endfunction()

function(sk_gltf_add_checks)
  get_property(files GLOBAL PROPERTY SK_GLTF_FILES)
  get_property(strict GLOBAL PROPERTY SK_GLTF_STRICT_FILES)
  get_property(expect GLOBAL PROPERTY SK_GLTF_EXPECT)
  get_property(fixtures GLOBAL PROPERTY SK_GLTF_FIXTURES)
  if(NOT expect)
    return()
  endif()
  list(REMOVE_DUPLICATES fixtures)
  find_program(SK_NODE node)
  if(SK_NODE)
    set(args)
    if(strict)
      list(APPEND args --strict ${strict})
    endif()
    if(files)
      list(APPEND args --no-strict ${files})
    endif()
    add_test(NAME gltf_validator COMMAND ${SK_NODE} ${PROJECT_SOURCE_DIR}/tests/gltf/validate.mjs ${args})
  else()
    add_test(NAME gltf_validator COMMAND sh -c "echo 'skip: node is not installed'; exit 77")
  endif()
  set_tests_properties(gltf_validator PROPERTIES FIXTURES_REQUIRED "${fixtures}"
                       SKIP_RETURN_CODE 77 TIMEOUT 120)
  # Blender takes seconds to start and the files are the same in a sanitizer build.
  if(NOT SK_SANITIZE)
    add_test(NAME gltf_blender_import
             COMMAND bash ${PROJECT_SOURCE_DIR}/tests/blender/run.sh
                     ${PROJECT_SOURCE_DIR}/tests/blender/import_gltf.py ${expect})
    set_tests_properties(gltf_blender_import PROPERTIES FIXTURES_REQUIRED "${fixtures}"
                         SKIP_RETURN_CODE 77 TIMEOUT 300)
  endif()
endfunction()

cmake_language(DEFER DIRECTORY ${PROJECT_SOURCE_DIR} CALL sk_gltf_add_checks)
