# Windows installer (NSIS) and a portable ZIP. Layout under the install folder: bin\ensil.exe with
# the DLLs it needs next to it (Qt's through windeployqt, the others found below).
set(CPACK_GENERATOR NSIS ZIP)

configure_file(${CMAKE_CURRENT_LIST_DIR}/ensil.rc.in ${CMAKE_CURRENT_BINARY_DIR}/ensil.rc @ONLY)
target_sources(ensil PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/ensil.rc)

# Not WIN32_EXECUTABLE: ensil is also a command-line tool (info, preprocess, render), and a GUI
# subsystem program has no console to print to.

# The DLLs that are not Qt's (VTK, netCDF, HDF5, oneTBB...), next to ensil.exe; they are looked
# for in the bin/ folders of the prefixes the build found its packages in (vcpkg, conda...).
list(TRANSFORM CMAKE_PREFIX_PATH APPEND /bin OUTPUT_VARIABLE dll_folders)
install(RUNTIME_DEPENDENCY_SET ensil_runtime_dlls
    DESTINATION ${CMAKE_INSTALL_BINDIR}
    DIRECTORIES ${dll_folders}
    PRE_EXCLUDE_REGEXES "^api-ms-" "^ext-ms-" "^Qt6"
    POST_EXCLUDE_REGEXES ".*[Ss]ystem32/.*")
set(CMAKE_INSTALL_SYSTEM_RUNTIME_DESTINATION ${CMAKE_INSTALL_BINDIR})
include(InstallRequiredSystemLibraries)  # the MSVC runtime

set(CPACK_NSIS_PACKAGE_NAME ensil)
set(CPACK_NSIS_DISPLAY_NAME "ensil ${PROJECT_VERSION}")
set(CPACK_NSIS_MUI_ICON ${ENSIL_ICON_ICO})
set(CPACK_NSIS_MUI_UNIICON ${ENSIL_ICON_ICO})
set(CPACK_NSIS_INSTALLED_ICON_NAME bin\\ensil.exe)
set(CPACK_NSIS_URL_INFO_ABOUT ${CPACK_PACKAGE_HOMEPAGE_URL})
set(CPACK_NSIS_ENABLE_UNINSTALL_BEFORE_INSTALL ON)
# Offer to put bin\ on PATH, so `ensil render ...` works from a terminal.
set(CPACK_NSIS_MODIFY_PATH ON)
set(CPACK_CREATE_DESKTOP_LINKS ensil)
file(READ ${CMAKE_CURRENT_LIST_DIR}/file-association.nsh CPACK_NSIS_EXTRA_INSTALL_COMMANDS)
file(READ ${CMAKE_CURRENT_LIST_DIR}/file-association-remove.nsh
     CPACK_NSIS_EXTRA_UNINSTALL_COMMANDS)
