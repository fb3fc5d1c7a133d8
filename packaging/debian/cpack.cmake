# Linux packages: a Debian package and a tarball of the same install tree (GNUInstallDirs layout
# under /usr: bin/, share/applications, share/icons/hicolor, share/metainfo, share/mime/packages).
set(CPACK_GENERATOR DEB TGZ)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # ensil_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# dpkg-shlibdeps turns every library ensil links (Qt, VTK, netCDF, HDF5, TBB...) into a
# dependency with the right version.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# What ensil loads at run time that no linked library names, so dpkg-shlibdeps cannot see it:
#   qt6-qpa-plugins   Qt's platform plugins (xcb, wayland, offscreen); libqt6gui6 only
#                     recommends them, and without one no window or offscreen context opens.
#   libqt6svg6        Qt's SVG icon engine and image plugin, for the window icon.
#   libgl1-mesa-dri, libegl-mesa0
#                     an OpenGL 4.1 driver (Mesa; llvmpipe where there is no GPU). The
#                     libglvnd dispatchers Qt links only recommend a driver.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins, libqt6svg6, libgl1-mesa-dri, libegl-mesa0")
# `ensil render` on a machine without a display runs under xvfb-run.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "xvfb, xauth")

install(FILES ${CMAKE_CURRENT_LIST_DIR}/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR})
