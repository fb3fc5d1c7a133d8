; Run by the NSIS uninstaller (CPACK_NSIS_EXTRA_UNINSTALL_COMMANDS): forgets the *.ensil
; association that file-association.nsh made.
DeleteRegKey SHCTX "Software\Classes\ensil.project"
ReadRegStr $0 SHCTX "Software\Classes\.ensil" ""
StrCmp $0 "ensil.project" 0 +2
  DeleteRegKey SHCTX "Software\Classes\.ensil"
System::Call 'shell32::SHChangeNotify(i 0x08000000, i 0, p 0, p 0)'
