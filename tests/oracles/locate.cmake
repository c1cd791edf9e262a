# Included at the end of tests/oracles/CMakeLists.txt, so skipped with the xcheck_delaunay_*
# tests (that file returns early when CGAL, Eigen, python3, rbox or qdelaunay is missing; this
# test itself needs only CGAL and python3). xcheck_locate (label `oracle`, ~5 s) checks
# `lifthull locate` exactly against CGAL's locate and nearest_vertex: compare_locate.py, with
# oracle_cgal_locate (Delaunay_triangulation_2/_3), on 2D and 3D uniform, grid and exactly
# cospherical sites.
if(LH_XCHECK_CGAL_TARGET AND Python3_FOUND)
  add_executable(oracle_cgal_locate oracle_cgal_locate.cpp)
  target_link_libraries(oracle_cgal_locate PRIVATE ${LH_XCHECK_CGAL_TARGET})
  # A reference, not code under test: optimized and uninstrumented in every build type.
  set_property(TARGET oracle_cgal_locate PROPERTY COMPILE_OPTIONS "")
  set_property(TARGET oracle_cgal_locate PROPERTY LINK_OPTIONS "")
  target_compile_options(oracle_cgal_locate PRIVATE -O2)
  target_compile_definitions(oracle_cgal_locate PRIVATE NDEBUG CGAL_NDEBUG)
  add_test(NAME xcheck_locate
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/compare_locate.py
            --lifthull $<TARGET_FILE:lifthull_cli> --oracle $<TARGET_FILE:oracle_cgal_locate>)
  set_tests_properties(xcheck_locate PROPERTIES LABELS oracle TIMEOUT 120)
else()
  message(STATUS "tests/oracles: CGAL or python3 missing; xcheck_locate not built")
endif()
