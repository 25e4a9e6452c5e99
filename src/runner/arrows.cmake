# The runner's folders and which of them each may include (README.md draws the flow). Read by
# CMakeLists.txt, which links each folder's target to these only, and by src/check_arrows.cmake
# (SCOPE runner), which fails the build on an #include "runner/<folder>/..." not listed here.
set(RTF_RUNNER_FOLDERS model suites plan reports schedule execution console history cli)
set(RTF_RUNNER_USES_model "")
set(RTF_RUNNER_USES_suites model)
set(RTF_RUNNER_USES_plan model)
set(RTF_RUNNER_USES_reports model)
set(RTF_RUNNER_USES_schedule plan model)
set(RTF_RUNNER_USES_execution model)
set(RTF_RUNNER_USES_console schedule model)
set(RTF_RUNNER_USES_history "")
set(RTF_RUNNER_USES_cli model suites plan reports schedule execution console history)
