# The folders of src/ and which of them each may include (src/README.md draws them). Read by the
# folders' CMakeLists.txt, which link each folder's targets to these only, and by
# check_arrows.cmake, which fails the build on an #include "<folder>/..." not listed here.
# The public API (<robottestingframework/...>, include/) belongs to core.
# Inside runner/, runner/arrows.cmake draws the arrows between its own folders.
set(RTF_SRC_FOLDERS platform variables core reporters web dll fixtures languages isolation
    runner)
set(RTF_SRC_USES_platform "")
set(RTF_SRC_USES_variables platform)
set(RTF_SRC_USES_core platform)
set(RTF_SRC_USES_reporters core platform)
set(RTF_SRC_USES_web reporters core platform)
set(RTF_SRC_USES_dll core platform)
set(RTF_SRC_USES_languages fixtures dll core platform)
set(RTF_SRC_USES_fixtures variables core platform)
set(RTF_SRC_USES_isolation languages core platform)
set(RTF_SRC_USES_runner isolation fixtures languages dll web reporters core variables platform)
