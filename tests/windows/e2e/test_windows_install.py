"""The installed Windows tree (`cmake --install`, the windows.e2e.install fixture) stands on its
own, as it does on a user's machine where no build tree exists: every DLL its programs and
libraries import is in its bin\\ or is Windows' own, no build-tree path is written into them,
and a copy moved elsewhere runs C++ plug-ins in worker processes and Lua tests with the worker
and the Lua module of its own tree (a copy without them says which file is missing)."""
import os
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

from conftest import BUILD_DIR, RUNNER, copy_plugins, run_runner, windows_path

PREFIX = Path(os.environ["RTF_INSTALL_PREFIX"])
# The DLLs Windows itself has: what Wine's prefix holds in system32.
SYSTEM32 = Path(os.environ["WINEPREFIX"]) / "drive_c" / "windows" / "system32"
OBJDUMP = "x86_64-w64-mingw32-objdump"
STRIP = "x86_64-w64-mingw32-strip"

# What a user of the Windows build runs and loads.
PROGRAMS = ["robottestingframework-testrunner.exe", "robottestingframework-worker.exe"]
LIBRARIES = ["libRobotTestingFramework.dll", "libRobotTestingFrameworkDll.dll",
             "libRobotTestingFrameworkLua.dll", "libRobotTestingFrameworkWeb.dll"]
MINGW_RUNTIME = ["libstdc++-6.dll", "libgcc_s_seh-1.dll", "libwinpthread-1.dll"]
LUA_MODULE = Path("lib") / "robottestingframework" / "robottestingframework-lua.dll"

LUA_TEST = """TestCase.run = function()
    robottestingframework.testCheck(2 + 2 == 4, "arithmetic holds")
end
"""


def installed_binaries():
    return sorted([*PREFIX.glob("bin/*.exe"), *PREFIX.glob("bin/*.dll"),
                   *PREFIX.glob("lib/robottestingframework/*.dll")])


def imports(binary):
    dump = subprocess.run([OBJDUMP, "-p", str(binary)], capture_output=True, text=True,
                          timeout=60, check=True).stdout
    return re.findall(r"DLL Name: (\S+)", dump)


def test_the_tree_has_the_programs_libraries_module_headers_and_runtime():
    bin_dir = PREFIX / "bin"
    missing = [name for name in PROGRAMS + LIBRARIES + MINGW_RUNTIME
               if not (bin_dir / name).is_file()]
    assert not missing, f"not installed into {bin_dir}: {missing}"
    assert (PREFIX / LUA_MODULE).is_file()
    assert (PREFIX / "include" / "robottestingframework" / "TestCase.h").is_file()
    assert (PREFIX / "lib" / "libRobotTestingFramework.dll.a").is_file()
    # Not where the Linux tree has it: a program in libexec\ would not find bin\'s DLLs.
    assert not (PREFIX / "libexec").exists()


def test_every_imported_dll_is_in_the_tree_or_windows_own():
    bin_names = {path.name.lower() for path in (PREFIX / "bin").glob("*.dll")}
    system_names = {path.name.lower() for path in SYSTEM32.glob("*.dll")}
    assert "kernel32.dll" in system_names  # the prefix is the one the tests run in
    unresolved = {}
    binaries = installed_binaries()
    assert len(binaries) >= len(PROGRAMS + LIBRARIES + MINGW_RUNTIME) + 1
    for binary in binaries:
        names = imports(binary)
        assert names, f"{binary}: objdump found no imports"
        lost = [name for name in names
                if name.lower() not in bin_names and name.lower() not in system_names]
        if lost:
            unresolved[str(binary.relative_to(PREFIX))] = lost
    assert not unresolved, f"imports found neither in bin\\ nor in Windows: {unresolved}"


def test_no_build_tree_path_is_written_into_the_installed_files(tmp_path):
    build = str(BUILD_DIR.resolve())
    forms = {build, windows_path(BUILD_DIR), build.replace("/", "\\")}
    patterns = [form.encode(encoding) for form in forms for encoding in ("utf-8", "utf-16-le")]
    found = []
    for binary in installed_binaries():
        # The debug information names the build folder the compiler ran in; the code and data
        # a program runs with must not.
        stripped = tmp_path / binary.name
        subprocess.run([STRIP, "--strip-debug", "-o", str(stripped), str(binary)], check=True,
                       timeout=60)
        content = stripped.read_bytes()
        found += [f"{binary.name}: {pattern!r}" for pattern in patterns if pattern in content]
    for text_file in [path for path in PREFIX.rglob("*") if path.suffix in (".h", ".txt")]:
        if build in text_file.read_text(errors="replace"):
            found.append(str(text_file))
    assert not found, found


def moved_tree(tmp_path):
    """A copy of the installed tree in another folder, as a user unpacks it."""
    moved = tmp_path / "Robot Testing Framework"
    shutil.copytree(PREFIX, moved)
    return moved


def write_suite(folder):
    folder.mkdir()
    copy_plugins(folder, "passing_test.dll")
    (folder / "check.lua").write_text(LUA_TEST)
    (folder / "suite.xml").write_text(
        '<suite name="moved">\n'
        '  <test name="cpp">passing_test.dll</test>\n'
        '  <test name="lua">check.lua</test>\n'
        '</suite>\n')
    return folder


def run_moved(moved, *args, cwd):
    return run_runner(*args, cwd=cwd, runner=moved / "bin" / RUNNER.name)


def test_a_moved_copy_runs_workers_and_lua_from_its_own_folders(tmp_path):
    moved = moved_tree(tmp_path)
    suite = write_suite(tmp_path / "suite")
    run = run_moved(moved, "-s", "suite.xml", "-o", "junit:r.xml", cwd=suite)
    assert run.returncode == 0, run
    report = ET.parse(suite / "r.xml").getroot()
    cases = {case.get("name"): case for case in report.iter("testcase")}
    assert set(cases) == {"cpp", "lua"}, ET.tostring(report)
    assert all(len(case) == 0 or all(child.tag.startswith("system-") for child in case)
               for case in cases.values()), ET.tostring(report)

    # Without its worker the moved tree does not borrow the build tree's: the runner says
    # which program it misses.
    (moved / "bin" / "robottestingframework-worker.exe").unlink()
    no_worker = run_moved(moved, "-t", "passing_test.dll", cwd=suite)
    assert no_worker.returncode != 0, no_worker
    assert "cannot find robottestingframework-worker" in no_worker.output, no_worker

    # Without its Lua module the Lua test errors, naming the module file of the moved tree.
    (moved / LUA_MODULE).unlink()
    no_lua = run_moved(moved, "-t", "check.lua", "--isolation", "none", cwd=suite)
    assert no_lua.returncode != 0, no_lua
    assert "robottestingframework-lua.dll" in no_lua.output, no_lua
    assert "Robot Testing Framework" in no_lua.output, no_lua
