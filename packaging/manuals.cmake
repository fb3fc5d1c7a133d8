# Manual pages (help2man) and bash and zsh completion, made at build time from the built ensil's
# own --help (packaging/make-manuals.sh, make-completions.sh), so neither can drift from the
# option tables; installed by the Linux packages. Not in the sanitizer build (running ensil at
# build time there would need the tests' leak suppressions). Without help2man (a developer's
# machine) only the completion is made; packaging/install-deps.sh installs it, and
# test-package.sh checks the package holds the pages.
set(ensil_manuals_dir ${CMAKE_CURRENT_BINARY_DIR}/man)
set(ensil_completion_dir ${CMAKE_CURRENT_BINARY_DIR}/completion)
find_program(HELP2MAN help2man)
set(ensil_generated ${ensil_completion_dir}/ensil ${ensil_completion_dir}/_ensil)
add_custom_command(OUTPUT ${ensil_generated}
    COMMAND ${PROJECT_SOURCE_DIR}/packaging/make-completions.sh $<TARGET_FILE:ensil>
            ${ensil_completion_dir}
    DEPENDS ensil ${PROJECT_SOURCE_DIR}/packaging/make-completions.sh
    COMMENT "Shell completion from ensil --help" VERBATIM)
install(FILES ${ensil_completion_dir}/ensil
        DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/bash-completion/completions)
install(FILES ${ensil_completion_dir}/_ensil
        DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/zsh/vendor-completions)
if(HELP2MAN)
    # One page per command: the stamp stands for the folder, whose page names come from the
    # commands that `ensil --help` lists.
    set(ensil_manuals_stamp ${ensil_manuals_dir}/.made)
    add_custom_command(OUTPUT ${ensil_manuals_stamp}
        COMMAND ${PROJECT_SOURCE_DIR}/packaging/make-manuals.sh $<TARGET_FILE:ensil>
                ${PROJECT_VERSION} ${ensil_manuals_dir}
        COMMAND ${CMAKE_COMMAND} -E touch ${ensil_manuals_stamp}
        DEPENDS ensil ${PROJECT_SOURCE_DIR}/packaging/make-manuals.sh
        COMMENT "Manual pages from ensil --help (help2man)" VERBATIM)
    list(APPEND ensil_generated ${ensil_manuals_stamp})
    install(DIRECTORY ${ensil_manuals_dir}/ DESTINATION ${CMAKE_INSTALL_MANDIR}/man1
            FILES_MATCHING PATTERN "*.1.gz")
else()
    message(STATUS "help2man not found: no manual pages (packaging/install-deps.sh installs it)")
endif()
add_custom_target(ensil_manuals ALL DEPENDS ${ensil_generated})

if(ENSIL_BUILD_TESTS)
    # The bash completion as bash runs it: a command's options after "-", the commands first.
    add_test(NAME packaging.completion_offers_the_parsers_options
        COMMAND bash -c "source '${ensil_completion_dir}/ensil'
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
