# Linux packages: a Debian package and a tarball of the same install tree (GNUInstallDirs layout
# under /usr: bin/, share/applications, share/icons/hicolor, share/metainfo, share/mime/packages).
set(CPACK_GENERATOR DEB TGZ)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # ensil_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# dpkg-shlibdeps turns every library ensil links (Qt, VTK, netCDF, HDF5, TBB...) into a
# dependency with the right version.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# What ensil loads at run time through plugins and dispatchers, which dpkg-shlibdeps cannot see:
#   libqt6svg6        Qt's SVG icon engine and image plugin: without it the window has no icon.
#   libgl1-mesa-dri, libegl-mesa0
#                     an OpenGL 4.1 driver for GLX and EGL (Mesa; llvmpipe where there is no
#                     GPU). Debian 12's libglx0 and libegl1 pull these in too; naming them
#                     states what ensil needs instead of relying on that.
# Debian 12's libqt6gui6 holds the xcb and offscreen platform plugins itself; qt6-qpa-plugins
# only adds VNC and TUIO, so it is not needed.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6svg6, libgl1-mesa-dri, libegl-mesa0")
# The Python module (python/CMakeLists.txt) under /usr/lib/python3/dist-packages: the
# interpreter it was built for (its ABI tag names one minor version) and NumPy, which
# dpkg-shlibdeps cannot see either (an extension module links no libpython).
if(ENSIL_PYTHON_PACKAGE_DEPENDS)
    string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", ${ENSIL_PYTHON_PACKAGE_DEPENDS}")
endif()
# Native Wayland windows (without it, Qt uses XWayland).
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-wayland")
# `ensil render` on a machine without a display runs under xvfb-run.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "xvfb, xauth")

install(FILES ${CMAKE_CURRENT_LIST_DIR}/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR})
