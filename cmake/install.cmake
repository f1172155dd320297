# make install PREFIX=... (cmake --install build --prefix PREFIX): the shared and static library,
# the public headers (include/curvbench/ only; the layers' internal headers are not installed),
# the CMake package (find_package(curvbench CONFIG) -> curvbench::curvbench, shared, and
# curvbench::curvbench_static), the curvbench command, the Python module and the recommendations
# table they read (share/curvbench/recommendations.csv: harness/report/recommend_table.h looks there,
# under the prefix of the program, not under CMAKE_INSTALL_DATADIR) with the advice cases beside it
# (advice_cases.csv: the advice from mesh features, harness/report/advice.h; advice_measured.csv:
# what `recommend --measure` did on the swept meshes, which it quotes).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(CURVBENCH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/curvbench)

install(TARGETS curvbench_shared EXPORT curvbenchTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(FILES ${CURVBENCH_STATIC_ARCHIVE} DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(FILES ${PROJECT_SOURCE_DIR}/include/curvbench/curvbench.h
              ${PROJECT_SOURCE_DIR}/include/curvbench/estimator_options.h
              ${PROJECT_SOURCE_DIR}/include/curvbench/errors.h
              ${PROJECT_SOURCE_DIR}/include/curvbench/status.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/curvbench)
install(EXPORT curvbenchTargets NAMESPACE curvbench:: DESTINATION ${CURVBENCH_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/curvbenchConfig.cmake.in
  ${PROJECT_BINARY_DIR}/curvbenchConfig.cmake INSTALL_DESTINATION ${CURVBENCH_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_LIBDIR CMAKE_INSTALL_INCLUDEDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/curvbenchConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/curvbenchConfig.cmake
              ${PROJECT_BINARY_DIR}/curvbenchConfigVersion.cmake
        DESTINATION ${CURVBENCH_CMAKE_DIR})
if(TARGET curvbench)
  install(TARGETS curvbench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
if(TARGET curvbench_python)
  install(TARGETS curvbench_python LIBRARY DESTINATION ${CURVBENCH_PYTHON_INSTALL_DIR})
endif()
if(EXISTS ${PROJECT_SOURCE_DIR}/results/recommendations.csv)
  install(FILES ${PROJECT_SOURCE_DIR}/results/recommendations.csv DESTINATION share/curvbench)
endif()
foreach(_advice advice_cases.csv advice_measured.csv)
  if(EXISTS ${PROJECT_SOURCE_DIR}/results/${_advice})
    install(FILES ${PROJECT_SOURCE_DIR}/results/${_advice} DESTINATION share/curvbench)
  endif()
endforeach()
