# Bash and zsh completion and manual pages (help2man), made at build time from the built
# ensil's own --help by packaging/make-command-help.sh, so neither can drift from the option
# tables; installed by the Linux packages. Not in the sanitizer build (running ensil at build
# time there would need the tests' leak suppressions). Without help2man (a developer's machine)
# only the completion is made; packaging/install-deps.sh installs it, and test-package.sh
# checks that the package holds the pages.
set(ensil_help_dir ${CMAKE_CURRENT_BINARY_DIR}/command-help)
find_program(HELP2MAN help2man)
# The stamp stands for the folder, whose page names come from the commands `ensil --help` lists.
set(ensil_help_stamp ${ensil_help_dir}/.made)
add_custom_command(OUTPUT ${ensil_help_stamp}
    COMMAND ${PROJECT_SOURCE_DIR}/packaging/make-command-help.sh $<TARGET_FILE:ensil>
            ${PROJECT_VERSION} ${ensil_help_dir}
    COMMAND ${CMAKE_COMMAND} -E touch ${ensil_help_stamp}
    DEPENDS ensil ${PROJECT_SOURCE_DIR}/packaging/make-command-help.sh
    COMMENT "Shell completion and manual pages from ensil --help" VERBATIM)
add_custom_target(ensil_command_help ALL DEPENDS ${ensil_help_stamp})
install(FILES ${ensil_help_dir}/completion/ensil
        DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/bash-completion/completions)
install(FILES ${ensil_help_dir}/completion/_ensil
        DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/zsh/vendor-completions)
if(HELP2MAN)
    install(DIRECTORY ${ensil_help_dir}/man/ DESTINATION ${CMAKE_INSTALL_MANDIR}/man1
            FILES_MATCHING PATTERN "*.1.gz")
else()
    message(STATUS "help2man not found: no manual pages (packaging/install-deps.sh installs it)")
endif()

if(ENSIL_BUILD_TESTS)
    # The bash completion as bash runs it: a command's options after "-", the commands first.
    add_test(NAME packaging.completion_offers_the_parsers_options
        COMMAND bash -c "source '${ensil_help_dir}/completion/ensil'
            COMP_WORDS=(ensil render --i); COMP_CWORD=2; _ensil
            [[ \" \${COMPREPLY[*]} \" == *' --iso '* ]] || { echo \"render --i: \${COMPREPLY[*]}\"; exit 1; }
            COMP_WORDS=(ensil stats --q); COMP_CWORD=2; _ensil
            [[ \" \${COMPREPLY[*]} \" == *' --quiet '* ]] || { echo \"stats --q: \${COMPREPLY[*]}\"; exit 1; }
            COMP_WORDS=(ensil pre); COMP_CWORD=1; _ensil
            [[ \" \${COMPREPLY[*]} \" == *' preprocess '* ]] || { echo \"pre: \${COMPREPLY[*]}\"; exit 1; }
            COMP_WORDS=(ensil -); COMP_CWORD=1; _ensil
            [[ \" \${COMPREPLY[*]} \" == *' --version '* ]] || { echo \"-: \${COMPREPLY[*]}\"; exit 1; }")
    set_tests_properties(packaging.completion_offers_the_parsers_options PROPERTIES LABELS packaging)
endif()
