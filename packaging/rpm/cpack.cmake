# An RPM for Fedora, RHEL and openSUSE users, of the same install tree as the .deb (built here
# with Debian's rpm tools; packaging/test-rpm.sh inspects it, as CI does). Built only where
# rpmbuild is installed (packaging/install-deps.sh installs `rpm`).
find_program(ENSIL_RPMBUILD rpmbuild)
if(NOT ENSIL_RPMBUILD)
    message(STATUS "ensil: no RPM package (rpmbuild not found)")
    return()
endif()
list(APPEND CPACK_GENERATOR RPM)

set(CPACK_RPM_FILE_NAME RPM-DEFAULT)  # ensil-<version>-<release>.<arch>.rpm
set(CPACK_RPM_PACKAGE_RELEASE 1)
set(CPACK_RPM_PACKAGE_GROUP "Applications/Engineering")
set(CPACK_RPM_PACKAGE_URL ${CPACK_PACKAGE_HOMEPAGE_URL})
set(CPACK_RPM_PACKAGE_DESCRIPTION ${CPACK_PACKAGE_DESCRIPTION})
# rpm's own dependency generator names every shared library ensil links (Qt, VTK, netCDF, HDF5,
# PROJ, ecCodes...) by soname, as dpkg-shlibdeps does for the .deb.
set(CPACK_RPM_PACKAGE_AUTOREQ ON)
set(CPACK_RPM_PACKAGE_AUTOPROV OFF)  # ensil provides no library
# What ensil loads at run time through plugins and dispatchers, which rpm cannot see (as for the
# .deb, debian/cpack.cmake), by Fedora's package names: Qt's SVG plugin for the window's icon,
# and Mesa's OpenGL 4.1 drivers for GLX and EGL.
set(CPACK_RPM_PACKAGE_REQUIRES "qt6-qtsvg, mesa-dri-drivers, mesa-libEGL")
# The Python module: the interpreter's ABI it was built for (python(abi), as Fedora's Python
# packages provide it) and NumPy.
if(ENSIL_PYTHON_RPM_REQUIRES)
    string(APPEND CPACK_RPM_PACKAGE_REQUIRES ", ${ENSIL_PYTHON_RPM_REQUIRES}")
endif()
set(CPACK_RPM_PACKAGE_SUGGESTS "xorg-x11-server-Xvfb")
# The package owns its files, not the system's folders they go into (the filesystem package
# and the desktop, icon and MIME packages own those; owning them too is a conflict).
set(ensil_rpm_system_folders
    /usr/share/applications /usr/share/metainfo /usr/share/mime /usr/share/mime/packages
    /usr/share/icons /usr/share/icons/hicolor /usr/share/man /usr/share/man/man1
    /usr/share/bash-completion /usr/share/bash-completion/completions /usr/share/zsh
    /usr/share/zsh/vendor-completions /usr/lib/python3 /usr/lib/python3/dist-packages)
foreach(size scalable 16x16 24x24 32x32 48x48 64x64 128x128 256x256)
    list(APPEND ensil_rpm_system_folders /usr/share/icons/hicolor/${size}
         /usr/share/icons/hicolor/${size}/apps)
endforeach()
set(CPACK_RPM_EXCLUDE_FROM_AUTO_FILELIST_ADDITION ${ensil_rpm_system_folders})
