# CTest checks of `lifthull triangle` (2D meshing, issue #7) against Triangle 1.6 and CGAL,
# included by tests/oracles/CMakeLists.txt after the oracle_cgal_cdt target.
#
# Each test is one tests/oracles/mesh2_case.sh run (1-3 s): the mesher under test is
# `lifthull triangle`, the references Triangle (node triangle/triangle_run.mjs, npm
# triangle-wasm installed by scripts/deps.sh test) and oracle_cgal_cdt; compare_mesh2.py
# decides. Label `oracle`.
#   mesh2_cdt_<input>   lifthull triangle -pQ == CGAL CDT_2 of the domain (identical triangles;
#                       differences that are only exactly-cocircular ties pass, said so)
#   mesh2_q30_<input>   -pq30Q: every angle >= 30 but at small input angles / Triangle's shell
#                       rule, segments kept, holes empty, area exact, count <= 1.15 x Triangle's
#   mesh2_cgal_<input>  -pq20.7Q: the same checks, count <= 1.0 x CGAL Mesh_2's (B = 0.125).
#                       Triangle itself exceeds CGAL on double_hex.poly (198 / 194 = 1.02).
# Inputs: tests/data/triangle (.poly) and tests/data/polygons (earcut JSON rings, even-odd
# domain; oracle_cgal_cdt writes them as a .poly with hole points for lifthull and Triangle).
# Left out: simplified-us-border, water, water-huge, water-huge2 (segments cross: 2, 19, 65,
# 133 proper crossings) and, for the quality checks, water2/3/3b/4 (hole rings lying along other
# rings' edges: the even-odd domain of constrained edges is not the rings' area) and
# water-huge3 (its area check alone takes ~90 s).
find_program(LH_NODE node)
set(LH_MESH2_TRIANGLE_JS ${CMAKE_CURRENT_SOURCE_DIR}/triangle/triangle_run.mjs)
if(NOT TARGET oracle_cgal_cdt OR NOT Python3_FOUND OR NOT LH_NODE
   OR NOT EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/triangle/node_modules/triangle-wasm/triangle.out.wasm)
  message(STATUS "tests/oracles: oracle_cgal_cdt, python3, node or triangle-wasm (npm ci --prefix "
                 "tests/oracles/triangle) missing; mesh2_* tests not built")
  return()
endif()

# -DLH_MESH2_TOOL="node .../triangle_run.mjs" runs the checks on Triangle itself (the harness
# validated against its own reference; every test passes but mesh2_cgal_double_hex).
set(LH_MESH2_TOOL "$<TARGET_FILE:lifthull_cli> triangle" CACHE STRING
    "the mesher the mesh2_* tests check, run as TOOL -SWITCHES FILE.poly")
set(LH_MESH2_DATA ${CMAKE_CURRENT_SOURCE_DIR}/../data)
set(LH_MESH2_ARGS
  --tool "${LH_MESH2_TOOL}"
  --triangle "${LH_NODE} ${LH_MESH2_TRIANGLE_JS}"
  --cgal $<TARGET_FILE:oracle_cgal_cdt>
  --python ${Python3_EXECUTABLE})

# NAME:MODE:INPUT[:--convex | :--ratio=R]
set(LH_MESH2_CASES
  # the CDT equality set
  A:cdt:triangle/A.poly
  box:cdt:triangle/box.poly:--convex
  double_hex:cdt:triangle/double_hex.poly
  double_hex2:cdt:triangle/double_hex2.poly
  double_hex3:cdt:triangle/double_hex3.poly
  face:cdt:triangle/face.poly
  fish_and_rectangle:cdt:triangle/fish-and-rectangle.poly
  la:cdt:triangle/la.poly
  square_circle_hole:cdt:triangle/square_circle_hole.poly
  boxy:cdt:polygons/boxy.json
  building:cdt:polygons/building.json
  dude:cdt:polygons/dude.json
  earcut:cdt:polygons/earcut.json
  eberly_3:cdt:polygons/eberly-3.json
  eberly_6:cdt:polygons/eberly-6.json
  hilbert:cdt:polygons/hilbert.json
  issue34:cdt:polygons/issue34.json
  issue35:cdt:polygons/issue35.json
  issue52:cdt:polygons/issue52.json
  rain:cdt:polygons/rain.json
  steiner:cdt:polygons/steiner.json
  water2:cdt:polygons/water2.json
  water3:cdt:polygons/water3.json
  water3b:cdt:polygons/water3b.json
  water4:cdt:polygons/water4.json
  water_huge3:cdt:polygons/water-huge3.json
  # -q30 against Triangle (the issue's set)
  A:q30:triangle/A.poly
  face:q30:triangle/face.poly
  la:q30:triangle/la.poly
  box:q30:triangle/box.poly:--convex
  double_hex:q30:triangle/double_hex.poly
  double_hex2:q30:triangle/double_hex2.poly
  double_hex3:q30:triangle/double_hex3.poly
  square_circle_hole:q30:triangle/square_circle_hole.poly
  dude:q30:polygons/dude.json
  eberly_6:q30:polygons/eberly-6.json
  issue35:q30:polygons/issue35.json
  # 20.7 degrees against CGAL Mesh_2
  A:cgal20.7:triangle/A.poly
  face:cgal20.7:triangle/face.poly
  la:cgal20.7:triangle/la.poly
  box:cgal20.7:triangle/box.poly:--convex
  double_hex:cgal20.7:triangle/double_hex.poly
  double_hex2:cgal20.7:triangle/double_hex2.poly
  double_hex3:cgal20.7:triangle/double_hex3.poly
  square_circle_hole:cgal20.7:triangle/square_circle_hole.poly
  dude:cgal20.7:polygons/dude.json)

foreach(case IN LISTS LH_MESH2_CASES)
  string(REPLACE ":" ";" c "${case}")
  list(GET c 0 name)
  list(GET c 1 mode)
  list(GET c 2 input)
  list(LENGTH c len)
  set(extra)
  if(len GREATER 3)
    list(GET c 3 extra)
    string(REPLACE "=" ";" extra "${extra}") # --ratio=R -> --ratio R
  endif()
  string(REPLACE "." "_" tag "${mode}")
  if(mode STREQUAL "cgal20.7")
    set(tag cgal)
  endif()
  add_test(NAME mesh2_${tag}_${name}
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/mesh2_case.sh ${LH_MESH2_ARGS} ${extra}
            ${mode} ${LH_MESH2_DATA}/${input})
  set_tests_properties(mesh2_${tag}_${name} PROPERTIES LABELS oracle TIMEOUT 60)
endforeach()
