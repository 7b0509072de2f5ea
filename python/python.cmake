# python/python.cmake - `make install` of the Python package python/qdot
# (docs/python.md): the package goes where Debian's python3 finds it, and a
# generated qdot/_paths.py tells it where the installed libqdot.so is.
#
#   prefix /usr        -> /usr/lib/python3/dist-packages/qdot
#   any other prefix P -> P/lib/python3.X/dist-packages/qdot (X: /usr/bin/python3's)
#   -DQDOT_PYTHON_DIR=DIR overrides both (relative: under the prefix).
#
# The prefix is known only when installing (cmake --install --prefix), so the
# directory is chosen then, by python/install_python.cmake.
set(QDOT_PYTHON_DIR "" CACHE STRING
    "Where make install puts the qdot Python package (empty: Debian's dist-packages)")
find_program(QDOT_SYSTEM_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
set(QDOT_PY_MM "3")
if(QDOT_SYSTEM_PYTHON)
  execute_process(COMMAND ${QDOT_SYSTEM_PYTHON} -c
                  "import sys; print('%d.%d' % sys.version_info[:2])"
                  OUTPUT_VARIABLE QDOT_PY_MM OUTPUT_STRIP_TRAILING_WHITESPACE)
endif()
install(CODE "set(QDOT_SRC \"${CMAKE_CURRENT_SOURCE_DIR}\")
set(QDOT_PY_MM \"${QDOT_PY_MM}\")
set(QDOT_PYTHON_DIR \"${QDOT_PYTHON_DIR}\")
set(QDOT_LIBDIR \"${CMAKE_INSTALL_LIBDIR}\")")
install(SCRIPT ${CMAKE_CURRENT_SOURCE_DIR}/python/install_python.cmake)
