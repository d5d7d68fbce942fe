# What the viewer decides without OpenGL, a window or ImGui (camera motion, reload merging,
# scripts, which files changed): plain C++, like the scene. app/CMakeLists.txt and the fuzz
# project (tests/fuzz) both include this file, so the fuzzed library is the shipped one.
add_library(ptview_viewer_model STATIC
  ${CMAKE_CURRENT_LIST_DIR}/CameraController.cpp
  ${CMAKE_CURRENT_LIST_DIR}/FileWatcher.cpp
  ${CMAKE_CURRENT_LIST_DIR}/SceneInput.cpp
  ${CMAKE_CURRENT_LIST_DIR}/SceneMerge.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ViewerScript.cpp)
target_include_directories(ptview_viewer_model PUBLIC "${CMAKE_CURRENT_LIST_DIR}")
target_link_libraries(ptview_viewer_model PUBLIC ptview_scene ptview_settings PRIVATE ptview_warnings)
