
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/src/decompose/decompose.cpp" "CMakeFiles/madd.dir/src/decompose/decompose.cpp.o" "gcc" "CMakeFiles/madd.dir/src/decompose/decompose.cpp.o.d"
  "/work/main/src/decompose/grading.cpp" "CMakeFiles/madd.dir/src/decompose/grading.cpp.o" "gcc" "CMakeFiles/madd.dir/src/decompose/grading.cpp.o.d"
  "/work/main/src/decompose/grading_state.cpp" "CMakeFiles/madd.dir/src/decompose/grading_state.cpp.o" "gcc" "CMakeFiles/madd.dir/src/decompose/grading_state.cpp.o.d"
  "/work/main/src/decompose/scheduler.cpp" "CMakeFiles/madd.dir/src/decompose/scheduler.cpp.o" "gcc" "CMakeFiles/madd.dir/src/decompose/scheduler.cpp.o.d"
  "/work/main/src/graph/bisect.cpp" "CMakeFiles/madd.dir/src/graph/bisect.cpp.o" "gcc" "CMakeFiles/madd.dir/src/graph/bisect.cpp.o.d"
  "/work/main/src/graph/bisect_connect.cpp" "CMakeFiles/madd.dir/src/graph/bisect_connect.cpp.o" "gcc" "CMakeFiles/madd.dir/src/graph/bisect_connect.cpp.o.d"
  "/work/main/src/graph/bisect_initial.cpp" "CMakeFiles/madd.dir/src/graph/bisect_initial.cpp.o" "gcc" "CMakeFiles/madd.dir/src/graph/bisect_initial.cpp.o.d"
  "/work/main/src/graph/coarsen.cpp" "CMakeFiles/madd.dir/src/graph/coarsen.cpp.o" "gcc" "CMakeFiles/madd.dir/src/graph/coarsen.cpp.o.d"
  "/work/main/src/graph/fm.cpp" "CMakeFiles/madd.dir/src/graph/fm.cpp.o" "gcc" "CMakeFiles/madd.dir/src/graph/fm.cpp.o.d"
  "/work/main/src/graph/graph.cpp" "CMakeFiles/madd.dir/src/graph/graph.cpp.o" "gcc" "CMakeFiles/madd.dir/src/graph/graph.cpp.o.d"
  "/work/main/src/graph/metis_io.cpp" "CMakeFiles/madd.dir/src/graph/metis_io.cpp.o" "gcc" "CMakeFiles/madd.dir/src/graph/metis_io.cpp.o.d"
  "/work/main/src/graph/partition.cpp" "CMakeFiles/madd.dir/src/graph/partition.cpp.o" "gcc" "CMakeFiles/madd.dir/src/graph/partition.cpp.o.d"
  "/work/main/src/kernel/error.cpp" "CMakeFiles/madd.dir/src/kernel/error.cpp.o" "gcc" "CMakeFiles/madd.dir/src/kernel/error.cpp.o.d"
  "/work/main/src/kernel/predicates.cpp" "CMakeFiles/madd.dir/src/kernel/predicates.cpp.o" "gcc" "CMakeFiles/madd.dir/src/kernel/predicates.cpp.o.d"
  "/work/main/src/kernel/resource_limits.cpp" "CMakeFiles/madd.dir/src/kernel/resource_limits.cpp.o" "gcc" "CMakeFiles/madd.dir/src/kernel/resource_limits.cpp.o.d"
  "/work/main/src/kernel/segment_grid.cpp" "CMakeFiles/madd.dir/src/kernel/segment_grid.cpp.o" "gcc" "CMakeFiles/madd.dir/src/kernel/segment_grid.cpp.o.d"
  "/work/main/src/medial/medial.cpp" "CMakeFiles/madd.dir/src/medial/medial.cpp.o" "gcc" "CMakeFiles/madd.dir/src/medial/medial.cpp.o.d"
  "/work/main/src/output/geo.cpp" "CMakeFiles/madd.dir/src/output/geo.cpp.o" "gcc" "CMakeFiles/madd.dir/src/output/geo.cpp.o.d"
  "/work/main/src/output/geojson.cpp" "CMakeFiles/madd.dir/src/output/geojson.cpp.o" "gcc" "CMakeFiles/madd.dir/src/output/geojson.cpp.o.d"
  "/work/main/src/output/poly.cpp" "CMakeFiles/madd.dir/src/output/poly.cpp.o" "gcc" "CMakeFiles/madd.dir/src/output/poly.cpp.o.d"
  "/work/main/src/output/report_json.cpp" "CMakeFiles/madd.dir/src/output/report_json.cpp.o" "gcc" "CMakeFiles/madd.dir/src/output/report_json.cpp.o.d"
  "/work/main/src/output/split.cpp" "CMakeFiles/madd.dir/src/output/split.cpp.o" "gcc" "CMakeFiles/madd.dir/src/output/split.cpp.o.d"
  "/work/main/src/output/subdomains.cpp" "CMakeFiles/madd.dir/src/output/subdomains.cpp.o" "gcc" "CMakeFiles/madd.dir/src/output/subdomains.cpp.o.d"
  "/work/main/src/output/svg.cpp" "CMakeFiles/madd.dir/src/output/svg.cpp.o" "gcc" "CMakeFiles/madd.dir/src/output/svg.cpp.o.d"
  "/work/main/src/output/vtk.cpp" "CMakeFiles/madd.dir/src/output/vtk.cpp.o" "gcc" "CMakeFiles/madd.dir/src/output/vtk.cpp.o.d"
  "/work/main/src/pslg/poly_reader.cpp" "CMakeFiles/madd.dir/src/pslg/poly_reader.cpp.o" "gcc" "CMakeFiles/madd.dir/src/pslg/poly_reader.cpp.o.d"
  "/work/main/src/pslg/poly_writer.cpp" "CMakeFiles/madd.dir/src/pslg/poly_writer.cpp.o" "gcc" "CMakeFiles/madd.dir/src/pslg/poly_writer.cpp.o.d"
  "/work/main/src/pslg/validate.cpp" "CMakeFiles/madd.dir/src/pslg/validate.cpp.o" "gcc" "CMakeFiles/madd.dir/src/pslg/validate.cpp.o.d"
  "/work/main/src/pslg/validate_faces.cpp" "CMakeFiles/madd.dir/src/pslg/validate_faces.cpp.o" "gcc" "CMakeFiles/madd.dir/src/pslg/validate_faces.cpp.o.d"
  "/work/main/src/pslg/validate_intersections.cpp" "CMakeFiles/madd.dir/src/pslg/validate_intersections.cpp.o" "gcc" "CMakeFiles/madd.dir/src/pslg/validate_intersections.cpp.o.d"
  "/work/main/src/quality/metrics.cpp" "CMakeFiles/madd.dir/src/quality/metrics.cpp.o" "gcc" "CMakeFiles/madd.dir/src/quality/metrics.cpp.o.d"
  "/work/main/src/quality/verify_decomposition.cpp" "CMakeFiles/madd.dir/src/quality/verify_decomposition.cpp.o" "gcc" "CMakeFiles/madd.dir/src/quality/verify_decomposition.cpp.o.d"
  "/work/main/src/quality/verify_decomposition_grid.cpp" "CMakeFiles/madd.dir/src/quality/verify_decomposition_grid.cpp.o" "gcc" "CMakeFiles/madd.dir/src/quality/verify_decomposition_grid.cpp.o.d"
  "/work/main/src/quality/verify_decomposition_util.cpp" "CMakeFiles/madd.dir/src/quality/verify_decomposition_util.cpp.o" "gcc" "CMakeFiles/madd.dir/src/quality/verify_decomposition_util.cpp.o.d"
  "/work/main/src/script/commands.cpp" "CMakeFiles/madd.dir/src/script/commands.cpp.o" "gcc" "CMakeFiles/madd.dir/src/script/commands.cpp.o.d"
  "/work/main/src/script/expression.cpp" "CMakeFiles/madd.dir/src/script/expression.cpp.o" "gcc" "CMakeFiles/madd.dir/src/script/expression.cpp.o.d"
  "/work/main/src/script/expression_parser.cpp" "CMakeFiles/madd.dir/src/script/expression_parser.cpp.o" "gcc" "CMakeFiles/madd.dir/src/script/expression_parser.cpp.o.d"
  "/work/main/src/script/script.cpp" "CMakeFiles/madd.dir/src/script/script.cpp.o" "gcc" "CMakeFiles/madd.dir/src/script/script.cpp.o.d"
  "/work/main/src/script/set.cpp" "CMakeFiles/madd.dir/src/script/set.cpp.o" "gcc" "CMakeFiles/madd.dir/src/script/set.cpp.o.d"
  "/work/main/src/split/chord.cpp" "CMakeFiles/madd.dir/src/split/chord.cpp.o" "gcc" "CMakeFiles/madd.dir/src/split/chord.cpp.o.d"
  "/work/main/src/split/density.cpp" "CMakeFiles/madd.dir/src/split/density.cpp.o" "gcc" "CMakeFiles/madd.dir/src/split/density.cpp.o.d"
  "/work/main/src/split/ends.cpp" "CMakeFiles/madd.dir/src/split/ends.cpp.o" "gcc" "CMakeFiles/madd.dir/src/split/ends.cpp.o.d"
  "/work/main/src/split/refine.cpp" "CMakeFiles/madd.dir/src/split/refine.cpp.o" "gcc" "CMakeFiles/madd.dir/src/split/refine.cpp.o.d"
  "/work/main/src/split/split.cpp" "CMakeFiles/madd.dir/src/split/split.cpp.o" "gcc" "CMakeFiles/madd.dir/src/split/split.cpp.o.d"
  "/work/main/src/subdivision/check.cpp" "CMakeFiles/madd.dir/src/subdivision/check.cpp.o" "gcc" "CMakeFiles/madd.dir/src/subdivision/check.cpp.o.d"
  "/work/main/src/subdivision/subdivision.cpp" "CMakeFiles/madd.dir/src/subdivision/subdivision.cpp.o" "gcc" "CMakeFiles/madd.dir/src/subdivision/subdivision.cpp.o.d"
  "/work/main/src/subdivision/walk.cpp" "CMakeFiles/madd.dir/src/subdivision/walk.cpp.o" "gcc" "CMakeFiles/madd.dir/src/subdivision/walk.cpp.o.d"
  "/work/main/src/triangulation/cdt_segments.cpp" "CMakeFiles/madd.dir/src/triangulation/cdt_segments.cpp.o" "gcc" "CMakeFiles/madd.dir/src/triangulation/cdt_segments.cpp.o.d"
  "/work/main/src/triangulation/delaunay.cpp" "CMakeFiles/madd.dir/src/triangulation/delaunay.cpp.o" "gcc" "CMakeFiles/madd.dir/src/triangulation/delaunay.cpp.o.d"
  "/work/main/src/triangulation/hilbert.cpp" "CMakeFiles/madd.dir/src/triangulation/hilbert.cpp.o" "gcc" "CMakeFiles/madd.dir/src/triangulation/hilbert.cpp.o.d"
  "/work/main/src/triangulation/triangulation.cpp" "CMakeFiles/madd.dir/src/triangulation/triangulation.cpp.o" "gcc" "CMakeFiles/madd.dir/src/triangulation/triangulation.cpp.o.d"
  "/work/main/src/triangulation/verify.cpp" "CMakeFiles/madd.dir/src/triangulation/verify.cpp.o" "gcc" "CMakeFiles/madd.dir/src/triangulation/verify.cpp.o.d"
  "/work/main/src/triangulation/verify_segments.cpp" "CMakeFiles/madd.dir/src/triangulation/verify_segments.cpp.o" "gcc" "CMakeFiles/madd.dir/src/triangulation/verify_segments.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
