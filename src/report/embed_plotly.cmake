# Embeds the vendored Plotly.js into tribolab_report (included from the top CMakeLists.txt
# before the report library is defined). `make deps` runs `npm ci` in report/vendor, which
# installs the exact version and sha512 hash pinned in report/vendor/package-lock.json;
# see docs/design.md#reports.
set(TRIBOLAB_VENDOR_DIR ${CMAKE_SOURCE_DIR}/report/vendor)
# Plotly's cartesian partial bundle (1.5 MB instead of the full 4.8 MB): its trace types
# (scatter, heatmap, contour, bar, box, histogram, ...) hold the two the reports draw, scatter
# and heatmap (src/report/plotly_json.cpp; checked in plotly_script_test.cpp).
set(TRIBOLAB_PLOTLY_PACKAGE plotly.js-cartesian-dist-min)
set(TRIBOLAB_PLOTLY_CARTESIAN_DIR ${TRIBOLAB_VENDOR_DIR}/node_modules/${TRIBOLAB_PLOTLY_PACKAGE}
    CACHE PATH "Folder of the vendored plotly.js-cartesian-dist-min package")
set(TRIBOLAB_PLOTLY_FILE plotly-cartesian.min.js)
set(plotly_js ${TRIBOLAB_PLOTLY_CARTESIAN_DIR}/${TRIBOLAB_PLOTLY_FILE})
if(NOT EXISTS ${plotly_js} OR NOT EXISTS ${TRIBOLAB_PLOTLY_CARTESIAN_DIR}/package.json)
  message(FATAL_ERROR
    "Plotly.js is not vendored (${plotly_js} is missing). Run `make deps`, or "
    "`npm ci --prefix report/vendor`, then configure again.")
endif()
if(plotly_js MATCHES "[\"\\\\]")
  message(FATAL_ERROR "the path ${plotly_js} must not contain quotes or backslashes")
endif()
file(READ ${TRIBOLAB_PLOTLY_CARTESIAN_DIR}/package.json plotly_package)
string(JSON plotly_version GET ${plotly_package} version)
# The SHA-384 of the vendored file, for the integrity attribute of `--plotly cdn` (html.cpp
# turns the hex digest into base64): computed here, never typed by hand.
file(SHA384 ${plotly_js} plotly_sha384)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${TRIBOLAB_PLOTLY_CARTESIAN_DIR}/package.json ${TRIBOLAB_VENDOR_DIR}/package-lock.json ${plotly_js})
set_source_files_properties(${CMAKE_SOURCE_DIR}/src/report/embedded.cpp PROPERTIES
  OBJECT_DEPENDS ${plotly_js}
  COMPILE_DEFINITIONS "TRIBOLAB_PLOTLY_JS_PATH=\"${plotly_js}\";TRIBOLAB_PLOTLY_VERSION=\"${plotly_version}\";TRIBOLAB_PLOTLY_PACKAGE=\"${TRIBOLAB_PLOTLY_PACKAGE}\";TRIBOLAB_PLOTLY_FILE=\"${TRIBOLAB_PLOTLY_FILE}\";TRIBOLAB_PLOTLY_SHA384=\"${plotly_sha384}\";TRIBOLAB_VERSION=\"${PROJECT_VERSION}\"")
file(SIZE ${plotly_js} plotly_bytes)
message(STATUS "Report: embedding Plotly.js ${plotly_version} (${TRIBOLAB_PLOTLY_PACKAGE}, ${plotly_bytes} bytes) from ${plotly_js}")
