# SPDX-License-Identifier: MIT
# Finds SuiteSparse CHOLMOD and UMFPACK from Debian's libsuitesparse-dev,
# which ships neither a CMake config nor a pkg-config file.
# Provides the imported target SuiteSparse::CHOLMOD (with its dependencies).

find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
set(_ff_suitesparse_libs cholmod umfpack amd colamd camd ccolamd suitesparseconfig)
set(CHOLMOD_LIBRARIES "")
foreach(_lib IN LISTS _ff_suitesparse_libs)
  find_library(CHOLMOD_${_lib}_LIBRARY NAMES ${_lib})
  if(CHOLMOD_${_lib}_LIBRARY)
    list(APPEND CHOLMOD_LIBRARIES ${CHOLMOD_${_lib}_LIBRARY})
  endif()
endforeach()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CHOLMOD
  REQUIRED_VARS CHOLMOD_INCLUDE_DIR CHOLMOD_cholmod_LIBRARY CHOLMOD_umfpack_LIBRARY
                CHOLMOD_amd_LIBRARY CHOLMOD_suitesparseconfig_LIBRARY)

if(CHOLMOD_FOUND AND NOT TARGET SuiteSparse::CHOLMOD)
  add_library(SuiteSparse::CHOLMOD INTERFACE IMPORTED)
  set_target_properties(SuiteSparse::CHOLMOD PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${CHOLMOD_LIBRARIES}")
endif()
mark_as_advanced(CHOLMOD_INCLUDE_DIR)
