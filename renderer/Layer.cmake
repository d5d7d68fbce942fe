# ptview_layer(TARGET LAYER), called in a library's folder: makes the folder's headers includable as
# <ptview/LAYER/Name.h>, and only by TARGET and what links it. The folder appears as ptview/LAYER in
# an include directory that holds nothing else, so a header of a layer a library does not link is
# "file not found": the layering of docs/architecture.md is a build rule, not a review comment.
function(ptview_layer target layer)
  set(root "${CMAKE_BINARY_DIR}/layers/${layer}")
  file(MAKE_DIRECTORY "${root}/ptview")
  file(CREATE_LINK "${CMAKE_CURRENT_SOURCE_DIR}" "${root}/ptview/${layer}" SYMBOLIC)
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    target_include_directories(${target} INTERFACE "${root}")
  else()
    target_include_directories(${target} PUBLIC "${root}")
  endif()
endfunction()
