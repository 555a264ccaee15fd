# cmake -D MANIFEST=<build>/install_manifest_linuxcnc.txt -D FILES=a;b;c -P uninstall.cmake:
# removes what `cmake --install --component linuxcnc` put in place (linuxcnc/CMakeLists.txt): the
# files the install recorded in MANIFEST (its actual prefix), else FILES (the configured paths),
# under the same DESTDIR as the install; says what it removed. A file not there is reported.
if(MANIFEST AND EXISTS "${MANIFEST}")
  file(STRINGS "${MANIFEST}" FILES)
endif()
foreach(f ${FILES})
  set(path "$ENV{DESTDIR}${f}")
  if(EXISTS "${path}" OR IS_SYMLINK "${path}")
    file(REMOVE "${path}")
    if(EXISTS "${path}")
      message(FATAL_ERROR "cannot remove ${path} (permissions? run as the user that installed it)")
    endif()
    message(STATUS "removed ${path}")
  else()
    message(STATUS "not installed: ${path}")
  endif()
endforeach()
if(MANIFEST AND EXISTS "${MANIFEST}")
  file(REMOVE "${MANIFEST}")
endif()
