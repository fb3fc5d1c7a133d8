; Installed with ensil.exe by the NSIS installer (CPACK_NSIS_EXTRA_INSTALL_COMMANDS): *.ensil
; project files open in ensil. SHCTX is HKLM for an all-users install, HKCU otherwise.
WriteRegStr SHCTX "Software\Classes\.ensil" "" "ensil.project"
WriteRegStr SHCTX "Software\Classes\.ensil" "Content Type" "application/x-ensil-project"
WriteRegStr SHCTX "Software\Classes\ensil.project" "" "ensil project"
WriteRegStr SHCTX "Software\Classes\ensil.project\DefaultIcon" "" "$INSTDIR\bin\ensil.exe,0"
WriteRegStr SHCTX "Software\Classes\ensil.project\shell\open\command" "" '"$INSTDIR\bin\ensil.exe" "%1"'
; Tell Explorer that associations changed (SHCNE_ASSOCCHANGED, SHCNF_IDLIST).
System::Call 'shell32::SHChangeNotify(i 0x08000000, i 0, p 0, p 0)'
