#----------------------------------------------------------------
# Generated CMake target import file for configuration "Release".
#----------------------------------------------------------------

# Commands may need to know the format version.
set(CMAKE_IMPORT_FILE_VERSION 1)

# Import target "madd::madd" for configuration "Release"
set_property(TARGET madd::madd APPEND PROPERTY IMPORTED_CONFIGURATIONS RELEASE)
set_target_properties(madd::madd PROPERTIES
  IMPORTED_LINK_INTERFACE_LANGUAGES_RELEASE "CXX"
  IMPORTED_LOCATION_RELEASE "${_IMPORT_PREFIX}/lib/libmadd.a"
  )

list(APPEND _cmake_import_check_targets madd::madd )
list(APPEND _cmake_import_check_files_for_madd::madd "${_IMPORT_PREFIX}/lib/libmadd.a" )

# Commands beyond this point should not need to know the version.
set(CMAKE_IMPORT_FILE_VERSION)
