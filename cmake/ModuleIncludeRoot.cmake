# rtf_module_include_root(TARGET MODULE [INTERFACE]): TARGET's headers are included by the path
# of their module under src/ ("runner/plan/run_plan.h" for MODULE runner/plan), and only by what
# links TARGET. src/ itself is never on an include path (that would show every module to
# everyone): each target gets a root of its own in the build tree, holding one link,
# <root>/MODULE -> src/MODULE.
function(rtf_module_include_root target module)
    set(root ${PROJECT_BINARY_DIR}/include-roots/${target})
    get_filename_component(parent ${root}/${module} DIRECTORY)
    file(MAKE_DIRECTORY ${parent})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/src/${module} ${root}/${module} SYMBOLIC)
    if(ARGV2 STREQUAL "INTERFACE")
        target_include_directories(${target} INTERFACE ${root})
    else()
        target_include_directories(${target} PUBLIC ${root})
    endif()
endfunction()
