# The library as others link it: every layer (core ... harness, api) in one shared library
# libcurvbench.so (target curvbench_shared, exported as curvbench::curvbench) and one static
# archive libcurvbench.a (the layers' archives merged; imported as curvbench::curvbench_static by
# the installed package). Users include only <curvbench/curvbench.h> (include/curvbench/).
set(CURVBENCH_LAYERS cb_api cb_harness cb_harness_run cb_harness_claims cb_harness_readings
                     cb_harness_report cb_harness_model cb_methods cb_meshgen cb_mesh cb_points cb_surfaces cb_core)

add_library(curvbench_shared SHARED ${PROJECT_SOURCE_DIR}/cmake/empty.cpp)
# Every object of every layer (--whole-archive), plus what the layers link.
set(_archives)
foreach(layer ${CURVBENCH_LAYERS})
  list(APPEND _archives $<TARGET_FILE:${layer}>)
endforeach()
target_link_libraries(curvbench_shared
  PRIVATE -Wl,--whole-archive ${_archives} -Wl,--no-whole-archive OpenMP::OpenMP_CXX CGAL::CGAL hwy::hwy
  PUBLIC Eigen3::Eigen)
add_dependencies(curvbench_shared ${CURVBENCH_LAYERS})
target_include_directories(curvbench_shared PUBLIC
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>)
set_target_properties(curvbench_shared PROPERTIES
  OUTPUT_NAME curvbench EXPORT_NAME curvbench
  VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
  LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/lib)
add_library(curvbench::curvbench ALIAS curvbench_shared)

# The static archive: the layers' archives merged with ar's MRI script (no second compilation).
set(_mri ${PROJECT_BINARY_DIR}/libcurvbench.mri)
set(CURVBENCH_STATIC_ARCHIVE ${PROJECT_BINARY_DIR}/lib/libcurvbench.a)
set(_mri_text "CREATE ${CURVBENCH_STATIC_ARCHIVE}\n")
foreach(layer ${CURVBENCH_LAYERS})
  string(APPEND _mri_text "ADDLIB $<TARGET_FILE:${layer}>\n")
endforeach()
string(APPEND _mri_text "SAVE\nEND\n")
file(GENERATE OUTPUT ${_mri} CONTENT "${_mri_text}")
add_custom_command(OUTPUT ${CURVBENCH_STATIC_ARCHIVE}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/lib
  COMMAND ${CMAKE_COMMAND} -E rm -f ${CURVBENCH_STATIC_ARCHIVE}
  COMMAND sh ${PROJECT_SOURCE_DIR}/cmake/merge_archives.sh ${CMAKE_AR} ${_mri}
  DEPENDS ${CURVBENCH_LAYERS} ${_mri}
  COMMENT "Merging the layers into lib/libcurvbench.a")
add_custom_target(curvbench_static ALL DEPENDS ${CURVBENCH_STATIC_ARCHIVE})
