# macOS disk image (DragNDrop): ensil.app at the image's root next to a link to /Applications.
# The bundle's Info.plist is Info.plist.in here (set on the target in app/CMakeLists.txt, before
# its install rule); macdeployqt, run by the Qt deploy script, copies the libraries into it.
set(CPACK_GENERATOR DragNDrop)

set_source_files_properties(${ENSIL_ICON_ICNS} PROPERTIES MACOSX_PACKAGE_LOCATION Resources)
target_sources(ensil PRIVATE ${ENSIL_ICON_ICNS})
get_filename_component(icns_name ${ENSIL_ICON_ICNS} NAME)
set_target_properties(ensil PROPERTIES
    MACOSX_BUNDLE_BUNDLE_NAME ensil
    MACOSX_BUNDLE_GUI_IDENTIFIER ${ENSIL_APP_ID}
    MACOSX_BUNDLE_ICON_FILE ${icns_name}
    MACOSX_BUNDLE_SHORT_VERSION_STRING ${PROJECT_VERSION}
    MACOSX_BUNDLE_BUNDLE_VERSION ${PROJECT_VERSION}
    MACOSX_BUNDLE_COPYRIGHT "${ENSIL_COPYRIGHT}")

set(CPACK_DMG_VOLUME_NAME "ensil ${PROJECT_VERSION}")
set(CPACK_DMG_FORMAT UDBZ)
