# How a script language becomes a module (script_module_interface.h) and a plug-in loader
# library, on every platform (included by CMakeLists.txt here).
# Where the modules are: relative to the program (bin/ or libexec/ of the build or install
# tree), then where they were installed.
set(RTF_LANGUAGE_MODULE_DIR ${CMAKE_INSTALL_LIBDIR}/robottestingframework)
file(RELATIVE_PATH language_relative_dir ${CMAKE_INSTALL_FULL_BINDIR}
     ${CMAKE_INSTALL_FULL_LIBDIR}/robottestingframework)
set_source_files_properties(script_module_loading-${RTF_PLATFORM_FAMILY}.cpp PROPERTIES
    COMPILE_DEFINITIONS
    "RTF_LANGUAGE_RELATIVE_DIR=\"${language_relative_dir}\";RTF_LANGUAGE_INSTALL_DIR=\"${CMAKE_INSTALL_FULL_LIBDIR}/robottestingframework\"")

# rtf_add_language_module(<language> <TYPE> SOURCES <files> LIBRARIES <targets>): the module
# robottestingframework-<language>.so (.dll on Windows). It links the framework's shared
# libraries (one copy of TestCase::current() and the Asserter for the whole process), never
# rtf_languages.
function(rtf_add_language_module language define)
    cmake_parse_arguments(arg "" "" "SOURCES;LIBRARIES" ${ARGN})
    set(target rtf_language_${language})
    add_library(${target} MODULE ${arg_SOURCES})
    target_link_libraries(${target} PRIVATE rtf_language_headers RobotTestingFramework::RTF
                          RobotTestingFramework::RTF_dll ${arg_LIBRARIES} rtf_warnings)
    # Everything it needs is linked in: a missing symbol fails the build, not the first test.
    target_link_options(${target} PRIVATE -Wl,--no-undefined)
    set_target_properties(${target} PROPERTIES
        PREFIX ""
        OUTPUT_NAME robottestingframework-${language}
        LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/${RTF_LANGUAGE_MODULE_DIR}
        # lib/robottestingframework/ -> lib/, in the build tree as in the install tree.
        INSTALL_RPATH "$ORIGIN/.."
        BUILD_WITH_INSTALL_RPATH ON)
    install(TARGETS ${target} LIBRARY DESTINATION ${RTF_LANGUAGE_MODULE_DIR})
    # The type is supported; whatever links rtf_languages gets the module built first.
    target_compile_definitions(rtf_languages PUBLIC ${define})
    add_dependencies(rtf_languages ${target})
endfunction()

# rtf_add_plugin_loader(<language> <Name> SOURCES <files>): RobotTestingFramework::RTF_<language>,
# the library with <Name>PluginLoader (include/robottestingframework/<language>/) for programs
# that load script tests themselves. It does not link the interpreter: it loads the module on
# the first open(), from lib/robottestingframework/ beside itself.
function(rtf_add_plugin_loader language name)
    cmake_parse_arguments(arg "" "" "SOURCES" ${ARGN})
    set(target RTF_${language})
    add_library(${target} SHARED ${arg_SOURCES})
    add_library(RobotTestingFramework::${target} ALIAS ${target})
    set_target_properties(${target} PROPERTIES
        OUTPUT_NAME RobotTestingFramework${name}
        VERSION ${PROJECT_VERSION}
        SOVERSION ${PROJECT_VERSION_MAJOR}
        EXPORT_NAME ${target})
    target_link_libraries(${target} PUBLIC RobotTestingFramework::RTF
                          PRIVATE rtf_language_modules rtf_warnings)
    target_link_options(${target} PRIVATE -Wl,--no-undefined)
    add_dependencies(${target} rtf_language_${language})  # what it loads, built with it
    rtf_add_rtf2_library_name(${target} robottestingframework-${language})
    install(TARGETS ${target} EXPORT RobotTestingFrameworkTargets
            LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
            RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endfunction()
