# The library's modules (docs/architecture.md): each is one folder of src/ and one library,
# named shitsukan-<module>, that links only the modules below it that it calls and the
# outside libraries it needs. The native build (CMakeLists.txt) and the WebAssembly build
# (web/CMakeLists.txt) both read this table.
#
#   sk_module(<name> DIR <folder under src/> [MODULES <module>...] [PACKAGES <package>...])
#
# PACKAGES are the outside libraries by the names of cmake/packages.cmake (the native build
# resolves them to imported targets and pkg-config names; the WebAssembly build compiles
# a module only when it has all of them).
#
# Layers, bottom to top; a module may call only modules of lower layers, and modules of its
# own layer that it names (the hand's surface calls the hand's posture model):
#   base      plain types and helpers
#   models    skin, wood, hand, hand-surface, hand-lod, hand-scan, tissue
#   formats   files (atomic writes, output sets), images (PNG, EXR), formats (meshes,
#             motion, JSON, presets, glTF), hand-formats, tissue-formats
#   render    the ray tracer
#   products  draw (plots, contact sheets), maps (the map sets of skin and wood: layout,
#             store, encodings), hand-products, tissue-products, showcase
set(SK_MODULES "")
# the source tree this table describes, whichever project includes it
get_filename_component(SK_SOURCE_ROOT ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
macro(sk_module name)
  cmake_parse_arguments(SKM "" "DIR" "MODULES;PACKAGES" ${ARGN})
  list(APPEND SK_MODULES ${name})
  set(SK_MODULE_${name}_DIR ${SKM_DIR})
  set(SK_MODULE_${name}_MODULES ${SKM_MODULES})
  # every module's loops are OpenMP pragmas (its threads through the base's helpers)
  set(SK_MODULE_${name}_PACKAGES openmp ${SKM_PACKAGES})
  list(REMOVE_DUPLICATES SK_MODULE_${name}_PACKAGES)
endmacro()

sk_module(base DIR base)
sk_module(skin DIR models/skin MODULES base)
sk_module(wood DIR models/wood MODULES base)
sk_module(hand DIR models/hand MODULES base PACKAGES lapacke)
sk_module(hand-surface DIR models/hand_surface MODULES hand base)
sk_module(hand-lod DIR models/hand_lod MODULES hand-surface hand base PACKAGES meshoptimizer)
sk_module(hand-scan DIR models/hand_scan MODULES hand-surface hand base PACKAGES lapacke)
sk_module(tissue DIR models/tissue MODULES base)
sk_module(files DIR formats/files MODULES base)
sk_module(images DIR formats/images MODULES files base PACKAGES png openexr deflate)
sk_module(formats DIR formats MODULES images files base PACKAGES cjson)
sk_module(hand-formats DIR formats/hand MODULES formats images files hand-scan hand-surface hand base PACKAGES cjson)
sk_module(tissue-formats DIR formats/tissue MODULES formats images files tissue base PACKAGES cjson)
sk_module(render DIR render MODULES formats images files skin wood base PACKAGES embree)
sk_module(draw DIR products/draw MODULES formats images files base)
sk_module(maps DIR products/maps MODULES skin base)
sk_module(hand-products DIR products/hand
          MODULES draw hand-formats formats images files skin hand-scan hand-surface hand base)
sk_module(tissue-products DIR products/tissue
          MODULES draw render tissue-formats formats images files tissue base PACKAGES cjson)
sk_module(showcase DIR products/showcase
          MODULES hand-products tissue-products draw render hand-formats tissue-formats
                  formats images files skin wood hand-lod hand-surface hand tissue base PACKAGES smf cjson)

# The .c (and .cpp) files of a module.
function(sk_module_sources name out)
  file(GLOB srcs CONFIGURE_DEPENDS ${SK_SOURCE_ROOT}/src/${SK_MODULE_${name}_DIR}/*.c
       ${SK_SOURCE_ROOT}/src/${SK_MODULE_${name}_DIR}/*.cpp)
  set(${out} ${srcs} PARENT_SCOPE)
endfunction()
