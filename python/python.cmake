# python/python.cmake - `make install` of the Python package python/qdot
# (docs/python.md): the package goes where Debian's python3 finds it, and a
# generated qdot/_paths.py tells it where the installed libqdot.so is.
#
#   prefix /usr        -> /usr/lib/python3/dist-packages/qdot
#   any other prefix P -> P/lib/python3.X/dist-packages/qdot (X: /usr/bin/python3's)
#   -DQDOT_PYTHON_DIR=DIR overrides both (relative: under the prefix).
#
# The package's declarations of libqdot (python/qdot/_lib.py) are the
# headers, preprocessed by python/qdot/_cdef.py into the cffi module
# qdot/_ffi.py: made here at build time (a target of `make`, remade when a
# header changes) and installed with the package.  A source tree's package
# does not need it (it reads ../../include at import).
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
set(QDOT_PY_FFI "")
if(QDOT_SYSTEM_PYTHON)
  execute_process(COMMAND ${QDOT_SYSTEM_PYTHON} -c "import cffi"
                  RESULT_VARIABLE QDOT_NO_CFFI OUTPUT_QUIET ERROR_QUIET)
  if(QDOT_NO_CFFI)
    message(STATUS "python3 has no cffi (apt-get install python3-cffi): "
                   "make install leaves the Python package out")
  else()
    set(QDOT_PY_FFI "${CMAKE_BINARY_DIR}/python/_ffi.py")
    file(GLOB QDOT_PUBLIC_HEADERS CONFIGURE_DEPENDS
         "${CMAKE_CURRENT_SOURCE_DIR}/include/qdot/*.h")
    add_custom_command(OUTPUT ${QDOT_PY_FFI}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/python
      COMMAND ${CMAKE_COMMAND} -E env CC=${CMAKE_C_COMPILER}
              ${QDOT_SYSTEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/python/qdot/_cdef.py
              ${CMAKE_CURRENT_SOURCE_DIR}/include ${QDOT_PY_FFI}
      DEPENDS ${QDOT_PUBLIC_HEADERS} ${CMAKE_CURRENT_SOURCE_DIR}/python/qdot/_cdef.py
      COMMENT "Generating python/_ffi.py (the cffi declarations of include/qdot)")
    add_custom_target(qdot_python_ffi ALL DEPENDS ${QDOT_PY_FFI})
  endif()
endif()
install(CODE "set(QDOT_SRC \"${CMAKE_CURRENT_SOURCE_DIR}\")
set(QDOT_PY_MM \"${QDOT_PY_MM}\")
set(QDOT_PY_FFI \"${QDOT_PY_FFI}\")
set(QDOT_PYTHON_DIR \"${QDOT_PYTHON_DIR}\")
set(QDOT_LIBDIR \"${CMAKE_INSTALL_LIBDIR}\")")
install(SCRIPT ${CMAKE_CURRENT_SOURCE_DIR}/python/install_python.cmake)
