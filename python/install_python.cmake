# python/install_python.cmake - run by `cmake --install`: copies python/qdot
# to the directory python/python.cmake describes, with the build's
# qdot/_ffi.py (the declarations made from the headers), and writes qdot/_paths.py
# with the installed library directory (the package's second place to look
# for libqdot.so, after QDOT_LIB and a build tree next to it).
if(NOT QDOT_PY_FFI)
  message(STATUS "Skipping the Python package: python3 had no cffi at configure time")
  return()
endif()
if(QDOT_PYTHON_DIR)
  set(dir "${QDOT_PYTHON_DIR}")
  if(NOT IS_ABSOLUTE "${dir}")
    set(dir "${CMAKE_INSTALL_PREFIX}/${dir}")
  endif()
elseif(CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  set(dir "/usr/lib/python3/dist-packages")
else()
  set(dir "${CMAKE_INSTALL_PREFIX}/lib/python${QDOT_PY_MM}/dist-packages")
endif()
file(INSTALL "${QDOT_SRC}/python/qdot" DESTINATION "${dir}"
     FILES_MATCHING PATTERN "*.py" PATTERN "_paths.py" EXCLUDE PATTERN "__pycache__" EXCLUDE)
file(INSTALL "${QDOT_PY_FFI}" DESTINATION "${dir}/qdot")
set(paths "$ENV{DESTDIR}${dir}/qdot/_paths.py")
message(STATUS "Installing: ${paths}")
file(WRITE "${paths}" "# qdot/_paths.py - written by make install: where libqdot.so is.\n"
                      "LIBDIR = \"${CMAKE_INSTALL_PREFIX}/${QDOT_LIBDIR}\"\n")
