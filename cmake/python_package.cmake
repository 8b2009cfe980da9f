# The Python package libdbs (python/libdbs): the interpreter it is tested with and its
# installation.
#
# DBS_PYTHON: a python3 that imports NumPy (the package's array type): the one CMake finds,
# else Debian's /usr/bin/python3 (a python of a version manager earlier on PATH may lack the
# Debian packages scripts/setup.sh installs). Empty when there is none.
find_package(Python3 COMPONENTS Interpreter QUIET)
set(DBS_PYTHON "")
foreach(candidate ${Python3_EXECUTABLE} /usr/bin/python3)
  if(NOT DBS_PYTHON AND EXISTS "${candidate}")
    execute_process(COMMAND ${candidate} -c "import numpy" RESULT_VARIABLE numpy_missing OUTPUT_QUIET ERROR_QUIET)
    if(numpy_missing EQUAL 0)
      set(DBS_PYTHON ${candidate})
    endif()
  endif()
endforeach()
if(NOT DBS_PYTHON)
  message(STATUS "No python3 with NumPy: the Python package is neither tested nor installed")
endif()

# How the tests run Python on this build: the package from the source tree, this build's
# libdbs. An instrumented libdbs loaded into an uninstrumented python needs the sanitizer
# runtimes first in the process; python's own allocations are not ours to leak-check.
if(DBS_BUILD_SHARED)
  set(DBS_PYTHON_TEST_ENVIRONMENT "DBS_LIBRARY=$<TARGET_FILE:dbs>" "PYTHONPATH=${PROJECT_SOURCE_DIR}/python" "DBS_DATA=${PROJECT_SOURCE_DIR}/data")
  if(DBS_SANITIZE)
    execute_process(COMMAND ${CMAKE_C_COMPILER} -print-file-name=libasan.so OUTPUT_VARIABLE asan_runtime OUTPUT_STRIP_TRAILING_WHITESPACE)
    execute_process(COMMAND ${CMAKE_C_COMPILER} -print-file-name=libubsan.so OUTPUT_VARIABLE ubsan_runtime OUTPUT_STRIP_TRAILING_WHITESPACE)
    list(APPEND DBS_PYTHON_TEST_ENVIRONMENT "LD_PRELOAD=${asan_runtime}:${ubsan_runtime}" "ASAN_OPTIONS=detect_leaks=0")
  endif()
endif()

# `cmake --install` puts the package into the prefix's purelib directory as that python's
# sysconfig names it for the prefix (Debian's python3: .../dist-packages), with _installed.py
# naming the library installed beside it, so `import libdbs` finds it without DBS_LIBRARY.
option(DBS_INSTALL_PYTHON "Install the Python package libdbs (needs a shared libdbs and a python3 with NumPy)" ON)
if(DBS_INSTALL_PYTHON AND DBS_PYTHON AND DBS_BUILD_SHARED)
  install(CODE "
    set(prefix \"\${CMAKE_INSTALL_PREFIX}\")
    execute_process(COMMAND \"${DBS_PYTHON}\" -c \"import sys, sysconfig; print(sysconfig.get_path('purelib', vars={'base': sys.argv[1], 'platbase': sys.argv[1], 'installed_base': sys.argv[1], 'installed_platbase': sys.argv[1]}))\" \"\${prefix}\"
      OUTPUT_VARIABLE purelib OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE failed)
    if(failed OR NOT purelib)
      message(FATAL_ERROR \"cannot ask ${DBS_PYTHON} for its purelib directory under \${prefix}\")
    endif()
    file(INSTALL \"${PROJECT_SOURCE_DIR}/python/libdbs\" DESTINATION \"\${purelib}\" FILES_MATCHING PATTERN \"*.py\")
    set(library \"\${prefix}/${CMAKE_INSTALL_LIBDIR}/$<TARGET_SONAME_FILE_NAME:dbs>\")
    if(IS_ABSOLUTE \"${CMAKE_INSTALL_LIBDIR}\")
      set(library \"${CMAKE_INSTALL_LIBDIR}/$<TARGET_SONAME_FILE_NAME:dbs>\")
    endif()
    # Relative to the package, so that the installed tree may be moved as a whole.
    file(RELATIVE_PATH relative \"\${purelib}/libdbs\" \"\${library}\")
    message(STATUS \"Installing: \$ENV{DESTDIR}\${purelib}/libdbs/_installed.py\")
    file(WRITE \"\$ENV{DESTDIR}\${purelib}/libdbs/_installed.py\" \"# Written by cmake --install: the libdbs this package was installed with.\\nimport os\\n\\nLIBRARY = os.path.normpath(os.path.join(os.path.dirname(__file__), \\\"\${relative}\\\"))\\n\")
  ")
endif()
